// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/shaper_sensitivity.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>

namespace xyt {

ShaperSensitivity shaperSensitivity(const InputShaper& shaper, int points,
                                    double maxFrequencyRatio) {
    if (points < 2)
        throw InvalidInput("points", makeDiagnostic("at_least", {"2"}));
    requirePositive(maxFrequencyRatio, "maxFrequencyRatio");
    requirePositive(shaper.frequencyHz, "frequency");
    if (!(shaper.dampingRatio >= 0.0 && shaper.dampingRatio < 1.0))
        throw InvalidInput("damping", makeDiagnostic("in_zero_one_open_right"));
    ShaperSensitivity out;
    out.dampingRatio = shaper.dampingRatio;
    const double fMax = maxFrequencyRatio * shaper.frequencyHz;
    out.frequencyHz.reserve(static_cast<std::size_t>(points));
    out.vibration.reserve(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k) {
        const double f = fMax * static_cast<double>(k) / static_cast<double>(points - 1);
        out.frequencyHz.push_back(f);
        out.vibration.push_back(residualVibration(shaper, f, shaper.dampingRatio));
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
