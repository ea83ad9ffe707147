// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_design_args.h"

#include "app/cli_json.h"

#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/simulation/resample.h"
#include "core/simulation/trajectory.h"
#include "ui/files/session_file.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace xyt::cli {

const QStringList kPlantOptions = {"preset", "k0", "a1", "a2"};
const QStringList kDesignOptions = kPlantOptions + QStringList{"wn", "kp"};
const QString kUnitOption = "model-unit-scale";
const QStringList kTrajectoryOptions = {"trajectory", "x0",       "xf",        "t0",    "tf",
                                        "v0",         "vf",       "amplitude", "omega", "phase-deg",
                                        "ramp-in",    "duration", "dt",        "umax",  "csv"};

PlantInput parsePlant(const CliArgs& args) {
    PlantInput in{};
    if (const auto name = args.value("preset")) {
        in.preset = findGtPreset(name->toStdString());
        if (!in.preset)
            throw InvalidInput("--preset", "unknown preset '" + name->toStdString() +
                                               "' (lower-base or upper-base)");
        in.plant = in.preset->plant;
        in.modelUnitsPerPositionUnit = in.preset->modelUnitsPerPositionUnit;
    } else if (!args.has("k0") || !args.has("a1") || !args.has("a2")) {
        throw InvalidInput(args.has("k0") ? (args.has("a1") ? "--a2" : "--a1") : "--k0",
                           "is required without --preset");
    }
    in.plant.k0 = args.number("k0", in.plant.k0);
    in.plant.a1 = args.number("a1", in.plant.a1);
    in.plant.a2 = args.number("a2", in.plant.a2);
    if (in.plant.k0 == 0.0)
        throw InvalidInput("--k0", "must be nonzero");
    return in;
}

namespace {
/// Runs @p f, re-throwing a core field error as the CLI argument of that name ("tf" -> "--tf").
template <class F> auto asArgument(F&& f) {
    try {
        return f();
    } catch (const InvalidInput& e) {
        throw InvalidInput("--" + e.field(), e.reason());
    }
}
} // namespace

DesignInput parseDesign(const CliArgs& args) {
    const PlantInput plant = parsePlant(args);
    const auto& preset = plant.preset;
    DesignInput in{plant.plant, 0.0, 0.0, plant.modelUnitsPerPositionUnit};
    in.wn =
        args.number("wn", preset ? std::optional<double>(preset->omegaNRadPerSec) : std::nullopt);
    in.kp = args.number("kp", preset ? std::optional<double>(preset->kp) : std::nullopt);
    if (!(in.wn > 0.0))
        throw InvalidInput("--wn", "must be greater than zero");
    if (!(in.kp > 0.0))
        throw InvalidInput("--kp", "must be greater than zero");
    // Values the design cannot represent (wn^4 overflowing for --wn 1e300) are refused here,
    // naming the argument, before any command uses them.
    asArgument([&] { return designGuilleminTruxal(in.plant, in.wn, in.kp); });
    return in;
}

QJsonObject plantJson(const ThirdOrderPlant& plant) {
    return {{"k0", plant.k0},
            {"a1", plant.a1},
            {"a2", plant.a2},
            {"tf", continuousTf(plant.transferFunction())}};
}

QJsonObject designJson(const GtDesign& d) {
    return {{"plant", plantJson(d.plant)},
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
            {"closed_loop", QJsonObject{{"num", descending(d.closedLoop.num())},
                                        {"den", descending(d.closedLoop.den())},
                                        {"poles", complexPairs(d.closedLoopPoles)}}},
            {"stable", d.stable}};
}

Reference parseTrajectory(const CliArgs& args) {
    const QString kind = args.text("trajectory", "");
    if (kind == "cubic" || kind == "quintic") {
        const double t0 = args.number("t0", 0.0);
        const double x0 = args.number("x0", 0.0), xf = args.number("xf"), tf = args.number("tf");
        const double v0 = args.number("v0", 0.0), vf = args.number("vf", 0.0);
        const PointToPointMove move{x0, xf, tf};
        if (kind == "quintic") {
            const QuinticTrajectory quintic =
                asArgument([&] { return QuinticTrajectory(x0, xf, t0, tf, v0, vf); });
            return {[quintic](double t) { return quintic.position(t); }, tf, "quintic", move, t0};
        }
        const CubicTrajectory cubic =
            asArgument([&] { return CubicTrajectory(x0, xf, t0, tf, v0, vf); });
        return {[cubic](double t) { return cubic.position(t); }, cubic.tf(), "cubic", move, t0};
    }
    if (kind == "sine") {
        Sinusoid s;
        s.amplitude = args.number("amplitude");
        requirePosition(s.amplitude, "--amplitude");
        s.omegaRadPerSec = args.number("omega");
        s.phaseRad = args.number("phase-deg", 0.0) * std::numbers::pi / 180.0;
        s.rampInSeconds = args.number("ramp-in", 0.0);
        if (s.rampInSeconds < 0.0)
            throw InvalidInput("--ramp-in", "must be >= 0");
        if (s.omegaRadPerSec == 0.0)
            throw InvalidInput("--omega", "must be nonzero");
        const double period = 2.0 * std::numbers::pi / std::abs(s.omegaRadPerSec);
        return {[s](double t) { return s.value(t); }, period + s.rampInSeconds, "sine",
                std::nullopt, 0.0};
    }
    if (kind.isEmpty())
        throw InvalidInput("--trajectory", "is required (cubic, quintic or sine)");
    throw InvalidInput("--trajectory",
                       "must be cubic, quintic or sine, got '" + kind.toStdString() + "'");
}

double positiveNumber(const CliArgs& args, const QString& name, double fallback) {
    const double v = args.number(name, fallback);
    if (!(v > 0.0))
        throw InvalidInput(CliArgs::field(name), "must be greater than zero");
    return v;
}

SimulationSetup parseSimulationSetup(const CliArgs& args, const PlantInput& plant) {
    SimulationSetup s;
    s.options.modelUnitsPerPositionUnit =
        positiveNumber(args, kUnitOption, plant.modelUnitsPerPositionUnit);
    s.trajectory = parseTrajectory(args);
    s.options.dtSeconds = positiveNumber(args, "dt", 0.01);
    s.options.umaxVolts = positiveNumber(args, "umax", 2.5);
    if (s.trajectory.move) {
        // A move that no sample can see is not a run (--tf 0.005 --dt 0.01 used to
        // report every figure as 0).
        const double move = s.trajectory.move->endSeconds - s.trajectory.t0Seconds;
        const QString text =
            QStringLiteral("the move lasts %1 s (--tf minus --t0), %2 of --dt %3 s")
                .arg(move, 0, 'g', 6)
                .arg(move < s.options.dtSeconds ? QStringLiteral("less than one step")
                                                : QStringLiteral("only %1 steps")
                                                      .arg(std::floor(move / s.options.dtSeconds)))
                .arg(s.options.dtSeconds, 0, 'g', 6);
        if (move < s.options.dtSeconds)
            throw InvalidInput("--tf", text.toStdString() +
                                           ": too short to measure; lengthen --tf or shorten --dt");
        if (move < 10.0 * s.options.dtSeconds)
            std::fprintf(stderr,
                         "xytune-cli: warning: --tf: %s: the figures of so short a move mean "
                         "little; lengthen --tf or shorten --dt\n",
                         qPrintable(text));
    }
    resampleSetup(s, args, args.number("duration", s.trajectory.defaultDuration));
    return s;
}

void resampleSetup(SimulationSetup& s, const CliArgs& args, double durationSeconds) {
    s.durationSeconds = durationSeconds;
    if (!(s.durationSeconds > 0.0))
        throw InvalidInput("--duration", "must be greater than zero");
    std::vector<double> times;
    try {
        times = sampleTimes(s.durationSeconds, s.options.dtSeconds);
    } catch (const InvalidInput& e) {
        // Too many samples: blame what the user typed (--duration, else --dt, else the
        // trajectory argument that set the default duration).
        const std::string culprit = args.has("duration") ? "--duration"
                                    : args.has("dt")     ? "--dt"
                                    : s.trajectory.move  ? "--tf"
                                                         : "--omega";
        throw InvalidInput(e.field() == "duration" ? culprit : "--" + e.field(), e.reason());
    }
    if (times.size() < 2) // one sample: every metric would read 0, which is not a result
        throw InvalidInput(args.has("dt")         ? "--dt"
                           : args.has("duration") ? "--duration"
                           : s.trajectory.move    ? "--tf"
                                                  : "--omega",
                           "gives a single sample (dt " +
                               QString::number(s.options.dtSeconds).toStdString() +
                               " s, duration " + QString::number(s.durationSeconds).toStdString() +
                               " s); at least two samples are needed for the metrics");
    s.reference = sampled(s.trajectory.at, times);
}

void insertSetupJson(QJsonObject& out, const SimulationSetup& setup) {
    out.insert("trajectory", setup.trajectory.description);
    out.insert("duration", number(setup.durationSeconds));
    out.insert("dt", number(setup.options.dtSeconds));
    out.insert("umax", number(setup.options.umaxVolts));
    out.insert("model_unit_scale", number(setup.options.modelUnitsPerPositionUnit));
    out.insert("samples", static_cast<qint64>(setup.reference.size()));
}

namespace {
/// A CSV of inf/nan cells is not a result: refuse it, saying which signal and from when.
void requireFiniteSignals(const SimulationResult& run, const std::string& field) {
    const std::pair<const char*, const std::vector<double>*> columns[] = {
        {"r", &run.r}, {"y", &run.y}, {"e", &run.e}, {"u", &run.u}};
    for (const auto& [name, v] : columns)
        for (std::size_t k = 0; k < v->size(); ++k)
            if (!std::isfinite((*v)[k]))
                throw InvalidInput(
                    field, std::string("the simulated ") + name +
                               " is not finite from t = " + std::to_string(run.t[k]) +
                               " s (an unstable loop or values out of range); no CSV was written");
}
} // namespace

InvalidInput cannotWrite(const std::string& argument, const FileError& e) {
    return InvalidInput(argument, "cannot write " + std::string(e.what()) +
                                      "; nothing was written, an existing file is unchanged");
}

void writeFile(const std::string& argument, const QString& path,
               const std::function<void(const ByteSink&)>& produce) {
    try {
        writeFileAtomically(fileNameBytes(path), produce);
    } catch (const FileError& e) {
        throw cannotWrite(argument, e);
    }
}

void writeTextFile(const std::string& argument, const QString& path, const QString& text) {
    const std::string bytes = text.toStdString();
    writeFile(argument, path, [&bytes](const ByteSink& sink) { sink(bytes); });
}

void writeCsv(const QString& path, const SimulationResult& run, const SimulationResult* digital) {
    requireFiniteSignals(run, "--csv");
    const std::vector<std::size_t> held =
        digital ? heldSampleIndices(digital->t, run.t) : std::vector<std::size_t>();
    writeFile("--csv", path, [&](const ByteSink& sink) {
        sink(digital ? "t,r,y,e,u,t_digital,y_digital,e_digital,u_digital\n" : "t,r,y,e,u\n");
        char line[160];
        for (std::size_t k = 0; k < run.t.size(); ++k) {
            int n = std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%.10g", run.t[k],
                                  run.r[k], run.y[k], run.e[k], run.u[k]);
            sink(std::string_view(line, static_cast<std::size_t>(n)));
            if (digital)
                for (const std::vector<double>* v :
                     {&digital->t, &digital->y, &digital->e, &digital->u}) {
                    const double d = (*v)[held[k]];
                    n = std::isfinite(d) ? std::snprintf(line, sizeof line, ",%.17g", d)
                                         : std::snprintf(line, sizeof line, ",");
                    sink(std::string_view(line, static_cast<std::size_t>(n)));
                }
            sink("\n");
        }
    });
}

Session loadSessionOrThrow(const QString& path) {
    // Read here rather than by files::loadSessionFile: the file name goes to open(2) as the bytes
    // the shell passed, and a file-level error names the path once ("<path>: <reason>").
    const std::string name = fileNameBytes(path);
    std::string bytes;
    try {
        bytes = readRegularFile(name, static_cast<std::size_t>(files::kMaxSessionFileBytes));
    } catch (const FileError& e) {
        throw InvalidInput(name, e.reason());
    }
    const files::SessionLoadResult r = files::sessionFromBytes(QByteArray::fromStdString(bytes));
    for (const QString& w : r.warnings)
        std::fprintf(stderr, "xytune-cli: warning: %s\n", qPrintable(w));
    if (!r.ok)
        throw InvalidInput(name, r.message().toStdString());
    return r.session;
}

SampledDataOptions parseSampledDataOptions(const CliArgs& args, double umaxVolts) {
    SampledDataOptions options;
    options.delaySamples = args.integer("delay-samples", 0, 0, kMaxDelaySamples);
    options.encoderResolution = args.number("encoder-resolution", 0.0);
    options.dacBits = args.integer("dac-bits", 0, 0, 32);
    options.umaxVolts = umaxVolts;
    options.antiWindup = parseAntiWindup(args);
    try {
        validateSampledDataOptions(options);
    } catch (const InvalidInput& e) {
        throw InvalidInput(
            e.field() == "umax"
                ? "--umax"
                : CliArgs::field(QString::fromStdString(e.field()).replace('_', '-')),
            e.reason());
    }
    return options;
}

PiDiscretization parseDiscretization(const CliArgs& args, PiDiscretization fallback) {
    const auto method = args.value("discretization");
    if (!method)
        return fallback;
    if (*method == "tustin")
        return PiDiscretization::Tustin;
    if (*method == "backward-euler")
        return PiDiscretization::BackwardEuler;
    throw InvalidInput("--discretization", "must be tustin or backward-euler");
}

AntiWindup parseAntiWindup(const CliArgs& args) {
    const QString method = args.text("anti-windup", "clamp");
    for (const AntiWindup a : {AntiWindup::None, AntiWindup::Clamp, AntiWindup::BackCalculation})
        if (method == QString::fromStdString(antiWindupName(a)))
            return a;
    throw InvalidInput("--anti-windup", "must be none, clamp or back-calculation");
}

} // namespace xyt::cli
