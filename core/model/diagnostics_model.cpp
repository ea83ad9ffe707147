// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The refusals of core/model: the generic reasons of InvalidInput (errors.cpp) first.
const std::vector<DiagnosticTemplate>& model() {
    static const std::vector<DiagnosticTemplate> table = {
        XYT_DIAGNOSTIC("not_a_number", "must be a number, got NaN"),
        XYT_DIAGNOSTIC("not_finite", "must be finite, got infinity"),
        XYT_DIAGNOSTIC("not_positive", "must be greater than zero"),
        XYT_DIAGNOSTIC("zero", "must be nonzero"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
