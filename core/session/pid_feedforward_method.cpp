// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/pid_feedforward_method.h"

#include "core/analysis/frequency_response.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"
#include "core/model/root_matching.h"
#include "core/model/translatable_text.h"
#include "core/session/axis_run.h"
#include "core/session/c_export.h"
#include "core/session/continuous_plant_method.h"
#include "core/session/pid_feedforward_export.h"
#include "core/simulation/move_settle.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

// Braga et al.'s lower base under the paper's PI (wn = 2 rad/s, kp = 30 V/m: ki = wn^4/k0 =
// 0.2057 V/(m s)) in mm units, with the plant's exact inverse as the feedforward
// (modelFeedforwardGains): a new axis starts as the paper's design plus what every drive adds.
constexpr double kPaperK0 = 77.8, kPaperA1 = 125.3, kPaperA2 = 3665.0, kPaperUnit = 0.001;

MethodParameter gain(const char* name, const char* label, const char* unit, double value) {
    return {name, label, unit, value, 0.0, 1e6};
}

/// Whether a 0/1 choice holds 0 or 1 (the parameter range admits anything between).
bool choice(const AxisSettings& settings, int axisIndex, const MethodParameter& p) {
    const double v = methodParameterValue(settings, axisIndex, p);
    if (v != 0.0 && v != 1.0)
        throw InvalidInput(axisFieldPath(axisIndex, "parameters." + p.name),
                           makeDiagnostic("session_not_zero_or_one", {formatNumber(v)}));
    return v == 1.0;
}

const MethodParameter& parameter(const std::vector<MethodParameter>& all, const char* name) {
    for (const MethodParameter& p : all)
        if (p.name == name)
            return p;
    throw InvalidInput("method", makeDiagnostic("session_no_parameter", {name}));
}

/// C(s) = (P + I/s + D s/(Tf s + 1)) / unit, without the factors a zero gain leaves out.
TransferFunction continuousController(const ServoPidGains& g, double tf, double unit) {
    const double p = g.p / unit, i = g.i / unit, d = g.d / unit;
    if (d == 0.0) {
        if (i == 0.0)
            return {Polynomial::constant(p), Polynomial::constant(1.0)};
        return {Polynomial::fromDescending({p, i}), Polynomial::fromDescending({1.0, 0.0})};
    }
    if (i == 0.0)
        return {Polynomial::fromDescending({p * tf + d, p}), Polynomial::fromDescending({tf, 1.0})};
    return {Polynomial::fromDescending({p * tf + d, p + i * tf, i}),
            Polynomial::fromDescending({tf, 1.0, 0.0})};
}

/// The feedforward's share of the continuous run along @p motion (see the header): at each
/// sample, feedforwardVolts, less the D term's filtered share of r' when D acts on the
/// measurement (the first-order lag on the samples of r', exact for r' linear between them).
std::vector<double> continuousFeedforward(const PidFeedforwardDesign& d,
                                          const std::vector<MotionSample>& motion,
                                          double dtSeconds) {
    std::vector<double> ff(motion.size());
    double filtered = 0.0;
    const double tf = d.continuousFilterSeconds;
    const double a = std::exp(-dtSeconds / tf);
    for (std::size_t k = 0; k < motion.size(); ++k) {
        ff[k] = feedforwardVolts(d.gains, motion[k]);
        if (!d.gains.derivativeOnMeasurement || d.gains.d == 0.0)
            continue;
        if (k > 0) {
            // x' = (v - x)/Tf with v linear from v0 to v1 over dt: exact FOH step.
            const double v0 = motion[k - 1].velocity, v1 = motion[k].velocity;
            const double slope = (v1 - v0) / dtSeconds;
            filtered = a * filtered + (1.0 - a) * v0 + slope * (dtSeconds - tf * (1.0 - a));
        }
        ff[k] -= d.gains.d * filtered;
    }
    return ff;
}

/// The axis' command samples at @p times.
std::vector<MotionSample> motionAt(const Session& session, int axisIndex,
                                   const std::vector<double>& times) {
    const auto motion = axisMotion(session.trajectory, axisIndex);
    std::vector<MotionSample> out(times.size());
    for (std::size_t k = 0; k < times.size(); ++k)
        out[k] = motion(times[k]);
    return out;
}

std::vector<double> positions(const std::vector<MotionSample>& motion) {
    std::vector<double> r(motion.size());
    for (std::size_t k = 0; k < motion.size(); ++k)
        r[k] = motion[k].position;
    return r;
}

/// The continuous loop along @p motion at step @p dt with the feedforward (or without).
/// The table of @p axis is in the loop either way; the friction compensation belongs to the
/// feedforward.
template <typename Run>
auto onContinuousRun(const AxisSettings& axis, int axisIndex, const PidFeedforwardDesign& d,
                     const std::vector<MotionSample>& motion, double dt, bool withFeedforward,
                     double initialOutput, Run run) {
    LoopSimulationOptions options;
    options.dtSeconds = dt;
    options.umaxVolts = d.gains.maxOutput;
    options.modelUnitsPerPositionUnit = d.unit;
    options.initialOutput = initialOutput;
    options.table = axisTable(axis, axisIndex);
    const std::vector<double> r = positions(motion);
    std::vector<double> ff;
    if (withFeedforward) {
        ff = continuousFeedforward(d, motion, dt);
        addFeedforward(ff, frictionFeedforward(axis, axisIndex, r, dt));
        options.feedforwardVolts = &ff;
    }
    return run(r, options);
}

SimulationResult continuousRun(const AxisSettings& axis, int axisIndex,
                               const PidFeedforwardDesign& d,
                               const std::vector<MotionSample>& motion, double dt,
                               bool withFeedforward, double initialOutput = 0.0) {
    return onContinuousRun(axis, axisIndex, d, motion, dt, withFeedforward, initialOutput,
                           [&](const std::vector<double>& r, const LoopSimulationOptions& options) {
                               return simulateLoop(d.plant, d.controller, r, options);
                           });
}

/// The program's derivatives by central differences of its samples (axisMotion's rule).
std::vector<MotionSample> programMotion(const std::vector<double>& reference, double h) {
    const std::size_t n = reference.size();
    std::vector<MotionSample> motion(n);
    const auto at = [&](std::ptrdiff_t k) {
        return reference[static_cast<std::size_t>(
            std::clamp<std::ptrdiff_t>(k, 0, static_cast<std::ptrdiff_t>(n) - 1))];
    };
    for (std::size_t k = 0; k < n; ++k) {
        const auto i = static_cast<std::ptrdiff_t>(k);
        motion[k] = centralDifferenceMotion(at(i - 2), at(i - 1), at(i), at(i + 1), at(i + 2), h);
    }
    return motion;
}

/// A program's run refused naming the session's plant field for the loop's plant refusals.
template <typename Run> auto namingPlant(int axisIndex, Run run) {
    try {
        return run();
    } catch (const InvalidInput& e) {
        if (e.field() == "plant" || e.field() == "initial_output")
            throw InvalidInput(axisFieldPath(axisIndex, "gt.plant"), e.reasonDiagnostic());
        throw;
    }
}

void addWarnings(const Session& session, const PidFeedforwardDesign& d, AxisEvaluation& out) {
    if (!d.stable)
        out.warnings.push_back(makeDiagnostic("closed_loop_unstable"));
    if (!out.run.uFeedforward.empty()) {
        double peak = 0.0;
        for (double v : out.run.uFeedforward)
            peak = std::max(peak, std::abs(v));
        if (peak > d.gains.maxOutput)
            out.warnings.push_back(
                makeDiagnostic("feedforward_beyond_limit",
                               {formatNumber(peak, 4), formatNumber(d.gains.maxOutput, 4)}));
    }
    const TrajectorySettings& t = session.trajectory;
    if (t.kind == TrajectoryKind::Cubic && t.profile == MoveProfile::Cubic &&
        d.derivativeSource == CommandDerivativeSource::BackwardDifferences && d.gains.ff3 != 0.0) {
        // The cubic's acceleration steps at t0 (from 0 to 2 l2) and at tf (from 2 l2 + 6 l3 T
        // to 0); the backward differences turn a step of the acceleration into one sample of
        // cmd''' = step / Ts, which FF3 multiplies.
        const CubicTrajectory c(t.x0, t.xf, t.t0Seconds, t.tfSeconds, t.v0, t.vf);
        const auto& l = c.localCoefficients();
        const double step = std::max(
            std::abs(2.0 * l[2]), std::abs(2.0 * l[2] + 6.0 * l[3] * (t.tfSeconds - t.t0Seconds)));
        const double spike = std::abs(d.gains.ff3) * step / d.tsSeconds;
        if (spike > 0.01 * d.gains.maxOutput)
            out.warnings.push_back(
                makeDiagnostic("ff3_acceleration_spike", {formatNumber(spike, 3)}));
    }
}

/// @p continuousMotion: the command at the continuous run's samples (trajectory.dt), reused
/// when the controller samples at the same times.
void evaluateDigital(const Session& session, int axisIndex, double duration,
                     const PidFeedforwardDesign& design,
                     const std::vector<MotionSample>& continuousMotion, AxisEvaluation& out) {
    try {
        DigitalEvaluation d;
        d.tsSeconds = design.tsSeconds;
        SampledDataOptions options = sessionSampledDataOptions(session);
        const auto times =
            axisSampleTimes(session.trajectory, duration, design.tsSeconds, "controller_ts");
        const bool sameTimes = design.tsSeconds == session.trajectory.dtSeconds &&
                               times.size() == continuousMotion.size();
        const std::vector<MotionSample> command =
            sameTimes ? continuousMotion : motionAt(session, axisIndex, times);
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        options.table = axisTable(axis, axisIndex);
        const std::vector<double> ff =
            frictionFeedforward(axis, axisIndex, positions(command), design.tsSeconds);
        options.feedforwardVolts = &ff;
        d.run = simulateSampledServoPid(design.plant, design.gains, design.tsSeconds, command,
                                        design.derivativeSource, options, design.unit);
        d.poles = sampledServoPidLoopPoles(sampledPlant(design.plant, design.tsSeconds),
                                           design.gains, design.unit, options.delaySamples);
        d.designMinDamping = minContinuousDamping(design.closedLoopPoles);
        for (const auto& p : design.closedLoopPoles)
            d.designPoles.push_back(std::exp(p * design.tsSeconds));
        sortRoots(d.designPoles);
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    } catch (const InvalidInput& e) {
        out.warnings.push_back(
            makeDiagnostic("no_digital_implementation",
                           {makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()})}));
    }
}

class PidFeedforwardMethod final : public ContinuousPlantMethod {
public:
    DesignMethod method() const override { return DesignMethod::PidFeedforward; }
    std::string_view id() const override { return "pid-ff"; }
    std::string_view displayName() const override {
        return XYT_TRANSLATE_NOOP("xyt::MethodName", "PID + feedforward");
    }
    std::vector<MethodParameter> parameters() const override { return pidFeedforwardParameters(); }

    std::optional<AxisSettings> withoutFeedforward(const AxisSettings& settings) const override {
        // FF0..FF3 at 0 (a missing one would take its default, the plant's inverse).
        AxisSettings out = settings;
        bool any = false;
        for (const MethodParameter& p : pidFeedforwardParameters())
            if (p.name == "ff0" || p.name == "ff1" || p.name == "ff2" || p.name == "ff3") {
                const auto at = settings.parameters.find(p.name);
                any = any || (at == settings.parameters.end() ? p.defaultValue : at->second) != 0.0;
                out.parameters[p.name] = 0.0;
            }
        if (!any)
            return std::nullopt;
        return out;
    }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        auto design =
            std::make_shared<PidFeedforwardDesign>(designPidFeedforward(session, axisIndex));
        out.methodDesign = design;
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        const double dt = session.trajectory.dtSeconds;
        const auto reference = sessionReference(session.trajectory, axisIndex);
        const auto times =
            axisSampleTimes(session.trajectory, durationSeconds, dt, "trajectory.dt");
        const std::vector<MotionSample> motion = motionAt(session, axisIndex, times);
        out.run = continuousRun(axis, axisIndex, *design, motion, dt, true);
        out.metrics = trackingMetrics(out.run);
        out.step = stepCharacteristics(design->loop.complementarySensitivity);
        addWarnings(session, *design, out);
        // The move-only evaluation that chooses the run's duration (withDigital false) needs
        // neither the feedback's run alone nor the digital one.
        if (!withDigital)
            return;
        out.feedbackOnlyRun = continuousRun(axis, axisIndex, *design, motion, dt, false);
        out.rmseWithoutFf = trackingMetrics(out.feedbackOnlyRun).rmse;
        out.improvementPct =
            out.rmseWithoutFf > 0.0 ? 100.0 * (1.0 - out.metrics.rmse / out.rmseWithoutFf) : 0.0;
        evaluateDigital(session, axisIndex, durationSeconds, *design, motion, out);
    }

    AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& /*t*/,
                        const std::vector<double>& reference, double dtSeconds) const override {
        const PidFeedforwardDesign d = designPidFeedforward(session, axisIndex);
        const std::vector<MotionSample> motion = programMotion(reference, dtSeconds);
        AxisTrace out;
        out.run = namingPlant(axisIndex, [&] {
            return continuousRun(session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex, d,
                                 motion, dtSeconds, true, reference.front());
        });
        out.outputOnPath = out.run.y;
        return out;
    }

    std::unique_ptr<SampledLoopStepper>
    steppedDigitalPath(const Session& session, int axisIndex, const std::vector<double>& t,
                       const std::vector<double>& reference) const override {
        // As evaluateDigital: the servo PID at its Ts, the command's derivatives by central
        // differences of the program's positions (programMotion), the session's implementation,
        // the table and its friction compensation.
        const PidFeedforwardDesign design = designPidFeedforward(session, axisIndex);
        const std::vector<double> r =
            programAtPeriod(t, reference, design.tsSeconds, "controller_ts");
        const std::vector<MotionSample> command = programMotion(r, design.tsSeconds);
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        SampledDataOptions options = sessionSampledDataOptions(session);
        options.table = axisTable(axis, axisIndex);
        const std::vector<double> ff =
            frictionFeedforward(axis, axisIndex, positions(command), design.tsSeconds);
        options.feedforwardVolts = &ff;
        return steppedSampledServoPid(design.plant, design.gains, design.tsSeconds, command,
                                      design.derivativeSource, options, design.unit);
    }

    std::string cCoupledAxis(const Session& session, const AxisEvaluation& /*axis*/,
                             int axisIndex) const override {
        // The PID's output (limited to MAXOUTPUT), the feedforward and the coupling's voltage,
        // then the limit: SampledServoPidLoop::advance's operations.
        const std::string& id = session.axes.at(static_cast<std::size_t>(axisIndex)).id;
        return cexport::cCoupledAxisFunction(
            id, "xyt_" + id + "_pid_output(s, reference, measured, given)", true);
    }

    SampledAxisModel couplingModel(const Session& session, int axisIndex,
                                   double periodSeconds) const override {
        const PidFeedforwardDesign d = designPidFeedforward(session, axisIndex);
        return continuousAxisModel(d.plant, d.controller, d.unit, periodSeconds);
    }

    std::unique_ptr<SteppedLoop> steppedPath(const Session& session, int axisIndex,
                                             const std::vector<double>& /*t*/,
                                             const std::vector<double>& reference,
                                             double dtSeconds) const override {
        const PidFeedforwardDesign d = designPidFeedforward(session, axisIndex);
        const std::vector<MotionSample> motion = programMotion(reference, dtSeconds);
        return namingPlant(axisIndex, [&] {
            return onContinuousRun(
                session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex, d, motion,
                dtSeconds, true, reference.front(),
                [&](const std::vector<double>& r, const LoopSimulationOptions& options) {
                    return steppedLoop(d.plant, d.controller, r, options);
                });
        });
    }

    TransferFunction evaluatedController(const AxisEvaluation& axis) const override {
        return pidFeedforwardDesign(axis).controller;
    }
    TransferFunction designedController(const Session& session, int axisIndex) const override {
        return designPidFeedforward(session, axisIndex).controller;
    }

    RobustnessProblem robustnessProblem(const Session& session, int axisIndex,
                                        const AxisEvaluation& nominal) const override {
        RobustnessProblem p = ContinuousPlantMethod::robustnessProblem(session, axisIndex, nominal);
        // The feedforward is fixed numbers on the fixed trajectory: its voltage does not depend
        // on the plant drawn, so every plant runs with the nominal run's.
        p.feedforwardVolts = nominal.run.uFeedforward;
        return p;
    }

    std::string cController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                            const ExportOptions& options) const override {
        return pidFeedforwardFirmwareBlock(session, pidFeedforwardDesign(axis), axisIndex, options);
    }

    OctaveLines octaveController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                                 const ExportOptions& /*options*/,
                                 double /*durationSeconds*/) const override {
        return pidFeedforwardOctaveLines(session, pidFeedforwardDesign(axis), axisIndex);
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return std::nullopt;
        return pidFeedforwardDesign(axis).loop;
    }
    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        return pidFeedforwardDesign(axis).loop.complementarySensitivity;
    }
    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& /*settings*/) const override {
        if (!axis.methodDesign)
            return {};
        const PidFeedforwardDesign& d = pidFeedforwardDesign(axis);
        return {poleZeroSet("plant G", d.plant), poleZeroSet("PID C", d.controller),
                poleZeroSet("closed loop", d.loop.complementarySensitivity)};
    }
    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.methodDesign
                   ? continuousDecayPerSecond(pidFeedforwardDesign(axis).closedLoopPoles)
                   : 0.0;
    }

    std::vector<DesignCoefficient> coefficients(const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return {};
        const ServoPidGains& g = pidFeedforwardDesign(axis).gains;
        return {{"P", g.p, "V/mm"},          {"I", g.i, "V/(mm s)"},
                {"D", g.d, "V s/mm"},        {"FF0", g.ff0, "V/mm"},
                {"FF1", g.ff1, "V/(mm/s)"},  {"FF2", g.ff2, "V/(mm/s^2)"},
                {"FF3", g.ff3, "V/(mm/s^3)"}};
    }

    std::vector<std::string> reportLines(const AxisSettings& settings,
                                         const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return {};
        std::vector<std::string> lines = DesignMethodModule::reportLines(settings, axis);
        const PidFeedforwardDesign& d = pidFeedforwardDesign(axis);
        const auto percent = [](double v, double model) {
            return model != 0.0 ? formatNumber(100.0 * v / model, 4) + " %" : std::string("-");
        };
        lines.push_back(
            "feedforward of the model's FF1, FF2, FF3: " + percent(d.gains.ff1, d.model.ff1) +
            ", " + percent(d.gains.ff2, d.model.ff2) + ", " + percent(d.gains.ff3, d.model.ff3) +
            "; command derivatives from " +
            (d.derivativeSource == CommandDerivativeSource::BackwardDifferences
                 ? "backward differences"
                 : "the trajectory generator"));
        if (axis.rmseWithoutFf > 0.0)
            lines.push_back("RMSE " + formatNumber(axis.metrics.rmse, 4) +
                            " mm with the "
                            "feedforward, " +
                            formatNumber(axis.rmseWithoutFf, 4) + " mm with the feedback alone");
        if (!d.stable)
            lines.back() += "  UNSTABLE";
        return lines;
    }

    std::vector<Diagnostic> equations(const AxisSettings& /*settings*/,
                                      const AxisEvaluation& axis) const override {
        if (!axis.methodDesign)
            return {};
        const PidFeedforwardDesign& d = pidFeedforwardDesign(axis);
        const ServoPidGains& g = d.gains;
        const auto n = [](double v) { return formatNumber(v, 6); };
        return {"u = bias + P e + I ∫e dt + D e′ + FF0 r + FF1 r′ + FF2 r″ + FF3 r‴,  |u| ≤ " +
                    n(g.maxOutput) + " V",
                "P = " + n(g.p) + " V/mm, I = " + n(g.i) + " V/(mm s), D = " + n(g.d) + " V s/mm",
                makeDiagnostic(
                    "session_pid_equation_feedforward",
                    {n(g.ff1), n(g.ff2), n(g.ff3), n(d.model.ff1), n(d.model.ff2), n(d.model.ff3)}),
                makeDiagnostic("session_pid_equation_controller",
                               {n(d.continuousFilterSeconds), n(d.unit)})};
    }

    std::optional<TrackingFrequencyResponses>
    trackingResponses(const AxisEvaluation& axis,
                      const std::vector<double>& omegaRadPerSec) const override {
        if (!axis.methodDesign)
            return std::nullopt;
        const PidFeedforwardDesign& d = pidFeedforwardDesign(axis);
        return TrackingFrequencyResponses{
            frequencyResponse(d.loop.complementarySensitivity, omegaRadPerSec),
            frequencyResponse(d.trackingWithFeedforward, omegaRadPerSec)};
    }

    std::string designRunDescription() const override {
        return "the continuous loop with the feedforward, |u| limited";
    }
};

} // namespace

std::vector<MethodParameter> pidFeedforwardParameters() {
    const ModelFeedforwardGains ff =
        modelFeedforwardGains({kPaperK0, kPaperA1, kPaperA2}, kPaperUnit);
    const double wn = 2.0;
    return {
        gain("p", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Proportional gain P"), "V/mm",
             30.0 * kPaperUnit),
        gain("i", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Integral gain I"), "V/(mm s)",
             std::pow(wn, 4) / kPaperK0 * kPaperUnit),
        gain("d", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Derivative gain D"), "V s/mm", 0.0),
        gain("ff0", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Position feedforward FF0"), "V/mm",
             0.0),
        gain("ff1", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Velocity feedforward FF1"),
             "V/(mm/s)", ff.ff1),
        gain("ff2", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Acceleration feedforward FF2"),
             "V/(mm/s²)", ff.ff2),
        gain("ff3", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Jerk feedforward FF3"), "V/(mm/s³)",
             ff.ff3),
        {"bias", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Bias"), "V", 0.0, -1e3, 1e3},
        {"deadband", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Deadband"), "mm", 0.0, 0.0, 1e6},
        {"max_error_i", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Integrator limit (0: none)"),
         "mm s", 0.0, 0.0, 1e9},
        {"max_output", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "Output limit (0: umax)"), "V",
         0.0, 0.0, 1e6},
        {"derivative_filter", XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "D filter Tf (0: none)"),
         "s", 0.0, 0.0, 1e3},
        {"derivative_on_measurement",
         XYT_TRANSLATE_NOOP("xyt::ParameterLabel", "D on the measurement (1) or the error (0)"), "",
         0.0, 0.0, 1.0},
        {"command_derivatives",
         XYT_TRANSLATE_NOOP("xyt::ParameterLabel",
                            "Command derivatives: backward differences (0), trajectory (1)"),
         "", 0.0, 0.0, 1.0},
    };
}

double feedforwardVolts(const ServoPidGains& g, const MotionSample& m) {
    return g.bias + g.ff0 * m.position + g.ff1 * m.velocity + g.ff2 * m.acceleration +
           g.ff3 * m.jerk;
}

const PidFeedforwardDesign& pidFeedforwardDesign(const AxisEvaluation& axis) {
    const auto* d = dynamic_cast<const PidFeedforwardDesign*>(axis.methodDesign.get());
    if (!d)
        throw InvalidInput("axis", makeDiagnostic("session_axis_no_design"));
    return *d;
}

PidFeedforwardDesign designPidFeedforward(const Session& session, int axisIndex) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    const std::vector<MethodParameter> all = pidFeedforwardParameters();
    const auto value = [&](const char* name) {
        return methodParameterValue(axis, axisIndex, parameter(all, name));
    };
    PidFeedforwardDesign d;
    ServoPidGains& g = d.gains;
    g.p = value("p");
    g.i = value("i");
    g.d = value("d");
    g.ff0 = value("ff0");
    g.ff1 = value("ff1");
    g.ff2 = value("ff2");
    g.ff3 = value("ff3");
    g.bias = value("bias");
    g.deadband = value("deadband");
    g.maxErrorI = value("max_error_i");
    const double maxOutput = value("max_output");
    g.maxOutput = maxOutput > 0.0 ? std::min(maxOutput, session.umaxVolts) : session.umaxVolts;
    g.derivativeFilterSeconds = value("derivative_filter");
    g.derivativeOnMeasurement =
        choice(axis, axisIndex, parameter(all, "derivative_on_measurement"));
    d.derivativeSource = choice(axis, axisIndex, parameter(all, "command_derivatives"))
                             ? CommandDerivativeSource::TrajectoryGenerator
                             : CommandDerivativeSource::BackwardDifferences;
    d.tsSeconds = session.controllerTsSeconds;
    requirePositive(d.tsSeconds, "controller_ts");
    if (g.derivativeFilterSeconds > 0.0 && g.derivativeFilterSeconds < d.tsSeconds / kPi)
        throw InvalidInput(axisFieldPath(axisIndex, "parameters.derivative_filter"),
                           makeDiagnostic("session_derivative_filter_beyond_nyquist",
                                          {formatNumber(g.derivativeFilterSeconds),
                                           formatNumber(d.tsSeconds / kPi, 4)}));
    if (g.p == 0.0 && g.i == 0.0 && g.d == 0.0)
        throw InvalidInput(axisFieldPath(axisIndex, "parameters.p"),
                           makeDiagnostic("session_pid_no_feedback"));
    if (axis.gt.notch.present())
        throw InvalidInput(axisFieldPath(axisIndex, "gt.notch.centre"),
                           makeDiagnostic("session_pid_no_notch"));
    d.unit = axis.gt.modelUnitsPerPositionUnit;
    try {
        axis.gt.plant.validate();
        requirePositive(d.unit, "model_unit_scale");
        d.model = modelFeedforwardGains(axis.gt.plant, d.unit);
    } catch (const InvalidInput& e) {
        const std::string part =
            e.field() == "model_unit_scale" ? "gt.model_unit_scale" : "gt.plant." + e.field();
        throw InvalidInput(axisFieldPath(axisIndex, part), e.reasonDiagnostic());
    }
    d.continuousFilterSeconds =
        g.derivativeFilterSeconds > 0.0 ? g.derivativeFilterSeconds : d.tsSeconds / 2.0;
    d.plant = axisPlantTransferFunction(axis.gt, axisIndex);
    d.controller = continuousController(g, d.continuousFilterSeconds, d.unit);
    d.loop = unityFeedbackLoop(d.controller, d.plant);
    d.closedLoopPoles = d.loop.complementarySensitivity.poles();
    sortRoots(d.closedLoopPoles);
    d.stable = std::all_of(d.closedLoopPoles.begin(), d.closedLoopPoles.end(),
                           [](const std::complex<double>& p) { return p.real() < 0.0; });
    // r -> y with F = FF0 + FF1 s + FF2 s^2 + FF3 s^3 in volts per mm: (C + F/u) G S.
    const TransferFunction f(Polynomial::fromDescending(
                                 {g.ff3 / d.unit, g.ff2 / d.unit, g.ff1 / d.unit, g.ff0 / d.unit}),
                             Polynomial::constant(1.0));
    d.trackingWithFeedforward =
        parallel(d.loop.complementarySensitivity, series(series(f, d.plant), d.loop.sensitivity));
    return d;
}

std::vector<std::complex<double>> sampledServoPidLoopPoles(const SampledPlant& plant,
                                                           const ServoPidGains& g, double unit,
                                                           int delaySamples) {
    // z = [x (n); errorI; previous feedback; filtered D; u[k-1] .. u[k-m]], r = 0.
    const Eigen::Index n = plant.states, m = delaySamples;
    const Eigen::Index iI = n, iFb = n + 1, iDf = n + 2, iU = n + 3, size = n + 3 + m;
    const double ts = plant.tsSeconds;
    Eigen::RowVectorXd y = Eigen::RowVectorXd::Zero(size); // the feedback in mm
    for (Eigen::Index j = 0; j < n; ++j)
        y(j) = plant.c[static_cast<std::size_t>(j)] / unit;
    Eigen::RowVectorXd integral = -ts * y; // errorI + e Ts, e = -y
    integral(iI) += 1.0;
    Eigen::RowVectorXd raw = -y / ts; // D = cmd' - fb' = -(y - previous)/Ts
    raw(iFb) += 1.0 / ts;
    const double tf = g.derivativeFilterSeconds;
    Eigen::RowVectorXd filtered = raw;
    if (tf > 0.0) {
        filtered = ts * raw / (tf + ts);
        filtered(iDf) += tf / (tf + ts);
    }
    const Eigen::RowVectorXd u = -g.p * y + g.i * integral + g.d * filtered;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
    const Eigen::RowVectorXd applied =
        m == 0 ? u : Eigen::RowVectorXd(Eigen::RowVectorXd::Unit(size, iU + m - 1));
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j)
            a(i, j) = plant.phi[static_cast<std::size_t>(i * n + j)];
        a.row(i) += plant.gamma[static_cast<std::size_t>(i)] * applied;
    }
    a.row(iI) = integral;
    a.row(iFb) = y;
    a.row(iDf) = filtered;
    if (m > 0) {
        a.row(iU) = u;
        for (Eigen::Index k = 1; k < m; ++k)
            a(iU + k, iU + k - 1) = 1.0;
    }
    const Eigen::VectorXcd eig = a.eigenvalues();
    std::vector<std::complex<double>> poles(eig.data(), eig.data() + eig.size());
    sortRoots(poles);
    return poles;
}

AxisSettings withModelFeedforward(const AxisSettings& axis, int axisIndex) {
    AxisSettings out = axis;
    if (axis.method == DesignMethod::GuilleminTruxal) {
        const GtDesign gt = sessionGtDesign(axis.gt, axisIndex);
        const double unit = axis.gt.modelUnitsPerPositionUnit;
        out.method = DesignMethod::PidFeedforward;
        out.parameters["p"] = gt.kp * unit;
        out.parameters["i"] = gt.ki * unit;
        out.parameters["d"] = 0.0;
    } else if (axis.method != DesignMethod::PidFeedforward) {
        throw InvalidInput(
            axisFieldPath(axisIndex, "method"),
            makeDiagnostic("session_no_model_feedforward",
                           {std::string(designMethodModule(axis.method).displayName())}));
    }
    ModelFeedforwardGains ff;
    try {
        ff = modelFeedforwardGains(axis.gt.plant, axis.gt.modelUnitsPerPositionUnit);
    } catch (const InvalidInput& e) {
        const std::string part =
            e.field() == "model_unit_scale" ? "gt.model_unit_scale" : "gt.plant." + e.field();
        throw InvalidInput(axisFieldPath(axisIndex, part), e.reasonDiagnostic());
    }
    out.parameters["ff0"] = 0.0;
    out.parameters["ff1"] = ff.ff1;
    out.parameters["ff2"] = ff.ff2;
    out.parameters["ff3"] = ff.ff3;
    return out;
}

PidFeedbackGains pidGainsWithMovedZero(const PidFeedforwardDesign& design,
                                       std::complex<double> from, std::complex<double> to) {
    PidFeedbackGains out;
    const ServoPidGains& g = design.gains;
    if (!(to.real() < 0.0) || !std::isfinite(to.real()) || !std::isfinite(to.imag())) {
        out.reason = makeDiagnostic("session_pid_zero_not_in_lhp");
        return out;
    }
    const auto finish = [&](double p, double i, double d) {
        if (!(p >= 0.0 && i >= 0.0 && d >= 0.0) || !std::isfinite(p + i + d)) {
            out.reason = makeDiagnostic("session_pid_zero_negative_gain");
            return out;
        }
        out.ok = true;
        out.p = p;
        out.i = i;
        out.d = d;
        return out;
    };
    if (g.d == 0.0)
        return finish(g.p, -g.p * to.real(), 0.0);
    const double tf = design.continuousFilterSeconds;
    const double n2 = g.p * tf + g.d, n1 = g.p + g.i * tf, n0 = g.i;
    // The current zeros, the partner of the one nearest @p from.
    const double disc = n1 * n1 - 4.0 * n2 * n0;
    std::complex<double> z1, z2;
    if (disc >= 0.0) {
        const double q = -0.5 * (n1 + std::copysign(std::sqrt(disc), n1));
        z1 = q / n2;
        z2 = q != 0.0 ? n0 / q : 0.0;
    } else {
        z1 = {-n1 / (2.0 * n2), std::sqrt(-disc) / (2.0 * n2)};
        z2 = std::conj(z1);
    }
    const bool pair = disc < 0.0 || std::abs(to.imag()) > 0.0;
    const std::complex<double> partner =
        pair ? std::conj(to) : (std::abs(from - z1) <= std::abs(from - z2) ? z2 : z1);
    const std::complex<double> sum = to + partner, product = to * partner;
    const double n1New = -n2 * sum.real(), n0New = n2 * product.real();
    const double i = n0New, p = n1New - i * tf, d = n2 - p * tf;
    return finish(p, i, d);
}

const DesignMethodModule& pidFeedforwardMethod() {
    static const PidFeedforwardMethod module;
    return module;
}

} // namespace xyt
