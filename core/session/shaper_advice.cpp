// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/shaper_advice.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <cmath>

namespace xyt {

PowerSpectrum accelerometerShaperSpectrum(const AccelerometerSpectra& spectra,
                                          const std::string& axis) {
    PowerSpectrum out;
    out.frequencyHz = spectra.frequencyHz;
    if (axis == "x")
        out.power = spectra.psdX;
    else if (axis == "y")
        out.power = spectra.psdY;
    else if (axis == "z")
        out.power = spectra.psdZ;
    else if (axis == "sum")
        out.power = spectra.psdSum;
    else
        throw InvalidInput("axis", makeDiagnostic("session_spectrum_axis"));
    return klipperNormalizeToFrequencies(std::move(out));
}

PowerSpectrum flexibleModeSpectrum(const FlexibleMode& mode, double maxHz, double stepHz) {
    validateFlexibleMode(mode);
    if (!mode.present())
        throw InvalidInput("frequency", makeDiagnostic("session_no_mode_spectrum"));
    requirePositive(maxHz, "max");
    requirePositive(stepHz, "step");
    const TransferFunction r = mode.transferFunction();
    PowerSpectrum out;
    const auto bins = static_cast<std::size_t>(std::floor(maxHz / stepHz + 1e-9)) + 1;
    for (std::size_t k = 0; k < bins; ++k) {
        const double f = static_cast<double>(k) * stepHz;
        out.frequencyHz.push_back(f);
        out.power.push_back(std::norm(r.frequencyResponse(kTwoPi * f)));
    }
    return out;
}

} // namespace xyt
