// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli bode and margins: the frequency response and the exact stability
// margins of a Guillemin-Truxal design, a pole-placement design, or a loop given by N and D.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/analysis/frequency_response.h"
#include "core/analysis/loop_responses.h"
#include "core/analysis/nyquist.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace xyt::cli {

namespace {

const QStringList kLoopOptions = {"gt-preset", "wn", "kp", "pp-preset", "a",
                                  "b",         "t",  "ts", "num",       "den"};

/// The open loop L and, for a pole-placement design, the design (for the ZPETC tracking).
struct FrequencyLoop {
    TransferFunction openLoop;
    std::optional<PolePlacementDesign> pp;
};

Polynomial ascendingArgument(const CliArgs& args, const char* name) {
    const QString text = *args.value(name);
    return Polynomial::fromAscending(
        parseCoefficientList(text.toStdString(), std::string("--") + name),
        std::string("--") + name);
}

FrequencyLoop parseFrequencyLoop(const CliArgs& args) {
    const int kinds =
        (args.has("gt-preset") ? 1 : 0) +
        (args.has("pp-preset") || args.has("a") || args.has("b") || args.has("t") ? 1 : 0) +
        (args.has("num") || args.has("den") ? 1 : 0);
    if (kinds == 0)
        throw InvalidInput("--gt-preset",
                           "is required, or --pp-preset / --a --b --t, or --num --den");
    if (kinds > 1)
        throw InvalidInput("--gt-preset",
                           "give one loop: a GT design (--gt-preset), a pole-placement "
                           "design (--pp-preset or --a --b --t) or --num --den");
    FrequencyLoop out;
    if (const auto name = args.value("gt-preset")) {
        const auto preset = findGtPreset(name->toStdString());
        if (!preset)
            throw InvalidInput("--gt-preset", "unknown preset '" + name->toStdString() +
                                                  "' (lower-base or upper-base)");
        const double wn = args.number("wn", preset->omegaNRadPerSec);
        const double kp = args.number("kp", preset->kp);
        if (!(wn > 0.0) || !std::isfinite(wn))
            throw InvalidInput("--wn", "must be a finite number greater than zero");
        if (!(kp > 0.0) || !std::isfinite(kp))
            throw InvalidInput("--kp", "must be a finite number greater than zero");
        try {
            out.openLoop =
                gtLoopTransferFunctions(designGuilleminTruxal(preset->plant, wn, kp)).openLoop;
        } catch (const InvalidInput& e) {
            throw InvalidInput(
                e.field() == "wn" || e.field() == "kp" ? "--" + e.field() : e.field(), e.reason());
        }
        return out;
    }
    for (const char* gtOnly : {"wn", "kp"})
        if (args.has(gtOnly))
            throw InvalidInput(CliArgs::field(gtOnly), "needs --gt-preset");
    if (args.has("num") || args.has("den")) {
        for (const char* required : {"num", "den"})
            if (!args.has(required))
                throw InvalidInput(CliArgs::field(required), "is required with --num/--den");
        const std::vector<double> num =
            parseCoefficientList(args.value("num")->toStdString(), "--num");
        const std::vector<double> den =
            parseCoefficientList(args.value("den")->toStdString(), "--den");
        if (args.has("ts")) {
            const double ts = args.number("ts");
            if (!(ts > 0.0) || !std::isfinite(ts))
                throw InvalidInput("--ts", "must be a finite number greater than zero");
            out.openLoop =
                TransferFunction::fromZInverse(Polynomial::fromAscending(num, "--num"),
                                               Polynomial::fromAscending(den, "--den"), ts);
        } else {
            out.openLoop = TransferFunction(Polynomial::fromDescending(num, "--num"),
                                            Polynomial::fromDescending(den, "--den"));
        }
        return out;
    }
    std::optional<PolePlacementPreset> preset;
    if (const auto name = args.value("pp-preset")) {
        preset = findPolePlacementPreset(name->toStdString());
        if (!preset)
            throw InvalidInput("--pp-preset",
                               "unknown preset '" + name->toStdString() + "' (x-axis or y-axis)");
    } else {
        for (const char* required : {"a", "b", "t"})
            if (!args.has(required))
                throw InvalidInput(std::string("--") + required, "is required without --pp-preset");
    }
    const Polynomial a = args.has("a") ? ascendingArgument(args, "a") : preset->a;
    const Polynomial b = args.has("b") ? ascendingArgument(args, "b") : preset->b;
    const Polynomial t = args.has("t") ? ascendingArgument(args, "t") : preset->t;
    const double ts = args.number("ts", preset ? preset->tsSeconds : 0.07);
    try {
        out.pp = designPolePlacement(a, b, t, ts);
    } catch (const InvalidInput& e) {
        throw InvalidInput("--" + e.field(), e.reason());
    }
    out.openLoop = rstLoopTransferFunctions(*out.pp).openLoop;
    return out;
}

FrequencyGridOptions gridOptions(const CliArgs& args, const StabilityMargins& m) {
    FrequencyGridOptions grid;
    grid.omegaMinRadPerSec = args.number("wmin", 0.0);
    grid.omegaMaxRadPerSec = args.number("wmax", 0.0);
    grid.pointsPerDecade = args.count("points-per-decade", grid.pointsPerDecade, 1000);
    for (double w : {m.gainMarginOmegaRadPerSec, m.phaseMarginOmegaRadPerSec})
        if (std::isfinite(w) && w > 0.0)
            grid.extraFrequencies.push_back(w);
    return grid;
}

} // namespace

int runMargins(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kLoopOptions);
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(), "unexpected argument");
    const FrequencyLoop loop = parseFrequencyLoop(args);
    print(marginsJson(stabilityMargins(loop.openLoop), nyquistCurve(loop.openLoop)));
    return 0;
}

int runBode(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    QStringList allowed = kLoopOptions;
    allowed << "wmin"
            << "wmax"
            << "points-per-decade"
            << "csv";
    args.allowOnly(allowed);
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(), "unexpected argument");
    const FrequencyLoop loop = parseFrequencyLoop(args);
    const StabilityMargins m = stabilityMargins(loop.openLoop);
    FrequencyResponse l;
    try {
        l = adaptiveFrequencyResponse(loop.openLoop, gridOptions(args, m));
    } catch (const InvalidInput& e) {
        throw InvalidInput(e.field() == "omegaMin"   ? "--wmin"
                           : e.field() == "omegaMax" ? "--wmax"
                                                     : e.field(),
                           e.reason());
    }
    QJsonObject out{{"ts", number(l.tsSeconds)},
                    {"frequency", numbers(l.omegaRadPerSec)},
                    {"magnitude_db", numbers(l.magnitudeDb)},
                    {"phase_deg", numbers(l.phaseDeg)},
                    {"margins", marginsJson(m, nyquistCurve(loop.openLoop))}};
    std::optional<TrackingFrequencyResponses> tracking;
    if (loop.pp) {
        tracking =
            zpetcTrackingFrequencyResponses(*loop.pp, designZpetc(*loop.pp), l.omegaRadPerSec);
        out.insert(
            "tracking",
            QJsonObject{
                {"without_ff",
                 QJsonObject{{"magnitude_db", numbers(tracking->withoutFeedforward.magnitudeDb)},
                             {"phase_deg", numbers(tracking->withoutFeedforward.phaseDeg)}}},
                {"with_zpetc",
                 QJsonObject{{"magnitude_db", numbers(tracking->withZpetc.magnitudeDb)},
                             {"phase_deg", numbers(tracking->withZpetc.phaseDeg)}}}});
    }
    if (const auto csv = args.value("csv")) {
        writeFile("--csv", *csv, [&](const ByteSink& sink) {
            sink(tracking ? "frequency,magnitude_db,phase_deg,tracking_without_ff_db,tracking_"
                            "without_ff_deg,"
                            "tracking_with_zpetc_db,tracking_with_zpetc_deg\n"
                          : "frequency,magnitude_db,phase_deg\n");
            char line[256];
            // A pole on the frequency axis gives an infinite magnitude there: an empty cell.
            const auto cell = [](double v) {
                return std::isfinite(v) ? QString::number(v, 'g', 17) : QString();
            };
            for (std::size_t i = 0; i < l.omegaRadPerSec.size(); ++i) {
                QString row = cell(l.omegaRadPerSec[i]) + ',' + cell(l.magnitudeDb[i]) + ',' +
                              cell(l.phaseDeg[i]);
                if (tracking)
                    row += ',' + cell(tracking->withoutFeedforward.magnitudeDb[i]) + ',' +
                           cell(tracking->withoutFeedforward.phaseDeg[i]) + ',' +
                           cell(tracking->withZpetc.magnitudeDb[i]) + ',' +
                           cell(tracking->withZpetc.phaseDeg[i]);
                std::snprintf(line, sizeof line, "%s\n", row.toUtf8().constData());
                sink(line);
            }
        });
    }
    print(out);
    return 0;
}

} // namespace xyt::cli
