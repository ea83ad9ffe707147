// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/friction_identification.h"

#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <Eigen/Core>
#include <unsupported/Eigen/NonLinearOptimization>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace xyt {

namespace {

// The core is built as a unity build: the names below are unique across it.

constexpr std::size_t kFrictionMinSegmentSamples = 20;
/// Samples left out at the end of each cruise (see steadyJogPoints).
constexpr std::size_t kFrictionLookAheadSamples = 2;
constexpr std::size_t kFrictionMinSteadySamples = 10;
/// Speeds within this fraction of each other count as one (the distinct-speed rule).
constexpr double kFrictionDistinctSpeed = 0.01;
/// The F-test's level.
constexpr double kFrictionTestLevel = 0.01;

std::string frictionNumber(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", x);
    return buffer;
}

void requireFrictionColumn(const std::vector<double>& column, std::size_t n,
                           const std::string& field) {
    if (column.size() != n)
        throw InvalidInput(field,
                           makeDiagnostic("ident_friction_values_for_times",
                                          {std::to_string(column.size()), std::to_string(n)}));
    for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(column[k]))
            throw InvalidInput(field,
                               makeDiagnostic("ident_value_not_finite", {std::to_string(k + 1)}));
}

/// A constant-velocity run of the reference: samples first..last (inclusive) and its direction.
struct FrictionRun {
    std::size_t first = 0;
    std::size_t last = 0;
    double direction = 0;
};

/// The maximal runs of first differences within @p tolerance of their mean (see
/// FrictionIdentificationOptions::referenceTolerance), scanned from the start.
std::vector<FrictionRun> frictionRuns(const std::vector<double>& r, double tolerance) {
    std::vector<FrictionRun> runs;
    const std::size_t n = r.size();
    std::size_t k = 0; // the first difference of the run being grown
    while (k + 1 < n) {
        const double d0 = r[k + 1] - r[k];
        if (d0 == 0.0) {
            ++k;
            continue;
        }
        double lo = d0, hi = d0, sum = d0;
        std::size_t m = 1; // differences in the run: k .. k + m - 1
        while (k + m + 1 < n) {
            const double d = r[k + m + 1] - r[k + m];
            const double newLo = std::min(lo, d), newHi = std::max(hi, d), newSum = sum + d;
            const double mean = newSum / static_cast<double>(m + 1);
            if (mean == 0.0 || newHi - newLo > tolerance * std::abs(mean))
                break;
            lo = newLo;
            hi = newHi;
            sum = newSum;
            ++m;
        }
        if (m + 1 >= kFrictionMinSegmentSamples)
            runs.push_back(FrictionRun{k, k + m, sum > 0 ? 1.0 : -1.0});
        k += m;
    }
    return runs;
}

/// The steady part samples first..last of one run as a point (FrictionPoint's definitions).
FrictionPoint frictionPoint(const std::vector<double>& t, const std::vector<double>& position,
                            const std::vector<double>& command, std::size_t first,
                            std::size_t last) {
    const std::size_t n = last - first + 1;
    const double count = static_cast<double>(n);
    double tMean = 0, pMean = 0, uMean = 0;
    for (std::size_t k = first; k <= last; ++k) {
        tMean += t[k];
        pMean += position[k];
        uMean += command[k];
    }
    tMean /= count;
    pMean /= count;
    uMean /= count;
    // Centred sums: the slope of the least-squares line without the cancellation of the raw
    // normal equations (t is large, its spread small).
    double stt = 0, stp = 0, suu = 0, lag = 0;
    for (std::size_t k = first; k <= last; ++k) {
        const double dt = t[k] - tMean;
        const double du = command[k] - uMean;
        stt += dt * dt;
        stp += dt * (position[k] - pMean);
        suu += du * du;
        if (k < last)
            lag += du * (command[k + 1] - uMean);
    }
    FrictionPoint p;
    p.velocityMmPerS = stp / stt;
    p.volts = uMean;
    p.samples = n;
    if (suu > 0.0) {
        const double rho = std::max(0.0, lag / suu);
        p.voltsStd = std::sqrt(suu / (count - 1.0) / count * (1.0 + rho) / (1.0 - rho));
    }
    return p;
}

/// Stribeck model of the header at theta = (F_c, F_s, v_s, b), and its gradient.
double stribeckVolts(const Eigen::Vector4d& theta, double v, Eigen::Vector4d* gradient) {
    const double sign = v > 0 ? 1.0 : -1.0;
    const double x = std::abs(v) / theta(2);
    const double g = std::exp(-x * x);
    if (gradient) {
        (*gradient)(0) = sign * (1.0 - g);
        (*gradient)(1) = sign * g;
        // d g / d v_s = g 2 x^2 / v_s
        (*gradient)(2) = sign * (theta(1) - theta(0)) * g * 2.0 * x * x / theta(2);
        (*gradient)(3) = v;
    }
    return sign * (theta(0) + (theta(1) - theta(0)) * g) + theta(3) * v;
}

/// Residuals model - u and Jacobian for Eigen's MINPACK Levenberg-Marquardt. A negative return
/// (v_s = 0, a value not finite) stops the search: the model is then not kept.
struct StribeckResiduals {
    const std::vector<FrictionPoint>& points;

    Eigen::Index values() const { return static_cast<Eigen::Index>(points.size()); }

    int operator()(const Eigen::VectorXd& theta, Eigen::VectorXd& residuals) const {
        if (theta(2) == 0.0 || !theta.allFinite())
            return -1;
        residuals.resize(values());
        const Eigen::Vector4d th = theta;
        for (std::size_t i = 0; i < points.size(); ++i)
            residuals(static_cast<Eigen::Index>(i)) =
                stribeckVolts(th, points[i].velocityMmPerS, nullptr) - points[i].volts;
        return residuals.allFinite() ? 0 : -1;
    }

    int df(const Eigen::VectorXd& theta, Eigen::MatrixXd& jacobian) const {
        if (theta(2) == 0.0 || !theta.allFinite())
            return -1;
        jacobian.resize(values(), 4);
        const Eigen::Vector4d th = theta;
        Eigen::Vector4d gradient;
        for (std::size_t i = 0; i < points.size(); ++i) {
            stribeckVolts(th, points[i].velocityMmPerS, &gradient);
            jacobian.row(static_cast<Eigen::Index>(i)) = gradient.transpose();
        }
        return jacobian.allFinite() ? 0 : -1;
    }
};

/// Distinct speeds among @p speeds (|v|): sorted, a speed more than kFrictionDistinctSpeed
/// above the last distinct one is new.
std::size_t distinctFrictionSpeeds(std::vector<double> speeds) {
    std::sort(speeds.begin(), speeds.end());
    std::size_t count = 0;
    double lastDistinct = 0;
    for (double s : speeds)
        if (count == 0 || s > lastDistinct * (1.0 + kFrictionDistinctSpeed)) {
            ++count;
            lastDistinct = s;
        }
    return count;
}

/// The upper kFrictionTestLevel quantile of F(2, nu): P(F > x) = (1 + 2 x / nu)^(-nu / 2).
double frictionFQuantile(double nu) {
    return 0.5 * nu * (std::pow(kFrictionTestLevel, -2.0 / nu) - 1.0);
}

} // namespace

std::vector<FrictionPoint> steadyJogPoints(const std::vector<double>& t,
                                           const std::vector<double>& reference,
                                           const std::vector<double>& position,
                                           const std::vector<double>& command,
                                           const FrictionIdentificationOptions& options) {
    const std::size_t n = t.size();
    if (n < 2)
        throw InvalidInput("t", makeDiagnostic("ident_needs_two_samples"));
    for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(t[k]))
            throw InvalidInput("t",
                               makeDiagnostic("ident_value_not_finite", {std::to_string(k + 1)}));
    const double step = (t[n - 1] - t[0]) / static_cast<double>(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const double dt = t[k + 1] - t[k];
        if (!(dt > 0.0))
            throw InvalidInput(
                "t", makeDiagnostic("ident_friction_not_increasing", {std::to_string(k + 2)}));
        if (std::abs(dt - step) > 1e-6 * step)
            throw InvalidInput("t", makeDiagnostic("ident_friction_not_uniform",
                                                   {std::to_string(k + 1), frictionNumber(dt),
                                                    frictionNumber(step)}));
    }
    requireFrictionColumn(reference, n, "reference");
    requireFrictionColumn(position, n, "position");
    requireFrictionColumn(command, n, "command");
    if (!(options.settleFraction >= 0.0 && options.settleFraction < 1.0))
        throw InvalidInput("settle_fraction", makeDiagnostic("in_zero_one_open_right"));
    if (!(options.referenceTolerance > 0.0 && options.referenceTolerance <= 0.1))
        throw InvalidInput("reference_tolerance", makeDiagnostic("ident_in_zero_0_1"));

    std::vector<FrictionPoint> points;
    std::size_t forward = 0, backward = 0;
    for (const FrictionRun& run : frictionRuns(reference, options.referenceTolerance)) {
        const double steadyStart =
            t[run.first] + options.settleFraction * (t[run.last] - t[run.first]);
        std::size_t first = run.first;
        // 1e-9 of a step: a steady start that falls on a sample keeps that sample.
        while (first < run.last && t[first] < steadyStart - 1e-9 * step)
            ++first;
        // A controller that reads the planned path ahead (a feedforward from central
        // differences reads r[k + 1] and r[k + 2]) already commands the next ramp at the
        // cruise's last samples: they are left out.
        if (run.last < first + kFrictionLookAheadSamples)
            continue;
        const std::size_t last = run.last - kFrictionLookAheadSamples;
        if (last - first + 1 < kFrictionMinSteadySamples)
            continue;
        points.push_back(frictionPoint(t, position, command, first, last));
        (run.direction > 0 ? forward : backward) += 1;
    }
    if (forward < 2 || backward < 2)
        throw InvalidInput("reference",
                           makeDiagnostic("ident_friction_segments",
                                          {std::to_string(forward), std::to_string(backward)}));
    return points;
}

FrictionEstimate fitFrictionCurve(const std::vector<FrictionPoint>& points,
                                  const FrictionIdentificationOptions& options) {
    std::vector<double> forwardSpeeds, backwardSpeeds;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const FrictionPoint& p = points[i];
        if (!std::isfinite(p.velocityMmPerS) || !std::isfinite(p.volts) ||
            !std::isfinite(p.voltsStd))
            throw InvalidInput("points",
                               makeDiagnostic("point_not_finite", {std::to_string(i + 1)}));
        if (p.velocityMmPerS == 0.0)
            throw InvalidInput("points", makeDiagnostic("ident_friction_point_velocity_zero",
                                                        {std::to_string(i + 1)}));
        (p.velocityMmPerS > 0 ? forwardSpeeds : backwardSpeeds)
            .push_back(std::abs(p.velocityMmPerS));
    }
    if (forwardSpeeds.size() < 2 || backwardSpeeds.size() < 2)
        throw InvalidInput("points", makeDiagnostic("ident_friction_points_directions",
                                                    {std::to_string(forwardSpeeds.size()),
                                                     std::to_string(backwardSpeeds.size())}));

    const Eigen::Index n = static_cast<Eigen::Index>(points.size());
    Eigen::VectorXd u(n);
    Eigen::MatrixXd phi(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double v = points[static_cast<std::size_t>(i)].velocityMmPerS;
        u(i) = points[static_cast<std::size_t>(i)].volts;
        phi(i, 0) = v > 0 ? 1.0 : -1.0;
        phi(i, 1) = v;
    }
    Eigen::MatrixXd phiCopy = phi;
    const LinearLeastSquares line = linearLeastSquares(std::move(phiCopy), u);
    if (!line.fullRank())
        throw InvalidInput("points", makeDiagnostic("ident_friction_speeds_equal"));
    const double rssLine = (u - phi * line.theta).squaredNorm();
    const double dofLine = static_cast<double>(n - 2);
    const double s2Line = rssLine / dofLine;

    FrictionEstimate e;
    e.points = points;
    e.coulombVolts = line.theta(0);
    e.viscousVoltsPerMmPerS = line.theta(1);
    e.coulombStd = std::sqrt(s2Line * line.inverseGram(0, 0));
    e.viscousStd = std::sqrt(s2Line * line.inverseGram(1, 1));
    e.residualStdVolts = std::sqrt(s2Line);
    e.degreesOfFreedom = static_cast<std::size_t>(n - 2);

    if (!options.allowStribeck) {
        e.modelSelection = makeDiagnostic("ident_stribeck_not_allowed");
        return e;
    }
    if (distinctFrictionSpeeds(forwardSpeeds) < 3 || distinctFrictionSpeeds(backwardSpeeds) < 3) {
        e.modelSelection = makeDiagnostic("ident_stribeck_few_speeds");
        return e;
    }
    if (std::sqrt(rssLine) <= 1e-12 * u.norm()) {
        e.modelSelection = makeDiagnostic("ident_stribeck_line_exact");
        return e;
    }

    // Start: the line, F_s = the mean of sign(v) (u - b v) at the lowest speed of each
    // direction, v_s = the lowest |v|.
    std::size_t lowForward = points.size(), lowBackward = points.size();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double v = points[i].velocityMmPerS;
        std::size_t& low = v > 0 ? lowForward : lowBackward;
        if (low == points.size() || std::abs(v) < std::abs(points[low].velocityMmPerS))
            low = i;
    }
    const double b0 = line.theta(1);
    const double fsForward = points[lowForward].volts - b0 * points[lowForward].velocityMmPerS;
    const double fsBackward =
        -(points[lowBackward].volts - b0 * points[lowBackward].velocityMmPerS);
    Eigen::VectorXd theta(4);
    theta << line.theta(0), 0.5 * (fsForward + fsBackward),
        std::min(std::abs(points[lowForward].velocityMmPerS),
                 std::abs(points[lowBackward].velocityMmPerS)),
        b0;

    StribeckResiduals functor{points};
    Eigen::LevenbergMarquardt<StribeckResiduals> lm(functor);
    const Eigen::LevenbergMarquardtSpace::Status status = lm.minimize(theta);
    namespace Lm = Eigen::LevenbergMarquardtSpace;
    // 1-4: MINPACK's convergence tests; 6-8: the tolerances cannot be met at machine precision
    // (no further improvement is possible, as on exact data). 0, 5, 9: not converged.
    const bool converged =
        status == Lm::RelativeReductionTooSmall || status == Lm::RelativeErrorTooSmall ||
        status == Lm::RelativeErrorAndReductionTooSmall || status == Lm::CosinusTooSmall ||
        status == Lm::FtolTooSmall || status == Lm::XtolTooSmall || status == Lm::GtolTooSmall;
    if (!converged || !theta.allFinite()) {
        e.modelSelection = makeDiagnostic("ident_stribeck_not_converged",
                                          {std::to_string(static_cast<int>(status))});
        return e;
    }
    theta(2) = std::abs(theta(2)); // the model holds v_s^2 only
    if (!(theta(2) > 0.0) || !(theta(1) > theta(0))) {
        e.modelSelection = makeDiagnostic(
            "ident_stribeck_converged_wrong",
            {frictionNumber(theta(2)), frictionNumber(theta(1)), frictionNumber(theta(0))});
        return e;
    }
    Eigen::VectorXd residuals;
    Eigen::MatrixXd jacobian;
    if (functor(theta, residuals) < 0 || functor.df(theta, jacobian) < 0) {
        e.modelSelection = makeDiagnostic("ident_stribeck_not_finite");
        return e;
    }
    const LinearLeastSquares local = linearLeastSquares(jacobian, residuals);
    if (!local.fullRank()) {
        e.modelSelection = makeDiagnostic("ident_stribeck_rank_deficient");
        return e;
    }
    const double rssStribeck = residuals.squaredNorm();
    const double nu = static_cast<double>(n - 4);
    const double reduction = rssLine - rssStribeck;
    const double f = reduction <= 0.0     ? 0.0
                     : rssStribeck == 0.0 ? std::numeric_limits<double>::infinity()
                                          : (reduction / 2.0) / (rssStribeck / nu);
    const double critical = frictionFQuantile(nu);
    const std::string test = "F = " + frictionNumber(f) + (f > critical ? " > " : " <= ") +
                             "F(2, " + std::to_string(n - 4) +
                             "; 0.99) = " + frictionNumber(critical);
    if (!(f > critical)) {
        e.modelSelection = makeDiagnostic("ident_stribeck_test_not_kept", {test});
        return e;
    }
    const double s2 = rssStribeck / nu;
    e.coulombVolts = theta(0);
    e.coulombStd = std::sqrt(s2 * local.inverseGram(0, 0));
    e.hasStribeck = true;
    e.staticVolts = theta(1);
    e.staticStd = std::sqrt(s2 * local.inverseGram(1, 1));
    e.stribeckVelocityMmPerS = theta(2);
    e.stribeckStd = std::sqrt(s2 * local.inverseGram(2, 2));
    e.viscousVoltsPerMmPerS = theta(3);
    e.viscousStd = std::sqrt(s2 * local.inverseGram(3, 3));
    e.residualStdVolts = std::sqrt(s2);
    e.degreesOfFreedom = static_cast<std::size_t>(n - 4);
    e.modelSelection = makeDiagnostic("ident_stribeck_test_kept", {test});
    return e;
}

FrictionEstimate identifyFriction(const std::vector<double>& t,
                                  const std::vector<double>& reference,
                                  const std::vector<double>& position,
                                  const std::vector<double>& command,
                                  const FrictionIdentificationOptions& options) {
    return fitFrictionCurve(steadyJogPoints(t, reference, position, command, options), options);
}

} // namespace xyt
