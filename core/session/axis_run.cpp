// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_run.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/simulation/resample.h"
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
        throw RunRefused(e.field(), e.reasonDiagnostic());
    }
}

std::vector<double> axisSampleTimes(const TrajectorySettings& trajectory, double duration,
                                    double dt, const std::string& dtField) {
    const std::string culprit = trajectory.durationSeconds > 0.0 ? "trajectory.duration" : dtField;
    std::vector<double> times;
    try {
        times = sampleTimes(duration, dt);
    } catch (const InvalidInput& e) {
        throw RunRefused(e.field() == "dt" ? dtField : culprit, e.reasonDiagnostic());
    }
    if (times.size() < 2)
        throw RunRefused(culprit, makeDiagnostic("session_single_sample",
                                                 {formatNumber(dt), formatNumber(duration)}));
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
    // (a diagnostic of core/simulation, kept as it comes)
    if (const auto w = digitalDampingWarning(d.poles, d.designMinDamping, d.tsSeconds))
        out.warnings.push_back(Diagnostic(*w));
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
                makeDiagnostic("limit_cycle_at_rest", {formatNumber(d.limitCycle->peakToPeak, 4),
                                                       std::to_string(d.limitCycle->turns)}));
    }
}

/// Says which criteria

const TableFriction* axisTable(const AxisSettings& axis, int axisIndex) {
    if (axis.method == DesignMethod::PolePlacementZpetc) {
        // An ARX model has no mass to put friction on: its table is an input dead zone.
        const TableFriction& f = axis.friction;
        const auto refuse = [&](const char* field, const char* code) {
            throw InvalidInput(axisFieldPath(axisIndex, std::string("friction.") + field),
                               makeDiagnostic(code));
        };
        if (f.staticVolts > f.coulombVolts)
            refuse("static", "session_arx_static_level");
        if (f.viscousVoltsPerMmPerS != 0.0)
            refuse("viscous", "session_arx_viscous");
        if (f.backlashMm != 0.0)
            refuse("backlash", "session_arx_backlash");
        if (axis.frictionCompensation.percent != 0.0)
            refuse("compensation.percent", "session_arx_compensation");
    }
    if (!axis.friction.active())
        return nullptr;
    if (axis.method != DesignMethod::PolePlacementZpetc && axis.gt.flexibleMode.present())
        throw InvalidInput(axisFieldPath(axisIndex, "gt.flexible_mode.frequency"),
                           makeDiagnostic("session_mode_and_friction"));
    try {
        validateTableFriction(axis.friction);
    } catch (const InvalidInput& e) {
        throw InvalidInput(axisFieldPath(axisIndex, "friction." + e.field()), e.reasonDiagnostic());
    }
    return &axis.friction;
}

double arxInputDeadzoneVolts(const AxisSettings& axis, int axisIndex) {
    const TableFriction* table = axisTable(axis, axisIndex);
    return table ? table->coulombVolts + table->amplifierDeadbandVolts : 0.0;
}

std::vector<double> frictionFeedforward(const AxisSettings& axis, int axisIndex,
                                        const std::vector<double>& reference, double dtSeconds) {
    const FrictionCompensation& c = axis.frictionCompensation;
    if (c.percent == 0.0 || reference.size() < 2)
        return {};
    try {
        validateFrictionCompensation(c);
    } catch (const InvalidInput& e) {
        throw InvalidInput(axisFieldPath(axisIndex, "friction.compensation." + e.field()),
                           e.reasonDiagnostic());
    }
    const std::size_t n = reference.size();
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t lo = k == 0 ? 0 : k - 1;
        const std::size_t hi = k + 1 == n ? k : k + 1;
        const double velocity =
            (reference[hi] - reference[lo]) / (static_cast<double>(hi - lo) * dtSeconds);
        out[k] = frictionCompensationVolts(axis.friction, c, velocity);
    }
    return out;
}

void addFeedforward(std::vector<double>& into, const std::vector<double>& add) {
    if (add.empty())
        return;
    if (into.empty()) {
        into = add;
        return;
    }
    for (std::size_t k = 0; k < into.size() && k < add.size(); ++k)
        into[k] += add[k];
}

std::vector<double> programAtPeriod(const std::vector<double>& t,
                                    const std::vector<double>& reference, double periodSeconds,
                                    const std::string& field, std::size_t lead) {
    const double steps = std::floor(t.back() / periodSeconds + 1e-9);
    if (!(steps >= 1.0))
        throw InvalidInput(field,
                           makeDiagnostic("session_period_longer_than_run",
                                          {formatNumber(periodSeconds), formatNumber(t.back())}));
    if (steps + 1.0 + static_cast<double>(lead) > static_cast<double>(sampleLimit()))
        throw InvalidInput(field, makeDiagnostic("session_too_many_samples"));
    std::vector<double> times(static_cast<std::size_t>(steps) + 1 + lead);
    for (std::size_t k = 0; k < times.size(); ++k)
        times[k] = static_cast<double>(k) * periodSeconds;
    return resampleLinear(t, reference, times);
}

namespace {

/// traceContinuousAxis' loop, run by @p run(plant, options) with the options it needs.
template <typename Run>
auto onContinuousAxis(const AxisSettings& axis, int axisIndex, const std::vector<double>& reference,
                      double dtSeconds, double umaxVolts, Run run) {
    LoopSimulationOptions options;
    options.dtSeconds = dtSeconds;
    options.umaxVolts = umaxVolts;
    options.modelUnitsPerPositionUnit = axis.gt.modelUnitsPerPositionUnit;
    options.initialOutput = reference.front();
    options.table = axisTable(axis, axisIndex);
    const std::vector<double> ff = frictionFeedforward(axis, axisIndex, reference, dtSeconds);
    if (!ff.empty())
        options.feedforwardVolts = &ff;
    try {
        return run(axisPlantTransferFunction(axis.gt, axisIndex), options);
    } catch (const InvalidInput& e) {
        if (e.field() == "plant" || e.field() == "initial_output")
            throw InvalidInput(axisFieldPath(axisIndex, "gt.plant"), e.reasonDiagnostic());
        throw;
    }
}

} // namespace

SimulationResult traceContinuousAxis(const AxisSettings& axis, int axisIndex,
                                     const TransferFunction& controller,
                                     const std::vector<double>& reference, double dtSeconds,
                                     double umaxVolts) {
    return onContinuousAxis(axis, axisIndex, reference, dtSeconds, umaxVolts,
                            [&](const TransferFunction& plant, const LoopSimulationOptions& o) {
                                return simulateLoop(plant, controller, reference, o);
                            });
}

std::unique_ptr<SteppedLoop> steppedContinuousAxis(const AxisSettings& axis, int axisIndex,
                                                   const TransferFunction& controller,
                                                   const std::vector<double>& reference,
                                                   double dtSeconds, double umaxVolts) {
    return onContinuousAxis(axis, axisIndex, reference, dtSeconds, umaxVolts,
                            [&](const TransferFunction& plant, const LoopSimulationOptions& o) {
                                return steppedLoop(plant, controller, reference, o);
                            });
}

} // namespace xyt
