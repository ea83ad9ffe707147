// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <string>
#include <string_view>
#include <vector>

namespace xyt {

/// One entry of the catalogue: a code and its English template (%1, %2, ... for the arguments).
struct DiagnosticTemplate {
    const char* code;
    const char* englishTemplate;
};

/// Every coded warning the session evaluation and the contour run give, in one table: the user
/// interface translates each code (ui/session/diagnostic_text.cpp), the CLI prints the English.
const std::vector<DiagnosticTemplate>& diagnosticCatalogue();

/// The English template of @p code. @throws std::out_of_range for a code not in the catalogue
/// (a programming error: every code used is listed there).
const char* diagnosticTemplate(std::string_view code);

/// @p templ with %1 .. %9 replaced by @p args[0] .. @p args[8] (a placeholder without an
/// argument is left as it is).
std::string fillDiagnosticTemplate(std::string_view templ, const std::vector<std::string>& args);

/// The diagnostic @p code with @p args, its text the catalogue's English template filled in.
/// @throws std::out_of_range for a code not in the catalogue.
Diagnostic makeDiagnostic(std::string_view code, std::vector<std::string> args = {});

} // namespace xyt
