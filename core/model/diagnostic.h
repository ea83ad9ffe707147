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
 * and text cannot disagree. An uncoded diagnostic (code empty) carries only its English text:
 * the warnings that are composed from other messages (a reason caught from an exception inside
 * a longer sentence, a list of findings) stay uncoded, and the interface shows their English.
 *
 * A diagnostic reads as its text where a string is expected (for the CLI's and the tests'
 * loops over `const std::string&`), and a plain string makes an uncoded one.
 */
struct Diagnostic {
    std::string code;              ///< catalogue code, e.g. "closed_loop_unstable"; "" = uncoded
    std::vector<std::string> args; ///< the template's %1, %2, ... (numbers already formatted)
    std::string text;              ///< the English message

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
