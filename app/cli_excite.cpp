// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli excite: an excitation signal for an identification experiment, written as CSV or
// LabVIEW .lvm (core/identification/excitation.h); with --respond, a synthetic experiment: the
// signal played on a session axis' model with measurement noise (synthetic_experiment.h).
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/identification/excitation.h"
#include "core/identification/synthetic_experiment.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"

#include <cmath>

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

} // namespace

int runExcite(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    const QString signal = args.text("signal", "");
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
        throw InvalidInput("--signal", args.has("signal") ? "must be square, prbs or chirp"
                                                          : "is required (square, prbs or chirp)");
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
