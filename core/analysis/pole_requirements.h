// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <complex>
#include <limits>

namespace xyt {

/**
 * The step requirements of a specification as a region of the s-plane, as Control System
 * Designer draws them on a root locus (second-order approximations of a dominant pole pair):
 * damping ratio zeta >= minDamping (the overshoot limit) and Re s <= maxRealPartPerSec
 * (the settling-time limit). For a discrete loop the region is the image under z = exp(s Ts).
 */
struct PoleRequirements {
    double minDamping = 0.0; ///< in [0, 1]; 0: no overshoot limit worth a bound
    /// sigma = -4 / ts (rad/s), the 2 % settling of e^{sigma t}; +infinity without a limit.
    double maxRealPartPerSec = std::numeric_limits<double>::infinity();
};

/**
 * The damping of a second-order pole pair whose step overshoots @p overshootPct:
 *   zeta = -ln(Mp) / sqrt(pi^2 + ln^2 Mp),  Mp = overshootPct / 100;
 * Mp = 0 gives zeta = 1 (only the negative real axis), Mp >= 1 gives 0.
 * @throws InvalidInput "overshootPct" when negative or not a number.
 */
double dampingForOvershoot(double overshootPct);

/**
 * The region of @p maxOvershootPct and @p maxSettlingTimeSeconds (sigma = -4 / ts; an infinite
 * ts gives no settling bound).
 * @throws InvalidInput "maxOvershootPct" as dampingForOvershoot, "maxSettlingTimeSeconds"
 *         unless > 0.
 */
PoleRequirements poleRequirements(double maxOvershootPct, double maxSettlingTimeSeconds);

/// The radius of the z-plane image of Re s = sigma: |z| = exp(sigma Ts) (exp(-4 Ts / ts)).
/// @throws InvalidInput "tsSeconds" unless > 0 and finite.
double settlingRadius(const PoleRequirements& requirements, double tsSeconds);

/// Which requirement a closed-loop pole breaks.
struct PoleViolation {
    bool damping = false;  ///< zeta below minDamping
    bool settling = false; ///< Re s above maxRealPartPerSec (|z| above the settling radius)
    bool any() const { return damping || settling; }
};

/**
 * Judges one pole, continuous (@p tsSeconds = 0) or discrete (through s = ln(z) / Ts, as
 * dampingOf). Tolerances: zeta is compared with a slack of 1e-9, which lets a double real
 * pole found with a round-off imaginary part of about sqrt(eps) |s| ~ 1.5e-8 |s|
 * (1 - zeta ~ 1e-16) count as real, while a pole 4.5e-5 rad off the real axis already breaks
 * zeta = 1; Re s is compared with a relative slack of 1e-9 |sigma|.
 * @throws InvalidInput as dampingOf.
 */
PoleViolation checkPole(std::complex<double> pole, const PoleRequirements& requirements,
                        double tsSeconds = 0.0);

} // namespace xyt
