// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/errors.h"

#include <cmath>

namespace xyt {

InvalidInput::InvalidInput(std::string field, const std::string& reason)
    : std::invalid_argument(field + ": " + reason), field_(std::move(field)), reason_(reason) {}

void requireFinite(double value, const std::string& field) {
    if (std::isnan(value))
        throw InvalidInput(field, "must be a number, got NaN");
    if (std::isinf(value))
        throw InvalidInput(field, "must be finite, got infinity");
}

void requirePositive(double value, const std::string& field) {
    requireFinite(value, field);
    if (!(value > 0.0))
        throw InvalidInput(field, "must be greater than zero");
}

void requireNonZero(double value, const std::string& field) {
    requireFinite(value, field);
    if (value == 0.0)
        throw InvalidInput(field, "must be nonzero");
}

} // namespace xyt
