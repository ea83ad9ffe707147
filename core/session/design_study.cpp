// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/design_study.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/session/axis_run.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"

#include <cmath>
#include <optional>

namespace xyt {

DesignProblem sessionDesignProblem(const Session& session, int axis,
                                   const StudyFidelity& fidelity) {
    if (axis < 0 || static_cast<std::size_t>(axis) >= session.axes.size())
        throw InvalidInput("axis", makeDiagnostic("session_no_axis", {std::to_string(axis)}));
    const AxisSettings& settings = session.axes[static_cast<std::size_t>(axis)];
    std::optional<PidFeedforwardDesign> pid;
    if (settings.method == DesignMethod::PidFeedforward) {
        pid = designPidFeedforward(session, axis);
        if (pid->gains.d != 0.0)
            throw InvalidInput(axisFieldPath(axis, "parameters.d"),
                               makeDiagnostic("session_design_space_pi_only"));
    } else if (settings.method != DesignMethod::GuilleminTruxal) {
        throw InvalidInput("method", makeDiagnostic("session_design_space_methods"));
    }
    if (fidelity.maxSamples == 1)
        throw InvalidInput("max_samples", makeDiagnostic("session_max_samples"));
    DesignProblem problem;
    problem.plant = settings.gt.plant;
    if (settings.gt.flexibleMode.present())
        problem.plantFactor = flexibleModeTransferFunction(settings.gt, axis);
    if (settings.gt.notch.present() && !pid)
        problem.controllerFilter = notchTransferFunction(settings.gt, axis);
    problem.modelUnitsPerPositionUnit = settings.gt.modelUnitsPerPositionUnit;
    problem.spec = session.spec; // the one specification of the session
    problem.spec.umaxVolts = pid ? pid->gains.maxOutput : session.umaxVolts;
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
    const std::vector<double> times = sampleTimes(duration, dt);
    problem.reference = sampled(axisReference(t, axis), times);
    if (pid) {
        const auto motion = axisMotion(t, axis);
        problem.feedforwardVolts.resize(times.size());
        for (std::size_t k = 0; k < times.size(); ++k)
            problem.feedforwardVolts[k] = feedforwardVolts(pid->gains, motion(times[k]));
    }
    if (cubic)
        problem.move = PointToPointMove{t.x0, t.xf, t.tfSeconds};
    // The table with friction, and its compensation with the command feedforward.
    if (const TableFriction* table = axisTable(settings, axis))
        problem.table = *table;
    const std::vector<double> compensation =
        frictionFeedforward(settings, axis, problem.reference, dt);
    if (!compensation.empty()) {
        if (problem.feedforwardVolts.empty())
            problem.feedforwardVolts.assign(compensation.size(), 0.0);
        addFeedforward(problem.feedforwardVolts, compensation);
    }
    return problem;
}

} // namespace xyt
