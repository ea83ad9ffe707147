// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli shaper: one input shaper, its impulses, delay, Klipper's smoothing and max accel,
// and its sensitivity curve.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_json.h"

#include "core/design/input_shaper.h"
#include "core/design/shaper_recommendation.h"
#include "core/design/shaper_sensitivity.h"
#include "core/model/errors.h"

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

} // namespace

int runShaper(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
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
