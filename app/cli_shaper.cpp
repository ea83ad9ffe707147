// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli shaper: one input shaper, its impulses, delay, Klipper's smoothing and max accel,
// and its sensitivity curve; with --recommend, Klipper's choice of shaper for an accelerometer
// log or a modelled mode.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_json.h"

#include "core/design/input_shaper.h"
#include "core/design/shaper_recommendation.h"
#include "core/design/shaper_sensitivity.h"
#include "core/identification/accelerometer_log.h"
#include "core/model/errors.h"
#include "core/session/shaper_advice.h"

#include <QJsonArray>
#include <QJsonObject>

#include <string>

namespace xyt::cli {

namespace {

std::string shaperNamesList() {
    std::string names;
    for (const ShaperType t : {ShaperType::Zv, ShaperType::Mzv, ShaperType::Zvd, ShaperType::Zvdd,
                               ShaperType::Ei, ShaperType::TwoHumpEi, ShaperType::ThreeHumpEi})
        names += std::string(names.empty() ? "" : ", ") + shaperName(t);
    return names;
}

QJsonObject fitJson(const ShaperFit& f) {
    return {{"type", shaperName(f.shaper.type)},
            {"frequency", number(f.shaper.frequencyHz)},
            {"remaining_vibration", number(f.remainingVibrations)},
            {"smoothing", number(f.smoothing)},
            {"score", number(f.score)},
            {"max_accel", number(f.maxAccelMmPerS2)}};
}

/// shaper --recommend: the spectrum of --data (a Klipper accelerometer log, its --axis) or of
/// the mode --mode-frequency/--mode-damping, then recommendShaper.
int recommend(const CliArgs& args) {
    args.allowOnly({"recommend", "data", "axis", "mode-frequency", "mode-damping", "max-smoothing",
                    "scv", "damping", "klipper-shapers"});
    if (args.has("data") == args.has("mode-frequency"))
        throw InvalidInput("--recommend", "give either --data LOG.csv (a Klipper accelerometer "
                                          "log) or --mode-frequency F (a modelled mode)");
    ShaperRecommendationOptions options;
    options.dampingRatio = args.number("damping", 0.1);
    if (!(options.dampingRatio >= 0.0 && options.dampingRatio < 1.0))
        throw InvalidInput("--damping", "give a damping ratio in [0, 1)");
    options.squareCornerVelocityMmPerS = args.number("scv", 5.0);
    if (!(options.squareCornerVelocityMmPerS >= 0.0))
        throw InvalidInput("--scv", "give a square corner velocity >= 0 mm/s");
    if (args.has("max-smoothing")) {
        options.maxSmoothing = args.number("max-smoothing");
        if (!(*options.maxSmoothing > 0.0))
            throw InvalidInput("--max-smoothing", "give a smoothing limit > 0 mm");
    }
    if (args.flag("klipper-shapers")) {
        options.shapers = klipperAutotuneShapers();
        options.useKlipperMinimumFrequencies = true;
    }
    PowerSpectrum spectrum;
    QJsonObject source;
    if (args.has("data")) {
        const std::string path = args.text("data", QString()).toStdString();
        const AccelerometerLog log = readAccelerometerLogFile(path);
        const std::string axis = args.text("axis", "sum").toStdString();
        try {
            spectrum = accelerometerShaperSpectrum(
                accelerometerSpectra(log, options.maxSpectrumFrequencyHz), axis);
        } catch (const InvalidInput& e) {
            if (e.field() == "axis")
                throw InvalidInput("--axis", e.reason());
            throw;
        }
        source = {{"data", QString::fromStdString(path)},
                  {"axis", QString::fromStdString(axis)},
                  {"samples", static_cast<double>(log.timeSeconds.size())}};
    } else {
        FlexibleMode mode;
        mode.frequencyHz = args.number("mode-frequency");
        mode.dampingRatio = args.number("mode-damping", 0.05);
        try {
            spectrum = flexibleModeSpectrum(mode, options.maxSpectrumFrequencyHz, 0.2);
        } catch (const InvalidInput& e) {
            throw InvalidInput(e.field() == "damping" ? "--mode-damping" : "--mode-frequency",
                               e.reason());
        }
        source = {{"mode_frequency", number(mode.frequencyHz)},
                  {"mode_damping", number(mode.dampingRatio)}};
    }
    const ShaperRecommendation r = recommendShaper(spectrum, options);
    QJsonArray fits;
    for (const ShaperFit& f : r.fits)
        fits.append(fitJson(f));
    print(QJsonObject{{"source", source},
                      {"recommended", fitJson(r.best())},
                      {"shapers", fits},
                      {"damping", number(options.dampingRatio)},
                      {"scv", number(options.squareCornerVelocityMmPerS)}});
    return 0;
}

} // namespace

int runShaper(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, {"recommend", "klipper-shapers"});
    if (args.flag("recommend"))
        return recommend(args);
    args.allowOnly({"type", "frequency", "damping", "points", "scv"});
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(), "unexpected argument");
    const auto typeText = args.value("type");
    if (!typeText)
        throw InvalidInput("--type", "is required (" + shaperNamesList() + ")");
    ShaperType type = ShaperType::Zv;
    if (!shaperFromName(typeText->toStdString(), type))
        throw InvalidInput("--type", "unknown shaper '" + typeText->toStdString() + "' (" +
                                         shaperNamesList() + ")");
    const double frequency = args.number("frequency");
    if (!(frequency > 0.0))
        throw InvalidInput("--frequency", "give the mode's frequency in Hz, > 0");
    // Klipper's DEFAULT_DAMPING_RATIO when not given.
    const double damping = args.number("damping", 0.1);
    if (!(damping >= 0.0 && damping < 1.0))
        throw InvalidInput("--damping", "give a damping ratio in [0, 1)");
    const double scv = args.number("scv", 5.0);
    if (!(scv >= 0.0))
        throw InvalidInput("--scv", "give a square corner velocity >= 0 mm/s");
    const int points = args.integer("points", 251, 2, 100000);

    const InputShaper s = designInputShaper(type, frequency, damping);
    const ShaperSensitivity sensitivity = shaperSensitivity(s, points);
    print(QJsonObject{
        {"type", shaperName(type)},
        {"frequency", number(frequency)},
        {"damping", number(damping)},
        {"amplitudes", numbers(s.amplitudes)},
        {"times", numbers(s.times)},
        {"duration", number(s.duration())},
        {"delay", number(shaperDelaySeconds(s))},
        {"scv", number(scv)},
        {"smoothing", number(klipperShaperSmoothing(s, 5000.0, scv))},
        {"max_accel", number(klipperMaxAccel(s, scv))},
        {"sensitivity", QJsonObject{{"damping", number(sensitivity.dampingRatio)},
                                    {"frequency", numbers(sensitivity.frequencyHz)},
                                    {"vibration", numbers(sensitivity.vibration)}}},
    });
    return 0;
}

} // namespace xyt::cli
