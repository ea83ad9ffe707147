// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <stdexcept>
#include <string>

namespace xyt {

/**
 * Invalid input to a core function: a NaN, a zero denominator, a wrong size, a value out of
 * range. what() reads "<field>: <reason>" so a caller can show it next to the field.
 * The core gives every reason as a coded diagnostic (makeDiagnostic, diagnostic_catalogue.h), so
 * the workbench shows it in the user's language (reasonDiagnostic); tst_diagnostic_catalogue
 * fails on a refusal of the core without one. The English constructors serve the programs
 * (the CLI's own option checks).
 */
class InvalidInput : public std::invalid_argument {
public:
    InvalidInput(std::string field, const std::string& reason);
    InvalidInput(std::string field, const char* reason)
        : InvalidInput(std::move(field), std::string(reason)) {}
    /// A coded reason: its English text is the reason.
    InvalidInput(std::string field, const Diagnostic& reason);
    /// The name of the offending input, e.g. "kp" or "plant.den".
    const std::string& field() const noexcept { return field_; }
    /// The reason alone, without the field prefix.
    const std::string& reason() const noexcept { return reason_.text; }
    /// The reason with its code (uncoded, the English alone, when thrown by English text).
    const Diagnostic& reasonDiagnostic() const noexcept { return reason_; }

private:
    std::string field_;
    Diagnostic reason_;
};

/// @throws InvalidInput when @p value is NaN or infinite.
void requireFinite(double value, const std::string& field);
/// @throws InvalidInput unless @p value is finite and > 0.
void requirePositive(double value, const std::string& field);
/// @throws InvalidInput unless @p value is finite and nonzero.
void requireNonZero(double value, const std::string& field);

} // namespace xyt
