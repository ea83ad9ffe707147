// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/session_evaluation.h"

#include "core/simulation/mode_excitation.h"

#include "core/simulation/stick_slip.h"

#include "core/analysis/loop_responses.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/axis_run.h"
#include "core/session/design_method_module.h"
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

namespace {

/// The reference of the trajectory before its input shaper.
std::function<double(double)> unshapedAxisReference(const TrajectorySettings& trajectory,
                                                    int axisIndex);
/// Its motion (position and derivatives), as axisMotion gives it.
std::function<MotionSample(double)> unshapedAxisMotion(const TrajectorySettings& trajectory,
                                                       int axisIndex);

/// The trajectory's input shaper, refused at "trajectory.shaping.<field>"; a shaper longer than
/// a point-to-point move or a program is refused at its frequency.
std::optional<InputShaper> trajectoryShaper(const TrajectorySettings& trajectory) {
    if (!trajectory.shaping.active())
        return std::nullopt;
    const ReferenceShaping& s = trajectory.shaping;
    InputShaper shaper;
    try {
        shaper = designInputShaper(s.type, s.frequencyHz, s.dampingRatio);
    } catch (const InvalidInput& e) {
        throw InvalidInput("trajectory.shaping." + e.field(), e.reasonDiagnostic());
    }
    double move = 0.0;
    if (trajectory.kind == TrajectoryKind::Cubic)
        move = trajectory.tfSeconds - trajectory.t0Seconds;
    else if (trajectory.kind == TrajectoryKind::Gcode)
        move = trajectory.effectiveDurationSeconds() - shaper.duration();
    if (move > 0.0 && shaper.duration() > move)
        throw InvalidInput("trajectory.shaping.frequency",
                           makeDiagnostic("session_shaper_longer_than_move",
                                          {shaperName(s.type), formatNumber(s.frequencyHz),
                                           formatNumber(shaper.duration()), formatNumber(move)}));
    return shaper;
}

} // namespace

double shapedMoveEndSeconds(const TrajectorySettings& trajectory) {
    double shaper = 0.0;
    try {
        if (const std::optional<InputShaper> s = trajectoryShaper(trajectory))
            shaper = s->duration();
    } catch (const InvalidInput&) {
        // the evaluation names the bad field
    }
    return trajectory.tfSeconds + shaper;
}

std::function<double(double)> axisReference(const TrajectorySettings& trajectory, int axisIndex) {
    std::function<double(double)> r = unshapedAxisReference(trajectory, axisIndex);
    const std::optional<InputShaper> shaper = trajectoryShaper(trajectory);
    if (!shaper)
        return r;
    // r_s(t) = sum A_i r(t - t_i): exact, the reference being a function of time.
    return [r, a = shaper->amplitudes, tau = shaper->times](double t) {
        double sum = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i)
            sum += a[i] * r(t - tau[i]);
        return sum;
    };
}

namespace {

std::function<double(double)> unshapedAxisReference(const TrajectorySettings& trajectory,
                                                    int axisIndex) {
    if (trajectory.kind == TrajectoryKind::Gcode)
        return programAxisReference(trajectory, axisIndex); // names the session paths itself
    // Core checks name their own argument ("xf", "radius"); the session's user knows the path.
    try {
        if (trajectory.kind == TrajectoryKind::Cubic) {
            if (trajectory.profile == MoveProfile::Quintic) {
                const QuinticTrajectory quintic(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                                trajectory.tfSeconds, trajectory.v0, trajectory.vf);
                return [quintic](double t) { return quintic.position(t); };
            }
            const CubicTrajectory cubic(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                        trajectory.tfSeconds, trajectory.v0, trajectory.vf);
            return [cubic](double t) { return cubic.position(t); };
        }
    } catch (const InvalidInput& e) {
        throw InvalidInput("trajectory.cubic." + e.field(), e.reasonDiagnostic());
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
        throw InvalidInput("trajectory.circle." + e.field(), e.reasonDiagnostic());
    }
}

} // namespace

std::function<MotionSample(double)> axisMotion(const TrajectorySettings& trajectory,
                                               int axisIndex) {
    const std::function<MotionSample(double)> motion = unshapedAxisMotion(trajectory, axisIndex);
    const std::optional<InputShaper> shaper = trajectoryShaper(trajectory);
    if (!shaper)
        return motion;
    // Shaping is linear and time-invariant: each derivative is shaped as the position is.
    return [motion, a = shaper->amplitudes, tau = shaper->times](double t) {
        MotionSample sum;
        for (std::size_t i = 0; i < a.size(); ++i) {
            const MotionSample m = motion(t - tau[i]);
            sum.position += a[i] * m.position;
            sum.velocity += a[i] * m.velocity;
            sum.acceleration += a[i] * m.acceleration;
            sum.jerk += a[i] * m.jerk;
        }
        return sum;
    };
}

namespace {

std::function<MotionSample(double)> unshapedAxisMotion(const TrajectorySettings& trajectory,
                                                       int axisIndex) {
    const std::function<double(double)> position = unshapedAxisReference(trajectory, axisIndex);
    if (trajectory.kind == TrajectoryKind::Cubic) {
        // axisReference has checked the move, so these constructors do not throw.
        if (trajectory.profile == MoveProfile::Quintic) {
            const QuinticTrajectory q(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                      trajectory.tfSeconds, trajectory.v0, trajectory.vf);
            return [q](double t) { return q.motion(t); };
        }
        const CubicTrajectory c(trajectory.x0, trajectory.xf, trajectory.t0Seconds,
                                trajectory.tfSeconds, trajectory.v0, trajectory.vf);
        return [c](double t) { return c.motion(t); };
    }
    if (trajectory.kind == TrajectoryKind::Circle) {
        const Circle circle{trajectory.radius, trajectory.omegaRadPerSec, 0.0, 0.0,
                            trajectory.rampInSeconds};
        const Sinusoid s = axisIndex == 0 ? circle.xAxis() : circle.yAxis();
        return [s](double t) { return s.motion(t); };
    }
    const double h = trajectory.dtSeconds > 0.0 ? trajectory.dtSeconds : 0.01;
    return [position, h](double t) {
        return centralDifferenceMotion(position(t - 2.0 * h), position(t - h), position(t),
                                       position(t + h), position(t + 2.0 * h), h);
    };
}

} // namespace

GtDesign sessionGtDesign(const GtAxisSettings& gt, int axisIndex) {
    GtDesign design;
    try {
        design = designGuilleminTruxal(gt.plant, gt.omegaNRadPerSec, gt.kp);
    } catch (const InvalidInput& e) {
        const std::string axis = "axes[" + std::to_string(axisIndex) + "].gt.";
        if (e.field() == "wn" || e.field() == "kp")
            throw InvalidInput(axis + e.field(), e.reasonDiagnostic());
        if (e.field() == "k0" || e.field() == "a1" ||
            e.field() == "a2") // the session file's plant object
            throw InvalidInput(axis + "plant." + e.field(), e.reasonDiagnostic());
        throw;
    }
    if (!gt.flexibleMode.present() && !gt.notch.present())
        return design;
    return withLoopElements(design, flexibleModeTransferFunction(gt, axisIndex),
                            notchTransferFunction(gt, axisIndex));
}

TransferFunction flexibleModeTransferFunction(const GtAxisSettings& gt, int axisIndex) {
    const std::string prefix = "axes[" + std::to_string(axisIndex) + "].gt.flexible_mode.";
    validateFlexibleMode(gt.flexibleMode, prefix);
    return gt.flexibleMode.transferFunction();
}

TransferFunction notchTransferFunction(const GtAxisSettings& gt, int axisIndex) {
    const std::string prefix = "axes[" + std::to_string(axisIndex) + "].gt.notch.";
    validateNotchFilter(gt.notch, prefix);
    return gt.notch.transferFunction();
}

TransferFunction axisPlantTransferFunction(const GtAxisSettings& gt, int axisIndex) {
    const TransferFunction rigid = gt.plant.transferFunction();
    if (!gt.flexibleMode.present()) {
        validateFlexibleMode(gt.flexibleMode,
                             "axes[" + std::to_string(axisIndex) + "].gt.flexible_mode.");
        return rigid;
    }
    return series(rigid, flexibleModeTransferFunction(gt, axisIndex));
}

DigitalPi sessionDigitalPi(const Session& session, const GtDesign& design, int axisIndex) {
    try {
        DigitalPi pi = digitalPi(design.kp, design.ki, session.controllerTsSeconds,
                                 session.piDiscretization, session.implementation.antiWindup,
                                 session.implementation.trackingTimeSeconds);
        const NotchFilter& notch = session.axes.at(static_cast<std::size_t>(axisIndex)).gt.notch;
        if (notch.present()) {
            pi.errorNotch = discreteNotch(notch, pi.tsSeconds,
                                          "axes[" + std::to_string(axisIndex) + "].gt.notch.");
            pi.hasNotch = true;
        }
        return pi;
    } catch (const InvalidInput& e) {
        if (e.field() == "ts")
            throw InvalidInput("controller_ts", e.reasonDiagnostic());
        if (e.field() == "tracking_time")
            throw InvalidInput("implementation.tracking_time", e.reasonDiagnostic());
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
                           e.reasonDiagnostic());
    }
    return o;
}

namespace {

/// Says which criteria the design passes but its digital implementation fails, if any.
std::optional<Diagnostic> implementationVerdictWarning(const SpecificationCheck& design,
                                                       const SpecificationCheck& implementation) {
    std::vector<Diagnostic> failed;
    if (design.trackingError && !implementation.trackingError)
        failed.push_back(makeDiagnostic("session_criterion_tracking_error"));
    if (design.noSaturation && !implementation.noSaturation)
        failed.push_back(makeDiagnostic("session_criterion_actuator_limit"));
    if (design.settleApplies && design.settle && !implementation.settle)
        failed.push_back(makeDiagnostic("session_criterion_settle"));
    if (failed.empty())
        return std::nullopt;
    // "a", "a and b", "a, b and c"
    Diagnostic list = failed.back();
    if (failed.size() > 1) {
        failed.pop_back();
        list = makeDiagnostic("session_list_and", {joinDiagnostics(failed, "list_comma"), list});
    }
    return makeDiagnostic("session_implementation_fails", {list});
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

TransferFunction AxisEvaluation::closedLoop() const {
    return designMethodModule(method).closedLoop(*this);
}

namespace {

/// The stick-slip and hunting findings of the runs of a table with dry friction.
void addStickSlipWarnings(AxisEvaluation& out) {
    // The findings come from core/simulation, each kept as it comes; the digital run's are
    // prefixed here.
    const auto add = [&out](const std::vector<Diagnostic>& found) {
        out.warnings.insert(out.warnings.end(), found.begin(), found.end());
    };
    if (const auto f = stickSlipFindings(out.run))
        add(stickSlipWarnings(*f));
    if (out.digital)
        if (const auto f = stickSlipFindings(out.digital->run.result))
            add(stickSlipWarnings(*f, StickSlipRun::digitalImplementation));
}

/// evaluateAxis over a given duration.
/// The largest amplitude of the mode over the run of the trajectory @p t (a circle or a
/// program, shaped or not), its commanded acceleration sampled at the run's step.
double pathResidualMm(const TrajectorySettings& t, int axisIndex, const SimulationResult& run,
                      double modeHz, double modeDamping) {
    if (run.t.size() < 2)
        return 0.0;
    const auto motion = axisMotion(t, axisIndex);
    std::vector<double> a(run.t.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        a[k] = motion(run.t[k]).acceleration;
    const std::vector<double> amplitude =
        modeAmplitudes(a, run.t[1] - run.t[0], modeHz, modeDamping);
    return *std::max_element(amplitude.begin(), amplitude.end());
}

/// The amplitude the mode rings with when the unshaped point-to-point move of @p t ends (tf):
/// its acceleration on kMoveSteps equal steps of [t0, tf], linear within each (the cubic's is
/// linear on the whole move, so exact; the quintic's a smooth polynomial, O(h^2)).
double moveResidualMm(const TrajectorySettings& t, int axisIndex, double modeHz,
                      double modeDamping) {
    constexpr int kMoveSteps = 2000;
    TrajectorySettings plain = t;
    plain.shaping = {};
    const auto motion = axisMotion(plain, axisIndex);
    const double h = (t.tfSeconds - t.t0Seconds) / kMoveSteps;
    std::vector<double> a(kMoveSteps + 1);
    for (int k = 0; k <= kMoveSteps; ++k)
        a[static_cast<std::size_t>(k)] =
            k == 0 ? motion(t.t0Seconds + 0.5 * h * 1e-9).acceleration // the move's side of t0
                   : (k == kMoveSteps ? motion(t.tfSeconds - 0.5 * h * 1e-9).acceleration
                                      : motion(t.t0Seconds + k * h).acceleration);
    return modeAmplitudes(a, h, modeHz, modeDamping).back();
}

/// The axis' run unshaped beside the shaped @p shaped (ShapingComparison).
std::shared_ptr<const ShapingComparison> compareShaping(const Session& session, int axisIndex,
                                                        double seconds,
                                                        const SimulationResult& shaped) {
    auto out = std::make_shared<ShapingComparison>();
    const TrajectorySettings& t = session.trajectory;
    out->shaper = designInputShaper(t.shaping.type, t.shaping.frequencyHz, t.shaping.dampingRatio);
    Session plain = session;
    plain.trajectory.shaping = {};
    AxisEvaluation unshaped;
    designMethodModule(plain.axes.at(static_cast<std::size_t>(axisIndex)).method)
        .evaluate(plain, axisIndex, seconds, false, unshaped);
    out->unshapedRun = std::move(unshaped.run);
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    out->fromAxisMode =
        axis.method != DesignMethod::PolePlacementZpetc && axis.gt.flexibleMode.present();
    out->modeHz = out->fromAxisMode ? axis.gt.flexibleMode.frequencyHz : out->shaper.frequencyHz;
    out->modeDamping =
        out->fromAxisMode ? axis.gt.flexibleMode.dampingRatio : out->shaper.dampingRatio;
    out->afterMove = t.kind == TrajectoryKind::Cubic;
    if (out->afterMove) {
        // After the move the mode rings freely, so by superposition the shaped move leaves the
        // unshaped amplitude times the shaper's residual vibration (Singer and Seering).
        out->residualUnshapedMm = moveResidualMm(t, axisIndex, out->modeHz, out->modeDamping);
        out->residualShapedMm =
            out->residualUnshapedMm * residualVibration(out->shaper, out->modeHz, out->modeDamping);
    } else {
        out->residualShapedMm = pathResidualMm(t, axisIndex, shaped, out->modeHz, out->modeDamping);
        out->residualUnshapedMm = pathResidualMm(plain.trajectory, axisIndex, out->unshapedRun,
                                                 out->modeHz, out->modeDamping);
    }
    return out;
}

AxisEvaluation evaluateAxisOver(const Session& session, int axisIndex, const RunDuration& duration,
                                bool withDigital = true) {
    AxisEvaluation out;
    out.duration = duration;
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    out.method = axis.method;
    try {
        requirePositive(session.umaxVolts, "umax");
        designMethodModule(axis.method)
            .evaluate(session, axisIndex, duration.seconds, withDigital, out);
        if (out.metrics.diverged)
            out.warnings.push_back(makeDiagnostic("run_diverged"));
        addStickSlipWarnings(out);
        if (axis.method == DesignMethod::PolePlacementZpetc &&
            (axis.gt.flexibleMode.present() || axis.gt.notch.present()))
            out.warnings.push_back(makeDiagnostic("flexible_mode_on_arx"));
        const TrajectorySettings& t = session.trajectory;
        if (withDigital && t.shaping.active() && !out.run.t.empty())
            out.shaping = compareShaping(session, axisIndex, duration.seconds, out.run);
        if (t.kind == TrajectoryKind::Cubic) {
            try {
                out.moveSettle = moveSettleMetrics(out.run, {t.x0, t.xf, t.tfSeconds},
                                                   session.spec.inPositionWindowMm);
            } catch (const InvalidInput& e) {
                throw InvalidInput("specification." + e.field(), e.reasonDiagnostic());
            }
            if (!out.moveSettle->reachedMoveEnd)
                out.warnings.push_back(makeDiagnostic("run_ends_before_move"));
        }
        // The move-only evaluation of chooseRunDuration (withDigital false) needs no margins.
        if (withDigital) {
            try {
                if (const std::optional<LoopTransferFunctions> loop = axisLoop(out))
                    out.margins = stabilityMargins(loop->openLoop);
            } catch (const InvalidInput& e) {
                out.warnings.push_back(makeDiagnostic(
                    "no_stability_margins",
                    {makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()})}));
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
            if (const auto verdictDiagnostic =
                    implementationVerdictWarning(out.designCheck, *out.implementationCheck))
                out.warnings.push_back(*verdictDiagnostic);
        }
        out.ok = true;
    } catch (const InvalidInput& e) {
        out.ok = false;
        out.errorField = e.field();
        out.error = e.reasonDiagnostic();
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
    return designMethodModule(a.method).slowestDecayPerSecond(a);
}

} // namespace

RunDuration chooseRunDuration(const Session& session) {
    const TrajectorySettings& t = session.trajectory;
    RunDuration d;
    d.capSeconds = t.effectiveDurationSeconds();
    d.seconds = d.capSeconds;
    d.automatic = !(t.durationSeconds > 0.0) || t.kind == TrajectoryKind::Gcode;
    if (!d.automatic) {
        d.description = makeDiagnostic("session_duration_set", {formatNumber(d.seconds)});
        return d;
    }
    if (t.kind == TrajectoryKind::Circle) {
        d.description = makeDiagnostic("session_duration_circle", {formatNumber(d.seconds)});
        return d;
    }
    if (t.kind == TrajectoryKind::Gcode) {
        d.description = makeDiagnostic("session_duration_program", {formatNumber(d.seconds)});
        return d;
    }
    // The move alone first, on both axes, for their error at its end: tf, later by the input
    // shaper's duration when the reference is shaped.
    const double moveEnd = shapedMoveEndSeconds(t);
    RunDuration moveOnly = d;
    moveOnly.seconds = moveEnd;
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
        d.seconds = moveEnd;
        d.description = makeDiagnostic("session_duration_move_only", {formatNumber(d.seconds)});
        return d;
    }
    d.seconds = automaticMoveDurationSeconds(t.t0Seconds, moveEnd, need, d.capSeconds);
    d.capped = d.seconds == d.capSeconds && d.capSeconds > moveEnd;
    std::vector<Diagnostic> args = {
        formatNumber(d.seconds), formatNumber(t.tfSeconds),
        formatNumber(session.spec.inPositionWindowMm),
        std::isfinite(need) ? makeDiagnostic("study_value_seconds", {formatNumber(need)})
                            : makeDiagnostic("session_duration_never")};
    const char* code = "session_duration_settle";
    if (d.capped) {
        args.push_back(formatNumber(kAutomaticSettleMoves));
        code = d.capSeconds < t.tfSeconds + kAutomaticSettleMoves * (t.tfSeconds - t.t0Seconds)
                   ? "session_duration_settle_lowered"
                   : "session_duration_settle_capped";
    }
    d.description = makeDiagnostic(code, std::move(args));
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
            out.programError = makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()});
            if (e.field().rfind("cross_coupling", 0) == 0)
                out.couplingError = out.programError;
        }
    }
    if (session.crossCoupling.active() && session.trajectory.kind != TrajectoryKind::Gcode &&
        x.ok && y.ok) {
        try {
            out.coupledTrajectory = std::make_shared<const CoupledTrajectoryRun>(
                runCoupledTrajectory(session, x.run, y.run));
        } catch (const InvalidInput& e) {
            out.couplingError = makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()});
        }
    }
    return out;
}

} // namespace xyt
