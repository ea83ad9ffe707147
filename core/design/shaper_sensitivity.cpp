// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/shaper_sensitivity.h"

#include "core/model/errors.h"

#include <cmath>
#include <complex>
#include <numbers>

namespace xyt {

namespace {

/// residualVibration's formula, also at f = 0 (where it is |sum A_i|).
double sensitivityVibrationAt(const InputShaper& s, double frequencyHz) {
    const double zeta = s.dampingRatio;
    const double w = 2.0 * std::numbers::pi * frequencyHz;
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    const double tn = s.duration();
    std::complex<double> sum = 0.0;
    for (std::size_t i = 0; i < s.amplitudes.size(); ++i)
        sum += s.amplitudes[i] * std::exp(-zeta * w * (tn - s.times[i])) *
               std::polar(1.0, wd * s.times[i]);
    return std::abs(sum);
}

} // namespace

ShaperSensitivity shaperSensitivity(const InputShaper& shaper, int points,
                                    double maxFrequencyRatio) {
    if (points < 2)
        throw InvalidInput("points", "must be at least 2");
    requirePositive(maxFrequencyRatio, "maxFrequencyRatio");
    requirePositive(shaper.frequencyHz, "frequency");
    if (!(shaper.dampingRatio >= 0.0 && shaper.dampingRatio < 1.0))
        throw InvalidInput("damping", "must be in [0, 1)");
    ShaperSensitivity out;
    out.dampingRatio = shaper.dampingRatio;
    const double fMax = maxFrequencyRatio * shaper.frequencyHz;
    out.frequencyHz.reserve(static_cast<std::size_t>(points));
    out.vibration.reserve(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k) {
        const double f = fMax * static_cast<double>(k) / static_cast<double>(points - 1);
        out.frequencyHz.push_back(f);
        out.vibration.push_back(sensitivityVibrationAt(shaper, f));
    }
    return out;
}

double shaperDelaySeconds(const InputShaper& shaper) {
    double sum = 0.0;
    for (std::size_t i = 0; i < shaper.amplitudes.size(); ++i)
        sum += shaper.amplitudes[i] * shaper.times[i];
    return sum;
}

} // namespace xyt
