// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/design_study.h"

#include "core/model/errors.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"

#include <cmath>

namespace xyt {

DesignProblem sessionDesignProblem(const Session& session, int axis,
                                   const StudyFidelity& fidelity) {
    if (axis < 0 || static_cast<std::size_t>(axis) >= session.axes.size())
        throw InvalidInput("axis", "there is no axis " + std::to_string(axis));
    const AxisSettings& settings = session.axes[static_cast<std::size_t>(axis)];
    if (settings.method != DesignMethod::GuilleminTruxal)
        throw InvalidInput("method", "the design space applies to Guillemin-Truxal axes");
    if (fidelity.maxSamples == 1)
        throw InvalidInput("max_samples", "a run needs at least 2 samples (0: no limit)");
    DesignProblem problem;
    problem.plant = settings.gt.plant;
    problem.modelUnitsPerPositionUnit = settings.gt.modelUnitsPerPositionUnit;
    problem.spec = session.spec; // the one specification of the session
    problem.spec.umaxVolts = session.umaxVolts;
    problem.spec.validate();
    problem.stepSamples = fidelity.stepSamples;
    const TrajectorySettings& t = session.trajectory;
    const bool cubic = t.kind == TrajectoryKind::Cubic;
    const double duration =
        cubic && t.durationSeconds == 0.0
            ? moveSweepDurationSeconds(t.tfSeconds, problem.spec.maxSettleTimeSeconds)
            : t.effectiveDurationSeconds();
    double dt = t.dtSeconds;
    requirePositive(dt, "dt");
    if (fidelity.maxSamples > 0 &&
        std::floor(duration / dt + 1e-9) + 1.0 > static_cast<double>(fidelity.maxSamples))
        dt = duration / static_cast<double>(fidelity.maxSamples - 1);
    problem.dtSeconds = dt;
    problem.reference = sampled(axisReference(t, axis), sampleTimes(duration, dt));
    if (cubic)
        problem.move = PointToPointMove{t.x0, t.xf, t.tfSeconds};
    return problem;
}

} // namespace xyt
