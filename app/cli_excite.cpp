// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli excite: an excitation signal for an identification experiment, written as CSV or
// LabVIEW .lvm (core/identification/excitation.h); with --respond, a synthetic experiment: the
// signal played on a session axis' model with measurement noise (synthetic_experiment.h).
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/identification/excitation.h"
#include "core/identification/jog_experiment.h"
#include "core/identification/synthetic_experiment.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/model/normal_draws.h"
#include "core/session/design_method_module.h"

#include <QJsonArray>

#include <cmath>
#include <cstdio>
#include <random>

namespace xyt::cli {

namespace {

const QStringList kCommonOptions = {"signal",  "ts",   "duration",  "amplitude", "offset", "umax",
                                    "respond", "axis", "noise-std", "seed",      "o"};

/// Runs a core call and renames its field to the option the user typed ("period" -> "--period").
template <class F> ExcitationSignal asOptions(F make) {
    try {
        return make();
    } catch (const InvalidInput& e) {
        const QString name = QString::fromStdString(e.field());
        throw InvalidInput(CliArgs::field(name == "output" ? QStringLiteral("o") : name),
                           e.reason());
    }
}

/// --respond SESSION.json --axis x|y: the command played on the axis' model (a synthetic
/// experiment, for teaching and the examples), with --noise-std MM and --seed N.
ExcitationSignal respond(const CliArgs& args, ExcitationSignal s) {
    const Session session = loadSessionOrThrow(*args.value("respond"));
    const QString axisName = args.text("axis", "x");
    if (axisName != "x" && axisName != "y")
        throw InvalidInput("--axis", "must be x or y");
    const AxisSettings& axis = session.axes[axisName == "x" ? 0 : 1];
    const double noise = args.number("noise-std", 0.0);
    const double seed = args.number("seed", 1.0);
    if (seed < 0.0 || seed > 9007199254740992.0 || seed != std::floor(seed))
        throw InvalidInput("--seed", "must be a whole number from 0 to 2^53");
    return asOptions([&] {
        if (axis.method == DesignMethod::GuilleminTruxal) {
            ThirdOrderPlant mm = axis.gt.plant; // the model's output unit per mm of travel
            mm.k0 /= axis.gt.modelUnitsPerPositionUnit;
            return simulateExperiment(s, mm, noise, static_cast<std::uint64_t>(seed));
        }
        if (axis.method != DesignMethod::PolePlacementZpetc)
            throw InvalidInput("--axis", "axis " + axisName.toStdString() +
                                             " uses a method whose plant the experiment cannot "
                                             "simulate (a Guillemin-Truxal or pole-placement "
                                             "axis' plant only)");
        PolynomialModel m;
        m.a = axis.pp.a;
        m.b = axis.pp.b;
        m.tsSeconds = axis.pp.tsSeconds;
        return simulateExperiment(s, m, noise, static_cast<std::uint64_t>(seed));
    });
}

/// A whole number in [lo, hi], required.
int wholeNumber(const CliArgs& args, const QString& name, int lo, int hi) {
    const auto v = args.value(name);
    if (!v)
        throw InvalidInput(CliArgs::field(name), "is required");
    bool ok = false;
    const int n = v->toInt(&ok);
    if (!ok || n < lo || n > hi)
        throw InvalidInput(CliArgs::field(name), "must be a whole number from " +
                                                     std::to_string(lo) + " to " +
                                                     std::to_string(hi));
    return n;
}

/// "1,2,5": the jog speeds (mm/s).
std::vector<double> parseSpeeds(const CliArgs& args) {
    const auto text = args.value("speeds");
    if (!text)
        throw InvalidInput("--speeds", "give the jog speeds in mm/s, e.g. --speeds 1,2,5,10");
    std::vector<double> out;
    for (const QString& part : text->split(',')) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok)
            throw InvalidInput("--speeds", "'" + part.toStdString() + "' is not a number");
        out.push_back(v);
    }
    return out;
}

/**
 * excite --signal jog: the friction experiment (core/identification/jog_experiment.h) run in
 * closed loop under axis --axis of --respond SESSION (its design, its table with friction, as
 * the contour run traces a path), logged as t, r (reference, mm), y (measured position, mm,
 * with --noise-std) and u (command, V), as an engineer logs the jogs from the machine.
 */
int runJogExperiment(const CliArgs& args) {
    args.allowOnly({"signal", "speeds", "travel", "accel", "dwell", "ts", "respond", "axis",
                    "noise-std", "seed", "o"});
    const auto output = args.value("o");
    if (!output || !output->toLower().endsWith(".csv"))
        throw InvalidInput("-o", "give the log file to write (-o FILE.csv)");
    if (!args.has("respond"))
        throw InvalidInput("--respond", "the jogs run in closed loop: give the session whose "
                                        "axis runs them (--respond SESSION.json --axis x|y)");
    JogProgram program;
    program.speedsMmPerS = parseSpeeds(args);
    program.travelMm = args.number("travel", program.travelMm);
    program.accelMmPerS2 = args.number("accel", program.accelMmPerS2);
    program.dwellSeconds = args.number("dwell", program.dwellSeconds);
    program.tsSeconds = args.number("ts", program.tsSeconds);
    const JogReference jog = [&] {
        try {
            return jogReference(program);
        } catch (const InvalidInput& e) {
            throw InvalidInput(CliArgs::field(QString::fromStdString(e.field())), e.reason());
        }
    }();
    const Session session = loadSessionOrThrow(*args.value("respond"));
    const QString axisName = args.text("axis", "x");
    if (axisName != "x" && axisName != "y")
        throw InvalidInput("--axis", "must be x or y");
    const int axisIndex = axisName == "x" ? 0 : 1;
    const double noise = args.number("noise-std", 0.0);
    if (!(noise >= 0.0) || !std::isfinite(noise))
        throw InvalidInput("--noise-std", "must be a finite number >= 0 (mm)");
    const double seed = args.number("seed", 1.0);
    if (seed < 0.0 || seed > 9007199254740992.0 || seed != std::floor(seed))
        throw InvalidInput("--seed", "must be a whole number from 0 to 2^53");
    const AxisSettings& axis = session.axes[static_cast<std::size_t>(axisIndex)];
    if (axis.method == DesignMethod::PolePlacementZpetc)
        throw InvalidInput("--axis", "axis " + axisName.toStdString() +
                                         " is a pole-placement axis: the jogs need a continuous "
                                         "plant with its table (Guillemin-Truxal or PID)");
    const AxisTrace trace =
        designMethodModule(axis.method)
            .tracePath(session, axisIndex, jog.t, jog.position, program.tsSeconds);
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
    const std::string path = fileNameBytes(*output);
    const SimulationResult& run = trace.run;
    writeFile("-o", *output, [&](const ByteSink& sink) {
        sink("t,r,y,u\n");
        char line[160];
        for (std::size_t k = 0; k < run.t.size(); ++k) {
            const double y = run.y[k] + (noise > 0.0 ? noise * standardNormal(rng) : 0.0);
            const int n = std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", run.t[k],
                                        run.r[k], y, run.u[k]);
            sink(std::string_view(line, static_cast<std::size_t>(n)));
        }
    });
    QJsonArray segments;
    for (const JogSegment& g : jog.segments)
        segments.append(QJsonObject{{"start", number(g.startSeconds)},
                                    {"end", number(g.endSeconds)},
                                    {"velocity", number(g.velocityMmPerS)}});
    print(QJsonObject{{"path", QString::fromStdString(terminalText(path))},
                      {"signal", "jog"},
                      {"samples", static_cast<qint64>(run.t.size())},
                      {"ts", number(program.tsSeconds)},
                      {"axis", axisName},
                      {"columns", QJsonArray{"t", "r", "y", "u"}},
                      {"segments", segments},
                      {"noise_std", number(noise)},
                      {"synthetic", true}});
    return 0;
}

} // namespace

int runExcite(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    const QString signal = args.text("signal", "");
    if (signal == "jog")
        return runJogExperiment(args);
    QStringList allowed = kCommonOptions;
    if (signal == "square")
        allowed << "period";
    else if (signal == "prbs")
        allowed << "clock"
                << "register";
    else if (signal == "chirp")
        allowed << "f0"
                << "f1";
    else
        throw InvalidInput("--signal", args.has("signal")
                                           ? "must be square, prbs, chirp or jog"
                                           : "is required (square, prbs, chirp or jog)");
    args.allowOnly(allowed);
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(), "is not an option of excite");
    const auto output = args.value("o");
    if (!output || output->isEmpty())
        throw InvalidInput("-o", "an output file is required (-o FILE.csv or FILE.lvm)");
    const QString lower = output->toLower();
    if (!lower.endsWith(".csv") && !lower.endsWith(".lvm"))
        throw InvalidInput("-o", "the file name must end in .csv or .lvm");

    ExcitationTiming timing;
    timing.tsSeconds = args.number("ts");
    timing.durationSeconds = args.number("duration");
    timing.umaxVolts = args.number("umax", 2.5);
    const double amplitude = args.number("amplitude");
    const double offset = args.number("offset", 0.0);
    ExcitationSignal s;
    if (signal == "square") {
        const SquareWave w{amplitude, args.number("period"), offset};
        s = asOptions([&] { return squareWave(w, timing); });
    } else if (signal == "prbs") {
        Prbs p;
        p.amplitudeVolts = amplitude;
        p.offsetVolts = offset;
        p.clockSamples = wholeNumber(args, "clock", 1, 1'000'000);
        p.registerLength = wholeNumber(args, "register", 2, 31);
        s = asOptions([&] { return prbs(p, timing); });
    } else {
        const Chirp c{amplitude, args.number("f0"), args.number("f1"), offset};
        s = asOptions([&] { return chirp(c, timing); });
    }
    if (args.has("respond"))
        s = respond(args, std::move(s));
    else if (args.has("axis") || args.has("noise-std") || args.has("seed"))
        throw InvalidInput(args.has("axis")   ? "--axis"
                           : args.has("seed") ? "--seed"
                                              : "--noise-std",
                           "only with --respond SESSION.json");
    const std::string path = fileNameBytes(*output);
    try {
        writeExcitation(path, s); // atomic
    } catch (const FileError& e) {
        throw cannotWrite("-o", e);
    }
    double peak = 0.0;
    for (double v : s.u)
        peak = std::max(peak, std::abs(v));
    print(QJsonObject{{"path", QString::fromStdString(terminalText(path))},
                      {"samples", static_cast<qint64>(s.u.size())},
                      {"ts", number(s.tsSeconds)},
                      {"duration", number(double(s.u.size()) * s.tsSeconds)},
                      {"signal", signal},
                      {"description", QString::fromStdString(s.description)},
                      {"max_abs_u", number(peak)},
                      {"umax", number(*timing.umaxVolts)},
                      {"synthetic", !s.y.empty()}});
    return 0;
}

} // namespace xyt::cli
