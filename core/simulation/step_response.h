// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/transfer_function.h"

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

} // namespace xyt
