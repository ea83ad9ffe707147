// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/analysis.
const std::vector<DiagnosticTemplate>& analysis() {
    static const std::vector<DiagnosticTemplate> table = {
        // core/analysis/coupled_line_loop.cpp
        XYT_DIAGNOSTIC("analysis_model_has_no_state", "has no state"),
        XYT_DIAGNOSTIC("analysis_model_sizes_disagree",
                       "phi (%1 x %2), gamma (%3) and c (%4) sizes disagree"),
        XYT_DIAGNOSTIC("analysis_model_not_finite",
                       "has a coefficient that is not a finite number"),
        XYT_DIAGNOSTIC("analysis_discretization_overflows",
                       "the exact discretization overflows double precision (a very fast pole): "
                       "use a shorter period"),
        XYT_DIAGNOSTIC("analysis_a0_nonzero", "A(0) must be nonzero"),
        XYT_DIAGNOSTIC("analysis_b0_zero", "B(0) must be 0 (a delay of at least one sample)"),
        XYT_DIAGNOSTIC("analysis_f0_nonzero", "F(0) must be nonzero"),
        XYT_DIAGNOSTIC("analysis_axes_periods_differ",
                       "the two axes' models must have the same period"),
        // core/analysis/damping_grid.cpp
        XYT_DIAGNOSTIC("analysis_damping_ratios_range", "each damping ratio must be in [0, 1]"),
        XYT_DIAGNOSTIC("analysis_finite_and_not_negative", "must be finite and >= 0"),
        XYT_DIAGNOSTIC("analysis_exceeds_nyquist", "must not exceed the Nyquist frequency pi/Ts"),
        // core/analysis/frequency_response.cpp
        XYT_DIAGNOSTIC("analysis_frequencies_not_negative", "frequencies must be >= 0"),
        XYT_DIAGNOSTIC("analysis_above_nyquist_discrete",
                       "above the Nyquist frequency pi/Ts of a discrete system"),
        XYT_DIAGNOSTIC("analysis_above_nyquist", "above the Nyquist frequency pi/Ts"),
        XYT_DIAGNOSTIC("analysis_above_omega_min", "must be above omegaMin"),
        XYT_DIAGNOSTIC("analysis_finite_above_zero", "must be a finite number > 0"),
        XYT_DIAGNOSTIC("analysis_finite_above_one", "must be a finite number > 1"),
        // Ranges of options (nyquist.cpp, parameter_locus.cpp, root_locus.cpp)
        XYT_DIAGNOSTIC("analysis_in_open_range", "must be in (%1, %2)"),
        XYT_DIAGNOSTIC("analysis_in_range_open_left", "must be in (%1, %2]"),
        XYT_DIAGNOSTIC("analysis_in_integer_range", "must be in %1..%2"),
        XYT_DIAGNOSTIC("analysis_positive", "must be positive"),
        // core/analysis/nyquist.cpp, stability_margins.cpp
        XYT_DIAGNOSTIC("analysis_loop_improper", "the loop is improper (more zeros than poles)"),
        XYT_DIAGNOSTIC("analysis_nyquist_sampling_bound",
                       "the sampling bound was reached near a sharp turn of the curve: the "
                       "encirclement count may be wrong"),
        XYT_DIAGNOSTIC("analysis_nyquist_fractional_turns",
                       "the curve's turn around -1 is not a whole number of turns"),
        XYT_DIAGNOSTIC("analysis_nyquist_through_minus_one",
                       "the curve passes through -1: a closed-loop pole lies on the stability "
                       "boundary, the encirclement count is not defined"),
        XYT_DIAGNOSTIC("analysis_below_degree", "must be at least the degree of the polynomial"),
        XYT_DIAGNOSTIC("analysis_return_difference_zero", "1 + L is zero (L = -1)"),
        XYT_DIAGNOSTIC("analysis_margins_closed_loop_unstable",
                       "the closed loop is unstable: the margins and peaks describe the "
                       "frequency response, not robustness"),
        // core/analysis/parameter_locus.cpp
        XYT_DIAGNOSTIC("analysis_to_equals_from", "must differ from 'from'"),
        XYT_DIAGNOSTIC("analysis_locus_sample_skipped", "%1 = %2: skipped, the pole count changed"),
        XYT_DIAGNOSTIC("analysis_swept_values_not_positive", "the swept values must be > 0"),
        // core/analysis/pole_requirements.cpp
        XYT_DIAGNOSTIC("analysis_number_not_negative", "must be a number >= 0"),
        // core/analysis/root_locus.cpp
        XYT_DIAGNOSTIC("analysis_kmax_range", "must be finite and >= 0 (0: automatic)"),
        XYT_DIAGNOSTIC("analysis_ts_range", "must be finite and >= 0 (0: continuous)"),
        XYT_DIAGNOSTIC("analysis_view_empty", "needs reMin < reMax and imMin < imMax"),
        XYT_DIAGNOSTIC("analysis_locus_zero_numerator", "the numerator is zero: there is no locus"),
        XYT_DIAGNOSTIC("analysis_locus_no_poles",
                       "must have degree >= 1 (a loop without poles has no locus)"),
        XYT_DIAGNOSTIC("analysis_locus_improper",
                       "degree %1 exceeds the denominator's %2: the loop is improper"),
        XYT_DIAGNOSTIC("analysis_locus_biproper_infinity",
                       "the loop is biproper and d_n + K n_n vanishes at K = %1: a root passes "
                       "through infinity"),
        XYT_DIAGNOSTIC("analysis_locus_point_limit",
                       "stopped at the point limit (%1) at K = %2 before every branch converged"),
        XYT_DIAGNOSTIC("analysis_locus_work_bound",
                       "stopped at the work bound (about %1 million operations, %2 points) at K "
                       "= %3 before every branch converged: the loop's order %4 makes each "
                       "point expensive"),
        XYT_DIAGNOSTIC("analysis_locus_time_bound",
                       "stopped at the time bound (%1 s, %2 points) at K = %3 before every "
                       "branch converged: its roots are hard to find (an ill-conditioned loop)"),
        XYT_DIAGNOSTIC("analysis_locus_gain_limit",
                       "stopped at K > 1e250 before every branch converged"),
        XYT_DIAGNOSTIC("analysis_locus_step_bound", "the step bound could not be met near K = %1"),
        XYT_DIAGNOSTIC("analysis_locus_poles_ill_conditioned",
                       "the open-loop poles near %1 are ill-conditioned (clustered or multiple "
                       "roots): round-off alone can move them by about %2 of their size, so "
                       "they and the locus near them may be wrong"),
        XYT_DIAGNOSTIC("analysis_locus_zeros_ill_conditioned",
                       "the open-loop zeros near %1 are ill-conditioned (clustered or multiple "
                       "roots): round-off alone can move them by about %2 of their size, so "
                       "they and the locus near them may be wrong"),
        XYT_DIAGNOSTIC("analysis_locus_cancellation",
                       "near pole-zero cancellation at %1: that branch has (almost) no length"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
