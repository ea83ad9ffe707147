// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/model/polynomial.h"

#include <string>
#include <vector>

namespace xyt {

/// Above this condition number of the (column-scaled) Sylvester matrix, A and B are taken to
/// share a root: the equation has no solution for a general T (1e12 leaves four digits of a
/// double, less than the four decimals the ARX models are printed with).
inline constexpr double kCommonFactorCondition = 1e12;
/// Above this condition number a near-common factor is reported as a warning: a pole and a zero
/// about 1e-3 apart (relative) give ~1e4, the paper's plants 75 (x-axis) and 15 (y-axis).
inline constexpr double kNearCommonFactorCondition = 1e4;

/// The minimal-degree solution of A F + B G = T (see solveDiophantine).
struct DiophantineSolution {
    Polynomial f; ///< F(z^-1), ascending powers of z^-1, degree nf
    Polynomial g; ///< G(z^-1), ascending powers of z^-1, degree na - 1 (zero when na = 0)
    /// max_i |(A F + B G - T)_i| over all coefficients: the equation's own check.
    double residual = 0.0;
    /// 2-norm condition number of the Sylvester matrix after scaling its A and B column blocks to
    /// unit largest coefficient (so a small plant gain does not look like a common factor).
    double conditionNumber = 0.0;
    std::vector<Diagnostic> warnings;
};

/**
 * Solves the Diophantine (Bezout) equation of pole placement, Patrick, Ishak and Adnan Eq. 8
 * generalized: \f[ A(z^{-1}) F(z^{-1}) + B(z^{-1}) G(z^{-1}) = T(z^{-1}) \f] for the solution with
 * deg G = na - 1 (the minimal one) and deg F = nf = max(nb - 1, nt - na, 0), na = deg A, nb = deg B
 * (delay included), nt = deg T. The coefficient-matching equations form the square Sylvester system
 * E M = D of Patrick, Ishak and Adnan Sec. 5 (na + nf + 1 equations and unknowns); it is solved by
 * SVD (Eigen::JacobiSVD), which also gives the condition number. When B(0) = 0 (a delay) and A(0) =
 * 1, F(0) = T(0): F is monic for a monic T.
 *
 * All polynomials in ascending powers of z^-1 (coefficient i belongs to z^-i).
 *
 * @throws InvalidInput "a" when A is zero or A(0) = 0; "b" when B is zero; "t" when T is zero;
 *         "b" when A and B share a root (Sylvester condition number above kCommonFactorCondition):
 *         the message names the common root in z (pole of A = zero of B) because then
 *         A F + B G = T has no solution (no unique one when T has that root too).
 * A condition number above kNearCommonFactorCondition adds a warning naming the closest
 * pole-zero pair and the condition number.
 */
DiophantineSolution solveDiophantine(const Polynomial& a, const Polynomial& b, const Polynomial& t);

/// The finite nonzero roots in z of p(z^-1) given in ascending powers of z^-1: the roots of
/// z^n p(1/z), n = deg p. A delay (leading zero coefficients, p = z^-d p') only shifts the
/// polynomial and gives no root. Sorted with sortRoots. @throws InvalidInput for the zero
/// polynomial.
std::vector<std::complex<double>> zInverseRoots(const Polynomial& p);

} // namespace xyt
