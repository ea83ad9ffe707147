// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/guillemin_truxal_method.h"

#include "core/model/root_matching.h"
#include "core/session/axis_run.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/trajectory.h"

#include <cmath>

namespace xyt {

namespace {

/// The digital implementation of a Guillemin-Truxal axis (its failures become a warning: the
/// export names the field when asked for the code).
void evaluateGtDigital(const Session& session, const AxisSettings& axis, int axisIndex,
                       double duration, AxisEvaluation& out) {
    try {
        DigitalEvaluation d;
        const DigitalPi pi = sessionDigitalPi(session, *out.gt);
        d.tsSeconds = pi.tsSeconds;
        const SampledDataOptions options = sessionSampledDataOptions(session);
        const TransferFunction plant = axis.gt.plant.transferFunction();
        // At the simulation step (the default: both 10 ms) the continuous run already holds the
        // reference at the controller's sample times.
        const bool sameTimes = pi.tsSeconds == session.trajectory.dtSeconds;
        d.run =
            simulateSampledPi(plant, pi,
                              sameTimes ? out.run.r
                                        : sampled(sessionReference(session.trajectory, axisIndex),
                                                  axisSampleTimes(session.trajectory, duration,
                                                                  pi.tsSeconds, "controller_ts")),
                              options, axis.gt.modelUnitsPerPositionUnit);
        d.poles = sampledPiLoopPoles(sampledPlant(plant, pi.tsSeconds), pi, options.delaySamples);
        d.designMinDamping = minContinuousDamping(out.gt->closedLoopPoles);
        for (const auto& p : out.gt->closedLoopPoles)
            d.designPoles.push_back(std::exp(p * pi.tsSeconds));
        sortRoots(d.designPoles);
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    } catch (const InvalidInput& e) {
        out.warnings.push_back("no digital implementation: " + std::string(e.what()));
    }
}

void evaluateGt(const Session& session, const AxisSettings& axis, int axisIndex, double duration,
                bool withDigital, AxisEvaluation& out) {
    const GtAxisSettings& gt = axis.gt;
    out.gt = sessionGtDesign(gt, axisIndex);
    LoopSimulationOptions options;
    options.dtSeconds = session.trajectory.dtSeconds;
    options.umaxVolts = session.umaxVolts;
    options.modelUnitsPerPositionUnit = gt.modelUnitsPerPositionUnit;
    // The reference first: an unreadable program has no run time, and its refusal names the
    // program rather than the step that a run of no length would be blamed on.
    const auto reference = sessionReference(session.trajectory, axisIndex);
    const auto times =
        axisSampleTimes(session.trajectory, duration, options.dtSeconds, "trajectory.dt");
    out.run = simulateLoop(gt.plant.transferFunction(), out.gt->controller,
                           sampled(reference, times), options);
    out.metrics = trackingMetrics(out.run);
    out.step = stepCharacteristics(out.gt->closedLoop);
    if (!out.gt->stable)
        out.warnings.push_back("the closed loop is unstable");
    if (withDigital)
        evaluateGtDigital(session, axis, axisIndex, duration, out);
}

/// A continuous axis on the reference sampled at dt, starting at rest at its first sample.
SimulationResult traceGt(const GtAxisSettings& gt, int axisIndex,
                         const std::vector<double>& reference, double dtSeconds, double umaxVolts) {
    const GtDesign design = sessionGtDesign(gt, axisIndex);
    LoopSimulationOptions options;
    options.dtSeconds = dtSeconds;
    options.umaxVolts = umaxVolts;
    options.modelUnitsPerPositionUnit = gt.modelUnitsPerPositionUnit;
    options.initialOutput = reference.front();
    try {
        return simulateLoop(gt.plant.transferFunction(), design.controller, reference, options);
    } catch (const InvalidInput& e) {
        if (e.field() == "plant" || e.field() == "initial_output")
            throw InvalidInput(axisFieldPath(axisIndex, "gt.plant"), e.reason());
        throw;
    }
}

class GuilleminTruxalMethod final : public DesignMethodModule {
public:
    DesignMethod method() const override { return DesignMethod::GuilleminTruxal; }
    std::string_view id() const override { return "guillemin-truxal"; }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        evaluateGt(session, session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex,
                   durationSeconds, withDigital, out);
    }

    AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& /*t*/,
                        const std::vector<double>& reference, double dtSeconds) const override {
        AxisTrace out;
        out.run = traceGt(session.axes.at(static_cast<std::size_t>(axisIndex)).gt, axisIndex,
                          reference, dtSeconds, session.umaxVolts);
        out.outputOnPath = out.run.y;
        return out;
    }

    std::vector<UncertainParameter> plantParameters(const AxisSettings& settings) const override {
        const ThirdOrderPlant& g = settings.gt.plant;
        return {{"k0", g.k0, 0.0}, {"a1", g.a1, 0.0}, {"a2", g.a2, 0.0}};
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.gt)
            return std::nullopt;
        return gtLoopTransferFunctions(*axis.gt);
    }

    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        if (!axis.gt)
            throw InvalidInput("axis", "has no design");
        return axis.gt->closedLoop;
    }

    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& /*settings*/) const override {
        if (!axis.gt)
            return {};
        return gtPoleZeroSets(*axis.gt);
    }

    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.gt ? continuousDecayPerSecond(axis.gt->closedLoopPoles) : 0.0;
    }
};

} // namespace

const DesignMethodModule& guilleminTruxalMethod() {
    static const GuilleminTruxalMethod module;
    return module;
}

} // namespace xyt
