// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/io_data.h"
#include "core/identification/polynomial_model.h"
#include "core/model/diagnostic.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace xyt {

/**
 * The two numerical engines the estimators share: a rank-revealing linear least-squares solve
 * with its covariance factor, and a damped Gauss-Newton (Levenberg-Marquardt) search for
 * nonlinear least squares. Both work on scaled columns (each column of the regressor or
 * Jacobian divided by its 2-norm), so that the rank threshold and the damping do not depend on
 * the units of u and y.
 */

/// Default rank threshold of linearLeastSquares: a pivot of the scaled QR below 1e-10 times the
/// largest one counts as zero (a condition number of the scaled regressor above 1e10).
inline constexpr double kDefaultRankThreshold = 1e-10;

/**
 * min_theta || y - Phi theta ||_2 by Eigen's column-pivoting Householder QR of the column-scaled
 * Phi (never the normal equations). rank is QR's rank with threshold @p rankThreshold (relative
 * to the largest pivot). When the rank is full, inverseGram = (Phi^T Phi)^-1 computed from R as
 * S^-1 P R^-1 R^-T P^T S^-1 (S the column scaling, P the pivoting); otherwise theta is QR's
 * basic solution and inverseGram is empty.
 */
struct LinearLeastSquares {
    Eigen::VectorXd theta;
    Eigen::MatrixXd inverseGram;
    Eigen::Index rank = 0;
    bool fullRank() const { return inverseGram.size() > 0; }
};
/// @p phi is taken by value, scaled and factored in place: move a regressor in that is not
/// needed afterwards (no copy of a 100,000-row regressor is made then).
LinearLeastSquares linearLeastSquares(Eigen::MatrixXd phi, const Eigen::VectorXd& y,
                                      double rankThreshold = kDefaultRankThreshold);

/// One nonlinear least-squares problem: minimize V(theta) = mean(e(theta)^2).
struct NonlinearProblem {
    /**
     * Residuals e(theta) (resized by the callee) and, when @p jacobian is not null, de/dtheta
     * (N x d). Returns false when they are not finite (the step is then rejected).
     */
    std::function<bool(const Eigen::VectorXd& theta, Eigen::VectorXd& residuals,
                       Eigen::MatrixXd* jacobian)>
        evaluate;
    /// Maps a trial theta back into the admissible set (e.g. reflects unstable roots); may be
    /// empty.
    std::function<void(Eigen::VectorXd& theta)> project;
};

/// Stopping rules and progress of the search.
struct SearchOptions {
    int maxIterations = 100;
    /// Converged when an accepted step lowers V by less than this fraction of V...
    double relativeLossTolerance = 1e-10;
    /// ...or moves theta by less than this fraction of |theta| (2-norms), or when no damping up
    /// to 1e12 lowers V (a minimum to working precision).
    double relativeStepTolerance = 1e-10;
    /**
     * Called after every iteration with the fraction of maxIterations done, and with exactly 1
     * at the end. Return false to cancel: the result says Cancelled and holds the best estimate
     * so far. May be empty. Runs on the caller's thread.
     */
    std::function<bool(double fraction)> progress;
};

/// The outcome of levenbergMarquardt.
struct SearchOutcome {
    EstimationStatus status = EstimationStatus::Failed;
    Eigen::VectorXd theta;
    Eigen::VectorXd residuals;
    Eigen::MatrixXd jacobian;        ///< at theta
    double loss = 0.0;               ///< V = mean(e^2) at theta
    int iterations = 0;              ///< accepted steps
    std::vector<double> lossHistory; ///< V at the start and after every accepted step
    Diagnostic message;              ///< how the search ended (coded)
};

/**
 * Levenberg-Marquardt with Marquardt's column scaling: each iteration solves
 * [J S^-1; sqrt(lambda) I] dx = -[e; 0] by Householder QR and steps theta += S^-1 dx (then
 * project); a step that lowers V is accepted and lambda divided by 10, otherwise lambda is
 * multiplied by 10 and the step tried again. Starts at lambda = 1e-4. A loss at or below
 * @p exactFitLoss counts as an exact fit (converged): below it the changes of V are round-off
 * (the estimators pass (1e-13 rms(y))^2, see exactFitLoss()).
 */
SearchOutcome levenbergMarquardt(const NonlinearProblem& problem, const Eigen::VectorXd& theta0,
                                 const SearchOptions& options, double exactFitLoss = 0.0);

/// Copies the search summary (status, message, iterations, loss history) of @p r into an
/// estimator's result, which has members of those names.
template <class Result> void takeSearchSummary(const SearchOutcome& r, Result& out) {
    out.status = r.status;
    out.message = r.message;
    out.iterations = r.iterations;
    out.lossHistory = r.lossHistory;
}

/// (1e-13 rms(y))^2: a mean squared residual this small is round-off of the data's magnitude.
double exactFitLoss(const std::vector<double>& y);

/**
 * sigma^2 (J^T J)^-1 and its diagonal's square roots, from the final Jacobian (through
 * linearLeastSquares' R). When J is rank-deficient the covariance is left empty, the standard
 * deviations NaN and a warning is added.
 */
void parameterCovariance(const Eigen::MatrixXd& jacobian, double sigma2,
                         Eigen::MatrixXd& covariance, std::vector<double>& standardDeviations,
                         std::vector<Diagnostic>& warnings);

/// @throws InvalidInput "data.u" / "data.y" (empty, different lengths, not finite),
///         "data.ts" unless tsSeconds > 0.
void validateIoData(const IoData& data);

/// Reflects the roots of a monic polynomial in z^-1 (ascending) that lie outside the unit
/// circle to 1 / conj(root); returns true when it changed anything.
bool reflectUnstableRoots(std::vector<double>& monic);

/// The largest root magnitude of a monic polynomial in z^-1 (0 for a constant).
double maxRootMagnitude(const std::vector<double>& monic);

} // namespace xyt
