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
        // Reasons many folders give (use these rather than a code of your own).
        XYT_DIAGNOSTIC("at_least", "must be at least %1"),
        XYT_DIAGNOSTIC("not_negative", "must be >= 0"),
        XYT_DIAGNOSTIC("finite_positive", "must be a finite number greater than zero"),
        XYT_DIAGNOSTIC("finite_not_negative", "must be a finite number >= 0"),
        XYT_DIAGNOSTIC("in_zero_one_open_right", "must be in [0, 1)"),
        XYT_DIAGNOSTIC("in_zero_one_open_left", "must be in (0, 1]"),
        XYT_DIAGNOSTIC("is_empty", "is empty"),
        XYT_DIAGNOSTIC("is_missing", "is missing"),
        XYT_DIAGNOSTIC("has_no_samples", "has no samples"),
        XYT_DIAGNOSTIC("not_finite_value", "is NaN or infinite"),
        XYT_DIAGNOSTIC("not_continuous_proper", "must be a continuous, proper transfer function"),
        XYT_DIAGNOSTIC("not_continuous_strictly_proper",
                       "must be a continuous, strictly proper transfer function"),
        // Joints of composed messages: a caught refusal with its field, lists of findings.
        XYT_DIAGNOSTIC("field_reason", "%1: %2"),
        XYT_DIAGNOSTIC("list_semicolon", "%1; %2"),
        XYT_DIAGNOSTIC("list_comma", "%1, %2"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
