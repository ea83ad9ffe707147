// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli identify --structure frf: the frequency response of a logged experiment (chirp,
// PRBS, noise) as Welch's H1 estimate (core/identification/spectral_estimate.h), with the
// coherence, Bendat and Piersol's band of the gain, and the half-power resonance pick.
#include "app/cli_args.h"
#include "app/cli_json.h"
#include "app/cli_spectra.h"

#include "core/model/errors.h"

#include <QJsonArray>

#include <cmath>

namespace xyt::cli {

namespace {

constexpr double kFrfPi = 3.14159265358979323846;

/// Linear interpolation of @p v at @p f on the increasing grid @p grid (clamped to its ends).
double frfInterpolate(const std::vector<double>& grid, const std::vector<double>& v, double f) {
    if (f <= grid.front())
        return v.front();
    for (std::size_t k = 1; k < grid.size(); ++k)
        if (f <= grid[k]) {
            const double t = (f - grid[k - 1]) / (grid[k] - grid[k - 1]);
            return v[k - 1] + t * (v[k] - v[k - 1]);
        }
    return v.back();
}

std::vector<double> degrees(const std::vector<double>& radians) {
    std::vector<double> out(radians.size());
    for (std::size_t k = 0; k < radians.size(); ++k)
        out[k] = radians[k] * 180.0 / kFrfPi;
    return out;
}

} // namespace

ResonanceBand parseResonanceBand(const QString& option, const QString& text) {
    const QStringList parts = text.split(':');
    bool ok0 = false, ok1 = false;
    const double f0 = parts.size() == 2 ? parts[0].toDouble(&ok0) : 0.0;
    const double f1 = parts.size() == 2 ? parts[1].toDouble(&ok1) : 0.0;
    if (!ok0 || !ok1 || !std::isfinite(f0) || !std::isfinite(f1) || !(f1 > f0) || f0 < 0.0)
        throw InvalidInput(option.toStdString(),
                           "'" + text.toStdString() + "' is not F0:F1 in Hz with 0 <= F0 < F1");
    return {f0, f1};
}

QJsonObject resonanceJson(const ResonancePick& pick) {
    const auto optional = [](const std::optional<double>& v) {
        return v ? number(*v) : QJsonValue(QJsonValue::Null);
    };
    return {{"frequency", number(pick.frequencyHz)},
            {"peak", number(pick.peakValue)},
            {"damping", optional(pick.dampingRatio)},
            {"low_half_power", optional(pick.lowHalfPowerHz)},
            {"high_half_power", optional(pick.highHalfPowerHz)},
            {"note", QString::fromStdString(pick.note)}};
}

int identifyFrequencyResponse(const CliArgs& args) {
    args.allowOnly({"data", "time-col", "ts", "input-col", "output-col", "output-unit",
                    "mm-per-count", "segment", "structure", "range", "detrend", "remove-means",
                    "decimate", "segment-length", "mode-frequency", "band"});
    if (!args.has("data"))
        throw InvalidInput("--data", "give the experiment file (CSV/TSV, .lvm or .mat)");
    const IoData d = identifyRecord(args, "--data", args.text("data", QString()));
    WelchOptions options;
    if (args.has("segment-length"))
        options.segmentLength =
            static_cast<std::size_t>(args.integer("segment-length", 0, 4, 1 << 24));
    FrequencyResponseEstimate e;
    try {
        e = estimateFrequencyResponse(d.u, d.y, d.tsSeconds, options);
    } catch (const InvalidInput& error) {
        // A record too short for the segments is the segment's fault when one was given; a
        // sample that is not finite belongs to its column.
        const bool segments =
            error.field() == "segment" || error.reason().find("segments") != std::string::npos;
        const std::string field = segments
                                      ? (args.has("segment-length") ? "--segment-length" : "--data")
                                  : error.field() == "u" ? "--input-col"
                                  : error.field() == "y" ? "--output-col"
                                                         : "--data";
        throw InvalidInput(field, d.source + ": " + error.reason());
    }
    ResonanceBand band;
    if (const auto text = args.value("band"))
        band = parseResonanceBand("--band", *text);
    ResonancePick pick;
    try {
        pick = pickResonance(e.frequencyHz, e.magnitude, ResonanceQuantity::Magnitude, band);
    } catch (const InvalidInput& error) {
        throw InvalidInput("--band", error.reason());
    }
    const std::vector<double> phaseDeg = degrees(e.phaseRad);
    QJsonObject out{{"structure", "frf"},
                    {"data", QJsonObject{{"source", QString::fromStdString(d.source)},
                                         {"samples", static_cast<qint64>(d.size())},
                                         {"ts", number(d.tsSeconds)},
                                         {"start", number(d.startSeconds)}}},
                    {"frequency", numbers(e.frequencyHz)},
                    {"magnitude", numbers(e.magnitude)},
                    {"phase_deg", numbers(phaseDeg)},
                    {"coherence", numbers(e.coherence)},
                    {"relative_error", numbers(e.relativeError)},
                    {"magnitude_low", numbers(e.magnitudeLow)},
                    {"magnitude_high", numbers(e.magnitudeHigh)},
                    {"band_sigmas", number(e.bandSigmas)},
                    {"averages", static_cast<qint64>(e.segments.count)},
                    {"equivalent_averages", number(e.segments.equivalentAverages)},
                    {"segment", static_cast<qint64>(e.segments.segmentLength)},
                    {"window", "hann"},
                    {"overlap", 0.5},
                    {"resonance", resonanceJson(pick)}};
    if (args.has("mode-frequency")) {
        const double f = args.number("mode-frequency");
        requireBelowNyquist(f, d.tsSeconds, "--mode-frequency");
        out["mode"] = QJsonObject{
            {"frequency", number(f)},
            {"magnitude", number(frfInterpolate(e.frequencyHz, e.magnitude, f))},
            {"phase_deg", number(frfInterpolate(e.frequencyHz, phaseDeg, f))},
            {"coherence", number(frfInterpolate(e.frequencyHz, e.coherence, f))},
            {"magnitude_low", number(frfInterpolate(e.frequencyHz, e.magnitudeLow, f))},
            {"magnitude_high", number(frfInterpolate(e.frequencyHz, e.magnitudeHigh, f))}};
    }
    print(out);
    return 0;
}

} // namespace xyt::cli
