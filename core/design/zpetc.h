// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/model/polynomial.h"

#include <complex>
#include <vector>

namespace xyt {

/// Default ZPETC cancellation margin: zeros with |z| < 1 - 0.05 are cancelled. A zero just inside
/// the unit circle would become a barely damped feedforward pole (|z| = 0.95 decays by 1/e only
/// after 20 samples, and rings at Nyquist when negative), so such zeros are treated like NMP ones.
inline constexpr double kDefaultZpetcMargin = 0.05;

/// One zero of the closed-loop numerator, in z.
struct ZpetcZero {
    std::complex<double> z;
    bool cancelled = false; ///< in B+ (inverted by the feedforward) or in B- (phase-compensated)
};

/**
 * Tomizuka's zero phase error tracking controller for the closed loop
 * \f$ G_c = z^{-d} B_c(z^{-1}) / A_c(z^{-1}) \f$ (Patrick, Ishak and Adnan Eq. 5-6, Fig. 6), with
 * \f$ z^{-d} B_c = K_f B \f$ and \f$ A_c = T \f$ from the pole-placement design:
 * \f[ B_c = B_c^+ B_c^-, \qquad
 *     u_{ff}(k) = \frac{A_c(z^{-1})\, B_c^-(z)}{B_c^+(z^{-1})\, [B_c^-(1)]^2}\, r(k + d). \f]
 * B+ holds the zeros with |z| < 1 - margin and is monic (B+(0) = 1); B- holds the others and the
 * gain. With s = deg B-, \f$ B_c^-(z) = z^s B^{-*}(z^{-1}) \f$ where B-* is B- with its
 * coefficients reversed, so the feedforward is the causal filter
 * \f[ u_{ff}(k) = \frac{N_{ff}(z^{-1})}{D_{ff}(z^{-1})}\, r(k + p), \quad
 *     N_{ff} = A_c B^{-*}, \; D_{ff} = B^+ [B^-(1)]^2, \; p = d + s, \f]
 * fed with the reference previewed p samples. The overall response is the zero-phase FIR
 * \f$ y(k) = \sum_j h_j r(k + s - j) \f$, \f$ h = B^- B^{-*} / [B^-(1)]^2 \f$ (paper Fig. 8),
 * real and positive on the unit circle with unity DC gain.
 * All polynomials in ascending powers of z^-1.
 */
struct ZpetcDesign {
    int delay = 0; ///< d
    double margin = kDefaultZpetcMargin;
    Polynomial bPlus;             ///< B+(z^-1), B+(0) = 1
    Polynomial bMinus;            ///< B-(z^-1), with the gain: z^-d B+ B- = Kf B
    std::vector<ZpetcZero> zeros; ///< all zeros of Kf B in z, sorted
    double gainFactor = 0.0;      ///< [B-(1)]^2, the paper's low-frequency scaling factor
    int previewSteps = 0;         ///< p = d + deg B-: how far ahead the reference is read
    Polynomial feedforwardNum;    ///< N_ff = A_c B-*
    Polynomial feedforwardDen;    ///< D_ff = B+ [B-(1)]^2
    Polynomial overallFir;        ///< h = B- B-* / [B-(1)]^2, applied to r(k + deg B-)
};

/**
 * Factors the closed loop of @p loop and builds the ZPETC.
 * @throws InvalidInput "margin" unless 0 <= margin < 1; "b" when B-(1) = 0 (an uncancelled zero
 *         at z = 1: no low-frequency gain to normalize).
 */
ZpetcDesign designZpetc(const PolePlacementDesign& loop, double margin = kDefaultZpetcMargin);

/// The overall reference-to-output response at each frequency, without feedforward
/// (Kf B / T, i.e. r drives the loop) and with the ZPETC ahead of the loop (z^p N_ff/D_ff times
/// Kf B / T, computed from the two filters, not from the FIR shortcut).
struct ZpetcFrequencyResponse {
    std::vector<double> omegaRadPerSec;
    std::vector<double> gainWithoutFf; ///< |H(e^{j w Ts})|
    std::vector<double> gainWithFf;
    std::vector<double> phaseWithoutFfRad; ///< arg H, in (-pi, pi]
    std::vector<double> phaseWithFfRad;    ///< ~0 at every frequency (zero phase error)
    /// Frequencies asked for but left out of the vectors above: a pole of the loop or of the
    /// feedforward lies on the unit circle there, so the response is not finite.
    std::vector<double> omittedOmegaRadPerSec;
};

/// @throws InvalidInput "omega" for a negative or non-finite frequency.
ZpetcFrequencyResponse zpetcFrequencyResponse(const PolePlacementDesign& loop,
                                              const ZpetcDesign& zpetc,
                                              const std::vector<double>& omegaRadPerSec);

/// @p points frequencies log-spaced from 1e-3 of the Nyquist frequency pi/Ts up to it.
/// @throws InvalidInput "ts" unless ts > 0, "points" unless points >= 2.
std::vector<double> nyquistLogGrid(double tsSeconds, int points);

} // namespace xyt
