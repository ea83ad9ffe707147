// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <QString>

namespace xyt::ui {

/**
 * A core warning in the user's language: the translation of its code's template (the same
 * placeholders as the core's English template, diagnostic_catalogue.h) filled with its
 * arguments. An uncoded warning, or a code this table does not know, shows the English text.
 */
QString diagnosticText(const Diagnostic& d);

/// Whether @p code has a translatable template here (tests check every catalogue code has).
bool hasDiagnosticText(const std::string& code);

} // namespace xyt::ui
