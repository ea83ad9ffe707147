// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/io_data.h"
#include "core/identification/least_squares.h"
#include "core/identification/polynomial_model.h"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * Output-error model \f$ y(t) = \frac{B(q)}{F(q)} u(t) + e(t) \f$ (MATLAB's `oe` orders):
 * B has nb coefficients after nk delays, F = 1 + f1 q^-1 + ... + f_nf q^-nf.
 */
struct OeOrders {
    int nb = 3;                   ///< >= 1
    int nf = 2;                   ///< >= 0
    int nk = 1;                   ///< >= 0
    std::string toString() const; ///< "OE(3,2,1)"
    /// @throws InvalidInput "nb", "nf", "nk" (nb >= 1, the others >= 0, each at most 100).
    void validate() const;
};

/**
 * Box-Jenkins model \f$ y(t) = \frac{B(q)}{F(q)} u(t) + \frac{C(q)}{D(q)} e(t) \f$
 * (MATLAB's `bj` orders nb, nc, nd, nf, nk); C and D monic of degrees nc and nd.
 */
struct BjOrders {
    int nb = 3;                   ///< >= 1
    int nc = 1;                   ///< >= 0
    int nd = 1;                   ///< >= 0
    int nf = 2;                   ///< >= 0
    int nk = 1;                   ///< >= 0
    std::string toString() const; ///< "BJ(3,1,1,2,1)"
    /// @throws InvalidInput "nb", "nc", "nd", "nf", "nk" as OeOrders::validate.
    void validate() const;
};

/// Search settings of the prediction-error methods.
struct PemOptions {
    /**
     * Iterations (>= 1), tolerances and the progress callback: search.progress gets the
     * fraction done in [0, 1] after each iteration (and exactly 1 at the end), on the caller's
     * thread; returning false cancels (status Cancelled, best estimate so far), as
     * SweepOptions::progress in core/study/design_sweep.h.
     */
    SearchOptions search;
    /// Start here instead of the instrumental-variable estimate (its polynomials must have the
    /// orders' lengths; B with its nk leading zeros).
    std::optional<PolynomialModel> initial;
};

/**
 * A prediction-error estimate. theta = [b_nk .. (nb), c1 .. c_nc, d1 .. d_nd, f1 .. f_nf]
 * (MATLAB's order for bj; OE has no c, d) with parameterNames "b1", "c1", "d1", "f1" (b named by
 * its power of z^-1). model holds B (with nk leading zeros), C, D, F in ascending powers of
 * z^-1 and A = {1}.
 */
struct PemResult {
    EstimationStatus status = EstimationStatus::Failed;
    Diagnostic message;    ///< how the search ended, or why it failed (coded)
    std::string structure; ///< "OE(3,2,1)" or "BJ(3,1,1,2,1)"
    PolynomialModel model;
    PolynomialModel initialModel; ///< where the search started
    std::string initialization;   ///< "instrumental variable", "ARX" or "given"
    std::vector<double> parameters;
    std::vector<std::string> parameterNames;
    /// sigma^2 (J^T J)^-1 with J = de/dtheta at the estimate (d x d, theta's order); empty
    /// (standard deviations NaN, a warning) when J is rank-deficient.
    Eigen::MatrixXd covariance;
    std::vector<double> standardDeviations;
    double noiseVariance = 0.0; ///< sigma^2 = ||e||^2 / (N - d)
    double loss = 0.0;          ///< V = ||e||^2 / N (for FPE and AIC)
    std::size_t samples = 0;    ///< N
    int iterations = 0;
    std::vector<double> lossHistory; ///< V at the start and after every accepted step
    /// One-step prediction errors e(t) = D/C (y - B/F u) at the estimate, from rest, length N.
    std::vector<double> residuals;
    std::vector<Diagnostic> warnings; ///< coded
};

/**
 * Prediction-error estimate of an OE model: minimizes V = (1/N) sum e(t)^2,
 * e = y - B/F u, by Levenberg-Marquardt (levenbergMarquardt in least_squares.h) with the
 * analytic gradient by filtering (Ljung, System Identification, 2nd ed., Sec. 10.2):
 * de/db_k = -q^-k u / F, de/df_k = q^-k (B/F u) / F. The predictor starts from rest (zero
 * initial conditions: detrended data starting at rest). Initial values: the ARX(nf, nb, nk)
 * estimate and one instrumental-variable step with instruments simulated from it (Ljung
 * Sec. 7.6), whichever has the smaller OE loss. Unstable F roots are reflected into the unit
 * circle at the start and after every step.
 * @throws InvalidInput from validateIoData, OeOrders::validate, "max_iterations" (< 1),
 *         "initial" (wrong lengths), "data" when N < n0 + d + 1 with
 *         n0 = max(nf, nk + nb - 1) and d the number of parameters (the message names the
 *         orders).
 */
PemResult estimateOe(const IoData& data, const OeOrders& orders, const PemOptions& options = {});

/**
 * Prediction-error estimate of a BJ model: e = D/C (y - B/F u), gradients
 * de/db_k = -q^-k D/(C F) u, de/df_k = q^-k D/(C F) (B/F u), de/dc_k = -q^-k e / C,
 * de/dd_k = q^-k (y - B/F u) / C (Ljung Sec. 10.3). Initial B, F as estimateOe's; D from an
 * AR(nd) least-squares fit to y - B/F u; C = 1. Unstable roots of F, C and D are reflected.
 * @throws InvalidInput as estimateOe, with "nc", "nd".
 */
PemResult estimateBj(const IoData& data, const BjOrders& orders, const PemOptions& options = {});

} // namespace xyt
