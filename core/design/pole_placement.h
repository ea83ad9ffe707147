// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * A discrete RST pole-placement design for an ARX axis model A(z^-1) y = B(z^-1) u
 * (Patrick, Ishak and Adnan Sec. 5, Fig. 9):
 * \f[ F(z^{-1}) u(k) = K_f r(k) - G(z^{-1}) y(k), \qquad A F + B G = T, \qquad
 *     K_f = T(1) / B(1), \f]
 * so the closed loop is \f$ y/r = K_f B(z^{-1}) / T(z^{-1}) \f$ (paper Eq. 7 with Eq. 8) with
 * unity DC gain. All polynomials in ascending powers of z^-1.
 */
struct PolePlacementDesign {
    Polynomial a; ///< A(z^-1) as used: monic (A(0) = 1)
    Polynomial b; ///< B(z^-1) as used (divided by the typed A(0) when that was not 1)
    Polynomial t; ///< T(z^-1), T(0) = 1: the desired closed-loop denominator
    double tsSeconds = 0.0;
    int delay = 0;         ///< d >= 1: the number of leading zero coefficients of B
    Polynomial f;          ///< F(z^-1), degree max(nb - 1, nt - na); F(0) = 1 up to round-off
    Polynomial g;          ///< G(z^-1), degree na - 1
    double kf = 0.0;       ///< T(1) / B(1) (paper Eq. 7, Kf = sum T / sum B)
    double residual = 0.0; ///< max |coefficient of A F + B G - T|
    double conditionNumber = 0.0; ///< of the scaled Sylvester matrix (see solveDiophantine)
    Polynomial closedLoopNum;     ///< Kf B(z^-1)
    Polynomial closedLoopDen;     ///< T(z^-1)
    std::vector<std::complex<double>> plantPoles; ///< roots of A in z
    std::vector<std::complex<double>> plantZeros; ///< nonzero roots of B in z
    std::vector<Diagnostic> warnings;

    /// Kf B / T as a discrete transfer function in z (sample time tsSeconds).
    TransferFunction closedLoop() const;
};

/**
 * Designs the RST loop by solving A F + B G = T (solveDiophantine).
 * A typed with A(0) != 1 is normalized (A and B divided by A(0): the same plant), with a warning.
 * @throws InvalidInput "ts" unless ts > 0; "a" for a zero A or A(0) = 0; "b" when B(0) != 0
 *         (no delay: the loop would be algebraic), when B(1) = 0 (a zero at z = 1, no
 *         steady-state gain), when B(1) is so small that Kf = T(1)/B(1) overflows, or when A
 *         and B share a root (the message names it); "t" unless
 *         T(0) = 1 or when a root of T is not strictly inside the unit circle.
 */
PolePlacementDesign designPolePlacement(const Polynomial& a, const Polynomial& b,
                                        const Polynomial& t, double tsSeconds);

/// A named axis model with its design target (Patrick, Ishak and Adnan Eq. 1, 3, 9, 10).
struct PolePlacementPreset {
    std::string name;
    std::string description;
    Polynomial a;
    Polynomial b;
    Polynomial t;
    double tsSeconds = 0.07;
};

/// "x-axis" (Eq. 1) and "y-axis" (Eq. 3), both with T = 1 - 0.2 z^-1 and Ts = 70 ms.
std::vector<PolePlacementPreset> polePlacementPresets();
std::optional<PolePlacementPreset> findPolePlacementPreset(const std::string& name);

} // namespace xyt
