// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/design.
const std::vector<DiagnosticTemplate>& design() {
    static const std::vector<DiagnosticTemplate> table = {
        // core/design/cross_coupling.cpp, digital_controller.cpp
        XYT_DIAGNOSTIC("design_coupling_not_negative",
                       "must be >= 0 (0 switches the coupling off)"),
        XYT_DIAGNOSTIC("design_tracking_time_not_negative", "must be >= 0 (0: Tt = Ti = kp/ki)"),
        XYT_DIAGNOSTIC("design_ti_not_positive", "Ti = kp/ki is not a positive time; give Tt (s)"),
        XYT_DIAGNOSTIC("design_z0_nonzero", "the z^0 coefficient must be nonzero"),
        // core/design/diophantine.cpp
        XYT_DIAGNOSTIC("design_zero_polynomial_no_roots", "the zero polynomial has no roots"),
        XYT_DIAGNOSTIC("design_common_factor_root",
                       "shares the root z = %1 with A (common factor of A and B): A F + B G = T "
                       "has no solution (Sylvester condition number %2)"),
        XYT_DIAGNOSTIC("design_common_factor",
                       "shares a root with A (common factor of A and B): A F + B G = T has no "
                       "solution (Sylvester condition number %1)"),
        XYT_DIAGNOSTIC("design_diophantine_overflow",
                       "the coefficients of A and B are too large in magnitude: A F + B G "
                       "overflows a double"),
        XYT_DIAGNOSTIC("design_near_common_factor_pair",
                       "near-common factor of A and B: pole z = %1 and zero z = %2 are %3 "
                       "apart; Sylvester condition number %4, F and G are large and sensitive"),
        XYT_DIAGNOSTIC("design_near_common_factor",
                       "near-common factor of A and B; Sylvester condition number %1, F and G "
                       "are large and sensitive"),
        // core/design/guillemin_truxal.cpp
        XYT_DIAGNOSTIC("design_gt_wn_out_of_range",
                       "%1 rad/s is out of range: wn^4 = %2 and a2/wn^2 = %3 must be finite "
                       "nonzero numbers for the reference model (Braga et al. Eq. 11-18)"),
        XYT_DIAGNOSTIC("design_gt_k0_out_of_range",
                       "plant gain k0 = %1 is out of range with kp = %2 and wn = %3 rad/s: kp "
                       "k0 = %4, psi1 = wn^4/(kp k0) = %5 and ki = kp psi1 = %6 must be finite "
                       "nonzero numbers for the Guillemin-Truxal design"),
        XYT_DIAGNOSTIC("design_gt_kp_out_of_range",
                       "%1 is out of range with this plant and wn (plant gain k0 = %2, wn = %3 "
                       "rad/s): kp k0 = %4, psi1 = wn^4/(kp k0) = %5 and ki = kp psi1 = %6 must "
                       "be finite nonzero numbers for the Guillemin-Truxal design"),
        // core/design/notch_filter.cpp
        XYT_DIAGNOSTIC("design_notch_centre_range", "must be 0 (no notch) or a frequency > 0 Hz"),
        XYT_DIAGNOSTIC("design_notch_width_range",
                       "must be a bandwidth > 0 Hz and below twice the centre frequency"),
        XYT_DIAGNOSTIC("design_notch_depth_range", "must be an attenuation in (0, 120] dB"),
        XYT_DIAGNOSTIC("design_notch_no_mode",
                       "the axis has no flexible mode to design a notch for"),
        XYT_DIAGNOSTIC("design_notch_above_nyquist",
                       "lies at or above the controller's Nyquist frequency of %1 Hz (1 / (2 Ts))"),
        // core/design/pid_tuning.cpp: the refusals' reasons and the warnings
        XYT_DIAGNOSTIC("design_pid_pi_phase_too_high",
                       "a PI gives a phase between -90 and 0 deg at %1 rad/s (plant phase %2 "
                       "deg, so the phase margin of %3 deg needs a controller phase of %4 deg): "
                       "lower the phase margin or the crossover, or add D"),
        XYT_DIAGNOSTIC("design_pid_pi_phase_too_low",
                       "a PI gives a phase between -90 and 0 deg at %1 rad/s (plant phase %2 "
                       "deg, so the phase margin of %3 deg needs a controller phase of %4 deg): "
                       "raise the crossover or the phase margin"),
        XYT_DIAGNOSTIC("design_pid_phase_out_of_reach",
                       "a PID with Ti = 4 Td gives a phase between -90 and 90 deg at %1 rad/s "
                       "(plant phase %2 deg, so the phase margin of %3 deg needs a controller "
                       "phase of %4 deg): lower the phase margin or the crossover"),
        XYT_DIAGNOSTIC("design_pid_gains_out_of_range",
                       "the gains for this target overflow or vanish in double precision (P = "
                       "%1 V/mm, I = %2 V/(mm s), D = %3 V s/mm) at %4 rad/s (plant phase %5 "
                       "deg, so the phase margin of %6 deg needs a controller phase of %7 deg)"),
        XYT_DIAGNOSTIC("design_pid_several_crossovers",
                       "the loop has %1 gain crossovers (a lightly damped plant, a1^2 < 2 a2): "
                       "the margin holds at the target, check the others on the Bode plot"),
        XYT_DIAGNOSTIC("design_pid_conditionally_stable",
                       "the closed loop is unstable although the phase margin at the crossover "
                       "is met (a conditionally stable loop): lower the phase margin or raise "
                       "the crossover"),
        // core/design/pole_placement.cpp
        XYT_DIAGNOSTIC("design_b0_not_zero",
                       "the z^0 coefficient must be 0 (at least one sample of delay; otherwise "
                       "u(k) and y(k) form an algebraic loop)"),
        XYT_DIAGNOSTIC("design_t0_not_one", "T(0), the z^0 coefficient, must be 1"),
        XYT_DIAGNOSTIC("design_t_root_outside",
                       "root z = %1 is not inside the unit circle: the closed loop would be "
                       "unstable"),
        XYT_DIAGNOSTIC("design_a0_normalized",
                       "A(0) = %1: A and B divided by it so that A is monic (same plant)"),
        XYT_DIAGNOSTIC("design_b_zero", "B is zero: the plant has no input"),
        XYT_DIAGNOSTIC("design_b1_zero",
                       "B(1) = 0 (a zero at z = 1): the plant has no steady-state gain and Kf = "
                       "T(1)/B(1) does not exist"),
        XYT_DIAGNOSTIC("design_b1_too_small",
                       "B(1) = %1 is too small: Kf = T(1)/B(1) overflows a double"),
        XYT_DIAGNOSTIC("design_b1_negligible",
                       "B(1) = %1 is negligible: the controller (Kf = %2) would need gains "
                       "beyond 1e100"),
        // core/design/relay_experiment.cpp: the limit cycle's status, the simulation's warnings
        XYT_DIAGNOSTIC("design_relay_no_half_period",
                       "no half period between %1 and %2 s gives a symmetric relay oscillation "
                       "(y at the switch keeps its sign)"),
        XYT_DIAGNOSTIC("design_relay_not_falling",
                       "the periodic solution of half period %1 s does not cross zero downwards "
                       "at the switch (y' = %2 mm/s): not a relay oscillation"),
        XYT_DIAGNOSTIC("design_relay_early_crossing",
                       "the periodic solution of half period %1 s crosses zero at t = %2 s "
                       "inside the half period: the relay would switch more often"),
        XYT_DIAGNOSTIC("design_relay_too_many_steps",
                       "%1 s makes %2 steps over %3 s; at most 2e6: raise the step or shorten "
                       "the run"),
        XYT_DIAGNOSTIC("design_relay_coarse_step",
                       "the step of %1 s is coarse against the expected period of %2 s: a step "
                       "spanning two sign changes of y misses both"),
        XYT_DIAGNOSTIC("design_relay_chattering",
                       "the relay switched more than 64 times within one step near t = %1 s "
                       "(chattering): stopped there"),
        XYT_DIAGNOSTIC("design_relay_too_few_switches",
                       "fewer than two switches to +d in %1 s: no period or amplitude measured "
                       "(run longer)"),
        // core/design/shaper_recommendation.cpp
        XYT_DIAGNOSTIC("design_spectrum_sizes_differ", "has %1 values for %2 frequencies"),
        XYT_DIAGNOSTIC("design_spectrum_frequency_order",
                       "must be finite, >= 0 and increasing (value %1)"),
        XYT_DIAGNOSTIC("design_spectrum_power_negative", "must be finite and >= 0 (value %1)"),
        XYT_DIAGNOSTIC("design_spectrum_power_zero", "is zero at every frequency used"),
        XYT_DIAGNOSTIC("design_above_min_frequency", "must be above minFrequencyHz"),
        XYT_DIAGNOSTIC("design_no_frequency_to_test", "leaves no frequency to test"),
        XYT_DIAGNOSTIC("design_spectrum_no_frequency", "has no frequency up to %1 Hz"),
        // core/design/zpetc.cpp
        XYT_DIAGNOSTIC("design_zpetc_b_minus_zero",
                       "B-(1) = 0 (a zero at z = 1): ZPETC cannot normalize the gain"),
        XYT_DIAGNOSTIC("design_zpetc_b_minus_out_of_range",
                       "B-(1) = %1 is too small (or too large) to square in double precision: "
                       "scale B, ZPETC cannot normalize its gain"),
        XYT_DIAGNOSTIC("design_zpetc_overflow",
                       "the ZPETC filter overflows in double precision for this B and T: scale B"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
