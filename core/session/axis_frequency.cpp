// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_frequency.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace xyt {

AxisFrequencyAnalysis analyzeAxisFrequency(const Session& session,
                                           const AxisEvaluation& evaluation) {
    AxisFrequencyAnalysis out;
    out.referenceOmegaRadPerSec = session.trajectory.kind == TrajectoryKind::Circle
                                      ? session.trajectory.omegaRadPerSec
                                      : std::numeric_limits<double>::quiet_NaN();
    const std::optional<LoopTransferFunctions> loop = axisLoop(evaluation);
    if (!loop) {
        out.error = evaluation.ok ? makeDiagnostic("session_no_loop_to_analyse") : evaluation.error;
        return out;
    }
    try {
        out.loop = *loop;
        out.margins =
            evaluation.margins ? *evaluation.margins : stabilityMargins(out.loop.openLoop);
        // One grid for every curve, holding the crossovers (where the margins are drawn) and
        // the reference frequency (where the tracking is read).
        FrequencyGridOptions grid;
        for (const GainMarginCrossing& c : out.margins.gainMargins)
            if (std::isfinite(c.omegaRadPerSec) && c.omegaRadPerSec > 0.0)
                grid.extraFrequencies.push_back(c.omegaRadPerSec);
        for (const PhaseMarginCrossing& c : out.margins.phaseMargins)
            if (std::isfinite(c.omegaRadPerSec) && c.omegaRadPerSec > 0.0)
                grid.extraFrequencies.push_back(c.omegaRadPerSec);
        const bool discrete = out.loop.openLoop.tsSeconds() > 0.0;
        const double nyquistOmega =
            discrete ? std::numbers::pi / out.loop.openLoop.tsSeconds() : 0.0;
        if (std::isfinite(out.referenceOmegaRadPerSec) && out.referenceOmegaRadPerSec > 0.0 &&
            (!discrete || out.referenceOmegaRadPerSec < nyquistOmega))
            grid.extraFrequencies.push_back(out.referenceOmegaRadPerSec);
        const FrequencyResponse l = adaptiveFrequencyResponse(out.loop.openLoop, grid);
        out.responses = loopFrequencyResponses(out.loop, l.omegaRadPerSec);
        out.nyquist = nyquistCurve(out.loop.openLoop);
        const DesignMethodModule& module = designMethodModule(evaluation.method);
        out.tracking = module.trackingResponses(evaluation, l.omegaRadPerSec);
        out.feedforwardName = std::string(module.feedforwardName());
        if (evaluation.gt) {
            const TransferFunction pi = TransferFunction::fromDescending(
                {evaluation.gt->kp, evaluation.gt->ki}, {1.0, 0.0});
            if (!(evaluation.gt->controller == pi)) {
                const TransferFunction open = series(pi, evaluation.gt->loopPlant);
                out.openLoopWithoutNotch = frequencyResponse(open, l.omegaRadPerSec);
                out.marginsWithoutNotch = stabilityMargins(open);
            }
        }
        out.ok = true;
    } catch (const InvalidInput& e) {
        const double reference = out.referenceOmegaRadPerSec;
        out = AxisFrequencyAnalysis{};
        out.referenceOmegaRadPerSec = reference;
        out.error = makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()});
    }
    return out;
}

} // namespace xyt
