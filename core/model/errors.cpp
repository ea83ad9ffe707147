// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/errors.h"

#include "core/model/diagnostic_catalogue.h"

#include <cmath>

namespace xyt {

InvalidInput::InvalidInput(std::string field, const std::string& reason)
    : std::invalid_argument(field + ": " + reason), field_(std::move(field)), reason_(reason) {}

InvalidInput::InvalidInput(std::string field, const Diagnostic& reason)
    : std::invalid_argument(field + ": " + reason.text), field_(std::move(field)), reason_(reason) {
}

void requireFinite(double value, const std::string& field) {
    if (std::isnan(value))
        throw InvalidInput(field, makeDiagnostic("not_a_number"));
    if (std::isinf(value))
        throw InvalidInput(field, makeDiagnostic("not_finite"));
}

void requirePositive(double value, const std::string& field) {
    requireFinite(value, field);
    if (!(value > 0.0))
        throw InvalidInput(field, makeDiagnostic("not_positive"));
}

void requireNonZero(double value, const std::string& field) {
    requireFinite(value, field);
    if (value == 0.0)
        throw InvalidInput(field, makeDiagnostic("zero"));
}

} // namespace xyt
