// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the reader of Klipper's raw accelerometer log
// (core/identification/accelerometer_log.h) on arbitrary text, then its spectra with Klipper's
// parameters and the half-power pick on their sum. Either a one-line InvalidInput, or a
// consistent log (equal column lengths, at least kMinAccelerometerSamples rows, finite values,
// strictly increasing times whose intervals lie within the stated tolerance of the mean, an
// accepted mean interval) whose spectra are finite, non-negative, on increasing frequencies no
// higher than asked for, with psd_sum the sum of the three axes.
#include "tests/fuzz/fuzz_support.h"

#include "core/identification/accelerometer_log.h"
#include "core/identification/experiment_table.h"
#include "core/model/errors.h"

#include <cmath>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    xyt::AccelerometerLog log;
    try {
        log = xyt::readAccelerometerLog(text, "fuzz.csv");
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        return 0;
    }
    const std::size_t n = log.size();
    XYT_FUZZ_REQUIRE(n >= xyt::kMinAccelerometerSamples);
    XYT_FUZZ_REQUIRE(log.x.size() == n && log.y.size() == n && log.z.size() == n);
    XYT_FUZZ_REQUIRE_FINITE(log.timeSeconds);
    XYT_FUZZ_REQUIRE_FINITE(log.x);
    XYT_FUZZ_REQUIRE_FINITE(log.y);
    XYT_FUZZ_REQUIRE_FINITE(log.z);
    XYT_FUZZ_REQUIRE(log.meanIntervalSeconds >= xyt::kMinSampleTimeSeconds &&
                     log.meanIntervalSeconds <= xyt::kMaxSampleTimeSeconds);
    for (std::size_t i = 1; i < n; ++i) {
        const double dt = log.timeSeconds[i] - log.timeSeconds[i - 1];
        XYT_FUZZ_REQUIRE(dt > 0.0);
        XYT_FUZZ_REQUIRE(std::abs(dt / log.meanIntervalSeconds - 1.0) <=
                         xyt::kAccelerometerIntervalTolerance);
    }
    // The last byte picks the band shown: Klipper's 200 Hz, or a lower one.
    const std::uint8_t last = size > 0 ? data[size - 1] : 1;
    const double maxHz = last % 2 ? 200.0 : 1.0 + last;
    xyt::AccelerometerSpectra s;
    try {
        s = xyt::accelerometerSpectra(log, maxHz);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        return 0;
    }
    const std::size_t bins = s.frequencyHz.size();
    XYT_FUZZ_REQUIRE(s.psdX.size() == bins && s.psdY.size() == bins && s.psdZ.size() == bins &&
                     s.psdSum.size() == bins);
    XYT_FUZZ_REQUIRE(s.segments.count >= 2 && s.segments.segmentLength < n);
    for (std::size_t k = 0; k < bins; ++k) {
        XYT_FUZZ_REQUIRE(s.frequencyHz[k] <= maxHz &&
                         (k == 0 || s.frequencyHz[k] > s.frequencyHz[k - 1]));
        XYT_FUZZ_REQUIRE_FINITE(s.psdSum[k]);
        XYT_FUZZ_REQUIRE(s.psdX[k] >= 0.0 && s.psdY[k] >= 0.0 && s.psdZ[k] >= 0.0);
        XYT_FUZZ_REQUIRE(s.psdSum[k] == s.psdX[k] + s.psdY[k] + s.psdZ[k]);
    }
    if (bins >= 3) {
        try {
            const xyt::ResonancePick p =
                xyt::pickResonance(s.frequencyHz, s.psdSum, xyt::ResonanceQuantity::Power);
            XYT_FUZZ_REQUIRE_FINITE(p.frequencyHz);
            XYT_FUZZ_REQUIRE(p.frequencyHz >= s.frequencyHz.front() &&
                             p.frequencyHz <= s.frequencyHz.back());
            XYT_FUZZ_REQUIRE(p.dampingRatio.has_value() == p.note.text.empty());
            if (p.dampingRatio)
                XYT_FUZZ_REQUIRE(std::isfinite(*p.dampingRatio) && *p.dampingRatio >= 0.0);
        } catch (const xyt::InvalidInput& e) {
            xyt::fuzz::requireOneLine(e); // a band of fewer than 3 bins
        }
    }
    return 0;
}
