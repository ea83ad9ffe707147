// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/notch_filter.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <cmath>

namespace xyt {

void validateNotchFilter(const NotchFilter& notch, const std::string& prefix) {
    if (!std::isfinite(notch.centreHz) || notch.centreHz < 0.0)
        throw InvalidInput(prefix + "centre", makeDiagnostic("design_notch_centre_range"));
    if (!notch.present())
        return;
    if (!std::isfinite(notch.widthHz) || notch.widthHz <= 0.0 ||
        notch.widthHz >= 2.0 * notch.centreHz)
        throw InvalidInput(prefix + "width", makeDiagnostic("design_notch_width_range"));
    if (!std::isfinite(notch.depthDb) || notch.depthDb <= 0.0 || notch.depthDb > 120.0)
        throw InvalidInput(prefix + "depth", makeDiagnostic("design_notch_depth_range"));
}

TransferFunction NotchFilter::transferFunction() const {
    validateNotchFilter(*this);
    if (!present())
        return TransferFunction::gain(1.0);
    const double w0 = kTwoPi * centreHz;
    return TransferFunction::fromDescending({1.0, 2.0 * zeroDamping() * w0, w0 * w0},
                                            {1.0, 2.0 * poleDamping() * w0, w0 * w0});
}

NotchFilter notchForMode(const FlexibleMode& mode) {
    validateFlexibleMode(mode);
    if (!mode.present())
        throw InvalidInput("frequency", makeDiagnostic("design_notch_no_mode"));
    NotchFilter n;
    n.centreHz = mode.frequencyHz;
    const double peakDb =
        mode.dampingRatio > 0.0 ? 20.0 * std::log10(1.0 / (2.0 * mode.dampingRatio)) : 40.0;
    // To 0.01 dB: a number to type into a drive's parameter, and what the field shows.
    n.depthDb = std::round(std::clamp(peakDb, 6.0, 40.0) * 100.0) / 100.0;
    n.widthHz = std::max(4.0 * 2.0 * mode.dampingRatio * mode.frequencyHz, 0.1 * mode.frequencyHz);
    return n;
}

TransferFunction Biquad::transferFunction(double tsSeconds) const {
    return TransferFunction::fromZInverse(Polynomial::fromAscending({b0, b1, b2}),
                                          Polynomial::fromAscending({1.0, a1, a2}), tsSeconds);
}

Biquad discreteNotch(const NotchFilter& notch, double tsSeconds, const std::string& prefix) {
    validateNotchFilter(notch, prefix);
    requirePositive(tsSeconds, "ts");
    if (!notch.present())
        return {};
    const double nyquistHz = 0.5 / tsSeconds;
    if (notch.centreHz >= nyquistHz)
        throw InvalidInput(prefix + "centre", makeDiagnostic("design_notch_above_nyquist",
                                                             {std::to_string(nyquistHz)}));
    const double w0 = kTwoPi * notch.centreHz;
    const double k = w0 / std::tan(0.5 * w0 * tsSeconds);
    const double k2 = k * k, w2 = w0 * w0;
    const double zz = 2.0 * notch.zeroDamping() * w0 * k;
    const double zp = 2.0 * notch.poleDamping() * w0 * k;
    const double a0 = k2 + zp + w2;
    Biquad f;
    f.b0 = (k2 + zz + w2) / a0;
    f.b1 = 2.0 * (w2 - k2) / a0;
    f.b2 = (k2 - zz + w2) / a0;
    f.a1 = 2.0 * (w2 - k2) / a0;
    f.a2 = (k2 - zp + w2) / a0;
    return f;
}

} // namespace xyt
