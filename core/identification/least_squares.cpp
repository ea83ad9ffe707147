// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/least_squares.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/polynomial.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace xyt {

namespace {

/// Column 2-norms, with 1 for an all-zero column (it then only meets the damping or the rank
/// test, never a division by zero).
Eigen::VectorXd columnScales(const Eigen::MatrixXd& m) {
    Eigen::VectorXd s(m.cols());
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
        const double n = m.col(j).norm();
        s(j) = n > 0.0 ? n : 1.0;
    }
    return s;
}

} // namespace

LinearLeastSquares linearLeastSquares(Eigen::MatrixXd phi, const Eigen::VectorXd& y,
                                      double rankThreshold) {
    LinearLeastSquares out;
    const Eigen::Index d = phi.cols();
    const Eigen::VectorXd s = columnScales(phi);
    phi *= s.cwiseInverse().asDiagonal(); // the scaled regressor, in place
    // In place: the QR overwrites phi with its factors (Eigen's Inplace decomposition).
    Eigen::ColPivHouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(phi);
    qr.setThreshold(rankThreshold);
    out.rank = qr.rank();
    out.theta = qr.solve(y).cwiseQuotient(s);
    if (out.rank == d && d > 0) {
        // (Phi^T Phi)^-1 = S^-1 P R^-1 R^-T P^T S^-1, from the triangular factor only.
        const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(d, d).triangularView<Eigen::Upper>();
        const Eigen::MatrixXd rInv =
            r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(d, d));
        const Eigen::MatrixXd m = qr.colsPermutation() * rInv;
        out.inverseGram =
            s.cwiseInverse().asDiagonal() * (m * m.transpose()) * s.cwiseInverse().asDiagonal();
    }
    return out;
}

SearchOutcome levenbergMarquardt(const NonlinearProblem& problem, const Eigen::VectorXd& theta0,
                                 const SearchOptions& options, double exactFitLoss) {
    SearchOutcome out;
    out.theta = theta0;
    if (problem.project)
        problem.project(out.theta);
    if (!problem.evaluate(out.theta, out.residuals, &out.jacobian) || !out.jacobian.allFinite()) {
        out.message = makeDiagnostic("ident_search_not_finite_initial");
        return out;
    }
    const Eigen::Index d = out.theta.size();
    const double n = static_cast<double>(out.residuals.size());
    out.loss = out.residuals.squaredNorm() / n;
    out.lossHistory.push_back(out.loss);
    out.status = EstimationStatus::IterationLimit;
    double lambda = 1e-4;
    Eigen::VectorXd trialResiduals;
    for (int iter = 0; iter < options.maxIterations; ++iter) {
        if (options.progress &&
            !options.progress(static_cast<double>(iter) / options.maxIterations)) {
            out.status = EstimationStatus::Cancelled;
            out.message =
                makeDiagnostic("ident_search_cancelled", {std::to_string(out.iterations)});
            return out;
        }
        if (out.loss <= exactFitLoss) {
            out.status = EstimationStatus::Converged;
            out.message = makeDiagnostic("ident_search_exact_fit");
            break;
        }
        // QR of the scaled Jacobian once per iteration; each damping trial then solves the
        // small system [R; sqrt(lambda) I] dx = -[Q^T e; 0].
        const Eigen::VectorXd s = columnScales(out.jacobian);
        const Eigen::MatrixXd scaled = out.jacobian * s.cwiseInverse().asDiagonal();
        Eigen::HouseholderQR<Eigen::MatrixXd> qr(scaled);
        const Eigen::Index rows = std::min<Eigen::Index>(scaled.rows(), d);
        Eigen::MatrixXd r = Eigen::MatrixXd::Zero(d, d);
        r.topRows(rows) = qr.matrixQR().topRows(rows).triangularView<Eigen::Upper>();
        Eigen::VectorXd g = Eigen::VectorXd::Zero(d);
        g.head(rows) = (qr.householderQ().transpose() * out.residuals).head(rows);
        bool accepted = false;
        Eigen::VectorXd trialTheta;
        Eigen::VectorXd step;
        double trialLoss = 0.0;
        while (lambda <= 1e12) {
            Eigen::MatrixXd aug(2 * d, d);
            aug.topRows(d) = r;
            aug.bottomRows(d) = std::sqrt(lambda) * Eigen::MatrixXd::Identity(d, d);
            Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * d);
            rhs.head(d) = -g;
            step = aug.householderQr().solve(rhs).cwiseQuotient(s);
            trialTheta = out.theta + step;
            if (problem.project)
                problem.project(trialTheta);
            if (trialTheta.allFinite() && problem.evaluate(trialTheta, trialResiduals, nullptr)) {
                trialLoss = trialResiduals.squaredNorm() / n;
                if (std::isfinite(trialLoss) && trialLoss < out.loss) {
                    accepted = true;
                    break;
                }
            }
            lambda *= 10.0;
        }
        if (!accepted) {
            out.status = EstimationStatus::Converged;
            out.message = makeDiagnostic("ident_search_no_damped_step");
            break;
        }
        const double lossDrop = (out.loss - trialLoss) / out.loss;
        const double stepSize = (trialTheta - out.theta).norm() /
                                std::max(out.theta.norm(), std::numeric_limits<double>::min());
        Eigen::MatrixXd jacobian;
        Eigen::VectorXd residuals;
        if (!problem.evaluate(trialTheta, residuals, &jacobian) || !jacobian.allFinite()) {
            out.status = EstimationStatus::Failed;
            out.message = makeDiagnostic("ident_search_gradient_not_finite");
            break;
        }
        out.theta = trialTheta;
        out.residuals = std::move(residuals);
        out.jacobian = std::move(jacobian);
        out.loss = out.residuals.squaredNorm() / n;
        out.lossHistory.push_back(out.loss);
        ++out.iterations;
        lambda = std::max(lambda / 10.0, 1e-12);
        if (lossDrop < options.relativeLossTolerance || stepSize < options.relativeStepTolerance) {
            out.status = EstimationStatus::Converged;
            out.message = makeDiagnostic(lossDrop < options.relativeLossTolerance
                                             ? "ident_search_loss_tolerance"
                                             : "ident_search_step_tolerance");
            break;
        }
    }
    if (out.status == EstimationStatus::IterationLimit)
        out.message =
            makeDiagnostic("ident_search_stopped", {std::to_string(options.maxIterations)});
    if (options.progress)
        options.progress(1.0);
    return out;
}

double exactFitLoss(const std::vector<double>& y) {
    double sum = 0.0;
    for (double v : y)
        sum += v * v;
    return y.empty() ? 0.0 : 1e-26 * sum / static_cast<double>(y.size());
}

void parameterCovariance(const Eigen::MatrixXd& jacobian, double sigma2,
                         Eigen::MatrixXd& covariance, std::vector<double>& standardDeviations,
                         std::vector<Diagnostic>& warnings) {
    const LinearLeastSquares ls =
        linearLeastSquares(jacobian, Eigen::VectorXd::Zero(jacobian.rows()));
    standardDeviations.assign(static_cast<std::size_t>(jacobian.cols()),
                              std::numeric_limits<double>::quiet_NaN());
    if (!ls.fullRank()) {
        covariance.resize(0, 0);
        warnings.push_back(makeDiagnostic(
            "ident_jacobian_rank", {std::to_string(ls.rank), std::to_string(jacobian.cols())}));
        return;
    }
    covariance = sigma2 * ls.inverseGram;
    for (Eigen::Index j = 0; j < covariance.rows(); ++j)
        standardDeviations[static_cast<std::size_t>(j)] = std::sqrt(covariance(j, j));
}

void validateIoData(const IoData& data) {
    if (data.y.empty())
        throw InvalidInput("data.y", makeDiagnostic("has_no_samples"));
    if (data.u.size() != data.y.size())
        throw InvalidInput(
            "data.u", makeDiagnostic("ident_data_u_y_lengths", {std::to_string(data.u.size()),
                                                                std::to_string(data.y.size())}));
    for (std::size_t k = 0; k < data.y.size(); ++k) {
        if (!std::isfinite(data.u[k]))
            throw InvalidInput("data.u", makeDiagnostic("sample_not_finite", {std::to_string(k)}));
        if (!std::isfinite(data.y[k]))
            throw InvalidInput("data.y", makeDiagnostic("sample_not_finite", {std::to_string(k)}));
    }
    requirePositive(data.tsSeconds, "data.ts");
}

namespace {

/// z^n p(1/z) as a Polynomial in z (ascending powers of z) for p ascending in z^-1.
Polynomial inPositivePowers(const std::vector<double>& p) {
    return Polynomial::fromAscending(std::vector<double>(p.rbegin(), p.rend()));
}

} // namespace

bool reflectUnstableRoots(std::vector<double>& monic) {
    if (monic.size() < 2)
        return false;
    std::vector<std::complex<double>> roots = inPositivePowers(monic).roots();
    bool changed = false;
    for (auto& r : roots)
        if (std::abs(r) > 1.0) {
            r = 1.0 / std::conj(r);
            changed = true;
        }
    if (!changed)
        return false;
    const std::vector<double> z = Polynomial::fromRoots(roots).ascending(); // monic in z
    const std::size_t n = monic.size() - 1;
    for (std::size_t i = 0; i <= n; ++i)
        monic[i] = i <= n && n - i < z.size() ? z[n - i] : 0.0;
    return true;
}

double maxRootMagnitude(const std::vector<double>& monic) {
    std::size_t last = monic.size();
    while (last > 1 && monic[last - 1] == 0.0)
        --last; // trailing zeros are roots at z = 0
    if (last < 2)
        return 0.0;
    double m = 0.0;
    for (const auto& r :
         inPositivePowers(std::vector<double>(monic.begin(), monic.begin() + last)).roots())
        m = std::max(m, std::abs(r));
    return m;
}

} // namespace xyt
