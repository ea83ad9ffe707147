// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"

#include <limits>
#include <string>
#include <vector>

namespace xyt {

/// A phase crossover: L(j omega) real and negative. Scaling the loop by gainFactor puts -1 on
/// the Nyquist curve there (the closed loop of gainFactor L has a pole on the boundary).
struct GainMarginCrossing {
    double omegaRadPerSec = 0.0;
    double gainFactor = 0.0; ///< -1 / L(j omega) > 0
    double gainDb = 0.0; ///< 20 log10 gainFactor (negative: the loop tolerates a gain decrease of
                         ///< that much only)
};

/// A gain crossover: |L(j omega)| = 1.
struct PhaseMarginCrossing {
    double omegaRadPerSec = 0.0;
    /// 180 + arg L(j omega) in degrees, wrapped to (-180, 180] (MATLAB's convention; Octave's
    /// margin reports 180 + arg L in (0, 360], the same angle for margins up to 180).
    double phaseMarginDeg = 0.0;
    /// The smallest delay tau >= 0 with e^{-j omega tau} L(j omega) = -1:
    /// ((phaseMarginDeg mod 360) in [0, 360)) pi/180 / omega, seconds.
    double delayMarginSeconds = 0.0;
    /// delayMarginSeconds / Ts for a discrete loop (a real number of samples); NaN when
    /// continuous.
    double delayMarginSamples = std::numeric_limits<double>::quiet_NaN();
};

/**
 * Stability margins and closed-loop peaks of the unity negative feedback loop around L,
 * computed from polynomial roots, not read off a frequency grid.
 *
 * Continuous L = N/D: with N(j omega) = N_e(u) + j omega N_o(u), u = omega^2 (same for D), the
 * gain crossovers are the positive real roots u of |N|^2 - |D|^2 = N_e^2 + u N_o^2 - D_e^2 -
 * u D_o^2 and the phase crossovers those of Im(N(j omega) D(-j omega)) / omega =
 * N_o D_e - N_e D_o with Re(L) < 0; each root is then refined by Newton steps on
 * log|L(j omega)| (or arg(-L(j omega))) with the analytic derivative, kept while the residual
 * decreases. omega = 0 is a phase crossover when L(0) is finite and negative. Before the roots
 * are taken, s is scaled by a power of two near the geometric mean of the nonzero pole and zero
 * moduli (conditioning).
 *
 * Discrete L(z): the bilinear substitution z = (1 + w)/(1 - w) maps the unit circle exactly
 * onto the imaginary axis w = j nu with nu = tan(omega Ts / 2); N and D times (1 - w)^n
 * (n = deg D) are polynomials in w, solved as above, and omega = 2 atan(nu) / Ts; the
 * refinement is done on L(e^{j omega Ts}) itself. z = -1 (omega = pi/Ts) is a phase crossover
 * when L(-1) is finite and negative.
 *
 * Conventions:
 * - Every crossing is listed (like MATLAB's allmargin), by increasing frequency.
 * - The gain margin reported is the one closest to 0 dB (the smallest |log gainFactor|): for a
 *   conditionally stable loop, which tolerates gain changes only within a band, that is the
 *   nearer edge of the band, below 1 (negative dB) if a gain decrease destabilizes first. The
 *   nearest factors above and below 1 are given too. No phase crossover: +inf (factor and dB),
 *   frequency NaN.
 * - The phase margin reported is the one of smallest magnitude; no gain crossover: +inf,
 *   frequency NaN. The delay margin is the smallest over the gain crossovers (+inf when none).
 *   Margins are given whether or not the closed loop is stable (see closedLoopStable: for an
 *   unstable closed loop they are not robustness measures).
 * - Ms = max over omega of |S|, S = 1/(1 + L), and Mt = max |T|, T = L/(1 + L), from the
 *   stationary points (roots of A'B - AB' for |S|^2 = A(u)/B(u)) plus omega = 0 and the end
 *   (omega -> inf, or pi/Ts); +inf when the closed loop has a pole on the boundary. These are
 *   peaks of the frequency response, computed also for an unstable closed loop.
 * - Bandwidth: the lowest frequency at which |T| falls to |T(0)|/sqrt(2) (-3 dB from the DC
 *   gain, MATLAB's bandwidth); +inf when it never does (up to pi/Ts for a discrete loop), NaN
 *   when T(0) is zero or infinite.
 */
struct StabilityMargins {
    double tsSeconds = 0.0;
    std::vector<GainMarginCrossing> gainMargins;
    std::vector<PhaseMarginCrossing> phaseMargins;

    double gainMarginFactor = std::numeric_limits<double>::infinity();
    double gainMarginDb = std::numeric_limits<double>::infinity();
    double gainMarginOmegaRadPerSec = std::numeric_limits<double>::quiet_NaN();
    /// The smallest factor above 1 (+inf when none): the gain increase the loop tolerates.
    double upperGainMarginFactor = std::numeric_limits<double>::infinity();
    /// The largest factor below 1 (0 when none): the gain decrease it tolerates.
    double lowerGainMarginFactor = 0.0;

    double phaseMarginDeg = std::numeric_limits<double>::infinity();
    double phaseMarginOmegaRadPerSec = std::numeric_limits<double>::quiet_NaN();

    double delayMarginSeconds = std::numeric_limits<double>::infinity();
    /// Discrete loops: in samples (delayMarginSeconds / Ts); NaN for continuous loops.
    double delayMarginSamples = std::numeric_limits<double>::quiet_NaN();
    double delayMarginOmegaRadPerSec = std::numeric_limits<double>::quiet_NaN();

    double peakSensitivity = std::numeric_limits<double>::quiet_NaN(); ///< Ms
    double peakSensitivityOmegaRadPerSec = std::numeric_limits<double>::quiet_NaN();
    double peakComplementarySensitivity = std::numeric_limits<double>::quiet_NaN(); ///< Mt
    double peakComplementarySensitivityOmegaRadPerSec = std::numeric_limits<double>::quiet_NaN();
    double bandwidthRadPerSec = std::numeric_limits<double>::quiet_NaN();

    /// All roots of D + N strictly inside the stable region.
    bool closedLoopStable = false;
    std::vector<Diagnostic> warnings;
};

/**
 * @throws InvalidInput "num" when L is improper (more zeros than poles) and "den" when D + N
 *         is zero (L = -1).
 */
StabilityMargins stabilityMargins(const TransferFunction& openLoop);

/**
 * The bilinear image of a discrete polynomial: p((1 + w)/(1 - w)) (1 - w)^n, for n >= deg p.
 * The unit circle z = e^{j theta} maps to w = j tan(theta/2).
 */
Polynomial bilinearToW(const Polynomial& p, int n);

} // namespace xyt
