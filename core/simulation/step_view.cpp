// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/step_view.h"

#include <cmath>

namespace xyt {

StepView stepView(const TransferFunction& closedLoop, const StepCharacteristics& step,
                  const StepEnvelope& limits, const PolePlacementDesign* pp,
                  const ZpetcDesign* zpetc, bool zpetcRuns) {
    StepView out;
    out.step = step;
    out.envelope = limits;
    out.stable = step.stable;
    if (!out.stable)
        return out;
    out.envelope.finalValue = step.finalValue;
    const double ts = closedLoop.tsSeconds();
    out.sampleTimeSeconds = ts;
    out.horizonSeconds =
        stepViewHorizonSeconds(step, ts > 0.0 ? 20.0 * ts : 0.0, limits.settlingTimeSeconds);
    if (pp && zpetc) {
        StepViewCurve alone{StepCurveKind::LoopAlone,
                            stepResponseCurve(pp->closedLoop(), out.horizonSeconds)};
        StepViewCurve with{StepCurveKind::WithZpetc,
                           zpetcStepResponseCurve(*pp, *zpetc, out.horizonSeconds)};
        out.curves = zpetcRuns ? std::vector{with, alone} : std::vector{alone, with};
    } else {
        out.curves.push_back(
            {StepCurveKind::ClosedLoop, stepResponseCurve(closedLoop, out.horizonSeconds)});
    }
    const StepResponseCurve& main = out.curves.front().curve;
    if (std::isfinite(step.finalValue) && step.finalValue != 0.0)
        out.rise = riseTime(main, step.finalValue);
    if (std::isfinite(out.envelope.finalValue))
        out.violations = envelopeViolations(main, out.envelope);
    return out;
}

} // namespace xyt
