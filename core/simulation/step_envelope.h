// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/metrics.h"
#include "core/simulation/step_response.h"

#include <limits>
#include <vector>

namespace xyt {

/**
 * The step-response requirements of a specification as a region of the (t, y) plane, as a
 * control-system designer draws them over a step plot: y never above the overshoot bound
 * finalValue (1 + (maxOvershootPct + overshootSlackPct) / 100), and from settlingTimeSeconds
 * after the step on, |y - finalValue| <= band |finalValue|. An infinite limit leaves that part
 * out.
 */
struct StepEnvelope {
    double finalValue = 1.0;
    double maxOvershootPct = std::numeric_limits<double>::infinity();
    /// Round-off slack on the overshoot bound (the specification's kOvershootRoundOffPct), so
    /// that the drawn bound and the pass/fail verdict agree.
    double overshootSlackPct = 0.0;
    double settlingTimeSeconds = std::numeric_limits<double>::infinity(); ///< after the step
    double band = 0.02;

    /// finalValue (1 + (maxOvershootPct + overshootSlackPct) / 100), +infinity without a limit.
    double overshootBound() const;
};

/**
 * Which samples of @p curve leave @p envelope: y_k above the overshoot bound, or, at
 * t_k - stepAtSeconds >= settlingTimeSeconds, outside the band around the final value. A
 * non-finite sample is a violation.
 * @throws InvalidInput "curve" when t and y differ in length, "envelope" when finalValue is not
 *         finite or band is not in (0, 1).
 */
std::vector<bool> envelopeViolations(const StepResponseCurve& curve, const StepEnvelope& envelope);

/**
 * How long after the step a step plot should run so that its transient is readable: 1.5 times
 * the settling time (the peak time included when it comes no later than 4 settling times: a
 * slow pole-zero pair's late, tiny peak is quoted, not drawn), at least @p minimumSeconds (e.g.
 * 20 samples of a discrete loop, whose step may settle in a few). A settling limit a little
 * beyond that (up to 3 times) is brought into view, at 1.15 times the limit, so the band it
 * starts is seen; a limit further out is left beyond the edge (say so where it is drawn).
 * An unstable or empty figure set gives max(minimumSeconds, 1 s).
 * @throws InvalidInput "minimumSeconds" when negative or not finite.
 */
double
stepViewHorizonSeconds(const StepCharacteristics& step, double minimumSeconds = 0.0,
                       double settlingLimitSeconds = std::numeric_limits<double>::infinity());

} // namespace xyt
