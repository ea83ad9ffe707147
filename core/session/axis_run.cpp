// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_run.h"

#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <cmath>

namespace xyt {

std::string axisFieldPath(int axisIndex, const std::string& field) {
    return "axes[" + std::to_string(axisIndex) + "]." + field;
}

std::function<double(double)> sessionReference(const TrajectorySettings& trajectory,
                                               int axisIndex) {
    try {
        return axisReference(trajectory, axisIndex);
    } catch (const InvalidInput& e) {
        throw RunRefused(e.field(), e.reason());
    }
}

std::vector<double> axisSampleTimes(const TrajectorySettings& trajectory, double duration,
                                    double dt, const std::string& dtField) {
    const std::string culprit = trajectory.durationSeconds > 0.0 ? "trajectory.duration" : dtField;
    std::vector<double> times;
    try {
        times = sampleTimes(duration, dt);
    } catch (const InvalidInput& e) {
        throw RunRefused(e.field() == "dt" ? dtField : culprit, e.reason());
    }
    if (times.size() < 2)
        throw RunRefused(culprit, "gives a single sample (step " + formatNumber(dt) +
                                      " s, duration " + formatNumber(duration) +
                                      " s); at least two samples are needed for the metrics");
    return times;
}

double minContinuousDamping(const std::vector<std::complex<double>>& poles) {
    double out = 1.0;
    for (const auto& p : poles)
        if (std::abs(p) > 0.0)
            out = std::min(out, -p.real() / std::abs(p));
    return out;
}

double minDigitalDamping(const std::vector<std::complex<double>>& poles) {
    double out = 1.0;
    for (const auto& z : poles)
        if (std::abs(z) >= 1e-9)
            out = std::min(out, zDampingRatio(z));
    return out;
}

void finishDigital(const Session& session, DigitalEvaluation& d, AxisEvaluation& out) {
    d.metrics = trackingMetrics(d.run.result);
    d.minDamping = minDigitalDamping(d.poles);
    if (const auto w = digitalDampingWarning(d.poles, d.designMinDamping, d.tsSeconds))
        out.warnings.push_back(*w);
    const TrajectorySettings& t = session.trajectory;
    if (t.kind != TrajectoryKind::Cubic)
        return;
    d.moveSettle =
        moveSettleMetrics(d.run.result, {t.x0, t.xf, t.tfSeconds}, session.spec.inPositionWindowMm);
    const ImplementationSettings& impl = session.implementation;
    if (impl.encoderResolutionMm > 0.0 || impl.dacBits > 0) {
        const auto& times = d.run.result.t;
        const auto rest = std::lower_bound(times.begin(), times.end(), t.tfSeconds);
        d.limitCycle =
            restLimitCycle(d.run.measured, static_cast<std::size_t>(rest - times.begin()));
        if (d.limitCycle)
            out.warnings.push_back(
                "a limit cycle at rest: after the move the measured position keeps oscillating (" +
                formatNumber(d.limitCycle->peakToPeak, 4) + " mm peak to peak, " +
                std::to_string(d.limitCycle->turns) +
                " turns in the last half of the rest), caused by the encoder/DAC quantization");
    }
}

/// Says which criteria

SimulationResult traceContinuousAxis(const AxisSettings& axis, int axisIndex,
                                     const TransferFunction& controller,
                                     const std::vector<double>& reference, double dtSeconds,
                                     double umaxVolts) {
    LoopSimulationOptions options;
    options.dtSeconds = dtSeconds;
    options.umaxVolts = umaxVolts;
    options.modelUnitsPerPositionUnit = axis.gt.modelUnitsPerPositionUnit;
    options.initialOutput = reference.front();
    try {
        return simulateLoop(axis.gt.plant.transferFunction(), controller, reference, options);
    } catch (const InvalidInput& e) {
        if (e.field() == "plant" || e.field() == "initial_output")
            throw InvalidInput(axisFieldPath(axisIndex, "gt.plant"), e.reason());
        throw;
    }
}

} // namespace xyt
