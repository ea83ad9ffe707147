// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/pole_placement_method.h"

#include "core/model/number_format.h"
#include "core/session/axis_run.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/resample.h"
#include "core/simulation/zpetc_step.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

Polynomial fromCoefficients(const std::vector<double>& c, const std::string& field) {
    return Polynomial::fromAscending(c, field);
}

/**
 * A plant that does not integrate (A(1) != 0) holds a position y only with the steady command
 * u = y A(1) / B(1): beyond the actuator limit the axis cannot stay where the trajectory goes,
 * whatever the controller (Patrick, Ishak and Adnan's x-axis model needs 3.03 V at 600 mm).
 */
std::optional<std::string> reachWarning(const PpAxisSettings& pp,
                                        const std::vector<double>& reference, double umaxVolts) {
    double a1 = 0.0, b1 = 0.0, farthest = 0.0;
    for (double c : pp.a)
        a1 += c;
    for (double c : pp.b)
        b1 += c;
    for (double r : reference)
        farthest = std::max(farthest, std::abs(r));
    // |A(1)| below 1e-9 of the coefficients' scale: an integrator within round-off.
    double scale = 0.0;
    for (double c : pp.a)
        scale = std::max(scale, std::abs(c));
    if (!(std::abs(a1) > 1e-9 * scale) || b1 == 0.0 || !std::isfinite(farthest))
        return std::nullopt;
    const double hold = farthest * a1 / b1;
    if (!(std::abs(hold) > umaxVolts))
        return std::nullopt;
    return "the trajectory is out of the plant's reach: holding " + formatNumber(farthest, 4) +
           " mm needs " + formatNumber(std::abs(hold), 3) +
           " V (the model's steady gain B(1)/A(1) = " + formatNumber(b1 / a1, 4) +
           " mm/V), beyond the " + formatNumber(umaxVolts) + " V limit";
}

void evaluatePp(const Session& session, const AxisSettings& axis, int axisIndex, double duration,
                bool withDigital, AxisEvaluation& out) {
    const PpAxisSettings& pp = axis.pp;
    requireFinite(pp.t1, "t1");
    if (std::abs(pp.t1) >= 1.0)
        throw InvalidInput("t1", "the desired pole -t1 must lie inside the unit circle (|t1| < 1)");
    out.pp = designPolePlacement(fromCoefficients(pp.a, "a"), fromCoefficients(pp.b, "b"),
                                 Polynomial::fromAscending({1.0, pp.t1}), pp.tsSeconds);
    out.zpetc = designZpetc(*out.pp);
    for (const auto& w : out.pp->warnings)
        out.warnings.push_back(w);
    const auto reference = sessionReference(session.trajectory, axisIndex); // first, as evaluateGt
    const auto times = axisSampleTimes(session.trajectory, duration, pp.tsSeconds,
                                       "axes[" + std::to_string(axisIndex) + "].pp.ts");
    const std::size_t n = times.size();
    std::vector<double> r(n + static_cast<std::size_t>(out.zpetc->previewSteps));
    for (std::size_t k = 0; k < r.size(); ++k)
        r[k] = reference(static_cast<double>(k) * pp.tsSeconds);
    const std::vector<double> rLoop(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n));
    out.feedbackOnlyRun = discreteRun(times, r, simulateFeedbackLoop(*out.pp, rLoop),
                                      session.umaxVolts, pp.tsSeconds);
    out.rmseWithoutFf = rootMeanSquare(out.feedbackOnlyRun.e);
    if (pp.zpetcEnabled) {
        out.run = discreteRun(times, r, simulateZpetcLoop(*out.pp, *out.zpetc, r, n),
                              session.umaxVolts, pp.tsSeconds);
        const double with = rootMeanSquare(out.run.e);
        out.improvementPct =
            out.rmseWithoutFf > 0.0 ? 100.0 * (1.0 - with / out.rmseWithoutFf) : 0.0;
    } else {
        out.run = out.feedbackOnlyRun;
    }
    out.metrics = trackingMetrics(out.run);
    if (const auto w = reachWarning(pp, out.run.r, session.umaxVolts))
        out.warnings.push_back(*w);
    // The step figures of the system the axis runs: with ZPETC the step previewed through the
    // feedforward and the loop (the loop Kf B / T alone overshoots 52 % through the
    // NMP zero, which the axis never does); without it the loop alone.
    out.step = pp.zpetcEnabled && out.zpetc && out.pp->closedLoop().isStable()
                   ? zpetcStepCharacteristics(*out.pp, *out.zpetc)
                   : loopStepCharacteristics(*out.pp);
    if (!out.step.stable)
        out.warnings.push_back("the closed loop is unstable");
    if (out.metrics.saturated)
        out.warnings.push_back("|u| exceeds the actuator limit (the discrete loop is simulated "
                               "without saturation)");
    if (!withDigital)
        return;
    try {
        DigitalEvaluation d;
        d.tsSeconds = pp.tsSeconds;
        const SampledDataOptions options = sessionSampledDataOptions(session);
        const ZpetcDesign* zpetc = pp.zpetcEnabled ? &*out.zpetc : nullptr;
        d.run = simulateSampledRst(*out.pp, zpetc, r, n, options);
        d.poles = sampledRstLoopPoles(*out.pp, options.delaySamples);
        d.designPoles = sampledRstLoopPoles(*out.pp, 0);
        d.designMinDamping = minDigitalDamping(d.designPoles);
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    } catch (const InvalidInput& e) {
        out.warnings.push_back("no digital implementation: " + std::string(e.what()));
    }
}

/// A discrete axis: the reference resampled at its Ts (held at the end for the ZPETC's
/// preview), the table at rest at the first sample (StartCondition::AtReference).
SimulationResult tracePp(const PpAxisSettings& pp, int axisIndex, const std::vector<double>& t,
                         const std::vector<double>& reference, double umaxVolts) {
    PolePlacementDesign loop;
    ZpetcDesign zpetc;
    try {
        requireFinite(pp.t1, "t1");
        if (std::abs(pp.t1) >= 1.0)
            throw InvalidInput("t1",
                               "the desired pole -t1 must lie inside the unit circle (|t1| < 1)");
        loop = designPolePlacement(Polynomial::fromAscending(pp.a, "a"),
                                   Polynomial::fromAscending(pp.b, "b"),
                                   Polynomial::fromAscending({1.0, pp.t1}), pp.tsSeconds);
        zpetc = designZpetc(loop);
    } catch (const InvalidInput& e) {
        throw InvalidInput(axisFieldPath(axisIndex, "pp." + e.field()), e.reason());
    }
    const double steps = std::floor(t.back() / pp.tsSeconds + 1e-9);
    if (!(steps >= 1.0))
        throw InvalidInput(axisFieldPath(axisIndex, "pp.ts"),
                           formatNumber(pp.tsSeconds) + " s is longer than the program's run (" +
                               formatNumber(t.back()) + " s)");
    if (steps + 1.0 > static_cast<double>(sampleLimit()))
        throw InvalidInput(axisFieldPath(axisIndex, "pp.ts"),
                           "the run needs more samples than this machine holds");
    const std::size_t n = static_cast<std::size_t>(steps) + 1;
    std::vector<double> times(n + static_cast<std::size_t>(zpetc.previewSteps));
    for (std::size_t k = 0; k < times.size(); ++k)
        times[k] = static_cast<double>(k) * pp.tsSeconds;
    const std::vector<double> r = resampleLinear(t, reference, times);
    times.resize(n);
    const DiscreteRun run =
        pp.zpetcEnabled
            ? simulateZpetcLoop(loop, zpetc, r, n)
            : simulateFeedbackLoop(
                  loop, std::vector<double>(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n)));
    return discreteRun(times, r, run, umaxVolts, pp.tsSeconds);
}

class PolePlacementMethod final : public DesignMethodModule {
public:
    DesignMethod method() const override { return DesignMethod::PolePlacementZpetc; }
    std::string_view id() const override { return "pole-placement-zpetc"; }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        evaluatePp(session, session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex,
                   durationSeconds, withDigital, out);
    }

    AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& t,
                        const std::vector<double>& reference, double /*dtSeconds*/) const override {
        AxisTrace out;
        out.run = tracePp(session.axes.at(static_cast<std::size_t>(axisIndex)).pp, axisIndex, t,
                          reference, session.umaxVolts);
        out.outputOnPath = resampleLinear(out.run.t, out.run.y, t);
        return out;
    }

    std::vector<UncertainParameter> plantParameters(const AxisSettings& settings) const override {
        // As designPolePlacement uses the model: A and B divided by A(0).
        const Polynomial a = Polynomial::fromAscending(settings.pp.a, "a");
        const Polynomial b = Polynomial::fromAscending(settings.pp.b, "b");
        const double a0 = a.coefficient(0);
        if (a0 == 0.0)
            throw InvalidInput("a", "A(0) must be nonzero");
        std::vector<UncertainParameter> out;
        const auto& ac = a.ascending();
        for (std::size_t i = 1; i < ac.size(); ++i)
            out.push_back({"a" + std::to_string(i), ac[i] / a0, 0.0});
        const auto& bc = b.ascending();
        for (std::size_t i = 1; i < bc.size(); ++i)
            if (bc[i] != 0.0)
                out.push_back({"b" + std::to_string(i), bc[i] / a0, 0.0});
        return out;
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.pp)
            return std::nullopt;
        return rstLoopTransferFunctions(*axis.pp);
    }

    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        if (!axis.pp)
            throw InvalidInput("axis", "has no design");
        return axis.pp->closedLoop();
    }

    /// "plant B/A", "feedback G/F", "closed loop Kf B/T" and, when the feedforward runs,
    /// "ZPETC feedforward" (it is designed for the with/without comparison even when switched
    /// off; the map shows what runs).
    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& settings) const override {
        std::vector<PoleZeroSet> sets;
        if (!axis.pp)
            return sets;
        const PolePlacementDesign& pp = *axis.pp;
        const double ts = pp.tsSeconds;
        sets.push_back(poleZeroSet("plant B/A", TransferFunction::fromZInverse(pp.b, pp.a, ts)));
        sets.push_back(poleZeroSet("feedback G/F", TransferFunction::fromZInverse(pp.g, pp.f, ts)));
        sets.push_back(poleZeroSet("closed loop Kf B/T", pp.closedLoop()));
        if (axis.zpetc && settings.pp.zpetcEnabled)
            sets.push_back(poleZeroSet("ZPETC feedforward", TransferFunction::fromZInverse(
                                                                axis.zpetc->feedforwardNum,
                                                                axis.zpetc->feedforwardDen, ts)));
        return sets;
    }

    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.pp ? discreteDecayPerSecond(axis.pp->closedLoop().poles(), axis.pp->tsSeconds)
                       : 0.0;
    }
};

} // namespace

const DesignMethodModule& polePlacementMethod() {
    static const PolePlacementMethod module;
    return module;
}

} // namespace xyt
