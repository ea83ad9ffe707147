// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <vector>

namespace xyt {

/**
 * y sampled at the times @p t by linear interpolation in (ts, ys) (held at the ends), so that
 * axes with different sample times can be paired for the XY contour. @p ts must be increasing;
 * a time of @p t equal to a sample time of @p ts gives that sample exactly.
 */
std::vector<double> resampleLinear(const std::vector<double>& ts, const std::vector<double>& ys,
                                   const std::vector<double>& t);

/**
 * For each time of @p t, the index of the last sample of @p ts at or before it: the sample whose
 * value a zero-order hold (a digital controller's output register) shows at that time. A time
 * within 1e-9 of the sample period before a sample counts as at it, so that t = k dt and
 * ts = j Ts computed in floating point agree where they are meant to coincide (7 x 0.01 and
 * 1 x 0.07). Times before the first sample give 0. @p ts must be increasing and non-empty.
 */
std::vector<std::size_t> heldSampleIndices(const std::vector<double>& ts,
                                           const std::vector<double>& t);

} // namespace xyt
