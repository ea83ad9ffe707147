// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/io_data.h"
#include "core/identification/polynomial_model.h"
#include "core/model/diagnostic.h"

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/**
 * Orders of the ARX model
 *   \f$ A(q) y(t) = B(q) u(t) + e(t) \f$,
 *   \f$ A = 1 + a_1 q^{-1} + \dots + a_{na} q^{-na} \f$,
 *   \f$ B = b_{nk} q^{-nk} + \dots + b_{nk+nb-1} q^{-(nk+nb-1)} \f$
 * (MATLAB's convention: nb coefficients, nk samples of dead time; Patrick, Ishak and Adnan's ARX231
 * is na = 2, nb = 3, nk = 1). GNU Octave control 3.4's `arx(..., 'nk', 0)` is this nk = 1: see
 * tests/data/README.md.
 */
struct ArxOrders {
    int na = 2; ///< >= 0
    int nb = 3; ///< >= 1
    int nk = 1; ///< >= 0
    /// "ARX(2,3,1)"
    std::string toString() const;
    /// @throws InvalidInput "na" (< 0), "nb" (< 1), "nk" (< 0), each at most 100.
    void validate() const;
};

/**
 * An ARX estimate. Parameters theta = [a1 .. a_na, b_nk .. b_{nk+nb-1}] (parameterNames
 * "a1", ..., "b1", ..., a b named by its power of z^-1). The model's A = {1, a1, .., a_na} and
 * B = {0 (nk times), b_nk, ...} in ascending powers of z^-1, as PpAxisSettings
 * (core/session/session.h): ARX(2,3,1) gives A = {1, a1, a2}, B = {0, b1, b2, b3}.
 */
struct ArxResult {
    EstimationStatus status = EstimationStatus::Failed; ///< Converged or NotPersistentlyExciting
    Diagnostic message; ///< why a status other than Converged, e.g. "input not persistently
                        ///< exciting for nb = 3" (coded)
    ArxOrders orders;
    PolynomialModel model;
    std::vector<double> parameters;
    std::vector<std::string> parameterNames;
    /// sigma^2 (Phi^T Phi)^-1 (d x d, theta's order), computed from the QR factor R.
    Eigen::MatrixXd covariance;
    std::vector<double> standardDeviations; ///< sqrt of the covariance's diagonal
    /// sigma^2 = ||e||^2 / (rows - d): the unbiased noise-variance estimate (output unit^2).
    double noiseVariance = 0.0;
    /// V = ||e||^2 / rows: the loss that FPE and AIC use (informationCriteria).
    double loss = 0.0;
    std::size_t rows = 0;       ///< regressor rows: N - max(na, nk + nb - 1)
    std::size_t firstRow = 0;   ///< the sample index of the first regressor row
    Eigen::Index rank = 0;      ///< rank of the scaled regressor by QR
    double rankThreshold = 0.0; ///< the relative pivot threshold that rank used
    /// Equation errors e(t) = A y - B u for t >= firstRow (0 before it), length N.
    std::vector<double> residuals;
    std::vector<Diagnostic> warnings; ///< coded
};

/**
 * Least-squares ARX estimate: Phi theta = y over the rows t = n0 .. N-1,
 * n0 = max(na, nk + nb - 1), row [-y(t-1) .. -y(t-na), u(t-nk) .. u(t-nk-nb+1)], solved by
 * column-pivoting Householder QR of the column-scaled regressor (linearLeastSquares) with the
 * relative rank threshold @p rankThreshold. A rank-deficient regressor is a status:
 * NotPersistentlyExciting with "input not persistently exciting for nb = 3" when the input block
 * alone is deficient, else a message naming the orders (noise-free data of a lower order).
 * @throws InvalidInput from validateIoData and ArxOrders::validate; "data" when N is too few for
 *         the orders ("... samples are too few for ARX(2,3,1): at least 9 needed").
 */
ArxResult estimateArx(const IoData& data, const ArxOrders& orders, double rankThreshold = 1e-10);

} // namespace xyt
