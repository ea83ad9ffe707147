// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/servo_pid.h"

namespace xyt {

namespace {

/// @p v limited to +-limit; a limit of 0 is none (LinuxCNC's convention).
double limited(double v, double limit) {
    if (limit == 0.0)
        return v;
    return v > limit ? limit : (v < -limit ? -limit : v);
}

} // namespace

ServoPidState servoPidAtRest(double position) {
    ServoPidState s;
    s.previousCommand = position;
    s.previousFeedback = position;
    return s;
}

ServoPidTerms stepServoPid(const ServoPidGains& g, ServoPidState& s, double command,
                           double feedback, double tsSeconds,
                           const ServoPidCommandDerivatives* given) {
    const double rate = 1.0 / tsSeconds;
    ServoPidTerms t;
    double e = limited(command - feedback, g.maxError);
    if (e > g.deadband)
        e -= g.deadband;
    else if (e < -g.deadband)
        e += g.deadband;
    else
        e = 0.0;
    t.error = e;
    if (e * s.limitState <= 0.0) // not pushing further into the output limit
        s.errorI += e * tsSeconds;
    s.errorI = limited(s.errorI, g.maxErrorI);
    const double commandV = given ? given->velocity : (command - s.previousCommand) * rate;
    const double feedbackV = (feedback - s.previousFeedback) * rate;
    const double d = g.derivativeOnMeasurement ? -feedbackV : commandV - feedbackV;
    if (g.derivativeFilterSeconds > 0.0)
        s.filteredD = (g.derivativeFilterSeconds * s.filteredD + tsSeconds * d) /
                      (g.derivativeFilterSeconds + tsSeconds);
    else
        s.filteredD = d;
    t.errorD = s.filteredD;
    const double previousD = s.commandD, previousDD = s.commandDD;
    s.commandD = commandV;
    s.commandDD = (s.commandD - previousD) * rate;
    if (given)
        s.commandDD = given->acceleration;
    t.commandD = s.commandD;
    t.commandDD = s.commandDD;
    t.commandDDD = given ? given->jerk : (s.commandDD - previousDD) * rate;
    s.previousCommand = command;
    s.previousFeedback = feedback;
    t.feedback = g.bias + g.p * e + g.i * s.errorI + g.d * t.errorD;
    t.feedforward =
        g.ff0 * command + g.ff1 * t.commandD + g.ff2 * t.commandDD + g.ff3 * t.commandDDD;
    const double u = t.feedback + t.feedforward;
    t.output = limited(u, g.maxOutput);
    if (g.maxOutput != 0.0)
        s.limitState = u > g.maxOutput ? 1.0 : (u < -g.maxOutput ? -1.0 : 0.0);
    return t;
}

} // namespace xyt
