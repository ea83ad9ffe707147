// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/session_evaluation.h"

#include "core/analysis/loop_responses.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/program_trajectory.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/trajectory.h"
#include "core/simulation/zpetc_step.h"
#include "core/study/helper_thread.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace xyt {

std::function<double(double)> axisReference(const TrajectorySettings& trajectory, int axisIndex) {
    if (trajectory.kind == TrajectoryKind::Gcode)
        return programAxisReference(trajectory, axisIndex); // names the session paths itself
    // Core checks name their own argument ("xf", "radius"); the session's user knows the path.
    try {
        if (trajectory.kind == TrajectoryKind::Cubic) {
            const CubicTrajectory cubic(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                        trajectory.tfSeconds, trajectory.v0, trajectory.vf);
            return [cubic](double t) { return cubic.position(t); };
        }
    } catch (const InvalidInput& e) {
        throw InvalidInput("trajectory.cubic." + e.field(), e.reason());
    }
    try {
        requirePositive(trajectory.radius, "radius");
        requirePosition(trajectory.radius, "radius");
        requireNonZero(trajectory.omegaRadPerSec, "omega");
        const Circle circle{trajectory.radius, trajectory.omegaRadPerSec, 0.0, 0.0,
                            trajectory.rampInSeconds};
        Sinusoid s = axisIndex == 0 ? circle.xAxis() : circle.yAxis();
        s.validate();
        return [s](double t) { return s.value(t); };
    } catch (const InvalidInput& e) {
        throw InvalidInput("trajectory.circle." + e.field(), e.reason());
    }
}

namespace {

/// A refusal of the run itself (AxisEvaluation::runRefused), not of one axis' design.
struct RunRefused : InvalidInput {
    using InvalidInput::InvalidInput;
};

/// axisReference, its refusals marked as refusals of the run.
std::function<double(double)> sessionReference(const TrajectorySettings& trajectory,
                                               int axisIndex) {
    try {
        return axisReference(trajectory, axisIndex);
    } catch (const InvalidInput& e) {
        throw RunRefused(e.field(), e.reason());
    }
}

/**
 * The sample times of one axis (step @p dt, named @p dtField in the session), refused naming
 * the session field when the run would not fit in memory or would hold a single sample (every
 * metric would read 0, which is not a result). The duration is blamed when the session sets it,
 * else the step.
 */
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

} // namespace

GtDesign sessionGtDesign(const GtAxisSettings& gt, int axisIndex) {
    try {
        return designGuilleminTruxal(gt.plant, gt.omegaNRadPerSec, gt.kp);
    } catch (const InvalidInput& e) {
        const std::string axis = "axes[" + std::to_string(axisIndex) + "].gt.";
        if (e.field() == "wn" || e.field() == "kp")
            throw InvalidInput(axis + e.field(), e.reason());
        if (e.field() == "k0" || e.field() == "a1" ||
            e.field() == "a2") // the session file's plant object
            throw InvalidInput(axis + "plant." + e.field(), e.reason());
        throw;
    }
}

DigitalPi sessionDigitalPi(const Session& session, const GtDesign& design) {
    try {
        return digitalPi(design.kp, design.ki, session.controllerTsSeconds,
                         session.piDiscretization, session.implementation.antiWindup,
                         session.implementation.trackingTimeSeconds);
    } catch (const InvalidInput& e) {
        if (e.field() == "ts")
            throw InvalidInput("controller_ts", e.reason());
        if (e.field() == "tracking_time")
            throw InvalidInput("implementation.tracking_time", e.reason());
        throw;
    }
}

std::vector<PoleZeroSet> digitalPoleZeroSets(const AxisEvaluation& axis) {
    if (!axis.digital)
        return {};
    const DigitalEvaluation& d = *axis.digital;
    return {{"digital loop", d.tsSeconds, d.poles, {}},
            {"design at Ts", d.tsSeconds, d.designPoles, {}}};
}

SampledDataOptions sessionSampledDataOptions(const Session& session) {
    SampledDataOptions o;
    o.delaySamples = session.implementation.delaySamples;
    o.encoderResolution = session.implementation.encoderResolutionMm;
    o.dacBits = session.implementation.dacBits;
    o.umaxVolts = session.umaxVolts;
    o.antiWindup = session.implementation.antiWindup;
    try {
        validateSampledDataOptions(o);
    } catch (const InvalidInput& e) {
        throw InvalidInput(e.field() == "umax" ? "umax" : "implementation." + e.field(),
                           e.reason());
    }
    return o;
}

namespace {

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

/// The figures, move-and-settle, damping and limit-cycle warnings of a digital run.
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

/// Says which criteria the design passes but its digital implementation fails, if any.
std::optional<std::string> implementationVerdictWarning(const SpecificationCheck& design,
                                                        const SpecificationCheck& implementation) {
    std::vector<std::string> failed;
    if (design.trackingError && !implementation.trackingError)
        failed.push_back("the tracking error");
    if (design.noSaturation && !implementation.noSaturation)
        failed.push_back("the actuator limit");
    if (design.settleApplies && design.settle && !implementation.settle)
        failed.push_back("the settle after the move");
    if (failed.empty())
        return std::nullopt;
    std::string list;
    for (std::size_t i = 0; i < failed.size(); ++i)
        list += (i == 0 ? "" : i + 1 == failed.size() ? " and " : ", ") + failed[i];
    return "the design meets " + list +
           ", its digital implementation does not: the verdict is the "
           "implementation's";
}

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

} // namespace

SimulationResult discreteRun(const std::vector<double>& t, const std::vector<double>& r,
                             const DiscreteRun& run, double umaxVolts, double ts) {
    SimulationResult out;
    out.t = t;
    out.r.assign(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(t.size()));
    out.y = run.y;
    out.u = run.u;
    out.e.resize(t.size());
    out.clipped.resize(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) {
        out.e[k] = out.r[k] - out.y[k];
        out.clipped[k] = k < out.u.size() && std::abs(out.u[k]) > umaxVolts;
    }
    if (out.u.size() < t.size())
        out.u.resize(t.size(), 0.0);
    out.dtSeconds = ts;
    out.umaxVolts = umaxVolts;
    return out;
}

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

} // namespace

TransferFunction AxisEvaluation::closedLoop() const {
    if (gt)
        return gt->closedLoop;
    if (pp)
        return pp->closedLoop();
    throw InvalidInput("axis", "has no design");
}

namespace {

/// evaluateAxis over a given duration.
AxisEvaluation evaluateAxisOver(const Session& session, int axisIndex, const RunDuration& duration,
                                bool withDigital = true) {
    AxisEvaluation out;
    out.duration = duration;
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    out.method = axis.method;
    try {
        requirePositive(session.umaxVolts, "umax");
        if (axis.method == DesignMethod::GuilleminTruxal)
            evaluateGt(session, axis, axisIndex, duration.seconds, withDigital, out);
        else
            evaluatePp(session, axis, axisIndex, duration.seconds, withDigital, out);
        if (out.metrics.diverged)
            out.warnings.push_back("the simulated run diverged (a sample is not a finite number): "
                                   "it has no tracking figures");
        const TrajectorySettings& t = session.trajectory;
        if (t.kind == TrajectoryKind::Cubic) {
            try {
                out.moveSettle = moveSettleMetrics(out.run, {t.x0, t.xf, t.tfSeconds},
                                                   session.spec.inPositionWindowMm);
            } catch (const InvalidInput& e) {
                throw InvalidInput("specification." + e.field(), e.reason());
            }
            if (!out.moveSettle->reachedMoveEnd)
                out.warnings.push_back("the run ends before the move does (tf): no settle figures");
        }
        // The move-only evaluation of chooseRunDuration (withDigital false) needs no margins.
        if (withDigital) {
            try {
                out.margins = stabilityMargins(out.gt ? gtLoopTransferFunctions(*out.gt).openLoop
                                                      : rstLoopTransferFunctions(*out.pp).openLoop);
            } catch (const InvalidInput& e) {
                out.warnings.push_back(std::string("no stability margins: ") + e.what());
            }
        }
        std::optional<LoopMarginFigures> margins;
        if (out.margins)
            margins = LoopMarginFigures{out.margins->phaseMarginDeg, out.margins->gainMarginDb};
        Specification spec = session.spec;
        spec.umaxVolts = session.umaxVolts;
        out.designCheck = checkSpecification(spec, out.metrics, out.step, out.moveSettle, margins);
        out.check = out.designCheck;
        if (out.digital) {
            out.implementationCheck = checkSpecification(spec, out.digital->metrics, out.step,
                                                         out.digital->moveSettle, margins);
            out.check = bothPass(out.designCheck, *out.implementationCheck);
            if (const auto w =
                    implementationVerdictWarning(out.designCheck, *out.implementationCheck))
                out.warnings.push_back(*w);
        }
        out.ok = true;
    } catch (const InvalidInput& e) {
        out.ok = false;
        out.errorField = e.field();
        out.error = e.reason();
        out.runRefused = dynamic_cast<const RunRefused*>(&e) != nullptr;
    }
    return out;
}

/// Both axes over a duration. They are independent, so the y axis is evaluated on the helper
/// thread while the x axis is on this one (runAlongside): a slider step evaluates both, and two
/// cores halve its time (the slider-to-repaint target).
std::array<AxisEvaluation, 2> evaluateAxesOver(const Session& session, const RunDuration& duration,
                                               bool withDigital = true) {
    std::array<AxisEvaluation, 2> out;
    runAlongside([&] { out[1] = evaluateAxisOver(session, 1, duration, withDigital); },
                 [&] { out[0] = evaluateAxisOver(session, 0, duration, withDigital); });
    return out;
}

/// The slowest decay rate of an axis' closed loop (1/s); 0 or less when not asymptotically stable.
double slowestDecayPerSecond(const AxisEvaluation& a) {
    if (a.gt)
        return continuousDecayPerSecond(a.gt->closedLoopPoles);
    if (a.pp)
        return discreteDecayPerSecond(a.pp->closedLoop().poles(), a.pp->tsSeconds);
    return 0.0;
}

std::string seconds(double v) {
    return formatNumber(v) + " s";
}

} // namespace

RunDuration chooseRunDuration(const Session& session) {
    const TrajectorySettings& t = session.trajectory;
    RunDuration d;
    d.capSeconds = t.effectiveDurationSeconds();
    d.seconds = d.capSeconds;
    d.automatic = !(t.durationSeconds > 0.0) || t.kind == TrajectoryKind::Gcode;
    if (!d.automatic) {
        d.description = "duration " + seconds(d.seconds) + " (set in the session)";
        return d;
    }
    if (t.kind == TrajectoryKind::Circle) {
        d.description =
            "duration " + seconds(d.seconds) + " (automatic: the ramp-in and one revolution)";
        return d;
    }
    if (t.kind == TrajectoryKind::Gcode) {
        d.description = "duration " + seconds(d.seconds) + " (the program's feed profile)";
        return d;
    }
    // The move alone first, on both axes, for their error at tf.
    RunDuration moveOnly = d;
    moveOnly.seconds = t.tfSeconds;
    double need = 0.0;
    bool any = false;
    for (const AxisEvaluation& a : evaluateAxesOver(session, moveOnly, false)) {
        if (!a.ok || !a.step.stable || a.metrics.diverged || a.run.e.empty())
            continue; // it will not settle whatever the duration; its evaluation says why
        any = true;
        need = std::max(need,
                        settleTimeEstimateSeconds(a.run.e.back(), session.spec.inPositionWindowMm,
                                                  slowestDecayPerSecond(a)));
    }
    d.includesSettle = any;
    d.settleEstimateSeconds = need;
    if (!any) {
        d.seconds = t.tfSeconds;
        d.description = "duration " + seconds(d.seconds) +
                        " (automatic: the move only; no axis has a stable design to settle)";
        return d;
    }
    d.seconds = automaticMoveDurationSeconds(t.t0Seconds, t.tfSeconds, need, d.capSeconds);
    d.capped = d.seconds == d.capSeconds && d.capSeconds > t.tfSeconds;
    d.description =
        "duration " + seconds(d.seconds) + " (automatic: the move to tf = " + seconds(t.tfSeconds) +
        " and the settle into " + formatNumber(session.spec.inPositionWindowMm) +
        " mm, estimated " + (std::isfinite(need) ? seconds(need) : std::string("never")) +
        " after tf from the slowest closed-loop pole" +
        (d.capped
             ? "; cut to the cap of tf + " + formatNumber(kAutomaticSettleMoves) +
                   " move durations" +
                   (d.capSeconds < t.tfSeconds + kAutomaticSettleMoves * (t.tfSeconds - t.t0Seconds)
                        ? " (lowered to what a million samples hold at this dt)"
                        : "")
             : "") +
        ")";
    return d;
}

AxisEvaluation evaluateAxis(const Session& session, int axisIndex) {
    return evaluateAxisOver(session, axisIndex, chooseRunDuration(session));
}

SessionEvaluation evaluateSession(const Session& session) {
    SessionEvaluation out;
    out.duration = chooseRunDuration(session);
    out.axes = evaluateAxesOver(session, out.duration);
    const auto& x = out.axes[0];
    const auto& y = out.axes[1];
    if (session.trajectory.kind == TrajectoryKind::Circle && x.ok && y.ok) {
        const Circle circle{session.trajectory.radius, session.trajectory.omegaRadPerSec, 0.0, 0.0,
                            session.trajectory.rampInSeconds};
        const std::vector<double> yOnX = resampleLinear(y.run.t, y.run.y, x.run.t);
        try {
            out.contour = circleContourError(x.run.t, x.run.y, yOnX, circle);
        } catch (const InvalidInput&) {
            out.contour.reset(); // the run ended inside the ramp-in: no contour to judge
        }
    }
    if (session.trajectory.kind == TrajectoryKind::Gcode && x.ok && y.ok) {
        // The program's contour run simulates both axes once more, from the same reference
        // samples, for the contour error along the path and (one full circle) the ballbar runs.
        try {
            const std::shared_ptr<const GcodeProgram> program =
                sessionProgram(session.trajectory.gcode);
            out.program = std::make_shared<const ContourRun>(runSessionProgram(session, *program));
            // The path of the shared program itself (aliasing it), not a copy per evaluation.
            out.programPath = std::shared_ptr<const Path>(program, &program->path);
        } catch (const InvalidInput& e) {
            out.programError = e.what();
        }
    }
    return out;
}

} // namespace xyt
