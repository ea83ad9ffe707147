// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli psd: the power spectral densities of a Klipper accelerometer log
// (core/identification/accelerometer_log.h), computed as Klipper's shaper_calibrate.py does,
// with the half-power pick of their sum.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_json.h"
#include "app/cli_spectra.h"

#include "core/identification/accelerometer_log.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"

#include <QJsonArray>

namespace xyt::cli {

/// Klipper's MIN_FREQ (shaper_calibrate.py): the pick ignores what lies below.
constexpr double kPsdMinPickHz = 5.0;

int runPsd(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly({"data", "max-frequency", "band"});
    if (!args.has("data"))
        throw InvalidInput("--data", "give the accelerometer log (Klipper's raw_data CSV)");
    const double maxHz = args.number("max-frequency", 200.0);
    AccelerometerLog log;
    try {
        log = readAccelerometerLogFile(fileNameBytes(args.text("data", QString())));
    } catch (const FileError& e) {
        throw InvalidInput("--data", e.what());
    }
    const AccelerometerSpectra s = accelerometerSpectra(log, maxHz);
    // The default band is Klipper's: from MIN_FREQ to the maximum shown (from the third bin
    // when the maximum is lower still); a band too narrow is the option's fault that set it.
    ResonanceBand band{kPsdMinPickHz, maxHz};
    if (maxHz <= kPsdMinPickHz)
        band.lowHz.reset();
    if (const auto text = args.value("band"))
        band = parseResonanceBand("--band", *text);
    ResonancePick pick;
    try {
        pick = pickResonance(s.frequencyHz, s.psdSum, ResonanceQuantity::Power, band);
    } catch (const InvalidInput& e) {
        throw InvalidInput(args.has("band") ? "--band" : "--max-frequency", e.reason());
    }
    print(QJsonObject{{"frequency", numbers(s.frequencyHz)},
                      {"psd_x", numbers(s.psdX)},
                      {"psd_y", numbers(s.psdY)},
                      {"psd_z", numbers(s.psdZ)},
                      {"psd_sum", numbers(s.psdSum)},
                      {"sample_time", number(1.0 / s.samplingHz)},
                      {"sampling_frequency", number(s.samplingHz)},
                      {"samples", static_cast<qint64>(s.samples)},
                      {"segment", static_cast<qint64>(s.segments.segmentLength)},
                      {"averages", static_cast<qint64>(s.segments.count)},
                      {"window", "kaiser"},
                      {"kaiser_beta", kKlipperKaiserBeta},
                      {"overlap", 0.5},
                      {"peak", resonanceJson(pick)}});
    return 0;
}

} // namespace xyt::cli
