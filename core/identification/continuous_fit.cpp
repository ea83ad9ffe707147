// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/continuous_fit.h"

#include "core/identification/arx.h"
#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/polynomial.h"
#include "core/model/state_space.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace xyt {

namespace {

/// Phi and Gamma of the exact ZOH discretization of the companion realization x = [y, y', y''].
struct ZohStep {
    double phi[3][3];
    double gamma[3];
};

ZohStep zohStep(double k0, double a1, double a2, double ts) {
    StateSpace c;
    c.a = Eigen::MatrixXd::Zero(3, 3);
    c.a(0, 1) = 1.0;
    c.a(1, 2) = 1.0;
    c.a(2, 1) = -a2;
    c.a(2, 2) = -a1;
    c.b = Eigen::MatrixXd::Zero(3, 1);
    c.b(2, 0) = k0;
    c.c = Eigen::MatrixXd::Zero(1, 3);
    c.c(0, 0) = 1.0;
    c.d = Eigen::MatrixXd::Zero(1, 1);
    const StateSpace d = discretizeZoh(c, ts);
    ZohStep s{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            s.phi[i][j] = d.a(i, j);
        s.gamma[i] = d.b(i, 0);
    }
    return s;
}

void simulate(const ZohStep& s, const double* u, double* y, std::size_t n) {
    double x0 = 0.0, x1 = 0.0, x2 = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        y[k] = x0;
        const double n0 =
            s.phi[0][0] * x0 + s.phi[0][1] * x1 + s.phi[0][2] * x2 + s.gamma[0] * u[k];
        const double n1 =
            s.phi[1][0] * x0 + s.phi[1][1] * x1 + s.phi[1][2] * x2 + s.gamma[1] * u[k];
        const double n2 =
            s.phi[2][0] * x0 + s.phi[2][1] * x1 + s.phi[2][2] * x2 + s.gamma[2] * u[k];
        x0 = n0;
        x1 = n1;
        x2 = n2;
    }
}

bool plantOk(const ThirdOrderPlant& p) {
    return std::isfinite(p.k0) && std::isfinite(p.a1) && std::isfinite(p.a2) && p.k0 != 0.0;
}

/// Output-error residuals of theta = [k0, a1, a2]; false when the discretization fails or the
/// run is not finite. With @p removeMean the residuals' mean is taken off: the optimal constant
/// initial position for this theta projected out (variable projection, Golub and Pereyra 1973),
/// so that a search over theta alone finds the same minimum as one over theta and y0.
bool residuals(const IoData& data, const Eigen::VectorXd& theta, Eigen::VectorXd& e,
               bool removeMean = false) {
    ZohStep s;
    try {
        s = zohStep(theta(0), theta(1), theta(2), data.tsSeconds);
    } catch (const InvalidInput&) {
        return false;
    }
    const std::size_t n = data.size();
    e.resize(static_cast<Eigen::Index>(n));
    simulate(s, data.u.data(), e.data(), n);
    for (std::size_t k = 0; k < n; ++k)
        e(static_cast<Eigen::Index>(k)) = data.y[k] - e(static_cast<Eigen::Index>(k));
    if (removeMean)
        e.array() -= e.mean();
    return e.allFinite();
}

double lossOf(const IoData& data, const ThirdOrderPlant& p) {
    Eigen::VectorXd e;
    if (!plantOk(p) || !residuals(data, Eigen::Vector3d(p.k0, p.a1, p.a2), e))
        return std::numeric_limits<double>::infinity();
    return e.squaredNorm() / static_cast<double>(e.size());
}

/// The ARX(3,3,1) estimate converted to continuous time (see fitThirdOrderPlant); nullopt when
/// it gives no real positive a1, a2.
std::optional<ThirdOrderPlant> convertedArx(const IoData& data) {
    const ArxResult arx = estimateArx(data, ArxOrders{3, 3, 1});
    if (arx.status != EstimationStatus::Converged)
        return std::nullopt;
    const std::vector<double>& a = arx.model.a;
    std::vector<std::complex<double>> z;
    try {
        z = Polynomial::fromAscending({a[3], a[2], a[1], a[0]}).roots();
    } catch (const InvalidInput&) {
        return std::nullopt;
    }
    if (z.size() != 3)
        return std::nullopt;
    // The integrator: the root nearest z = 1.
    std::size_t integrator = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (std::abs(z[i] - 1.0) < std::abs(z[integrator] - 1.0))
            integrator = i;
    std::vector<std::complex<double>> others;
    for (std::size_t i = 0; i < 3; ++i)
        if (i != integrator)
            others.push_back(z[i]);
    const double ts = data.tsSeconds;
    const std::complex<double> s1 = std::log(others[0]) / ts;
    const std::complex<double> s2 = std::log(others[1]) / ts;
    const std::complex<double> a1 = -(s1 + s2);
    const std::complex<double> a2 = s1 * s2;
    const double tol = 1e-6 * (std::abs(a1) + std::abs(a2));
    if (std::abs(a1.imag()) > tol || std::abs(a2.imag()) > tol || a1.real() <= 0.0 ||
        a2.real() <= 0.0)
        return std::nullopt;
    double bAtOne = 0.0;
    for (double c : arx.model.b)
        bAtOne += c;
    const std::complex<double> a2AtOne = (1.0 - others[0]) * (1.0 - others[1]);
    ThirdOrderPlant p{a2.real() * bAtOne / (ts * a2AtOne.real()), a1.real(), a2.real()};
    if (!plantOk(p))
        return std::nullopt;
    return p;
}

/// The plant with poles -p1, -p2 and the least-squares k0 for them: the output is linear in
/// k0, so k0 = <y, s> / <s, s> with s the response for k0 = 1.
ThirdOrderPlant withBestGain(const IoData& data, double p1, double p2) {
    const ThirdOrderPlant unit{1.0, p1 + p2, p1 * p2};
    Eigen::VectorXd e;
    if (!residuals(data, Eigen::Vector3d(1.0, unit.a1, unit.a2), e))
        return ThirdOrderPlant{std::numeric_limits<double>::quiet_NaN(), unit.a1, unit.a2};
    double ys = 0.0, ss = 0.0;
    for (std::size_t k = 0; k < data.size(); ++k) {
        const double s = data.y[k] - e(static_cast<Eigen::Index>(k)); // the unit response
        ys += data.y[k] * s;
        ss += s * s;
    }
    return ThirdOrderPlant{ss > 0.0 ? ys / ss : std::numeric_limits<double>::quiet_NaN(), unit.a1,
                           unit.a2};
}

/// The stated heuristic: real poles -p1, -p2 with p1 <= p2 from {0.003, 0.01, 0.03, 0.1, 0.3,
/// 1} / Ts (21 pairs), each with its least-squares k0; the pair of smallest loss.
ThirdOrderPlant gridStart(const IoData& data) {
    const double grid[] = {0.003, 0.01, 0.03, 0.1, 0.3, 1.0};
    ThirdOrderPlant best{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
    double bestLoss = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < std::size(grid); ++i)
        for (std::size_t j = i; j < std::size(grid); ++j) {
            const ThirdOrderPlant p =
                withBestGain(data, grid[i] / data.tsSeconds, grid[j] / data.tsSeconds);
            const double loss = lossOf(data, p);
            if (loss < bestLoss) {
                bestLoss = loss;
                best = p;
            }
        }
    return best;
}

} // namespace

std::optional<double> subtractInitialPosition(IoData& data) {
    if (data.y.empty())
        return std::nullopt;
    const double y0 = data.y.front();
    for (double& y : data.y)
        y -= y0;
    return y0;
}

std::vector<double> simulateThirdOrderPlant(const ThirdOrderPlant& plant,
                                            const std::vector<double>& u, double tsSeconds) {
    plant.validate();
    requirePositive(tsSeconds, "ts");
    std::vector<double> y(u.size());
    simulate(zohStep(plant.k0, plant.a1, plant.a2, tsSeconds), u.data(), y.data(), u.size());
    return y;
}

PolynomialModel discretizedThirdOrderPlant(const ThirdOrderPlant& plant, double tsSeconds) {
    plant.validate();
    const TransferFunction g = c2dZoh(plant.transferFunction(), tsSeconds);
    PolynomialModel m;
    m.tsSeconds = tsSeconds;
    const Polynomial den = g.denZInverse();
    const Polynomial num = g.numZInverse();
    m.a = den.ascending();
    const double lead = m.a[0];
    for (double& c : m.a)
        c /= lead;
    m.b = num.ascending();
    for (double& c : m.b)
        c /= lead;
    return m;
}

ContinuousFitResult fitThirdOrderPlant(const IoData& data, const ContinuousFitOptions& options) {
    validateIoData(data);
    if (options.search.maxIterations < 1)
        throw InvalidInput("max_iterations", makeDiagnostic("at_least", {"1"}));
    if (!(options.finiteDifferenceStep > 0.0 && options.finiteDifferenceStep <= 0.1))
        throw InvalidInput("finite_difference_step", makeDiagnostic("ident_in_zero_0_1"));
    if (data.size() < 10)
        throw InvalidInput("data", makeDiagnostic("ident_too_few_samples_for",
                                                  {std::to_string(data.size()),
                                                   "k0/(s^3 + a1 s^2 + a2 s)", "10"}));
    ContinuousFitResult out;
    out.samples = data.size();
    if (options.initial) {
        options.initial->validate();
        out.initialPlant = *options.initial;
        out.initialization = "given";
    } else {
        const ThirdOrderPlant grid = gridStart(data);
        out.initialPlant = grid;
        out.initialization = "pole grid";
        if (const auto converted = convertedArx(data);
            converted && lossOf(data, *converted) <= lossOf(data, grid)) {
            out.initialPlant = *converted;
            out.initialization = "ARX(3,3,1) converted";
        }
    }

    const double h = options.finiteDifferenceStep;
    NonlinearProblem problem;
    problem.evaluate = [&](const Eigen::VectorXd& theta, Eigen::VectorXd& e, Eigen::MatrixXd* jac) {
        if (!residuals(data, theta, e, options.estimateInitialPosition))
            return false;
        if (!jac)
            return true;
        jac->resize(e.size(), 3);
        Eigen::VectorXd plus, minus;
        for (Eigen::Index j = 0; j < 3; ++j) {
            const double step = h * std::max(std::abs(theta(j)), 1e-12);
            Eigen::VectorXd tp = theta, tm = theta;
            tp(j) += step;
            tm(j) -= step;
            if (!residuals(data, tp, plus, options.estimateInitialPosition) ||
                !residuals(data, tm, minus, options.estimateInitialPosition))
                return false;
            jac->col(j) = (plus - minus) / (tp(j) - tm(j));
        }
        return true;
    };
    const SearchOutcome r = levenbergMarquardt(
        problem, Eigen::Vector3d(out.initialPlant.k0, out.initialPlant.a1, out.initialPlant.a2),
        options.search, exactFitLoss(data.y));
    takeSearchSummary(r, out);
    if (r.status == EstimationStatus::Failed)
        return out;
    out.plant = ThirdOrderPlant{r.theta(0), r.theta(1), r.theta(2)};
    const std::size_t n = data.size();
    out.residuals.assign(r.residuals.data(), r.residuals.data() + r.residuals.size());
    out.simulated.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        out.simulated[k] = data.y[k] - out.residuals[k]; // (with y0 when it is estimated)
    if (options.estimateInitialPosition) {
        const std::vector<double> fromRest =
            simulateThirdOrderPlant(out.plant, data.u, data.tsSeconds);
        double sum = 0.0;
        for (std::size_t k = 0; k < n; ++k)
            sum += data.y[k] - fromRest[k];
        out.initialPositionMm = sum / static_cast<double>(n);
    }
    const double sse = r.residuals.squaredNorm();
    const std::size_t parameters = options.estimateInitialPosition ? 4 : 3;
    out.loss = sse / static_cast<double>(n);
    out.noiseVariance = sse / static_cast<double>(n - parameters);
    Eigen::MatrixXd cov;
    std::vector<double> sd;
    parameterCovariance(r.jacobian, out.noiseVariance, cov, sd, out.warnings);
    for (std::size_t j = 0; j < 3; ++j)
        out.standardDeviations[j] = sd[j];
    if (cov.size() == 9)
        out.covariance = cov;
    else
        out.covariance.setConstant(std::numeric_limits<double>::quiet_NaN());
    if (out.plant.a1 <= 0.0 || out.plant.a2 <= 0.0)
        out.warnings.push_back(makeDiagnostic("ident_fit_a_not_positive"));
    return out;
}

} // namespace xyt
