// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/transfer_function.h"

#include <limits>
#include <vector>

namespace xyt {

/// A sampled unit-step response, the step applied at stepAtSeconds.
struct StepResponseCurve {
    std::vector<double> t; ///< s
    std::vector<double> y;
    double stepAtSeconds = 0.0;
};

/**
 * The unit step response of a closed loop from rest, exact at its samples: a continuous loop
 * on @p samples + 1 points evenly spread over [0, horizonSeconds] (simulateLinear: a constant
 * input is exact under its first-order hold), a discrete loop at its own sample time up to the
 * horizon (difference equation).
 * @throws InvalidInput "horizon" unless finite and > 0, "samples" unless 10 .. 1e6, and
 *         "system" as simulateLinear.
 */
StepResponseCurve stepResponseCurve(const TransferFunction& closedLoop, double horizonSeconds,
                                    int samples = 2000);

/**
 * The unit step as a pole-placement axis runs it with its ZPETC (the run behind
 * zpetcStepCharacteristics): the step at stepAtSeconds, the response moving ahead of it by the
 * preview. At least @p horizonSeconds long after the step.
 */
StepResponseCurve zpetcStepResponseCurve(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                                         double horizonSeconds);

/// Where a step response first reaches two fractions of its final value (rise time).
struct RiseTime {
    bool reached = false; ///< both levels were reached within the curve; else the rest is NaN
    double lowCrossingSeconds = std::numeric_limits<double>::quiet_NaN();  ///< curve's clock
    double highCrossingSeconds = std::numeric_limits<double>::quiet_NaN(); ///< curve's clock
    double seconds = std::numeric_limits<double>::quiet_NaN();             ///< high - low crossing
};

/**
 * The rise time of @p curve: the first instants at which y / finalValue reaches @p lowFraction
 * and @p highFraction (10 % and 90 % by default), each linearly interpolated between the two
 * samples that bracket it (a sample already at the level gives its own time), and their
 * difference. Times are on the curve's clock (t, not t - stepAtSeconds); the difference does
 * not depend on it. A level never reached leaves reached = false and NaN times.
 * @throws InvalidInput "curve" unless t and y have the same length >= 2, "finalValue" unless
 *         finite and non-zero, "fractions" unless 0 <= low < high <= 1.
 */
RiseTime riseTime(const StepResponseCurve& curve, double finalValue, double lowFraction = 0.1,
                  double highFraction = 0.9);

} // namespace xyt
