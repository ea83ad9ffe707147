// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/study.
const std::vector<DiagnosticTemplate>& study() {
    static const std::vector<DiagnosticTemplate> table = {

        // Reasons the studies share.
        XYT_DIAGNOSTIC("study_from_to", "must be from %1 to %2"),
        XYT_DIAGNOSTIC("study_range_percent", "must be from 0 to below 100 %"),
        XYT_DIAGNOSTIC("study_threads_range", "must be from 0 (all cores) to 1024"),
        XYT_DIAGNOSTIC("study_cancelled_statistics",
                       "cancelled: the statistics cover the plants computed before"),
        // The robustness studies (robustness.cpp, contour_robustness.cpp, plant_uncertainty.cpp).
        XYT_DIAGNOSTIC("study_circle_or_path", "give either a circle or a path"),
        XYT_DIAGNOSTIC("study_time_base_empty", "the time base is empty"),
        XYT_DIAGNOSTIC("study_time_base_not_increasing",
                       "the time base must be finite and increasing (sample %1)"),
        XYT_DIAGNOSTIC("study_coupling_one_grid",
                       "needs both axes on one grid with a direction for each sample"),
        XYT_DIAGNOSTIC("study_nominal_not_finite",
                       "the nominal design's run is not finite (it diverges): there is no contour "
                       "to compare with"),
        XYT_DIAGNOSTIC("study_no_sample_on_segment", "no sample on a measured segment"),
        XYT_DIAGNOSTIC("study_unstable_plant_pairs",
                       "%1 plant pairs are unstable or diverged with these controllers; they are "
                       "listed, not in the statistics"),
        XYT_DIAGNOSTIC("study_unstable_plants",
                       "%1 plants are unstable or diverged with this controller; they are listed, "
                       "not in the statistics"),
        XYT_DIAGNOSTIC("study_no_such_parameter", "no parameter '%1' in this plant (it has %2)"),
        XYT_DIAGNOSTIC("study_covariance_size", "must be %1 x %2 (one row per parameter)"),
        XYT_DIAGNOSTIC("study_covariance_not_finite", "holds a value that is not finite"),
        XYT_DIAGNOSTIC("study_covariance_not_symmetric", "is not symmetric"),
        XYT_DIAGNOSTIC("study_covariance_not_psd", "is not positive semi-definite"),
        XYT_DIAGNOSTIC("study_too_many_corners",
                       "%1 uncertain parameters have too many corners (at most 16 parameters)"),
        XYT_DIAGNOSTIC("study_controller_or_loop",
                       "give either a continuous controller or a discrete loop"),
        XYT_DIAGNOSTIC("study_zpetc_without_design", "ZPETC is enabled without its design"),
        XYT_DIAGNOSTIC("study_reference_too_short",
                       "the reference must hold the run (at least 2 samples) and the preview"),
        XYT_DIAGNOSTIC("study_plant_needs_parameter", "a continuous plant needs the parameter %1"),
        XYT_DIAGNOSTIC("study_continuous_run_samples",
                       "a continuous run has exactly the reference's samples"),
        XYT_DIAGNOSTIC("study_friction_real_poles",
                       "with the table's friction the poles of s^2 + a1 s + a2 must stay real "
                       "(a1^2 >= 4 a2) over the ranges of a1 and a2: narrow them"),
        XYT_DIAGNOSTIC("study_zpetc_sensitivity_needs_zpetc",
                       "the ZPETC sensitivity needs a pole-placement axis with ZPETC enabled"),
        XYT_DIAGNOSTIC("study_no_scale", "give at least one scale"),
        XYT_DIAGNOSTIC("study_scale_reason", "scale %1: %2"),
        // The design sweep and its diagnosis (design_sweep.cpp, sweep_diagnosis.cpp,
        // specification.cpp).
        XYT_DIAGNOSTIC("study_bounds_not_finite", "the bounds must be finite numbers"),
        XYT_DIAGNOSTIC("study_minimum_not_positive", "the minimum must be greater than zero"),
        XYT_DIAGNOSTIC("study_minimum_above_maximum", "the minimum is greater than the maximum"),
        XYT_DIAGNOSTIC("study_count_range", "the count must be from 1 to %1"),
        XYT_DIAGNOSTIC("study_designs_same_length",
                       "wn, kp and the results must have the same length"),
        XYT_DIAGNOSTIC("study_search_needs_feasible", "the search starts from a feasible design"),
        XYT_DIAGNOSTIC("study_outside_search_box", "is outside the search box"),
        XYT_DIAGNOSTIC("study_steps_not_finite", "the steps must be finite and >= 0"),
        XYT_DIAGNOSTIC("study_other_window",
                       "the study measured the settle with another window; run it again"),
        XYT_DIAGNOSTIC("study_sweep_cancelled",
                       "cancelled: %1 of %2 grid points computed, no refinement"),
        XYT_DIAGNOSTIC("study_no_feasible_design", "no design of the grid meets the specification"),
        XYT_DIAGNOSTIC("study_zero_or_more", "must be zero or more"),
        XYT_DIAGNOSTIC("study_phase_margin_at_most_180", "must be at most 180 degrees"),
        XYT_DIAGNOSTIC("study_criterion_stability", "stability"),
        XYT_DIAGNOSTIC("study_criterion_settling_time", "step settling time"),
        XYT_DIAGNOSTIC("study_criterion_overshoot", "step overshoot"),
        XYT_DIAGNOSTIC("study_criterion_clipped_time", "clipped time"),
        XYT_DIAGNOSTIC("study_criterion_tracking_error", "max tracking error"),
        XYT_DIAGNOSTIC("study_criterion_settle_time", "settle time after the move"),
        XYT_DIAGNOSTIC("study_criterion_phase_margin", "phase margin"),
        XYT_DIAGNOSTIC("study_criterion_gain_margin", "gain margin"),
        XYT_DIAGNOSTIC("study_value_seconds", "%1 s"),
        XYT_DIAGNOSTIC("study_value_percent", "%1 %"),
        XYT_DIAGNOSTIC("study_value_percent_of_travel", "%1 % of the travel"),
        XYT_DIAGNOSTIC("study_value_degrees", "%1 deg"),
        XYT_DIAGNOSTIC("study_value_decibels", "%1 dB"),
        XYT_DIAGNOSTIC("study_design_at", "wn = %1 rad/s, kp = %2"),
        XYT_DIAGNOSTIC("study_best_at_upper_edge",
                       "%1 = %2 (the best design) is the upper end of the %3 range %4..%5: the "
                       "optimum may lie above; widen the %6 range beyond %7"),
        XYT_DIAGNOSTIC("study_best_at_lower_edge",
                       "%1 = %2 (the best design) is the lower end of the %3 range %4..%5: the "
                       "optimum may lie below; widen the %6 range below %7"),
        XYT_DIAGNOSTIC("study_none_stable", "no design of the grid is stable"),
        XYT_DIAGNOSTIC("study_none_settles", "no design of the grid settles into the %1 mm window "
                                             "within the run (limit %2 s after the move)"),
        XYT_DIAGNOSTIC("study_limit_fails_everywhere",
                       "the %1 limit (%2) fails at every design of the grid"),
        XYT_DIAGNOSTIC("study_limit_fails_largest", "the %1 limit (%2) fails at every design of "
                                                    "the grid; the largest %3 found is %4 at %5"),
        XYT_DIAGNOSTIC("study_limit_fails_smallest", "the %1 limit (%2) fails at every design of "
                                                     "the grid; the smallest %3 found is %4 at %5"),
        XYT_DIAGNOSTIC("study_change_at_least", "%1 >= %2"),
        XYT_DIAGNOSTIC("study_change_at_most", "%1 <= %2"),
        XYT_DIAGNOSTIC("study_least_violating", "least-violating design: %1 (point %2)"),
        XYT_DIAGNOSTIC("study_least_violating_relaxed",
                       "least-violating design: %1 (point %2); it meets the specification with %3"),
        XYT_DIAGNOSTIC("study_least_violating_no_relaxing",
                       "least-violating design: %1 (point %2); relaxing a limit does not make it "
                       "pass (it clips the actuator, never settles, or has no positive margin)"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
