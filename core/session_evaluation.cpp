// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session_evaluation.h"

#include "core/errors.h"
#include "core/trajectory.h"

#include <algorithm>

namespace xyt {

std::function<double(double)> axisReference(const TrajectorySettings& trajectory, int axisIndex) {
    if (trajectory.kind == TrajectoryKind::Cubic) {
        const CubicTrajectory cubic(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                    trajectory.tfSeconds, trajectory.v0, trajectory.vf);
        return [cubic](double t) { return cubic.position(t); };
    }
    requirePositive(trajectory.radius, "radius");
    requireNonZero(trajectory.omegaRadPerSec, "omega");
    const Circle circle{trajectory.radius, trajectory.omegaRadPerSec, 0.0, 0.0,
                        trajectory.rampInSeconds};
    Sinusoid s = axisIndex == 0 ? circle.xAxis() : circle.yAxis();
    s.validate();
    return [s](double t) { return s.value(t); };
}

namespace {

void evaluateGt(const Session& session, const AxisSettings& axis, int axisIndex,
                AxisEvaluation& out) {
    const GtAxisSettings& gt = axis.gt;
    out.gt = designGuilleminTruxal(gt.plant, gt.omegaNRadPerSec, gt.kp);
    LoopSimulationOptions options;
    options.dtSeconds = session.trajectory.dtSeconds;
    options.umaxVolts = session.umaxVolts;
    options.modelUnitsPerPositionUnit = gt.modelUnitsPerPositionUnit;
    const auto times =
        sampleTimes(session.trajectory.effectiveDurationSeconds(), options.dtSeconds);
    out.run = simulateLoop(gt.plant.transferFunction(), out.gt->controller,
                           sampled(axisReference(session.trajectory, axisIndex), times), options);
    out.metrics = trackingMetrics(out.run);
    out.step = stepCharacteristics(out.gt->closedLoop);
    if (!out.gt->stable)
        out.warnings.push_back("the closed loop is unstable");
}

} // namespace

AxisEvaluation evaluateAxis(const Session& session, int axisIndex) {
    AxisEvaluation out;
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    out.method = axis.method;
    try {
        requirePositive(session.umaxVolts, "umax");
        if (axis.method == DesignMethod::GuilleminTruxal)
            evaluateGt(session, axis, axisIndex, out);
        else
            throw InvalidInput("method", "pole placement is not available in this build");
        out.ok = true;
    } catch (const InvalidInput& e) {
        out.ok = false;
        out.errorField = e.field();
        out.error = e.reason();
    }
    return out;
}

std::vector<double> resampleLinear(const std::vector<double>& ts, const std::vector<double>& ys,
                                   const std::vector<double>& t) {
    std::vector<double> out(t.size());
    if (ts.empty())
        return out;
    std::size_t j = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        while (j + 1 < ts.size() && ts[j + 1] <= t[k])
            ++j;
        if (t[k] <= ts.front())
            out[k] = ys.front();
        else if (j + 1 >= ts.size())
            out[k] = ys.back();
        else {
            const double w = (t[k] - ts[j]) / (ts[j + 1] - ts[j]);
            out[k] = ys[j] + w * (ys[j + 1] - ys[j]);
        }
    }
    return out;
}

SessionEvaluation evaluateSession(const Session& session) {
    SessionEvaluation out;
    for (int i = 0; i < 2; ++i)
        out.axes[static_cast<std::size_t>(i)] = evaluateAxis(session, i);
    const auto& x = out.axes[0];
    const auto& y = out.axes[1];
    if (session.trajectory.kind == TrajectoryKind::Circle && x.ok && y.ok) {
        const Circle circle{session.trajectory.radius, session.trajectory.omegaRadPerSec, 0.0,
                            0.0, session.trajectory.rampInSeconds};
        const std::vector<double> yOnX = resampleLinear(y.run.t, y.run.y, x.run.t);
        try {
            out.contour = circleContourError(x.run.t, x.run.y, yOnX, circle);
        } catch (const InvalidInput&) {
            out.contour.reset(); // the run ended inside the ramp-in: no contour to judge
        }
    }
    return out;
}

} // namespace xyt
