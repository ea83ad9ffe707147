// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/transfer_function.h"
#include "core/simulation/metrics.h"
#include "core/simulation/step_envelope.h"
#include "core/simulation/step_response.h"

#include <vector>

namespace xyt {

/// Which unit step a curve of a step view is.
enum class StepCurveKind {
    ClosedLoop, ///< a continuous axis' closed loop G_R
    LoopAlone,  ///< a pole-placement axis' feedback loop Kf B / T without feedforward
    WithZpetc,  ///< the same axis with its ZPETC (the step previewed, zpetcStepResponseCurve)
};

struct StepViewCurve {
    StepCurveKind kind = StepCurveKind::ClosedLoop;
    StepResponseCurve curve;
};

/**
 * Everything a step plot of one axis draws: the curves, the figures, the
 * requirement envelope and where the response leaves it.
 */
struct StepView {
    bool stable = false; ///< false: no curve (an unstable loop has no step response)
    /// curves[0] is the system the axis runs, the one the figures are of; a pole-placement axis
    /// has the other of (loop alone, with ZPETC) second.
    std::vector<StepViewCurve> curves;
    /// The figures the metrics panel quotes (AxisEvaluation::step), copied, not recomputed.
    StepCharacteristics step;
    RiseTime rise;               ///< 10 -> 90 % of step.finalValue on curves[0] (its clock)
    double horizonSeconds = 0.0; ///< after the step (stepViewHorizonSeconds)
    /// The loop's sample time (0: continuous); a discrete loop's curves are its samples, held.
    double sampleTimeSeconds = 0.0;
    StepEnvelope envelope;        ///< the limits given, with finalValue = step.finalValue
    std::vector<bool> violations; ///< envelopeViolations of curves[0]
};

/**
 * The step view of an axis from its design and its quoted figures @p step: a continuous closed
 * loop (@p pp null) gives one curve; a pole-placement loop @p pp with @p zpetc gives the loop
 * alone and the step with ZPETC, the one the axis runs (@p zpetcRuns) first. Curves run
 * horizonSeconds = stepViewHorizonSeconds(step, 20 Ts for a discrete loop, the envelope's
 * settling time) past the step; a continuous one on 2000 steps.
 * @throws InvalidInput as stepResponseCurve.
 */
StepView stepView(const TransferFunction& closedLoop, const StepCharacteristics& step,
                  const StepEnvelope& limits, const PolePlacementDesign* pp = nullptr,
                  const ZpetcDesign* zpetc = nullptr, bool zpetcRuns = false);

} // namespace xyt
