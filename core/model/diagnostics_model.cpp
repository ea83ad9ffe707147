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
        XYT_DIAGNOSTIC("point_not_finite", "point %1 is not finite"),
        XYT_DIAGNOSTIC("sample_not_finite", "sample %1 is not finite"),
        XYT_DIAGNOSTIC("not_continuous_proper", "must be a continuous, proper transfer function"),
        XYT_DIAGNOSTIC("not_continuous_strictly_proper",
                       "must be a continuous, strictly proper transfer function"),
        // Joints of composed messages: a caught refusal with its field, lists of findings.
        XYT_DIAGNOSTIC("field_reason", "%1: %2"),
        XYT_DIAGNOSTIC("list_semicolon", "%1; %2"),
        XYT_DIAGNOSTIC("list_comma", "%1, %2"),
        // The refusals of the model types: coefficient lists, polynomials, transfer functions,
        // state space, flexible modes, the table's friction, root matching.
        XYT_DIAGNOSTIC("model_expected_number", "expected a number, got nothing"),
        XYT_DIAGNOSTIC("model_number_out_of_range", "%1 is out of the range of a double"),
        XYT_DIAGNOSTIC("model_not_a_number_text", "%1 is not a number"),
        XYT_DIAGNOSTIC("model_not_a_finite_number_text", "%1 is not a finite number"),
        XYT_DIAGNOSTIC("model_unclosed_bracket", "an opening '[' has no closing ']'"),
        XYT_DIAGNOSTIC("model_too_many_coefficients", "more than %1 coefficients"),
        XYT_DIAGNOSTIC("model_empty_coefficient_list", "the coefficient list is empty"),
        XYT_DIAGNOSTIC("model_damping_ratio", "must be a damping ratio in [0, 1)"),
        XYT_DIAGNOSTIC("model_mode_frequency", "must be 0 (no mode) or a frequency > 0 Hz"),
        XYT_DIAGNOSTIC("model_anti_resonance_frequency",
                       "must be 0 (a resonant pair) or a frequency > 0 Hz"),
        XYT_DIAGNOSTIC("model_anti_resonance_below",
                       "must lie below the resonance (a two-mass model's motor side)"),
        XYT_DIAGNOSTIC("model_zero_polynomial_no_leading",
                       "the zero polynomial has no leading coefficient"),
        XYT_DIAGNOSTIC("model_at_least_degree", "must be at least the degree %1"),
        XYT_DIAGNOSTIC("model_zero_polynomial_no_roots",
                       "the zero polynomial has no finite set of roots"),
        XYT_DIAGNOSTIC("model_root_beyond_double",
                       "has a root beyond the range of a double (its leading coefficient is "
                       "negligible against the others)"),
        XYT_DIAGNOSTIC("model_division_by_zero_polynomial", "division by the zero polynomial"),
        XYT_DIAGNOSTIC("model_root_count", "has %1 roots, expected %2"),
        XYT_DIAGNOSTIC("model_improper_no_realization",
                       "an improper transfer function has no state-space realization"),
        XYT_DIAGNOSTIC("model_already_discrete", "is already discrete"),
        XYT_DIAGNOSTIC("model_discretization_overflows",
                       "the exact discretization over %1 s overflows double precision (a very fast "
                       "pole): use a smaller sample time"),
        XYT_DIAGNOSTIC("model_discretization_loses_precision",
                       "the exact discretization over %1 s loses double precision (a very fast "
                       "pole beside a large gain): its step matrix grows by %2 a step where the "
                       "system grows by %3; use a smaller sample time or rescale the model"),
        XYT_DIAGNOSTIC("model_static_below_coulomb",
                       "must be at least the Coulomb level (or 0 for the Coulomb level)"),
        XYT_DIAGNOSTIC("model_stribeck_velocity",
                       "must be > 0 when the static level is above the Coulomb level"),
        XYT_DIAGNOSTIC("model_compensation_percent", "must be between 0 and 200 %"),
        XYT_DIAGNOSTIC("model_compensation_band", "must be a finite number > 0 (mm/s)"),
        XYT_DIAGNOSTIC("model_sample_time",
                       "sample time must be a finite number >= 0 (0 for continuous)"),
        XYT_DIAGNOSTIC("model_denominator_zero", "the denominator is zero"),
        XYT_DIAGNOSTIC("model_z0_coefficient_zero",
                       "the z^0 coefficient of the denominator must be nonzero"),
        XYT_DIAGNOSTIC("model_continuous_no_zinv", "a continuous system has no z^-1 form"),
        XYT_DIAGNOSTIC("model_improper_no_zinv",
                       "an improper discrete system has no causal z^-1 form"),
        XYT_DIAGNOSTIC("model_different_sample_times",
                       "cannot combine systems with different sample times"),
        XYT_DIAGNOSTIC("model_sign", "must be +1 or -1"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
