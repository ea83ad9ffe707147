// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/flexible_mode.h"
#include "core/model/transfer_function.h"

#include <cmath>
#include <string>

namespace xyt {

/**
 * A notch (band-stop biquad) in a controller's path, the filter industrial drives put in the
 * loop against a mechanical resonance:
 *   N(s) = (s^2 + 2 zz w0 s + w0^2) / (s^2 + 2 zp w0 s + w0^2),  w0 = 2 pi centreHz,
 *   zp = widthHz / (2 centreHz),  zz = zp 10^(-depthDb / 20),
 * so |N| is 1 far from w0 and 10^(-depthDb/20) at w0, with no phase there; widthHz is the
 * bandwidth of the pole pair (for an infinitely deep notch, the -3 dB band). centreHz = 0: none.
 */
struct NotchFilter {
    double centreHz = 0.0; ///< 0: no notch
    double widthHz = 0.0;
    double depthDb = 20.0; ///< attenuation at the centre (dB, > 0)

    bool present() const { return centreHz != 0.0; }
    double poleDamping() const { return widthHz / (2.0 * centreHz); }
    double zeroDamping() const { return poleDamping() * std::pow(10.0, -depthDb / 20.0); }
    /// N(s) above; the gain 1 when !present().
    TransferFunction transferFunction() const;
    friend bool operator==(const NotchFilter&, const NotchFilter&) = default;
};

/// The widest notch accepted: the pole pair's damping below 1 (width < 2 centre).
/// @throws InvalidInput "centre" unless 0 or finite and > 0, "width" unless finite, > 0 and below
///         twice the centre, "depth" unless finite in (0, 120] dB; prefixed by @p prefix.
void validateNotchFilter(const NotchFilter& notch, const std::string& prefix = "");

/**
 * The notch for @p mode: centred on its resonance, as deep as its peak stands above the rigid
 * plant, 1 / (2 zr) (the resonant pair's gain at wr), held between 6 and 40 dB and rounded to
 * 0.01 dB, and four times
 * its half-power bandwidth 2 zr fr wide (at least a tenth of fr), so that the mode may move by
 * about its own bandwidth either way and stay in the notch.
 * @throws InvalidInput as validateFlexibleMode, "frequency" when there is no mode.
 */
NotchFilter notchForMode(const FlexibleMode& mode);

/// A second-order section in z^-1: y = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2) x.
struct Biquad {
    double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
    /// The section as a discrete transfer function at @p tsSeconds.
    TransferFunction transferFunction(double tsSeconds) const;
    friend bool operator==(const Biquad&, const Biquad&) = default;
};

/// Its state in direct form II transposed.
struct BiquadState {
    double s1 = 0.0, s2 = 0.0;
};

/// One sample in direct form II transposed (the exported C code does the same sums in this
/// order): y = b0 x + s1, s1 = b1 x - a1 y + s2, s2 = b2 x - a2 y.
inline double stepBiquad(const Biquad& f, BiquadState& s, double x) {
    const double y = f.b0 * x + s.s1;
    s.s1 = f.b1 * x - f.a1 * y + s.s2;
    s.s2 = f.b2 * x - f.a2 * y;
    return y;
}

/**
 * The notch discretized by the bilinear (Tustin) transform prewarped at its centre,
 * s = K (z - 1) / (z + 1) with K = w0 / tan(w0 Ts / 2) (Franklin, Powell and Workman, Digital
 * Control of Dynamic Systems, 3rd ed., section 6.3.2), so that the discrete notch has exactly
 * the continuous one's depth and zero phase at w0.
 * @throws InvalidInput "ts" unless > 0, "centre" unless the notch lies below the Nyquist
 *         frequency 1 / (2 Ts), and as validateNotchFilter; prefixed by @p prefix.
 */
Biquad discreteNotch(const NotchFilter& notch, double tsSeconds, const std::string& prefix = "");

} // namespace xyt
