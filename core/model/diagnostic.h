// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace xyt {

/**
 * A warning of a result, with a code the user interface translates.
 *
 * `text` is the English message (what the CLI prints and the tests compare); `code` names its
 * template in the catalogue (diagnostic_catalogue.h) and `args` fill the template's %1, %2, ...
 * in order, so a translation can say the same with the same numbers. A diagnostic built from
 * its code (makeDiagnostic) has its text made from the catalogue's English template, so code
 * and text cannot disagree. An argument is itself a diagnostic: a number or a name as text
 * (uncoded), or a coded message (a reason caught from an exception and put into a longer
 * sentence), which the interface translates in turn. An uncoded diagnostic (code empty) is
 * English text only: the core gives none to the user; a number or a name is one as an argument.
 *
 * A diagnostic reads as its text where a string is expected (for the CLI's and the tests'
 * loops over `const std::string&`), and a plain string makes an uncoded one.
 */
struct Diagnostic {
    std::string code; ///< catalogue code, e.g. "closed_loop_unstable"; "" = uncoded
    /// The template's %1, %2, ...: a number already formatted (an uncoded diagnostic), or a
    /// coded message of its own (a reason inside a longer sentence), translated in turn.
    std::vector<Diagnostic> args;
    std::string text; ///< the English message

    Diagnostic() = default;
    /// An uncoded diagnostic: @p englishText only.
    Diagnostic(std::string englishText) : text(std::move(englishText)) {}
    Diagnostic(const char* englishText) : text(englishText) {}

    operator const std::string&() const { return text; }
    bool coded() const { return !code.empty(); }

    friend bool operator==(const Diagnostic& a, const Diagnostic& b) {
        return a.code == b.code && a.args == b.args && a.text == b.text;
    }
    friend bool operator==(const Diagnostic& a, const std::string& b) { return a.text == b; }
};

} // namespace xyt
