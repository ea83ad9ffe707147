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

/**
 * Every coded warning and refusal of the core, in one catalogue: the CLI prints the English,
 * the user interface translates each code (ui/session/diagnostic_text.h). The tables are kept
 * per concern (core/model/diagnostics_<concern>.cpp, diagnostic_tables.h); every code is unique
 * across them (checked by tst_diagnostic_catalogue).
 */
const std::vector<DiagnosticTemplate>& diagnosticCatalogue();

/// The English template of @p code. @throws std::out_of_range for a code not in the catalogue
/// (a programming error: every code used is listed there).
const char* diagnosticTemplate(std::string_view code);

/// @p templ with %1 .. %9 replaced by the texts of @p args[0] .. @p args[8] in one pass (an
/// argument's own '%' is not read again; a placeholder without an argument is left as it is).
std::string fillDiagnosticTemplate(std::string_view templ, const std::vector<Diagnostic>& args);

/// The diagnostic @p code with @p args, its text the catalogue's English template filled in.
/// An argument is a formatted number or a name (text), or a coded diagnostic of its own.
/// @throws std::out_of_range for a code not in the catalogue.
Diagnostic makeDiagnostic(std::string_view code, std::vector<Diagnostic> args = {});

/// @p parts joined in order by the joint @p joinCode ("%1; %2": "list_semicolon", "%1, %2":
/// "list_comma"), each part keeping its own code: one part is itself, none an uncoded "".
Diagnostic joinDiagnostics(const std::vector<Diagnostic>& parts,
                           std::string_view joinCode = "list_semicolon");

} // namespace xyt

/**
 * One catalogue entry, in the tables of diagnostics_<concern>.cpp: XYT_DIAGNOSTIC("code",
 * "English template with %1"). The build tells Qt Linguist's lupdate that this spells
 * QT_TRANSLATE_NOOP(context, source) (ui/CMakeLists.txt), so each template is a message of the
 * workbench's catalogue with its code as the context, without Qt in the core.
 */
#define XYT_DIAGNOSTIC(code, englishTemplate)                                                      \
    ::xyt::DiagnosticTemplate {                                                                    \
        code, englishTemplate                                                                      \
    }

namespace xyt {} // namespace xyt
