// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/simulation.
const std::vector<DiagnosticTemplate>& simulation() {
    static const std::vector<DiagnosticTemplate> table = {
        // The digital implementation's poles (sampled_data.cpp).
        XYT_DIAGNOSTIC("digital_loop_unstable",
                       "the digital loop at Ts = %1 s is unstable (its largest closed-loop pole "
                       "has |z| = %2); lower the controller sample time"),
        XYT_DIAGNOSTIC("digital_loop_less_damped",
                       "the digital loop at Ts = %1 s is much less damped than the design "
                       "(damping ratio %2 against %3 in the z-plane poles); lower the controller "
                       "sample time or the delay"),
        // Samples and signals of a run.
        XYT_DIAGNOSTIC("sim_txy_different_lengths", "t, x and y have different lengths"),
        XYT_DIAGNOSTIC("sim_no_sample_after_ramp_in", "no sample after the ramp-in"),
        XYT_DIAGNOSTIC("sim_needs_one_sample", "needs at least one sample"),
        XYT_DIAGNOSTIC("sim_needs_samples_preview",
                       "needs %1 samples (run length plus preview), got %2"),
        XYT_DIAGNOSTIC("sim_needs_samples", "needs %1 samples, got %2"),
        XYT_DIAGNOSTIC("sim_sample_not_finite", "sample %1 is not a finite number"),
        XYT_DIAGNOSTIC("sim_run_has_no_samples", "the run has no samples"),
        XYT_DIAGNOSTIC("sim_signals_different_lengths", "signals of different lengths"),
        XYT_DIAGNOSTIC("sim_one_sample_per_reference", "must have one sample per reference sample"),
        XYT_DIAGNOSTIC("sim_must_be_finite", "must be finite"),
        XYT_DIAGNOSTIC("sim_ty_same_length", "t and y must have the same length"),
        XYT_DIAGNOSTIC("sim_ty_same_length_two", "t and y must have the same length, at least 2"),
        XYT_DIAGNOSTIC("sim_y_x_sizes", "has %1 samples, x has %2"),
        XYT_DIAGNOSTIC("sim_single_sample", "gives a single sample (Ts %1 s, duration %2 s); at "
                                            "least two samples are needed for the metrics"),
        XYT_DIAGNOSTIC("sim_time_overflows",
                       "the last sample time of the run, or omega times it, overflows a double"),
        XYT_DIAGNOSTIC("sim_axes_share_ts", "the two axes must share one sample time"),
        XYT_DIAGNOSTIC("sim_more_than", "more than %1"),
        XYT_DIAGNOSTIC("sim_samples_beyond_limit", "needs %1 samples at this dt; the limit is %2"),
        XYT_DIAGNOSTIC("sim_samples_beyond_memory",
                       "needs %1 samples at this dt; the limit is %2 on this machine (%3 % of its "
                       "%4 GB of memory at %5 bytes per sample)"),
        XYT_DIAGNOSTIC("sim_position_beyond_limit",
                       "%1 is beyond the 1e9 mm (1000 km) that any table could move; refused "
                       "before it overflows the simulation"),
        XYT_DIAGNOSTIC("sim_tf_after_t0", "must be later than t0"),
        // Loops, plants and options of the simulations.
        XYT_DIAGNOSTIC("sim_coupling_periods_differ",
                       "needs both axes at one controller period: the x axis runs every %1 s, the "
                       "y axis every %2 s"),
        XYT_DIAGNOSTIC("sim_coupling_samples_differ",
                       "the two axes' runs do not have the same samples"),
        XYT_DIAGNOSTIC("sim_filter_not_causal",
                       "the z^0 coefficient must be nonzero (causal filter)"),
        XYT_DIAGNOSTIC("sim_between_zero_one", "must be between 0 and 1"),
        XYT_DIAGNOSTIC("sim_lie_in_zero_one", "must lie in (0, 1)"),
        XYT_DIAGNOSTIC("sim_move_not_finite", "start, target and end time must be finite numbers"),
        XYT_DIAGNOSTIC("sim_integer_up_to", "must be an integer in 0..%1"),
        XYT_DIAGNOSTIC("sim_encoder_resolution",
                       "must be a finite number >= 0 (mm per count; 0: ideal)"),
        XYT_DIAGNOSTIC("sim_dac_bits", "must be an integer in 0..32 (0: ideal DAC)"),
        XYT_DIAGNOSTIC("sim_umax_positive", "must be greater than zero (infinity for no limit)"),
        XYT_DIAGNOSTIC("sim_dac_needs_umax",
                       "a DAC needs a finite actuator limit umax (its full scale)"),
        XYT_DIAGNOSTIC("sim_discretization_overflows",
                       "the plant's discretization at this sample time overflows"),
        XYT_DIAGNOSTIC("sim_zpetc_den_zero",
                       "the feedforward's z^0 denominator coefficient is zero"),
        XYT_DIAGNOSTIC("sim_plant_cannot_rest_away",
                       "the plant has no pole at s = 0, so it cannot rest away from 0"),
        XYT_DIAGNOSTIC("sim_samples_range", "must lie in 10 .. 1000000"),
        XYT_DIAGNOSTIC("sim_finite_nonzero", "must be a finite number other than zero"),
        XYT_DIAGNOSTIC("sim_fractions_order", "must satisfy 0 <= low < high <= 1"),
        XYT_DIAGNOSTIC("sim_envelope_invalid", "needs a finite final value and a band in (0, 1)"),
        XYT_DIAGNOSTIC("sim_batch_lanes", "the results and moves must have one entry per loop"),
        XYT_DIAGNOSTIC("sim_batch_width", "must be 1, 2, 4 or 8"),
        // Input shaping of the reference (shaped_reference.cpp).
        XYT_DIAGNOSTIC("sim_shaper_sizes",
                       "needs as many impulse times as amplitudes (at least one)"),
        XYT_DIAGNOSTIC("sim_shaper_not_number", "has a value that is not a number"),
        XYT_DIAGNOSTIC("sim_shaper_times_order", "impulse times must start at 0 and increase"),
        XYT_DIAGNOSTIC("sim_shaper_longer_than_move",
                       "the shaper lasts %1 s, longer than the move of %2 s"),
        XYT_DIAGNOSTIC("sim_shaped_sizes_differ", "differs in size from shaped.x"),
        // The table with friction (table_dynamics.cpp).
        XYT_DIAGNOSTIC("sim_table_plant_shape",
                       "must be k0 / (s (s^2 + a1 s + a2)) with k0 > 0 for the table's friction"),
        XYT_DIAGNOSTIC("sim_table_poles_not_real",
                       "the poles of s^2 + a1 s + a2 must be real and stable to split the plant "
                       "into an electrical lag and a moving mass"),
        XYT_DIAGNOSTIC("sim_table_electrical_pole",
                       "the electrical pole must be > 0 (a2 = 0 leaves one pole at 0, which can "
                       "only be the mechanical one)"),
        XYT_DIAGNOSTIC("sim_table_controller_states",
                       "has more states than the friction simulation holds (%1)"),
        XYT_DIAGNOSTIC("sim_substeps_not_negative", "must be >= 0 (0: automatic)"),
        // Stick-slip and hunting of a run with dry friction (stick_slip.cpp).
        XYT_DIAGNOSTIC("sim_once", "once"),
        XYT_DIAGNOSTIC("sim_times", "%1 times"),
        XYT_DIAGNOSTIC("sim_stick_slip_during_move",
                       "stick-slip during the move: the table stopped %1 while the reference kept "
                       "moving (first at t = %2 s)"),
        XYT_DIAGNOSTIC("sim_hunting_at_rest",
                       "hunting at rest: the integral action broke the table free %1 after the "
                       "move (%2 um peak to peak): integral action against stiction"),
        XYT_DIAGNOSTIC("sim_digital_implementation_finding", "the digital implementation: %1"),
        XYT_DIAGNOSTIC("sim_realization_loses_stability",
                       "the loop's state-space realization loses the closed loop's stability to "
                       "round-off (an eigenvalue at %1 1/s for a stable loop): the plant's "
                       "coefficients are too far apart in scale to simulate"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
