// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace xyt {

/**
 * The first key that appears twice in one object of a JSON text, as the JSON path of that key
 * ("axes[1].gt.plant.k0"; array elements as [i]). RFC 8259 leaves duplicate names undefined and
 * readers disagree (Qt keeps the last, others the first), so a file holding them means two
 * different sessions to two programs; the session loader refuses it.
 * Keys are compared after decoding their escapes ("k0" and "k\u0030" are the same key).
 * @p json must already be valid JSON (parse it first); on malformed text the result is
 * unspecified but the scan stays within the text and finishes in linear time.
 */
std::optional<std::string> findDuplicateJsonKey(std::string_view json);

} // namespace xyt
