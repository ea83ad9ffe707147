// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace xyt {

/**
 * The position PID with command feedforward that CNC drives run, with the semantics of
 * LinuxCNC's `pid` HAL component (2.8 and later, src/hal/components/pid.c, calc_pid), one sample
 * per controller period Ts, position in mm and output in volts:
 *
 *   e     = command - feedback, limited to +-maxError (0: no limit), then the deadband taken off
 *           (|e| <= deadband gives 0, else e -/+ deadband);
 *   I     += e Ts, unless the output was limited on the last sample and e pushes further into
 *           the limit (e * limitState > 0); then limited to +-maxErrorI (mm s; 0: no limit);
 *   cmd'  = (command - previous command) / Ts, fb' = (feedback - previous feedback) / Ts,
 *   cmd'' = (cmd' - previous cmd') / Ts, cmd''' = (cmd'' - previous cmd'') / Ts
 *           (backward differences, as the component forms them when its -deriv pins are not
 *           connected);
 *   D     = cmd' - fb' (the error's derivative, before the deadband);
 *   u     = bias + P e + I_gain I + D_gain D + FF0 command + FF1 cmd' + FF2 cmd'' + FF3 cmd''',
 *           limited to +-maxOutput (0: no limit), which sets limitState to +1, -1 or 0.
 *
 * Gains in LinuxCNC's units with position in mm: P in V/mm, I in V/(mm s), D in V s/mm, FF0 in
 * V/mm, FF1 in V/(mm/s), FF2 in V/(mm/s^2), FF3 in V/(mm/s^3).
 *
 * Two additions LinuxCNC lacks, both off by default (then the output is LinuxCNC's bit for bit
 * in double precision):
 *  - derivativeOnMeasurement: D = -fb' (no kick when the command jumps);
 *  - derivativeFilterSeconds Tf > 0: D passes a first-order low-pass filter, discretized by
 *    backward Euler: Df = (Tf Df_previous + Ts D) / (Tf + Ts).
 */
struct ServoPidGains {
    double p = 0.0;
    double i = 0.0;
    double d = 0.0;
    double ff0 = 0.0;
    double ff1 = 0.0;
    double ff2 = 0.0;
    double ff3 = 0.0;
    double bias = 0.0;      ///< V
    double deadband = 0.0;  ///< mm
    double maxError = 0.0;  ///< mm; 0: no limit
    double maxErrorI = 0.0; ///< mm s; 0: no limit
    double maxOutput = 0.0; ///< V; 0: no limit
    double derivativeFilterSeconds = 0.0;
    bool derivativeOnMeasurement = false;
};

/// What the PID keeps between samples (LinuxCNC's error_i, prev_cmd, prev_fb, cmd_d, cmd_dd,
/// limit_state, plus the filtered derivative).
struct ServoPidState {
    double errorI = 0.0;
    double previousCommand = 0.0;
    double previousFeedback = 0.0;
    double commandD = 0.0;
    double commandDD = 0.0;
    double filteredD = 0.0;
    double limitState = 0.0;
};

/// One sample's terms, for plotting the output split into feedback and feedforward.
struct ServoPidTerms {
    double error = 0.0;  ///< after the error limit and the deadband
    double errorD = 0.0; ///< the derivative term's input (filtered when a filter is set)
    double commandD = 0.0, commandDD = 0.0, commandDDD = 0.0;
    double feedback = 0.0;    ///< bias + P e + I errorI + D errorD (V)
    double feedforward = 0.0; ///< FF0 ... FF3 (V)
    double output = 0.0;      ///< the limited sum (V)
};

/**
 * The state of a PID at rest at position @p position (command and feedback there, derivatives
 * zero): firmware starts a loop with its previous values at the current position, so the first
 * sample sees no derivative step. (LinuxCNC's component starts at zero.)
 */
ServoPidState servoPidAtRest(double position);

/**
 * The command's derivatives as the trajectory generator gives them (mm/s, mm/s^2, mm/s^3), for a
 * PID whose derivative inputs are connected (LinuxCNC's `command-deriv` pin): the feedforward and
 * the D term read them instead of backward differences of the command.
 */
struct ServoPidCommandDerivatives {
    double velocity = 0.0;
    double acceleration = 0.0;
    double jerk = 0.0;
};

/**
 * One sample of the PID at period @p tsSeconds (> 0): the output for @p command and
 * @p feedback (mm), updating @p state. With @p given, the command's first, second and third
 * derivatives are those values (the D term then reads given->velocity - fb'); without, the
 * backward differences above.
 */
ServoPidTerms stepServoPid(const ServoPidGains& gains, ServoPidState& state, double command,
                           double feedback, double tsSeconds,
                           const ServoPidCommandDerivatives* given = nullptr);

} // namespace xyt
