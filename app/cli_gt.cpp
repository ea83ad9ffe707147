// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli gt | simulate | report: the Guillemin-Truxal design of Braga et al.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_friction.h"
#include "app/cli_json.h"
#include "app/cli_pid.h"

#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"

#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/session/axis_run.h"
#include "core/simulation/contour_error.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"
#include "core/simulation/stick_slip.h"
#include "core/simulation/trajectory.h"
#include "core/study/specification.h"

#include <QJsonArray>
#include <QTextStream>

#include <algorithm>

#include <cmath>
#include <cstdio>

namespace xyt::cli {

int runGt(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kDesignOptions);
    const DesignInput in = parseDesign(args);
    print(designJson(designGuilleminTruxal(in.plant, in.wn, in.kp)));
    return 0;
}

namespace {

const QStringList kDigitalOptions{"digital",       "controller-ts",      "discretization",
                                  "delay-samples", "encoder-resolution", "dac-bits",
                                  "anti-windup",   "tracking-time"};

/// The run of the design as the firmware runs it (simulate --digital): the digital PI at
/// --controller-ts with the implementation options, on the same trajectory and duration; its
/// signals in @p run (for --csv).
QJsonObject digitalJson(const CliArgs& args, const DesignInput& in, const GtDesign& design,
                        const SimulationSetup& setup, double window, const AxisSettings& axis,
                        SimulationResult& runOut) {
    const double ts = positiveNumber(args, "controller-ts", 0.01);
    const AntiWindup antiWindup = parseAntiWindup(args);
    const double trackingTime = args.number("tracking-time", 0.0);
    if (trackingTime < 0.0)
        throw InvalidInput("--tracking-time", "must be >= 0 (s; 0: Tt = Ti = kp/ki)");
    SampledDataOptions options = parseSampledDataOptions(args, setup.options.umaxVolts);
    const DigitalPi pi =
        digitalPi(design.kp, design.ki, ts, parseDiscretization(args, PiDiscretization::Tustin),
                  antiWindup, trackingTime);
    std::vector<double> times;
    try {
        times = sampleTimes(setup.durationSeconds, ts);
    } catch (const InvalidInput& e) {
        throw InvalidInput("--controller-ts", e.reason());
    }
    const TransferFunction plant = in.plant.transferFunction();
    const std::vector<double> reference = sampled(setup.trajectory.at, times);
    options.table = &axis.friction;
    const std::vector<double> ff = frictionFeedforward(axis, 0, reference, ts);
    options.feedforwardVolts = &ff;
    const SampledDataRun run =
        simulateSampledPi(plant, pi, reference, options, setup.options.modelUnitsPerPositionUnit);
    const auto poles = sampledPiLoopPoles(sampledPlant(plant, ts), pi, options.delaySamples);
    double designDamping = 1.0, damping = 1.0;
    for (const auto& p : design.closedLoopPoles)
        designDamping = std::min(designDamping, -p.real() / std::abs(p));
    QJsonArray poleArray;
    for (const auto& z : poles) {
        poleArray.append(QJsonArray{z.real(), z.imag()});
        if (std::abs(z) >= 1e-9)
            damping = std::min(damping, zDampingRatio(z));
    }
    QJsonArray warnings;
    if (const auto w = digitalDampingWarning(poles, designDamping, ts))
        warnings.append(QString::fromStdString(*w));
    QJsonValue limitCycle;
    const std::optional<PointToPointMove>& move = setup.trajectory.move;
    if (move && (options.encoderResolution > 0.0 || options.dacBits > 0)) {
        const auto rest = std::lower_bound(times.begin(), times.end(), move->endSeconds);
        if (const auto cycle =
                restLimitCycle(run.measured, static_cast<std::size_t>(rest - times.begin()))) {
            limitCycle = QJsonObject{{"peak_to_peak", cycle->peakToPeak}, {"turns", cycle->turns}};
            warnings.append(
                QStringLiteral("a limit cycle at rest: the measured position keeps oscillating "
                               "after the move (%1 mm peak to peak), caused by the quantization")
                    .arg(cycle->peakToPeak, 0, 'g', 4));
        }
    }
    if (const auto f = stickSlipFindings(run.result))
        for (const std::string& w : stickSlipWarnings(*f))
            warnings.append(QString::fromStdString(w));
    runOut = run.result;
    return {{"controller_ts", ts},
            {"stick_slip", stickSlipJson(run.result)},
            {"discretization", QString::fromStdString(discretizationName(
                                   parseDiscretization(args, PiDiscretization::Tustin)))},
            {"delay_samples", options.delaySamples},
            {"encoder_resolution", options.encoderResolution},
            {"dac_bits", options.dacBits},
            {"anti_windup", QString::fromStdString(antiWindupName(antiWindup))},
            {"tracking_time", trackingTime},
            {"samples", static_cast<double>(times.size())},
            {"tracking", trackingJson(trackingMetrics(run.result))},
            {"move_and_settle",
             move ? QJsonValue(moveSettleJson(moveSettleMetrics(run.result, *move, window)))
                  : QJsonValue()},
            {"poles", poleArray},
            {"min_damping", number(damping)},
            {"design_min_damping", number(designDamping)},
            {"limit_cycle", limitCycle},
            {"warnings", warnings}};
}

} // namespace

int runSimulate(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, simulateFlags());
    if (simulatesThroughSession(args))
        return simulateThroughSession(args);
    for (const QString& name : kPidGainOptions + kPidFlags)
        if (args.has(name))
            throw InvalidInput(CliArgs::field(name),
                               "needs --method pid-ff (the PID with command feedforward)");
    args.allowOnly(kDesignOptions + kTrajectoryOptions + kDigitalOptions + kFrictionOptions +
                   QStringList{kUnitOption, "in-position-window", "method"});
    const TableFriction friction = parseFriction(args);
    const FrictionCompensation compensation = parseFrictionCompensation(args);
    if (!args.flag("digital"))
        for (const QString& name : kDigitalOptions)
            if (name != "digital" && args.has(name))
                throw InvalidInput(CliArgs::field(name),
                                   "needs --digital (the run of the digital controller)");
    const DesignInput in = parseDesign(args);
    SimulationSetup setup = parseSimulationSetup(args, parsePlant(args));
    const double window =
        positiveNumber(args, "in-position-window", Specification{}.inPositionWindowMm);
    const GtDesign design = designGuilleminTruxal(in.plant, in.wn, in.kp);
    AxisSettings axis; // the table and compensation, as a session axis holds them
    axis.friction = friction;
    axis.frictionCompensation = compensation;
    auto simulate = [&] {
        LoopSimulationOptions options = setup.options;
        options.table = &friction;
        const std::vector<double> ff =
            frictionFeedforward(axis, 0, setup.reference, options.dtSeconds);
        options.feedforwardVolts = &ff;
        return simulateLoop(in.plant.transferFunction(), design.controller, setup.reference,
                            options);
    };
    SimulationResult run = simulate();
    const std::optional<PointToPointMove>& move = setup.trajectory.move;
    QJsonObject durationJson{{"automatic", !args.has("duration")}, {"includes_settle", false}};
    if (move && !args.has("duration")) {
        // Automatic: the move, then the settle into the window estimated from the error at tf
        // and the slowest closed-loop pole (as a session's automatic duration, RunDuration).
        const double t0 = setup.trajectory.t0Seconds, tf = move->endSeconds;
        const double cap = automaticMoveCapSeconds(t0, tf, setup.options.dtSeconds);
        const bool settles = design.stable && !trackingMetrics(run).diverged;
        const double need =
            settles ? settleTimeEstimateSeconds(run.e.back(), window,
                                                continuousDecayPerSecond(design.closedLoopPoles))
                    : 0.0;
        const double duration = automaticMoveDurationSeconds(t0, tf, need, cap);
        if (settles && duration > setup.durationSeconds) {
            resampleSetup(setup, args, duration);
            run = simulate();
        }
        durationJson.insert("includes_settle", settles);
        durationJson.insert("settle_estimate", number(need));
        durationJson.insert("cap", number(cap));
        durationJson.insert("capped", settles && duration == cap && cap > tf);
    }
    QJsonValue digital;
    SimulationResult digitalRun;
    if (args.flag("digital"))
        digital = digitalJson(args, in, design, setup, window, axis, digitalRun);
    if (const auto csv = args.value("csv"))
        writeCsv(*csv, run, args.flag("digital") ? &digitalRun : nullptr);
    QJsonObject out = designJson(design);
    out.insert("method", "guillemin-truxal");
    insertSetupJson(out, setup);
    out.insert("duration_choice", durationJson);
    out.insert("tracking", trackingJson(trackingMetrics(run)));
    out.insert("step_response", stepResponseJson(stepCharacteristics(design.closedLoop)));
    out.insert("move_and_settle",
               move ? QJsonValue(moveSettleJson(moveSettleMetrics(run, *move, window)))
                    : QJsonValue());
    if (friction.active() || compensation.percent != 0.0) {
        out.insert("friction", frictionJson(friction, compensation));
        out.insert("stick_slip", stickSlipJson(run));
        QJsonArray warnings;
        if (const auto f = stickSlipFindings(run))
            for (const std::string& w : stickSlipWarnings(*f))
                warnings.append(QString::fromStdString(w));
        out.insert("warnings", warnings);
    }
    if (args.flag("digital"))
        out.insert("digital", digital);
    print(out);
    return 0;
}

namespace {

QString fixed(double v, int decimals = 4) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("n/a");
}

void reportAxis(QTextStream& out, const GtPreset& preset, const Sinusoid& circleAxis,
                double circleDuration, SimulationResult& circleRun) {
    const GtDesign d = designGuilleminTruxal(preset.plant, preset.omegaNRadPerSec, preset.kp);
    const StepCharacteristics step = stepCharacteristics(d.closedLoop);
    out << "== " << QString::fromStdString(preset.description) << "\n";
    out << "  plant     G(s) = "
        << QString::fromStdString(preset.plant.transferFunction().num().toString()) << " / ("
        << QString::fromStdString(preset.plant.transferFunction().den().toString()) << ")\n";
    out << "  design    wn = " << preset.omegaNRadPerSec << " rad/s, kp = " << preset.kp << "\n";
    out << "  f1 = " << fixed(d.f1) << "  f2 = " << fixed(d.f2) << "  f3 = " << fixed(d.f3)
        << "  psi1 = " << QString::number(d.psi1, 'g', 6) << "  psi2 = " << d.psi2 << "\n";
    out << "  G_c(s)    = " << d.kp << " + " << QString::number(d.ki, 'g', 6) << "/s\n";
    out << "  G_R(s)    = (" << QString::fromStdString(d.referenceModel.num().toString()) << ") / ("
        << QString::fromStdString(d.referenceModel.den().toString()) << ")\n";
    out << "  closed-loop poles:";
    for (const auto& p : d.closedLoopPoles)
        out << "  " << QString::number(p.real(), 'g', 6) << (p.imag() >= 0 ? "+" : "-")
            << QString::number(std::abs(p.imag()), 'g', 6) << "j";
    out << "\n  margins   " << marginsText(stabilityMargins(gtLoopTransferFunctions(d).openLoop));
    out << "\n  step      settling (2 %) = " << fixed(step.settlingTimeSeconds, 2)
        << " s, overshoot = " << fixed(step.overshootPct, 3) << " %"
        << (d.stable ? "" : "  UNSTABLE") << "\n";

    LoopSimulationOptions options;
    options.umaxVolts = 2.5;
    options.modelUnitsPerPositionUnit = preset.modelUnitsPerPositionUnit;
    const CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    const auto times = sampleTimes(130.0, options.dtSeconds);
    const SimulationResult cubicRun =
        simulateLoop(preset.plant.transferFunction(), d.controller,
                     sampled([&](double t) { return cubic.position(t); }, times), options);
    const TrackingMetrics cm = trackingMetrics(cubicRun);
    out << "  cubic 0 -> 600 in 130 s: RMSE " << fixed(cm.rmse) << ", max |e| "
        << fixed(cm.maxAbsError) << " (" << fixed(cm.maxAbsErrorPct, 3) << " % of travel), max |u| "
        << fixed(cm.maxAbsU) << " V, saturated " << (cm.saturated ? "yes" : "no") << ", ITAE "
        << fixed(cm.itae, 2) << "\n";

    const auto circleTimes = sampleTimes(circleDuration, options.dtSeconds);
    circleRun =
        simulateLoop(preset.plant.transferFunction(), d.controller,
                     sampled([&](double t) { return circleAxis.value(t); }, circleTimes), options);
    const TrackingMetrics sm = trackingMetrics(circleRun);
    out << "  circle axis: RMSE " << fixed(sm.rmse) << ", max |e| " << fixed(sm.maxAbsError)
        << ", max |u| " << fixed(sm.maxAbsU) << " V, saturated " << (sm.saturated ? "yes" : "no")
        << " (" << fixed(sm.saturatedTimeSeconds, 2) << " s)\n";
}

} // namespace

int runReport(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly({});
    if (args.positional().size() > 1)
        throw InvalidInput("SESSION", "report takes at most one session file");
    if (args.positional().size() == 1)
        return runSessionReport(args.positional().first());
    QString text;
    QTextStream out(&text);
    out << "XY Tune report: the Guillemin-Truxal PI design of Braga et al. (default design)\n";
    out << "Cubic point-to-point 0 -> 600 in 130 s (dt 0.01 s, |u| <= 2.5 V); circle R = 25 mm at "
           "0.06 rad/s (x = lower base, sine; y = upper base, cosine), 10 s ramp-in, one "
           "revolution.\n\n";
    Circle circle;
    circle.rampInSeconds = 10.0;
    const double duration = circle.periodSeconds() + circle.rampInSeconds;
    SimulationResult xRun, yRun;
    reportAxis(out, *findGtPreset("lower-base"), circle.xAxis(), duration, xRun);
    out << "\n";
    reportAxis(out, *findGtPreset("upper-base"), circle.yAxis(), duration, yRun);
    const ContourError ce = circleContourError(xRun.t, xRun.y, yRun.y, circle);
    out << "\n== Circle contour (after the ramp-in)\n  radial error: max " << fixed(ce.maxAbs)
        << " mm, RMS " << fixed(ce.rms) << " mm\n";
    out.flush();
    std::fputs(text.toUtf8().constData(), stdout);
    return 0;
}

} // namespace xyt::cli
