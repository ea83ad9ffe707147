// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"

#include <complex>
#include <vector>

namespace xyt {

/**
 * The frequency response of a transfer function G on a grid of frequencies (rad/s):
 * \f$ G(j\omega) \f$ (continuous) or \f$ G(e^{j\omega T_s}) \f$ (discrete, up to the Nyquist
 * frequency \f$ \pi/T_s \f$).
 *
 * Phase convention (unwrapped, degrees): continuous in omega and anchored at the
 * low-frequency asymptote. With k = (poles minus zeros at s = 0, or at z = 1 for a discrete
 * system) and c the remaining low-frequency gain, G ~ c (j omega)^-k (discrete: c (e^{j omega Ts}
 * - 1)^-k) as omega -> 0, and the phase tends to -90 k degrees when c > 0 and to -90 k - 180
 * degrees when c < 0. The unwrapping does not depend on the grid: the phase is the sum of the
 * continuous angle of every pole and zero factor (each has no branch cut on the positive
 * frequency axis), and the principal argument of the directly evaluated value is moved by the
 * multiple of 360 degrees that brings it nearest to that sum. A pole or zero on the
 * frequency axis itself (undamped) makes the phase jump by -180 or +180 degrees per order
 * there; the value exactly at such a frequency is infinite or zero.
 */
struct FrequencyResponse {
    double tsSeconds = 0.0;                  ///< 0: continuous, > 0: discrete
    std::vector<double> omegaRadPerSec;      ///< increasing
    std::vector<std::complex<double>> value; ///< G at each frequency
    std::vector<double> magnitudeDb;         ///< 20 log10 |G| (-inf at a zero, +inf at a pole)
    std::vector<double> phaseDeg;            ///< unwrapped, see above
    int lowFrequencyIntegrators = 0;         ///< k: the phase starts at -90 k (or -90 k - 180)
};

/**
 * G at the given frequencies, in the given order.
 * No allocation per frequency beyond the output vectors: the factors used for the phase are
 * computed once.
 * @throws InvalidInput "omega" for a negative or non-finite frequency, or (discrete) above the
 *         Nyquist frequency pi/Ts (with a relative allowance of 1e-12 for round-off).
 */
FrequencyResponse frequencyResponse(const TransferFunction& g,
                                    const std::vector<double>& omegaRadPerSec);

/// Options of the adaptive grid (adaptiveFrequencyResponse).
struct FrequencyGridOptions {
    /// The range, rad/s. 0 = automatic: one decade below the lowest and one above the highest
    /// characteristic frequency (|r| of each nonzero pole and zero r, or |ln r|/Ts for a
    /// discrete one), rounded out to whole decades; discrete loops always end at pi/Ts.
    double omegaMinRadPerSec = 0.0;
    double omegaMaxRadPerSec = 0.0;
    /// The starting grid, log-spaced.
    int pointsPerDecade = 10;
    /// An interval is halved (in log frequency) while its ends differ by more than this ...
    double maxMagnitudeStepDb = 1.0;
    /// ... or by more than this in phase ...
    double maxPhaseStepDeg = 5.0;
    /// ... unless its ends are closer than this ratio (a jump at an undamped pole or zero cannot
    /// be resolved by halving) ...
    double minFrequencyRatio = 1.0 + 1e-9;
    /// ... or the grid holds this many points.
    int maxPoints = 5000;
    /// Frequencies that must be in the grid (say the crossovers of stabilityMargins); those out
    /// of range are ignored.
    std::vector<double> extraFrequencies;
};

/**
 * G on an adaptive log grid: the starting grid plus the natural frequency of every pole and
 * zero in range (and omega_n (1 -+ zeta) for damping ratios below 0.5, so that a sharp
 * resonance or anti-resonance is never stepped over), refined by halving every interval whose
 * ends differ by more than the allowed magnitude or phase step.
 * @throws InvalidInput "omegaMin"/"omegaMax" for a bad range (negative, not finite,
 *         min >= max, a discrete max above pi/Ts), "pointsPerDecade", "maxMagnitudeStepDb",
 *         "maxPhaseStepDeg", "minFrequencyRatio", "maxPoints" when not positive (maxPoints >= 2).
 */
FrequencyResponse adaptiveFrequencyResponse(const TransferFunction& g,
                                            const FrequencyGridOptions& options = {});

/// @p points frequencies log-spaced from @p omegaMin to @p omegaMax inclusive.
/// @throws InvalidInput "omegaMin"/"omegaMax" unless 0 < min < max finite, "points" unless >= 2.
std::vector<double> logFrequencyGrid(double omegaMinRadPerSec, double omegaMaxRadPerSec,
                                     int points);

/// The characteristic frequencies of the nonzero poles and zeros (|r|, or |ln r|/Ts for a
/// discrete system), sorted, duplicates kept. Used for the automatic range.
std::vector<double> characteristicFrequencies(const TransferFunction& g);

/**
 * Splits the roots at the low-frequency end of the boundary off a polynomial: p = x^k q
 * (continuous: exact zero coefficients) or p = (z - 1)^k q (discrete: divided by z - 1 while
 * |p(1)| <= 1e-10 sum |p_i|, so that integrators typed as (z - 1) products count even though
 * their computed roots scatter by sqrt(eps)). Returns k and sets @p rest to q.
 */
int splitLowFrequencyRoots(const Polynomial& p, bool discrete, Polynomial& rest);

/// The point of the stability boundary at a frequency: j omega, or e^{j omega Ts} when
/// tsSeconds > 0.
std::complex<double> boundaryPoint(double omegaRadPerSec, double tsSeconds);

/**
 * Continuous phase of a fixed transfer function: the factors are computed once, then
 * phaseRad(omega, value) costs one atan2 per pole and zero, without allocation. Used by
 * frequencyResponse, the margins and the loop responses; see FrequencyResponse for the
 * convention.
 */
class ContinuousPhase {
public:
    explicit ContinuousPhase(const TransferFunction& g);
    /// The unwrapped phase in radians at omega, given the directly evaluated value G there.
    double phaseRad(double omegaRadPerSec, std::complex<double> value) const;
    int lowFrequencyIntegrators() const { return integrators_; }

private:
    double factorSum(double omegaRadPerSec) const;
    double ts_ = 0.0;
    int integrators_ = 0; ///< poles minus zeros at s = 0 (z = 1)
    double constantRad_ = 0.0;
    double offsetRad_ = 0.0;
    std::vector<std::complex<double>> zeros_; ///< without those at s = 0 (z = 1)
    std::vector<std::complex<double>> poles_;
};

} // namespace xyt
