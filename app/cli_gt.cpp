// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli gt | simulate | report: the Guillemin-Truxal design of paper 000.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_json.h"

#include "core/contour_error.h"
#include "core/errors.h"
#include "core/guillemin_truxal.h"
#include "core/metrics.h"
#include "core/simulation.h"
#include "core/trajectory.h"

#include <QFile>
#include <QSaveFile>
#include <QTextStream>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

namespace xyt::cli {

namespace {

const QStringList kDesignOptions = {"preset", "k0", "a1", "a2", "wn", "kp"};
/// Only for commands that simulate: model units per trajectory unit.
const QString kUnitOption = "model-unit-scale";
const QStringList kTrajectoryOptions = {"trajectory", "x0", "xf", "t0", "tf", "v0", "vf",
                                        "amplitude", "omega", "phase-deg", "ramp-in",
                                        "duration", "dt", "umax", "csv"};

/// The plant from --preset and/or --k0 --a1 --a2 (explicit values override the preset's).
struct DesignInput {
    ThirdOrderPlant plant;
    double wn;
    double kp;
    double modelUnitsPerPositionUnit = 1.0; ///< the preset's (0.001: m per mm), else 1
};

DesignInput parseDesign(const CliArgs& args) {
    DesignInput in{};
    std::optional<GtPreset> preset;
    if (const auto name = args.value("preset")) {
        preset = findGtPreset(name->toStdString());
        if (!preset)
            throw InvalidInput("--preset", "unknown preset '" + name->toStdString() +
                                               "' (lower-base or upper-base)");
        in.plant = preset->plant;
        in.modelUnitsPerPositionUnit = preset->modelUnitsPerPositionUnit;
    } else if (!args.has("k0") || !args.has("a1") || !args.has("a2")) {
        throw InvalidInput(args.has("k0") ? (args.has("a1") ? "--a2" : "--a1") : "--k0",
                           "is required without --preset");
    }
    in.plant.k0 = args.number("k0", in.plant.k0);
    in.plant.a1 = args.number("a1", in.plant.a1);
    in.plant.a2 = args.number("a2", in.plant.a2);
    if (in.plant.k0 == 0.0)
        throw InvalidInput("--k0", "must be nonzero");
    in.wn = args.number("wn", preset ? std::optional<double>(preset->omegaNRadPerSec) : std::nullopt);
    in.kp = args.number("kp", preset ? std::optional<double>(preset->kp) : std::nullopt);
    if (!(in.wn > 0.0))
        throw InvalidInput("--wn", "must be greater than zero");
    if (!(in.kp > 0.0))
        throw InvalidInput("--kp", "must be greater than zero");
    return in;
}

QJsonObject designJson(const GtDesign& d) {
    return {{"plant", QJsonObject{{"k0", d.plant.k0}, {"a1", d.plant.a1}, {"a2", d.plant.a2},
                                  {"tf", continuousTf(d.plant.transferFunction())}}},
            {"wn", number(d.omegaNRadPerSec)},
            {"f1", number(d.f1)},
            {"f2", number(d.f2)},
            {"f3", number(d.f3)},
            {"psi1", number(d.psi1)},
            {"psi2", number(d.psi2)},
            {"kp", number(d.kp)},
            {"ki", number(d.ki)},
            {"reference_model", continuousTf(d.referenceModel)},
            {"controller", continuousTf(d.controller)},
            {"closed_loop",
             QJsonObject{{"num", descending(d.closedLoop.num())},
                         {"den", descending(d.closedLoop.den())},
                         {"poles", complexPairs(d.closedLoopPoles)}}},
            {"stable", d.stable}};
}

/// A reference signal and its default duration.
struct Reference {
    std::function<double(double)> at;
    double defaultDuration;
    QString description;
};

/// Runs @p f, reporting a core InvalidInput on field "x" as the CLI argument "--x" (the core
/// names its fields like the options: tf, duration, ...).
template <class F> auto asArgument(F&& f) {
    try {
        return f();
    } catch (const InvalidInput& e) {
        throw InvalidInput("--" + e.field(), e.reason());
    }
}

Reference parseTrajectory(const CliArgs& args) {
    const QString kind = args.text("trajectory", "");
    if (kind == "cubic") {
        const double t0 = args.number("t0", 0.0);
        const double x0 = args.number("x0", 0.0), xf = args.number("xf"), tf = args.number("tf");
        const double v0 = args.number("v0", 0.0), vf = args.number("vf", 0.0);
        const CubicTrajectory cubic =
            asArgument([&] { return CubicTrajectory(x0, xf, t0, tf, v0, vf); });
        return {[cubic](double t) { return cubic.position(t); }, cubic.tf(), "cubic"};
    }
    if (kind == "sine") {
        Sinusoid s;
        s.amplitude = args.number("amplitude");
        s.omegaRadPerSec = args.number("omega");
        s.phaseRad = args.number("phase-deg", 0.0) * std::numbers::pi / 180.0;
        s.rampInSeconds = args.number("ramp-in", 0.0);
        if (s.rampInSeconds < 0.0)
            throw InvalidInput("--ramp-in", "must be >= 0");
        if (s.omegaRadPerSec == 0.0)
            throw InvalidInput("--omega", "must be nonzero");
        const double period = 2.0 * std::numbers::pi / std::abs(s.omegaRadPerSec);
        return {[s](double t) { return s.value(t); }, period + s.rampInSeconds, "sine"};
    }
    if (kind.isEmpty())
        throw InvalidInput("--trajectory", "is required (cubic or sine)");
    throw InvalidInput("--trajectory", "must be cubic or sine, got '" + kind.toStdString() + "'");
}

void writeCsv(const QString& path, const SimulationResult& run) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        throw InvalidInput("--csv", "cannot write '" + path.toStdString() +
                                        "': " + file.errorString().toStdString());
    QTextStream out(&file);
    out.setRealNumberPrecision(10);
    out << "t,r,y,e,u\n";
    for (std::size_t k = 0; k < run.t.size(); ++k)
        out << run.t[k] << ',' << run.r[k] << ',' << run.y[k] << ',' << run.e[k] << ','
            << run.u[k] << '\n';
    out.flush();
    if (!file.commit())
        throw InvalidInput("--csv", "cannot write '" + path.toStdString() +
                                        "': " + file.errorString().toStdString());
}

double positiveNumber(const CliArgs& args, const QString& name, double fallback) {
    const double v = args.number(name, fallback);
    if (!(v > 0.0))
        throw InvalidInput(CliArgs::field(name), "must be greater than zero");
    return v;
}

} // namespace

int runGt(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kDesignOptions);
    const DesignInput in = parseDesign(args);
    print(designJson(designGuilleminTruxal(in.plant, in.wn, in.kp)));
    return 0;
}

int runSimulate(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    LoopSimulationOptions options;
    args.allowOnly(kDesignOptions + kTrajectoryOptions + QStringList{kUnitOption});
    const DesignInput in = parseDesign(args);
    options.modelUnitsPerPositionUnit =
        positiveNumber(args, kUnitOption, in.modelUnitsPerPositionUnit);
    const Reference ref = parseTrajectory(args);
    options.dtSeconds = positiveNumber(args, "dt", 0.01);
    options.umaxVolts = positiveNumber(args, "umax", 2.5);
    const double duration = args.number("duration", ref.defaultDuration);
    if (!(duration > 0.0))
        throw InvalidInput("--duration", "must be greater than zero");
    const std::vector<double> times =
        asArgument([&] { return sampleTimes(duration, options.dtSeconds); });
    const GtDesign design = designGuilleminTruxal(in.plant, in.wn, in.kp);
    const SimulationResult run = simulateLoop(in.plant.transferFunction(), design.controller,
                                              sampled(ref.at, times), options);
    if (const auto csv = args.value("csv"))
        writeCsv(*csv, run);
    QJsonObject out = designJson(design);
    out.insert("trajectory", ref.description);
    out.insert("duration", number(duration));
    out.insert("dt", number(options.dtSeconds));
    out.insert("umax", number(options.umaxVolts));
    out.insert("model_unit_scale", number(options.modelUnitsPerPositionUnit));
    out.insert("samples", static_cast<qint64>(run.t.size()));
    out.insert("metrics", metricsJson(trackingMetrics(run), stepCharacteristics(design.closedLoop)));
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
    out << "  plant     G(s) = " << QString::fromStdString(preset.plant.transferFunction().num().toString())
        << " / (" << QString::fromStdString(preset.plant.transferFunction().den().toString()) << ")\n";
    out << "  design    wn = " << preset.omegaNRadPerSec << " rad/s, kp = " << preset.kp << "\n";
    out << "  f1 = " << fixed(d.f1) << "  f2 = " << fixed(d.f2) << "  f3 = " << fixed(d.f3)
        << "  psi1 = " << QString::number(d.psi1, 'g', 6) << "  psi2 = " << d.psi2 << "\n";
    out << "  G_c(s)    = " << d.kp << " + " << QString::number(d.ki, 'g', 6) << "/s\n";
    out << "  G_R(s)    = (" << QString::fromStdString(d.referenceModel.num().toString()) << ") / ("
        << QString::fromStdString(d.referenceModel.den().toString()) << ")\n";
    out << "  closed-loop poles:";
    for (const auto& p : d.closedLoopPoles)
        out << "  " << QString::number(p.real(), 'g', 6)
            << (p.imag() >= 0 ? "+" : "-") << QString::number(std::abs(p.imag()), 'g', 6) << "j";
    out << "\n  step      settling (2 %) = " << fixed(step.settlingTimeSeconds, 2)
        << " s, overshoot = " << fixed(step.overshootPct, 3) << " %"
        << (d.stable ? "" : "  UNSTABLE") << "\n";

    LoopSimulationOptions options;
    options.umaxVolts = 2.5;
    options.modelUnitsPerPositionUnit = preset.modelUnitsPerPositionUnit;
    const CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    const auto times = sampleTimes(130.0, options.dtSeconds);
    const SimulationResult cubicRun = simulateLoop(preset.plant.transferFunction(), d.controller,
                                                   sampled([&](double t) { return cubic.position(t); }, times),
                                                   options);
    const TrackingMetrics cm = trackingMetrics(cubicRun);
    out << "  cubic 0 -> 600 in 130 s: RMSE " << fixed(cm.rmse) << ", max |e| " << fixed(cm.maxAbsError)
        << " (" << fixed(cm.maxAbsErrorPct, 3) << " % of travel), max |u| " << fixed(cm.maxAbsU)
        << " V, saturated " << (cm.saturated ? "yes" : "no") << ", ITAE " << fixed(cm.itae, 2) << "\n";

    const auto circleTimes = sampleTimes(circleDuration, options.dtSeconds);
    circleRun = simulateLoop(preset.plant.transferFunction(), d.controller,
                             sampled([&](double t) { return circleAxis.value(t); }, circleTimes),
                             options);
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
    out << "XY Tune report: the Guillemin-Truxal PI design of paper 000 (default design)\n";
    out << "Cubic point-to-point 0 -> 600 in 130 s (dt 0.01 s, |u| <= 2.5 V); circle R = 25 mm at "
           "0.06 rad/s (x = lower base, sine; y = upper base, cosine), 10 s ramp-in, one revolution.\n\n";
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
