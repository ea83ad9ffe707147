// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace xyt {

/**
 * The general polynomial black-box model of Ljung (System Identification, 2nd ed., Eq. 4.33):
 *   \f$ A(q)\, y(t) = \frac{B(q)}{F(q)}\, u(t) + \frac{C(q)}{D(q)}\, e(t) \f$
 * with e white. Every polynomial is in ASCENDING powers of q^-1 = z^-1 (A = {1, a1, a2, ...}),
 * A, C, D, F monic; B carries its delay as leading zeros: B = {0, b1, b2, b3} for nk = 1, as
 * PpAxisSettings in core/session/session.h. ARX is (A, B), OE is (B, F), BJ is (B, C, D, F):
 * absent polynomials are {1}. u in volts, y in the output unit (mm for IoData), tsSeconds > 0.
 */
struct PolynomialModel {
    std::vector<double> a{1.0};
    std::vector<double> b{0.0};
    std::vector<double> c{1.0};
    std::vector<double> d{1.0};
    std::vector<double> f{1.0};
    double tsSeconds = 0.0;

    /// The deterministic part's denominator A F (ascending z^-1).
    std::vector<double> inputDenominator() const;
    /// The noise model's denominator A D (ascending z^-1).
    std::vector<double> noiseDenominator() const;
    /// @throws InvalidInput "model.a" ("model.c", "model.d", "model.f") when the polynomial is
    ///         empty, not monic or has a non-finite coefficient, "model.b" when empty or not
    ///         finite, "model.ts" unless tsSeconds > 0.
    void validate() const;
};

/// How an estimation ended. Invalid input is thrown instead (InvalidInput).
enum class EstimationStatus {
    Converged,      ///< a least-squares solution, or the search met its tolerance
    IterationLimit, ///< the search stopped at maxIterations (the estimate is the best seen)
    Cancelled,      ///< the progress callback returned false (the best estimate so far)
    NotPersistentlyExciting, ///< rank-deficient regressor: no unique estimate (see message)
    Failed,                  ///< a non-finite loss or Jacobian: no estimate
};
/// "converged", "iteration-limit", "cancelled", "not-persistently-exciting", "failed".
std::string estimationStatusName(EstimationStatus status);

/// The product of two polynomials (ascending coefficients).
std::vector<double> polynomialProduct(const std::vector<double>& p, const std::vector<double>& q);

/**
 * y = N/D x from rest (zero initial conditions), N and D in ascending z^-1, D[0] = 1 (not
 * checked: internal use by the estimators, which build D monic). x and y may not alias.
 */
void filterMonic(const std::vector<double>& num, const std::vector<double>& den, const double* x,
                 double* y, std::size_t n);

} // namespace xyt
