// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/coupled_line_loop.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace xyt {

namespace {

/// A pole within this of the unit circle counts as on it (see CoupledLineLoop::stable).
constexpr double kLineLoopStabilityTolerance = 1e-12;
/// A pole this near z = 1, whose mode's eps is this small against the mode, is the hidden
/// integral mode (CoupledLineLoop::hiddenIntegralMode).
constexpr double kLineLoopHiddenModeTolerance = 1e-9;
/// An axis whose coupling gain |C| is at most this is left out of couplingLoop.
constexpr double kLineLoopNegligibleGain = 1e-12;

void lineLoopRequireModel(const SampledAxisModel& m, const std::string& field) {
    const Eigen::Index n = m.phi.rows();
    if (n == 0)
        throw InvalidInput(field, makeDiagnostic("analysis_model_has_no_state"));
    if (m.phi.cols() != n || m.gamma.size() != n || m.c.size() != n)
        throw InvalidInput(
            field, makeDiagnostic("analysis_model_sizes_disagree",
                                  {std::to_string(m.phi.rows()), std::to_string(m.phi.cols()),
                                   std::to_string(m.gamma.size()), std::to_string(m.c.size())}));
    if (!m.phi.allFinite() || !m.gamma.allFinite() || !m.c.allFinite())
        throw InvalidInput(field, makeDiagnostic("analysis_model_not_finite"));
    if (!(m.periodSeconds > 0.0) || !std::isfinite(m.periodSeconds))
        throw InvalidInput("period", makeDiagnostic("finite_positive"));
}

std::vector<std::complex<double>> lineLoopEigenvalues(const Eigen::MatrixXd& m) {
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(m, false).eigenvalues();
    return {ev.data(), ev.data() + ev.size()};
}

/// By increasing modulus, then argument: a deterministic order for equal moduli.
void lineLoopSortByModulus(std::vector<std::complex<double>>& poles) {
    std::sort(poles.begin(), poles.end(), [](std::complex<double> a, std::complex<double> b) {
        const double ma = std::abs(a), mb = std::abs(b);
        if (ma != mb)
            return ma < mb;
        return std::arg(a) < std::arg(b);
    });
}

/**
 * c (zI - Phi)^-1 gamma as N/D, with D = det(zI - Phi) and N = det(zI - Phi + gamma c) - D (the
 * identity c2dZoh uses), both from eigenvalues. The difference leaves round-off
 * (~1e-16 ||Phi||) in place of N's leading coefficients where those vanish exactly: the
 * coefficient of z^{n-1-j} is sum_i d_{n-j+i} c Phi^i gamma, so while the Markov parameters
 * c Phi^j gamma are exactly 0 (a delay of the RST model, B = b_2 z^-2 + ...) that coefficient is
 * set to 0 instead of leaving a spurious zero near infinity.
 */
TransferFunction lineLoopAxisTransfer(const SampledAxisModel& m) {
    const Polynomial den = characteristicPolynomial(m.phi);
    const Polynomial closed = characteristicPolynomial(m.phi - m.gamma * m.c);
    std::vector<double> num = (closed - den).ascending();
    const int n = static_cast<int>(m.phi.rows());
    num.resize(static_cast<std::size_t>(n), 0.0); // the z^n terms cancel (both monic)
    Eigen::VectorXd w = m.gamma;
    for (int j = 0; j < n && m.c.dot(w) == 0.0; ++j) {
        num[static_cast<std::size_t>(n - 1 - j)] = 0.0;
        w = m.phi * w;
    }
    return TransferFunction(Polynomial::fromAscending(num, "axis.num"), den, m.periodSeconds);
}

bool lineLoopSameDenominator(const Polynomial& a, const Polynomial& b) {
    if (a.degree() != b.degree())
        return false;
    const double scale = std::max(a.maxAbsCoefficient(), b.maxAbsCoefficient());
    for (int i = 0; i <= a.degree(); ++i)
        if (std::abs(a.coefficient(i) - b.coefficient(i)) > 1e-12 * scale)
            return false;
    return true;
}

/// Cx^2 Gx + Cy^2 Gy with the bookkeeping of CoupledLineLoop::couplingLoop.
TransferFunction lineLoopAxisSum(const SampledAxisModel& x, const SampledAxisModel& y, double cx,
                                 double cy) {
    const double ts = x.periodSeconds;
    const bool useX = std::abs(cx) > kLineLoopNegligibleGain;
    const bool useY = std::abs(cy) > kLineLoopNegligibleGain;
    if (useX && !useY) {
        const TransferFunction gx = lineLoopAxisTransfer(x);
        return TransferFunction(cx * cx * gx.num(), gx.den(), ts);
    }
    if (useY && !useX) {
        const TransferFunction gy = lineLoopAxisTransfer(y);
        return TransferFunction(cy * cy * gy.num(), gy.den(), ts);
    }
    const TransferFunction gx = lineLoopAxisTransfer(x);
    const TransferFunction gy = lineLoopAxisTransfer(y);
    if (lineLoopSameDenominator(gx.den(), gy.den()))
        return TransferFunction(cx * cx * gx.num() + cy * cy * gy.num(), gx.den(), ts);
    return TransferFunction(cx * cx * gx.num() * gy.den() + cy * cy * gy.num() * gx.den(),
                            gx.den() * gy.den(), ts);
}

/**
 * |S - 1/2| = |(1 - L) / (2 (1 + L))| at z = e^{j theta}, from the state-space models. With
 * C = Cn/Cd (Cn = kc z - kp, Cd = z - 1 when ki > 0; Cn = kp, Cd = 1 otherwise) it is
 * |(Cd - Cn G) / (2 (Cd + Cn G))|, finite at z = 1. Where G is infinite (z on an axis pole)
 * L is infinite and the value is its limit 1/2.
 */
class LineLoopDiskEvaluator {
public:
    LineLoopDiskEvaluator(const SampledAxisModel& x, const SampledAxisModel& y, double cx,
                          double cy, const CrossCoupling& coupling)
        : x_(x), y_(y), wx_(cx * cx), wy_(cy * cy), kp_(coupling.kp),
          kc_(coupling.kp + coupling.ki * x.periodSeconds), integral_(coupling.ki > 0.0) {}

    double operator()(double thetaRad) const {
        const std::complex<double> z = std::polar(1.0, thetaRad);
        const std::complex<double> g = wx_ * axis(x_, z) + wy_ * axis(y_, z);
        const std::complex<double> cn = integral_ ? kc_ * z - kp_ : std::complex<double>(kp_);
        const std::complex<double> cd = integral_ ? z - 1.0 : std::complex<double>(1.0);
        const std::complex<double> l = cn * g;
        if (!std::isfinite(l.real()) || !std::isfinite(l.imag()))
            return 0.5;
        const double value = std::abs((cd - l) / (2.0 * (cd + l)));
        return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
    }

private:
    static std::complex<double> axis(const SampledAxisModel& m, std::complex<double> z) {
        const Eigen::Index n = m.phi.rows();
        const Eigen::MatrixXcd a =
            z * Eigen::MatrixXcd::Identity(n, n) - m.phi.cast<std::complex<double>>();
        const Eigen::VectorXcd r =
            a.partialPivLu().solve(m.gamma.cast<std::complex<double>>().eval());
        return (m.c.cast<std::complex<double>>() * r)(0);
    }

    const SampledAxisModel& x_;
    const SampledAxisModel& y_;
    double wx_, wy_, kp_, kc_;
    bool integral_;
};

/// The maximum of f on [a, b] by golden-section search (f unimodal there), to 1e-12 relative.
template <class F> double lineLoopGoldenMax(const F& f, double a, double b) {
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - r * (b - a), d = a + r * (b - a);
    double fc = f(c), fd = f(d);
    double best = std::max({f(a), f(b), fc, fd});
    while (b - a > 1e-12 * std::max(std::abs(a), std::abs(b))) {
        if (fc >= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
            best = std::max(best, fc);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
            best = std::max(best, fd);
        }
    }
    return best;
}

/// max over 0 <= theta <= pi of the evaluator (see CoupledLineLoop::diskMargin for the grid).
double lineLoopDiskPeak(const LineLoopDiskEvaluator& f,
                        const std::vector<std::complex<double>>& poles) {
    constexpr double kPi = std::numbers::pi;
    double thetaMin = 1e-4;
    for (const auto& p : poles) {
        const double d = std::abs(1.0 - p);
        if (d > 0.0)
            thetaMin = std::min(thetaMin, 0.1 * d);
    }
    thetaMin = std::max(thetaMin, 1e-12);
    const double decades = std::log10(kPi / thetaMin);
    const int points = std::max(2, static_cast<int>(std::ceil(300.0 * decades)) + 1);
    std::vector<double> grid{0.0};
    for (int i = 0; i < points; ++i)
        grid.push_back(thetaMin * std::pow(10.0, decades * i / (points - 1)));
    grid.back() = kPi;
    for (const auto& p : poles) {
        const double angle = std::abs(std::arg(p));
        if (angle > 0.0 && angle < kPi)
            grid.push_back(angle);
    }
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());

    std::vector<double> values(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
        values[i] = f(grid[i]);
    // The local maxima of the grid, largest first; the five largest are refined.
    std::vector<std::size_t> maxima;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const bool left = i == 0 || values[i] >= values[i - 1];
        const bool right = i + 1 == grid.size() || values[i] >= values[i + 1];
        if (left && right)
            maxima.push_back(i);
    }
    std::sort(maxima.begin(), maxima.end(),
              [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
    double peak = *std::max_element(values.begin(), values.end());
    for (std::size_t m = 0; m < std::min<std::size_t>(5, maxima.size()); ++m) {
        const std::size_t i = maxima[m];
        const double a = grid[i > 0 ? i - 1 : 0];
        const double b = grid[std::min(i + 1, grid.size() - 1)];
        if (b > a)
            peak = std::max(peak, lineLoopGoldenMax(f, a, b));
    }
    return peak;
}

/// c (zI - Phi)^-1 gamma at one point z (an LU solve).
std::complex<double> lineLoopAxisAt(const SampledAxisModel& m, std::complex<double> z) {
    const Eigen::Index n = m.phi.rows();
    const Eigen::MatrixXcd a =
        z * Eigen::MatrixXcd::Identity(n, n) - m.phi.cast<std::complex<double>>();
    const Eigen::VectorXcd r = a.partialPivLu().solve(m.gamma.cast<std::complex<double>>().eval());
    return (m.c.cast<std::complex<double>>() * r)(0);
}

/**
 * Gain and phase margins of a loop given by its frequency response @p l(theta) on
 * 0 < theta <= pi (theta = omega T): the crossings of |L| = 1 and of arg L = 180 degrees on a
 * log grid (300 points a decade from @p thetaMin, plus the arguments of @p poles), each refined
 * by bisection to 1e-13 in theta; the margins closest to 0 (dB, degrees), inf without a crossing.
 */
template <class F>
void lineLoopGridMargins(const F& l, double thetaMin,
                         const std::vector<std::complex<double>>& poles, double periodSeconds,
                         AxisBrokenLoop& out) {
    constexpr double kPi = std::numbers::pi;
    const double decades = std::log10(kPi / thetaMin);
    const int points = std::max(2, static_cast<int>(std::ceil(300.0 * decades)) + 1);
    std::vector<double> grid;
    for (int i = 0; i < points; ++i)
        grid.push_back(thetaMin * std::pow(10.0, decades * i / (points - 1)));
    grid.back() = kPi;
    for (const auto& p : poles) {
        const double angle = std::abs(std::arg(p));
        if (angle > thetaMin && angle < kPi)
            grid.push_back(angle);
    }
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
    const auto refine = [&](double a, double b, const auto& sign) {
        const bool sa = sign(a);
        for (int i = 0; i < 200 && b - a > 1e-13 * b; ++i) {
            const double m = 0.5 * (a + b);
            (sign(m) == sa ? a : b) = m;
        }
        return 0.5 * (a + b);
    };
    const auto magnitudeAbove = [&](double t) { return std::abs(l(t)) > 1.0; };
    const auto upper = [&](double t) { return l(t).imag() > 0.0; };
    out.gainMarginDb = out.phaseMarginDeg = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
        const double a = grid[i], b = grid[i + 1];
        if (magnitudeAbove(a) != magnitudeAbove(b)) {
            const double t = refine(a, b, magnitudeAbove);
            double pm = 180.0 + std::arg(l(t)) * 180.0 / kPi;
            if (pm > 180.0)
                pm -= 360.0;
            if (std::abs(pm) < std::abs(out.phaseMarginDeg)) {
                out.phaseMarginDeg = pm;
                out.phaseCrossoverRadPerSec = t / periodSeconds;
            }
        }
        if (upper(a) != upper(b)) {
            const double t = refine(a, b, upper);
            const std::complex<double> v = l(t);
            if (v.real() < 0.0) {
                const double gm = -20.0 * std::log10(std::abs(v));
                if (std::abs(gm) < std::abs(out.gainMarginDb)) {
                    out.gainMarginDb = gm;
                    out.gainCrossoverRadPerSec = t / periodSeconds;
                }
            }
        }
    }
    const std::complex<double> atNyquist = l(kPi); // z = -1: real
    if (atNyquist.real() < 0.0) {
        const double gm = -20.0 * std::log10(std::abs(atNyquist));
        if (std::abs(gm) < std::abs(out.gainMarginDb)) {
            out.gainMarginDb = gm;
            out.gainCrossoverRadPerSec = kPi / periodSeconds;
        }
    }
}

} // namespace

SampledAxisModel continuousAxisModel(const TransferFunction& plant,
                                     const TransferFunction& controller, double modelUnitsPerMm,
                                     double periodSeconds) {
    // The wording of loopModes (core/simulation), which this module may not include.
    if (plant.isDiscrete() || !plant.isStrictlyProper())
        throw InvalidInput("plant", makeDiagnostic("not_continuous_strictly_proper"));
    if (controller.isDiscrete() || !controller.isProper())
        throw InvalidInput("controller", makeDiagnostic("not_continuous_proper"));
    requirePositive(periodSeconds, "period");
    requirePositive(modelUnitsPerMm, "model_unit_scale");
    const StateSpace p = realize(plant);
    const StateSpace c = realize(controller);
    const Eigen::Index np = p.states(), nc = c.states(), n = np + nc;
    const double dc = c.d(0, 0);
    StateSpace loop;
    loop.a = Eigen::MatrixXd::Zero(n, n);
    loop.a.topLeftCorner(np, np) = p.a - dc * p.b * p.c;
    loop.a.topRightCorner(np, nc) = p.b * c.c;
    loop.a.bottomLeftCorner(nc, np) = -c.b * p.c;
    loop.a.bottomRightCorner(nc, nc) = c.a;
    loop.b = Eigen::MatrixXd::Zero(n, 1);
    loop.b.topRows(np) = p.b; // v enters where u does
    loop.c = Eigen::MatrixXd::Zero(1, n);
    loop.c.leftCols(np) = p.c / modelUnitsPerMm;
    loop.d = Eigen::MatrixXd::Zero(1, 1);
    const StateSpace d = discretizeZoh(loop, periodSeconds);
    if (!d.a.allFinite() || !d.b.allFinite())
        throw InvalidInput("period", makeDiagnostic("analysis_discretization_overflows"));
    SampledAxisModel m;
    m.phi = d.a;
    m.gamma = d.b.col(0);
    m.c = d.c.row(0);
    m.periodSeconds = periodSeconds;
    return m;
}

SampledAxisModel rstAxisModel(const PolePlacementDesign& loop) {
    requirePositive(loop.tsSeconds, "ts");
    const double a0 = loop.a.coefficient(0);
    if (a0 == 0.0)
        throw InvalidInput("a", makeDiagnostic("analysis_a0_nonzero"));
    if (loop.b.coefficient(0) != 0.0)
        throw InvalidInput("b", makeDiagnostic("analysis_b0_zero"));
    const double f0 = loop.f.coefficient(0);
    if (f0 == 0.0)
        throw InvalidInput("f", makeDiagnostic("analysis_f0_nonzero"));
    const int na = loop.a.degree(), nb = loop.b.degree(), nf = loop.f.degree();
    const int ng = loop.g.degree();
    const int ny = std::max(na, ng);
    const int n = ny + nf + nb;
    // Offsets of the histories in the state: y(k-1-i), u(k-1-i), ua(k-1-i).
    const int oy = 0, ou = ny, oa = ny + nf;

    // y(k) = (sum_{i>=1} b_i ua(k-i) - sum_{i>=1} a_i y(k-i)) / a0 (runRstLoop, a0 = 1 there).
    Eigen::RowVectorXd cy = Eigen::RowVectorXd::Zero(n);
    for (int i = 1; i <= na; ++i)
        cy(oy + i - 1) = -loop.a.coefficient(i) / a0;
    for (int i = 1; i <= nb; ++i)
        cy(oa + i - 1) = loop.b.coefficient(i) / a0;
    // u(k) = (-g_0 y(k) - sum_{i>=1} g_i y(k-i) - sum_{i>=1} f_i u(k-i)) / f0.
    Eigen::RowVectorXd cu = -loop.g.coefficient(0) * cy;
    for (int i = 1; i <= ng; ++i)
        cu(oy + i - 1) -= loop.g.coefficient(i);
    for (int i = 1; i <= nf; ++i)
        cu(ou + i - 1) -= loop.f.coefficient(i);
    cu /= f0;

    SampledAxisModel m;
    m.phi = Eigen::MatrixXd::Zero(n, n);
    m.gamma = Eigen::VectorXd::Zero(n);
    m.c = cy;
    m.periodSeconds = loop.tsSeconds;
    // Each history shifts by one; its newest entry is y(k), u(k) or ua(k) = u(k) + v(k).
    const auto shift = [&m](int offset, int length) {
        for (int i = 1; i < length; ++i)
            m.phi(offset + i, offset + i - 1) = 1.0;
    };
    if (ny > 0) {
        m.phi.row(oy) = cy;
        shift(oy, ny);
    }
    if (nf > 0) {
        m.phi.row(ou) = cu;
        shift(ou, nf);
    }
    if (nb > 0) {
        m.phi.row(oa) = cu;
        m.gamma(oa) = 1.0;
        shift(oa, nb);
    }
    return m;
}

CoupledLineLoop coupledLineLoop(const SampledAxisModel& x, const SampledAxisModel& y,
                                double thetaRad, const CrossCoupling& coupling, bool withMargins) {
    validateCrossCoupling(coupling, "cross_coupling");
    lineLoopRequireModel(x, "x_axis");
    lineLoopRequireModel(y, "y_axis");
    const double ts = x.periodSeconds;
    if (std::abs(x.periodSeconds - y.periodSeconds) >
        1e-12 * std::max(x.periodSeconds, y.periodSeconds))
        throw InvalidInput("period", makeDiagnostic("analysis_axes_periods_differ"));
    requireFinite(thetaRad, "theta");

    CoupledLineLoop out;
    const Eigen::Index nx = x.phi.rows(), ny = y.phi.rows();
    if (!coupling.active()) {
        // No loop: each axis keeps its own poles.
        out.poles = lineLoopEigenvalues(x.phi);
        const auto py = lineLoopEigenvalues(y.phi);
        out.poles.insert(out.poles.end(), py.begin(), py.end());
        lineLoopSortByModulus(out.poles);
        out.spectralRadius = std::abs(out.poles.back());
        out.stable = out.spectralRadius < 1.0 - kLineLoopStabilityTolerance;
        out.bounded = out.stable;
        out.couplingLoop = TransferFunction::gain(0.0, ts);
        return out;
    }

    const double cx = -std::sin(thetaRad), cy = std::cos(thetaRad);
    const bool integral = coupling.ki > 0.0;
    const double kc = coupling.kp + coupling.ki * ts; // u_c = kc eps_k + ki I_k
    const Eigen::Index n = nx + ny + (integral ? 1 : 0);
    // eps_k = -h [x_x; x_y], h = [Cx c_x, Cy c_y]; g = [Cx gamma_x; Cy gamma_y] shares u_c.
    Eigen::RowVectorXd h(nx + ny);
    h << cx * x.c, cy * y.c;
    Eigen::VectorXd g(nx + ny);
    g << cx * x.gamma, cy * y.gamma;
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    m.topLeftCorner(nx, nx) = x.phi;
    m.block(nx, nx, ny, ny) = y.phi;
    m.topLeftCorner(nx + ny, nx + ny) -= kc * g * h;
    if (integral) {
        m.block(0, nx + ny, nx + ny, 1) = coupling.ki * g;
        m.block(nx + ny, 0, 1, nx + ny) = -ts * h;
        m(nx + ny, nx + ny) = 1.0;
    }
    out.poles = lineLoopEigenvalues(m);
    lineLoopSortByModulus(out.poles);
    out.spectralRadius = std::abs(out.poles.back());
    out.stable = out.spectralRadius < 1.0 - kLineLoopStabilityTolerance;
    out.bounded = out.stable;
    if (!out.stable && integral && out.poles.size() >= 2 &&
        std::abs(out.poles[out.poles.size() - 2]) < 1.0 - kLineLoopStabilityTolerance &&
        std::abs(out.poles.back() - 1.0) < kLineLoopHiddenModeTolerance) {
        // One pole at z = 1: bounded when its mode leaves eps at zero (hiddenIntegralMode).
        const Eigen::EigenSolver<Eigen::MatrixXd> solver(m, true);
        Eigen::Index at = 0;
        (solver.eigenvalues().array() - 1.0).abs().minCoeff(&at);
        const Eigen::VectorXcd v = solver.eigenvectors().col(at);
        const std::complex<double> eps = h.cast<std::complex<double>>() * v.head(nx + ny);
        out.hiddenIntegralMode = std::abs(eps) <= kLineLoopHiddenModeTolerance * v.norm();
        out.bounded = out.hiddenIntegralMode;
    }
    if (!withMargins)
        return out;

    // L = C (Cx^2 Gx + Cy^2 Gy), C = (kc z - kp)/(z - 1) or kp.
    const TransferFunction sum = lineLoopAxisSum(x, y, cx, cy);
    if (integral)
        out.couplingLoop =
            TransferFunction(Polynomial::fromAscending({-coupling.kp, kc}) * sum.num(),
                             Polynomial::fromAscending({-1.0, 1.0}) * sum.den(), ts);
    else
        out.couplingLoop = TransferFunction(coupling.kp * sum.num(), sum.den(), ts);
    out.margins = stabilityMargins(out.couplingLoop);
    // Broken at each axis' input, the other axis and the coupling closed:
    // L_x = C Cx^2 Gx / (1 + C Cy^2 Gy) = Cn Cx^2 Nx Dy / (Dx (Cd Dy + Cn Cy^2 Ny)).
    const Polynomial cn = integral ? Polynomial::fromAscending({-coupling.kp, kc})
                                   : Polynomial::constant(coupling.kp);
    const Polynomial cd =
        integral ? Polynomial::fromAscending({-1.0, 1.0}) : Polynomial::constant(1.0);
    const auto brokenAt = [&](const SampledAxisModel& at, double cAt, const SampledAxisModel& other,
                              double cOther) -> std::optional<AxisBrokenLoop> {
        if (std::abs(cAt) <= kLineLoopNegligibleGain)
            return std::nullopt; // the coupling does not reach this axis at this direction
        const TransferFunction g = lineLoopAxisTransfer(at);
        TransferFunction loop(cAt * cAt * cn * g.num(), cd * g.den(), ts);
        if (std::abs(cOther) > kLineLoopNegligibleGain) {
            const TransferFunction h = lineLoopAxisTransfer(other);
            loop = TransferFunction(cAt * cAt * cn * g.num() * h.den(),
                                    g.den() * (cd * h.den() + cOther * cOther * cn * h.num()), ts);
        }
        AxisBrokenLoop broken;
        broken.loop = loop;
        // The margins from the state-space models on the unit circle (L's polynomials are ill
        // conditioned near z = 1 when the axes' poles cluster there), as the disk margin.
        const auto l = [&](double theta) {
            const std::complex<double> z = std::polar(1.0, theta);
            const std::complex<double> c =
                integral ? (kc * z - coupling.kp) / (z - 1.0) : std::complex<double>(coupling.kp);
            const std::complex<double> g = cAt * cAt * lineLoopAxisAt(at, z);
            const std::complex<double> h = cOther * cOther * lineLoopAxisAt(other, z);
            return c * g / (1.0 + c * h);
        };
        std::vector<std::complex<double>> poles = out.poles;
        for (const Eigen::MatrixXd* phi : {&x.phi, &y.phi}) {
            const auto p = lineLoopEigenvalues(*phi);
            poles.insert(poles.end(), p.begin(), p.end());
        }
        double thetaMin = 1e-4;
        for (const auto& p : poles)
            if (std::abs(1.0 - p) > 0.0)
                thetaMin = std::min(thetaMin, 0.1 * std::abs(1.0 - p));
        lineLoopGridMargins(l, std::max(thetaMin, 1e-12), poles, ts, broken);
        return broken;
    };
    out.brokenAtX = brokenAt(x, cx, y, cy);
    out.brokenAtY = brokenAt(y, cy, x, cx);

    if (out.bounded) { // the hidden integral mode is not in L (G(1) = 0 cancels C's pole)
        std::vector<std::complex<double>> poles = out.poles;
        for (const Eigen::MatrixXd* phi : {&x.phi, &y.phi}) {
            const auto p = lineLoopEigenvalues(*phi);
            poles.insert(poles.end(), p.begin(), p.end());
        }
        const double peak = lineLoopDiskPeak(LineLoopDiskEvaluator(x, y, cx, cy, coupling), poles);
        const double alpha = 1.0 / peak;
        out.diskMargin = alpha;
        out.diskGainMarginDb = alpha >= 2.0
                                   ? std::numeric_limits<double>::infinity()
                                   : 20.0 * std::log10((1.0 + alpha / 2.0) / (1.0 - alpha / 2.0));
        out.diskPhaseMarginDeg = 2.0 * std::atan(alpha / 2.0) * 180.0 / std::numbers::pi;
    }
    return out;
}

} // namespace xyt
