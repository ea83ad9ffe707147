// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/session.
const std::vector<DiagnosticTemplate>& session() {
    static const std::vector<DiagnosticTemplate> table = {
        // The session evaluation of an axis (session_evaluation.cpp and the design methods).
        XYT_DIAGNOSTIC("closed_loop_unstable", "the closed loop is unstable"),
        XYT_DIAGNOSTIC("run_diverged", "the simulated run diverged (a sample is not a finite "
                                       "number): it has no tracking figures"),
        XYT_DIAGNOSTIC("flexible_mode_on_arx",
                       "the flexible mode and the notch of gt apply to a continuous plant: this "
                       "pole-placement axis runs its ARX model, which holds whatever mode its "
                       "data showed (identify it from a log that excites the mode)"),
        XYT_DIAGNOSTIC("run_ends_before_move",
                       "the run ends before the move does (tf): no settle figures"),
        XYT_DIAGNOSTIC("no_stability_margins", "no stability margins: %1"),
        XYT_DIAGNOSTIC("no_digital_implementation", "no digital implementation: %1"),
        XYT_DIAGNOSTIC("pp_u_exceeds_limit", "|u| exceeds the actuator limit (the discrete loop "
                                             "is simulated without saturation)"),
        XYT_DIAGNOSTIC("feedforward_beyond_limit", "the feedforward alone needs %1 V on this "
                                                   "trajectory, beyond the output limit of %2 V"),
        XYT_DIAGNOSTIC("ff3_acceleration_spike",
                       "the cubic's acceleration step becomes a %1 V spike of the FF3 term (one "
                       "controller period); the quintic move has no acceleration step"),
        XYT_DIAGNOSTIC("limit_cycle_at_rest",
                       "a limit cycle at rest: after the move the measured position keeps "
                       "oscillating (%1 mm peak to peak, %2 turns in the last half of the rest), "
                       "caused by the encoder/DAC quantization"),
        // The contour run (contour_run.cpp).
        XYT_DIAGNOSTIC("contour_axis_diverged", "%1 axis: the simulated run diverged (a sample "
                                                "is not a finite number)"),
        XYT_DIAGNOSTIC("contour_axis_saturated",
                       "%1 axis: |u| reached the actuator limit of %2 V for %3 s"),
        XYT_DIAGNOSTIC("iso230_circle_too_short",
                       "ISO 230-4: a full circle of the program lasts fewer than 3 samples: no "
                       "figures"),
        XYT_DIAGNOSTIC("circle_too_short",
                       "the circle lasts fewer than 3 samples: no ISO 230-4 figures"),
        XYT_DIAGNOSTIC("reversal_spikes", "reversal spikes up to %1 mm at the quadrant changes "
                                          "(the table's friction and backlash)"),
        // The axis runs, their friction and programs (axis_run.cpp, axis_vibration.cpp).
        XYT_DIAGNOSTIC("session_arx_static_level",
                       "a static level above the Coulomb level needs the moving mass of a "
                       "continuous plant; a pole-placement axis' ARX model takes the Coulomb level "
                       "and the amplifier deadband only, as a dead zone of its input"),
        XYT_DIAGNOSTIC("session_arx_viscous",
                       "viscous friction needs the moving mass of a continuous plant; a "
                       "pole-placement axis' ARX model takes the Coulomb level and the amplifier "
                       "deadband only, as a dead zone of its input"),
        XYT_DIAGNOSTIC("session_arx_backlash",
                       "backlash needs the moving mass of a continuous plant; a pole-placement "
                       "axis' ARX model takes the Coulomb level and the amplifier deadband only, "
                       "as a dead zone of its input"),
        XYT_DIAGNOSTIC("session_arx_compensation",
                       "friction compensation needs the moving mass of a continuous plant; a "
                       "pole-placement axis' ARX model takes the Coulomb level and the amplifier "
                       "deadband only, as a dead zone of its input"),
        XYT_DIAGNOSTIC(
            "session_mode_and_friction",
            "a flexible mode and the table's friction are not simulated together (the friction "
            "model's moving mass is rigid): set the mode's frequency or the friction levels to 0"),
        XYT_DIAGNOSTIC("session_period_longer_than_run",
                       "%1 s is longer than the program's run (%2 s)"),
        XYT_DIAGNOSTIC("session_too_many_samples",
                       "the run needs more samples than this machine holds"),
        XYT_DIAGNOSTIC("session_single_sample", "gives a single sample (step %1 s, duration %2 s); "
                                                "at least two samples are needed for the metrics"),
        XYT_DIAGNOSTIC("session_controller_continuous",
                       "must be continuous (a discrete loop has its own model)"),
        XYT_DIAGNOSTIC("session_vibration_arx_axis",
                       "a pole-placement axis runs its ARX model, which holds whatever mode its "
                       "data showed: the flexible mode and the notch apply to continuous plants"),
        // Exports (c_export.cpp, export_text.cpp, coupling_export.cpp, linuxcnc_export.cpp).
        XYT_DIAGNOSTIC("session_float_overflow",
                       "gives %1 for %2, beyond the largest float (%3): it would be inf in float "
                       "arithmetic; export in double precision; nothing was exported"),
        XYT_DIAGNOSTIC("session_float_underflow",
                       "gives %1 for %2, which rounds to 0 in float (the smallest is %3); export "
                       "in double precision; nothing was exported"),
        // Cross-coupling (contour_run.cpp, coupled_*.cpp, coupling_*.cpp, robustness_problem.cpp).
        XYT_DIAGNOSTIC("session_coupling_one_period_why",
                       "needs both axes at one controller period: the x axis runs every %1 s, the "
                       "y axis every %2 s (a pole-placement axis runs at its Ts, a continuous one "
                       "at the trajectory's dt)"),
        XYT_DIAGNOSTIC("session_coupling_one_digital_period",
                       "needs both digital controllers at one period: the x axis runs every %1 s, "
                       "the y axis every %2 s"),
        XYT_DIAGNOSTIC("session_digital_runs_samples",
                       "the two digital runs do not have the same samples"),
        XYT_DIAGNOSTIC("session_coupling_off", "is off (kp and ki are 0)"),
        XYT_DIAGNOSTIC("session_axis_no_digital_to_couple",
                       "axis %1 has no digital implementation to couple"),
        XYT_DIAGNOSTIC("session_coupled_loop_unstable",
                       "the coupled loop is unstable on %1 (direction %2): spectral radius %3; "
                       "lower the coupling's gains (kp %4 V/mm, ki %5 V/(mm s))"),
        XYT_DIAGNOSTIC("session_coupling_frozen_unstable",
                       "the coupled loop frozen at %1 of %2 directions is unstable (spectral "
                       "radius up to %3 at %4): on the arcs the coupling may not settle"),
        XYT_DIAGNOSTIC("session_iso230_note", "ISO 230-4: %1"),
        XYT_DIAGNOSTIC("session_cross_coupling_note", "cross-coupling: %1"),
        // The coupling sweep, the design methods and their registry.
        XYT_DIAGNOSTIC("session_needs_one_value", "needs at least one value"),
        XYT_DIAGNOSTIC("session_not_a_finite_gain", "%1 is not a finite gain >= 0"),
        XYT_DIAGNOSTIC("session_too_many_pairs",
                       "%1 values of kp and %2 of ki make %3 pairs: at most %4"),
        XYT_DIAGNOSTIC("session_coupled_run_diverged_because", "the coupled run diverged (%1)"),
        XYT_DIAGNOSTIC("session_coupled_run_diverged",
                       "the coupled run diverged (its contour error is not a finite number)"),
        XYT_DIAGNOSTIC("session_cannot_run", "cannot run: %1: %2"),
        XYT_DIAGNOSTIC("session_method_takes_no_coupling",
                       "the %1 method's loop takes no coupling"),
        XYT_DIAGNOSTIC("session_method_not_registered",
                       "no design method is registered for this value"),
        XYT_DIAGNOSTIC("session_no_module", "no module to register"),
        XYT_DIAGNOSTIC("session_bad_method_id",
                       "the id '%1' must be 1 to 32 lower-case letters, digits, '-' or '_'"),
        XYT_DIAGNOSTIC("session_method_registered",
                       "a method with the value or the id of '%1' is registered already"),
        XYT_DIAGNOSTIC("session_bad_method_parameter",
                       "the parameter '%1' of '%2' needs a name of lower-case letters, digits and "
                       "'_' and minimum <= default <= maximum"),
        XYT_DIAGNOSTIC("session_parameter_out_of_range",
                       "%1 is out of range: %2 must be within %3 .. %4"),
        XYT_DIAGNOSTIC("session_parameter_out_of_range_unit",
                       "%1 is out of range: %2 must be within %3 .. %4 %5"),
        XYT_DIAGNOSTIC("session_no_axis", "there is no axis %1"),
        XYT_DIAGNOSTIC("session_design_space_pi_only",
                       "the design space maps PI gains (with the feedforward): set D to 0"),
        XYT_DIAGNOSTIC("session_design_space_methods",
                       "the design space applies to Guillemin-Truxal and PI + feedforward axes"),
        XYT_DIAGNOSTIC("session_max_samples", "a run needs at least 2 samples (0: no limit)"),
        XYT_DIAGNOSTIC("session_export_not_finite",
                       "gives %1 in the export, not a finite number; nothing was exported"),
        XYT_DIAGNOSTIC("session_cannot_export", "cannot be exported: %1: %2"),
        XYT_DIAGNOSTIC(
            "session_bad_axis_id",
            "must be 1 to 16 lower-case letters or digits (it names the exported C functions)"),
        XYT_DIAGNOSTIC("session_axis_id_not_unique", "must differ from axes[0].id"),
        XYT_DIAGNOSTIC("session_no_digital_controller",
                       "this axis has no digital controller to export"),
        XYT_DIAGNOSTIC("session_program_no_closed_form",
                       "a G-code program's feed profile has no closed form for the script; export "
                       "the simulated signals as CSV instead"),
        XYT_DIAGNOSTIC("session_simulated_not_finite",
                       "the simulated %1 is %2 at t = %3 s (an unstable loop, or model_unit_scale "
                       "or the trajectory out of range); nothing was exported"),
        XYT_DIAGNOSTIC("session_axis_no_design", "has no design"),
        XYT_DIAGNOSTIC("session_not_zero_or_one", "must be 0 or 1, not %1"),
        XYT_DIAGNOSTIC("session_no_parameter", "has no parameter %1"),
        XYT_DIAGNOSTIC("session_derivative_filter_beyond_nyquist",
                       "%1 s puts the filter's corner 1/Tf beyond the Nyquist frequency pi/Ts of "
                       "the controller period: use 0 (no filter) or at least %2 s"),
        XYT_DIAGNOSTIC("session_pid_no_feedback", "P, I and D are all 0: the axis has no feedback"),
        XYT_DIAGNOSTIC(
            "session_pid_no_notch",
            "a PID + feedforward axis runs LinuxCNC's pid, which has no notch stage: set the "
            "centre to 0, or design the axis by Guillemin-Truxal, whose PI takes the notch"),
        XYT_DIAGNOSTIC("session_no_model_feedforward",
                       "a %1 axis has no feedforward from a continuous model (pole placement's "
                       "model-inverse feedforward is its ZPETC)"),
        XYT_DIAGNOSTIC("session_pid_zero_not_in_lhp",
                       "a zero in the right half plane (or on the axis) would not be a PID's"),
        XYT_DIAGNOSTIC("session_pid_zero_negative_gain", "that zero needs a negative P, I or D"),
        XYT_DIAGNOSTIC("session_model_no_estimate", "%1 has no estimate (%2)"),
        XYT_DIAGNOSTIC("session_model_no_estimate_because", "%1 has no estimate (%2: %3)"),
        XYT_DIAGNOSTIC("session_no_linuxcnc_pid", "a %1 axis has no LinuxCNC pid equivalent"),
        XYT_DIAGNOSTIC("session_contour_needs_path",
                       "the contour analysis needs a circle or a G-code program (a cubic drives "
                       "both axes along one line)"),
        XYT_DIAGNOSTIC("session_model_not_identified",
                       "the axis' model was not identified from data (set ranges instead)"),
        XYT_DIAGNOSTIC("session_identified_no_covariance",
                       "the identified %1 has no covariance to draw plants from"),
        XYT_DIAGNOSTIC("session_identified_wrong_method",
                       "the identified %1 is not a model of the axis' design method"),
        XYT_DIAGNOSTIC("session_spectrum_axis", "must be x, y, z or sum"),
        XYT_DIAGNOSTIC("session_no_mode_spectrum",
                       "there is no flexible mode to take a spectrum of"),
        XYT_DIAGNOSTIC("session_t1_outside_unit_circle",
                       "the desired pole -t1 must lie inside the unit circle (|t1| < 1)"),
        XYT_DIAGNOSTIC("session_out_of_reach",
                       "the trajectory is out of the plant's reach: holding %1 mm needs %2 V (the "
                       "model's steady gain B(1)/A(1) = %3 mm/V), beyond the %4 V limit"),
        // The session evaluation (session_evaluation.cpp, axis_frequency.cpp).
        XYT_DIAGNOSTIC("session_shaper_longer_than_move",
                       "the %1 shaper at %2 Hz lasts %3 s, longer than the move of %4 s: raise the "
                       "frequency or shorten the shaper"),
        XYT_DIAGNOSTIC("session_criterion_tracking_error", "the tracking error"),
        XYT_DIAGNOSTIC("session_criterion_actuator_limit", "the actuator limit"),
        XYT_DIAGNOSTIC("session_criterion_settle", "the settle after the move"),
        XYT_DIAGNOSTIC("session_list_and", "%1 and %2"),
        XYT_DIAGNOSTIC("session_implementation_fails",
                       "the design meets %1, its digital implementation does not: the verdict is "
                       "the implementation's"),
        XYT_DIAGNOSTIC("session_no_loop_to_analyse", "the axis has no loop to analyse"),
        // The specification advice (specification_advice.cpp).
        XYT_DIAGNOSTIC("session_advice_axis", "axis %1"),
        XYT_DIAGNOSTIC("session_advice_no_design", "%1 has no design (%2: %3)"),
        XYT_DIAGNOSTIC("session_advice_unstable",
                       "%1: the closed loop is unstable; no limit makes it pass"),
        XYT_DIAGNOSTIC("session_advice_overshoot", "%1: the step overshoots %2 % (limit %3 %)"),
        XYT_DIAGNOSTIC("session_advice_overshoot_gt",
                       "%1: the step overshoots %2 % (limit %3 %): every Guillemin-Truxal design "
                       "overshoots, its reference model is type 2 (the step error integrates to "
                       "zero), so 0 % cannot be met"),
        XYT_DIAGNOSTIC("session_advice_settling", "%1: the step settles in %2 s (limit %3 s)"),
        XYT_DIAGNOSTIC("session_advice_saturation", "%1: the command reaches the ±%2 V limit; a "
                                                    "looser limit elsewhere does not change that"),
        XYT_DIAGNOSTIC("session_advice_tracking",
                       "%1: the tracking error reaches %2 % of the travel (limit %3 %)"),
        XYT_DIAGNOSTIC("session_advice_settle_after",
                       "%1: it settles into ±%2 mm only %3 s after the move (limit %4 s)"),
        XYT_DIAGNOSTIC("session_advice_settle_estimated",
                       "%1: it settles into ±%2 mm only about %3 s after the move (estimated: not "
                       "within the run) (limit %4 s)"),
        XYT_DIAGNOSTIC("session_advice_settle_not_within",
                       "%1: it settles into ±%2 mm not within the run (limit %3 s)"),
        XYT_DIAGNOSTIC("session_advice_slowest_pole",
                       "%1: its slowest closed-loop pole, at -%2 rad/s beside the PI zero, decays "
                       "that slowly"),
        XYT_DIAGNOSTIC("session_advice_phase_margin", "%1: phase margin %2 deg (minimum %3)"),
        XYT_DIAGNOSTIC("session_advice_gain_margin", "%1: gain margin %2 dB (minimum %3)"),
        XYT_DIAGNOSTIC("session_advice_change", "%1 %2 %3"),
        XYT_DIAGNOSTIC("session_limit_max_overshoot", "max overshoot"),
        XYT_DIAGNOSTIC("session_limit_max_settling_time", "max settling time"),
        XYT_DIAGNOSTIC("session_limit_max_error", "max error"),
        XYT_DIAGNOSTIC("session_limit_max_settle_time", "max settle time"),
        XYT_DIAGNOSTIC("session_limit_in_position_window", "in-position window"),
        XYT_DIAGNOSTIC("session_limit_min_phase_margin", "min phase margin"),
        XYT_DIAGNOSTIC("session_limit_min_gain_margin", "min gain margin"),
        // The run's duration (chooseRunDuration) and the coupled lines.
        XYT_DIAGNOSTIC("session_duration_set", "duration %1 s (set in the session)"),
        XYT_DIAGNOSTIC("session_duration_circle",
                       "duration %1 s (automatic: the ramp-in and one revolution)"),
        XYT_DIAGNOSTIC("session_duration_program", "duration %1 s (the program's feed profile)"),
        XYT_DIAGNOSTIC(
            "session_duration_move_only",
            "duration %1 s (automatic: the move only; no axis has a stable design to settle)"),
        XYT_DIAGNOSTIC("session_duration_settle",
                       "duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, "
                       "estimated %4 after tf from the slowest closed-loop pole)"),
        XYT_DIAGNOSTIC("session_duration_settle_capped",
                       "duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, "
                       "estimated %4 after tf from the slowest closed-loop pole; cut to the cap of "
                       "tf + %5 move durations)"),
        XYT_DIAGNOSTIC(
            "session_duration_settle_lowered",
            "duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, estimated "
            "%4 after tf from the slowest closed-loop pole; cut to the cap of tf + %5 move "
            "durations (lowered to what a million samples hold at this dt))"),
        XYT_DIAGNOSTIC("session_duration_never", "never"),
        XYT_DIAGNOSTIC("session_program_line", "program line %1"),
        XYT_DIAGNOSTIC("session_the_move", "the move"),
        // The PID + feedforward method's equation lines with words (pid_feedforward_method.cpp).
        XYT_DIAGNOSTIC("session_pid_equation_feedforward",
                       "FF1 = %1, FF2 = %2, FF3 = %3 (model inverse: a2 u/k0 = %4, a1 u/k0 = %5, "
                       "u/k0 = %6)"),
        XYT_DIAGNOSTIC("session_pid_equation_controller",
                       "C(s) = (P + I/s + D s/(Tf s + 1)) / u,  Tf = %1 s, u = %2 model units per "
                       "mm"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
