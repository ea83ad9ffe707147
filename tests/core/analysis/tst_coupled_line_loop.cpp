// SPDX-License-Identifier: GPL-3.0-or-later
// The cross-coupled line loop: its poles against the symmetric split of identical axes (closed
// form), the closed-loop polynomial built from transfer functions (an independent path), the
// ZOH spectral mapping of the Guillemin-Truxal designs and the RST design's T; a free response
// run step by step with CrossCoupling's law; the disk margin against a scalar closed form and
// against the peak sensitivity of stabilityMargins on the transformed loop 2L/(1 - L).
#include "core/analysis/coupled_line_loop.h"
#include "core/analysis/stability_margins.h"
#include "core/design/cross_coupling.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/model/errors.h"
#include "core/model/root_matching.h"
#include "core/model/state_space.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

using namespace xyt;
using Complex = std::complex<double>;

namespace {

constexpr double kPi = std::numbers::pi;
/// The coupling's period for the continuous (Guillemin-Truxal) axes.
constexpr double kGtPeriod = 0.01;

CrossCoupling gains(double kp, double ki) {
    CrossCoupling c;
    c.kp = kp;
    c.ki = ki;
    return c;
}

GtDesign gtDesign(const char* preset) {
    const GtPreset p = *findGtPreset(preset);
    return designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
}

SampledAxisModel gtAxis(const char* preset, double ts = kGtPeriod) {
    const GtPreset p = *findGtPreset(preset);
    return continuousAxisModel(p.plant.transferFunction(), gtDesign(preset).controller,
                               p.modelUnitsPerPositionUnit, ts);
}

/// The independent path: v -> y of the closed axis is P/(1 + P K) (v added at the plant input),
/// discretized by c2dZoh (a transfer-function route, other realization), in mm.
TransferFunction gtAxisTransfer(const char* preset, double ts = kGtPeriod) {
    const GtPreset p = *findGtPreset(preset);
    const TransferFunction g =
        c2dZoh(feedback(p.plant.transferFunction(), gtDesign(preset).controller), ts);
    return TransferFunction((1.0 / p.modelUnitsPerPositionUnit) * g.num(), g.den(), ts);
}

/**
 * The closed form of the ZOH, by partial fractions: with G_c = P/(1 + P K) of simple poles p_i
 * and residues r_i = N_c(p_i)/D_c'(p_i), the step response is G_c(0) + sum (r_i/p_i) e^{p_i t},
 * and G(z) = (1 - z^-1) Z{step response} = G_c(0) + sum (r_i/p_i) (z - 1)/(z - e^{p_i T}),
 * in mm. Each term is well conditioned near z = 1, unlike a polynomial in z with poles at
 * 1 - 1e-5.
 */
Complex gtAxisResponse(const char* preset, Complex z, double ts = kGtPeriod) {
    const GtPreset p = *findGtPreset(preset);
    const TransferFunction gc = feedback(p.plant.transferFunction(), gtDesign(preset).controller);
    const Polynomial slope = gc.den().derivative();
    Complex sum = gc.dcGain(); // 0: the PI rejects a constant input
    for (const Complex& pole : gc.poles())
        sum += gc.num()(pole) / slope(pole) / pole * (z - 1.0) / (z - std::exp(pole * ts));
    return sum / p.modelUnitsPerPositionUnit;
}

/// Spectral mapping: the eigenvalues of e^{A T} are e^{p T}, p the continuous closed-loop poles
/// (GtDesign::closedLoopPoles, the roots of the reference model's denominator).
std::vector<Complex> gtSampledPoles(const char* preset, double ts = kGtPeriod) {
    std::vector<Complex> z;
    for (const Complex& s : gtDesign(preset).closedLoopPoles)
        z.push_back(std::exp(s * ts));
    return z;
}

PolePlacementDesign ppDesign(const char* preset) {
    const PolePlacementPreset p = *findPolePlacementPreset(preset);
    return designPolePlacement(p.a, p.b, p.t, p.tsSeconds);
}

/// The independent path of an RST axis: A y = B (u + v), F u = -G y give y = B F/(A F + B G) v.
TransferFunction ppAxisTransfer(const PolePlacementDesign& d) {
    return TransferFunction::fromZInverse(d.b * d.f, d.a * d.f + d.b * d.g, d.tsSeconds);
}

/// C(z) = kp + ki T z/(z - 1) as numerator and denominator (the law of cross_coupling.h).
void couplingPolynomials(const CrossCoupling& c, double ts, Polynomial& num, Polynomial& den) {
    if (c.ki > 0.0) {
        num = Polynomial::fromAscending({-c.kp, c.kp + c.ki * ts});
        den = Polynomial::fromAscending({-1.0, 1.0});
    } else {
        num = Polynomial::constant(c.kp);
        den = Polynomial::constant(1.0);
    }
}

/// The closed-loop polynomial from transfer functions (Gx = Nx/Dx, Gy = Ny/Dy, C = Nc/Dc):
/// det = Dx Dy Dc + Nc (Cx^2 Nx Dy + Cy^2 Ny Dx), made monic.
Polynomial transferDeterminant(const TransferFunction& gx, const TransferFunction& gy, double theta,
                               const CrossCoupling& c) {
    Polynomial nc, dc;
    couplingPolynomials(c, gx.tsSeconds(), nc, dc);
    const double cx = -std::sin(theta), cy = std::cos(theta);
    return (gx.den() * gy.den() * dc +
            nc * (cx * cx * gx.num() * gy.den() + cy * cy * gy.num() * gx.den()))
        .monic();
}

/**
 * The relative error to expect from evaluating N(z)/D(z) on the unit circle through
 * coefficients that each carry round-off of the size of the largest coefficient of N and D
 * (N is built from differences of characteristic polynomials of D's size):
 * eps (deg + 1) max|c| / |p(z)| summed over N and D (first-order perturbation bound), times 1e3
 * because the coefficients come from eigenvalues of matrices up to 15 x 15 expanded by products
 * (a few hundred roundings). Large where poles or zeros cluster near z (the GT axes' poles at
 * 1 - 1e-5 near z = 1).
 */
double evaluationTolerance(const TransferFunction& g, Complex z) {
    const double eps = std::numeric_limits<double>::epsilon();
    const double scale = std::max(g.num().maxAbsCoefficient(), g.den().maxAbsCoefficient());
    const auto term = [&](const Polynomial& p) {
        return eps * (p.degree() + 1) * scale / std::abs(p(z));
    };
    return 1e3 * (term(g.num()) + term(g.den()));
}

/// z^k.
Polynomial zPower(int k) {
    std::vector<double> c(static_cast<std::size_t>(k) + 1, 0.0);
    c.back() = 1.0;
    return Polynomial::fromAscending(c);
}

/// c (zI - Phi)^-1 gamma, straight from the model (a linear solve).
Complex modelResponse(const SampledAxisModel& m, Complex z) {
    const Eigen::Index n = m.phi.rows();
    const Eigen::MatrixXcd a = z * Eigen::MatrixXcd::Identity(n, n) - m.phi.cast<Complex>();
    const Eigen::VectorXcd r = a.partialPivLu().solve(m.gamma.cast<Complex>().eval());
    return (m.c.cast<Complex>() * r)(0);
}

/// Every expected root has its own computed one within tol (relative, 1 for |root| < 1): the
/// assignment of matchRoots, so a multiset comparison.
void compareRootSets(const std::vector<Complex>& actual, const std::vector<Complex>& expected,
                     double tol) {
    QCOMPARE(actual.size(), expected.size());
    const std::vector<Complex> matched = continueBranches(expected, actual);
    for (std::size_t i = 0; i < expected.size(); ++i)
        QVERIFY2(test::nearComplex(matched[i], expected[i], 0.0,
                                   tol * std::max(1.0, std::abs(expected[i]))),
                 qPrintable(QStringLiteral("root %1: actual %2%3j, expected %4%5j (tol %6)")
                                .arg(i)
                                .arg(matched[i].real(), 0, 'g', 17)
                                .arg(matched[i].imag(), 0, 'g', 17)
                                .arg(expected[i].real(), 0, 'g', 17)
                                .arg(expected[i].imag(), 0, 'g', 17)
                                .arg(tol)));
}

/// One free response run with CrossCoupling's law, written out here independently of the
/// library's matrix: at each sample eps = -(Cx y_x + Cy y_y), I+ = I + T eps,
/// u_c = kp eps + ki I+, x+ = Phi x + gamma C u_c. Returns ||[x_x; x_y; I]|| per sample.
std::vector<double> freeResponseNorms(const SampledAxisModel& x, const SampledAxisModel& y,
                                      double theta, const CrossCoupling& c, int samples) {
    const double cx = -std::sin(theta), cy = std::cos(theta), ts = x.periodSeconds;
    Eigen::VectorXd xx = Eigen::VectorXd::Ones(x.phi.rows());
    Eigen::VectorXd xy = Eigen::VectorXd::LinSpaced(y.phi.rows(), -1.0, 0.5);
    double integral = c.ki > 0.0 ? 0.3 : 0.0;
    std::vector<double> norms;
    for (int k = 0; k < samples; ++k) {
        norms.push_back(std::sqrt(xx.squaredNorm() + xy.squaredNorm() + integral * integral));
        const double eps = -(cx * x.c.dot(xx) + cy * y.c.dot(xy));
        const double integralPlus = integral + ts * eps;
        const double uc = c.kp * eps + c.ki * integralPlus;
        xx = (x.phi * xx + x.gamma * (cx * uc)).eval();
        xy = (y.phi * xy + y.gamma * (cy * uc)).eval();
        if (c.ki > 0.0)
            integral = integralPlus;
    }
    return norms;
}

/// A one-state axis G(z) = 1/(z - a).
SampledAxisModel firstOrderAxis(double a) {
    SampledAxisModel m;
    m.phi = Eigen::MatrixXd::Constant(1, 1, a);
    m.gamma = Eigen::VectorXd::Ones(1);
    m.c = Eigen::RowVectorXd::Ones(1);
    m.periodSeconds = 0.1;
    return m;
}

} // namespace

class TstCoupledLineLoop : public QObject {
    Q_OBJECT
private slots:
    void continuousAxisMatchesZohOfClosedAxis();
    void rstAxisHasTheDesignPoles_data();
    void rstAxisHasTheDesignPoles();
    void rstAxisRunsAsTheDifferenceEquations();
    void delayedRstAxisKeepsRelativeDegree();
    void identicalAxesSplitIntoTangentAndNormal_data();
    void identicalAxesSplitIntoTangentAndNormal();
    void differentAxesMatchTransferDeterminant_data();
    void differentAxesMatchTransferDeterminant();
    void couplingLoopMatchesAxisTransfers();
    void axisLeftOutAtRightAngles();
    void couplingOffGivesEachAxisPoles();
    void integralAgainstPiAxesLeavesPoleAtOne();
    void freeResponseDecaysAtSpectralRadius();
    void gainBeyondMarginDestabilizes();
    void diskMarginScalarClosedForm_data();
    void diskMarginScalarClosedForm();
    void diskMarginEqualsSensitivityPeakOfTransformedLoop();
    void refusals();
};

// Closed forms: the state model's v -> y response against the partial-fraction ZOH of
// P/(1 + P K) (gtAxisResponse), and its eigenvalues against e^{p T} of the design's continuous
// closed-loop poles (spectral mapping).
void TstCoupledLineLoop::continuousAxisMatchesZohOfClosedAxis() {
    for (const char* preset : {"lower-base", "upper-base"}) {
        const SampledAxisModel m = gtAxis(preset);
        QCOMPARE(m.periodSeconds, kGtPeriod);
        QCOMPARE(m.phi.rows(), Eigen::Index(4)); // plant 3 + PI 1
        for (const double omega : {0.01, 0.5, 3.0, 40.0, 250.0, kPi / kGtPeriod}) {
            const Complex z = std::polar(1.0, omega * kGtPeriod);
            // 1e-9: the matrix exponential (~1e-14 relative), the solve with zI - Phi, whose
            // condition reaches 1e4 at omega T = 1e-4 (poles at 1 - 7e-5), and the residues of
            // a quartic's simple roots (~1e-13).
            QVERIFY2(test::nearComplex(modelResponse(m, z), gtAxisResponse(preset, z), 1e-9),
                     qPrintable(QStringLiteral("omega %1").arg(omega)));
        }
        const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(m.phi).eigenvalues();
        // 1e-11: eigenvalues of a 4 x 4 exponential against exp of the roots of the reference
        // model's quartic; the two poles nearest z = 1 are 6e-3 apart, so no amplification.
        compareRootSets({ev.data(), ev.data() + ev.size()}, gtSampledPoles(preset), 1e-11);
    }
}

void TstCoupledLineLoop::rstAxisHasTheDesignPoles_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<std::vector<double>>("t");
    QTest::newRow("x-axis, the paper's T = 1 - 0.2 z^-1")
        << QStringLiteral("x-axis") << std::vector{1.0, -0.2};
    QTest::newRow("y-axis, the paper's T = 1 - 0.2 z^-1")
        << QStringLiteral("y-axis") << std::vector{1.0, -0.2};
    // Roots 0.6 +- 0.3742j: a complex pair, deg T = 2.
    QTest::newRow("x-axis, T = 1 - 1.2 z^-1 + 0.5 z^-2")
        << QStringLiteral("x-axis") << std::vector{1.0, -1.2, 0.5};
}

// Closed form: A F + B G = T (the Diophantine equation the design solves), so the closed loop's
// characteristic polynomial is z^n T(z^-1): the roots of T in z plus poles at z = 0 (the
// redundant histories). Compared by coefficients, which are well conditioned even where the
// eigenvalues at z = 0 (a defective cluster) are not.
void TstCoupledLineLoop::rstAxisHasTheDesignPoles() {
    QFETCH(QString, preset);
    QFETCH(std::vector<double>, t);
    const PolePlacementPreset p = *findPolePlacementPreset(preset.toStdString());
    const PolePlacementDesign d =
        designPolePlacement(p.a, p.b, Polynomial::fromAscending(t), p.tsSeconds);
    const SampledAxisModel m = rstAxisModel(d);
    QCOMPARE(m.periodSeconds, p.tsSeconds);
    const int n = static_cast<int>(m.phi.rows());
    // Histories: y max(deg A, deg G) = 2, u deg F, ua deg B = 3.
    QCOMPARE(n, std::max(d.a.degree(), d.g.degree()) + d.f.degree() + d.b.degree());
    const Polynomial expected = d.t.reversed(n); // z^n T(z^-1)
    // 1e-12 of the largest coefficient (1): the design's own residual is below 1e-14 and the
    // characteristic polynomial from the eigenvalues of a 7 x 7 matrix of norm ~25 is exact to
    // ~1e-14 in its coefficients (backward stable eigenvalues, small roots).
    test::comparePolynomials(characteristicPolynomial(m.phi), expected, 1e-12);
    // The roots of T, found among the eigenvalues: the roots of T are simple and away from the
    // zero cluster, so 1e-10 (the cluster's own eigenvalues scatter by up to eps^(1/6) ~ 3e-3,
    // which is why they are not compared one by one).
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(m.phi).eigenvalues();
    for (const Complex& r :
         TransferFunction::fromZInverse(Polynomial::constant(1.0), d.t, 1.0).poles()) {
        double nearest = std::numeric_limits<double>::infinity();
        for (Eigen::Index i = 0; i < ev.size(); ++i)
            nearest = std::min(nearest, std::abs(ev(i) - r));
        XYT_COMPARE_NEAR(nearest, 0.0, 0.0, 1e-10);
    }
}

// Independent computation: runRstLoop's difference equations written out here (A y = B ua,
// F u = -G y, ua = u + v) on a v sequence, against the state model's x+ = Phi x + gamma v,
// y = c x from rest; and the model's v -> y against B F / (A F + B G).
void TstCoupledLineLoop::rstAxisRunsAsTheDifferenceEquations() {
    for (const char* preset : {"x-axis", "y-axis"}) {
        const PolePlacementDesign d = ppDesign(preset);
        const SampledAxisModel m = rstAxisModel(d);
        const int count = 60;
        std::vector<double> v(count), y(count, 0.0), u(count, 0.0), ua(count, 0.0);
        for (int k = 0; k < count; ++k)
            v[k] = std::sin(0.7 * k) + (k == 3 ? 1.0 : 0.0);
        const auto at = [](const std::vector<double>& s, int k) { return k < 0 ? 0.0 : s[k]; };
        Eigen::VectorXd x = Eigen::VectorXd::Zero(m.phi.rows());
        double scale = 0.0, worst = 0.0;
        for (int k = 0; k < count; ++k) {
            double yk = 0.0;
            for (int i = 1; i <= d.b.degree(); ++i)
                yk += d.b.coefficient(i) * at(ua, k - i);
            for (int i = 1; i <= d.a.degree(); ++i)
                yk -= d.a.coefficient(i) * at(y, k - i);
            y[k] = yk;
            double uk = 0.0;
            for (int i = 0; i <= d.g.degree(); ++i)
                uk -= d.g.coefficient(i) * at(y, k - i);
            for (int i = 1; i <= d.f.degree(); ++i)
                uk -= d.f.coefficient(i) * at(u, k - i);
            u[k] = uk / d.f.coefficient(0);
            ua[k] = u[k] + v[k];
            const double modelY = m.c.dot(x);
            scale = std::max(scale, std::abs(yk));
            worst = std::max(worst, std::abs(modelY - yk));
            x = (m.phi * x + m.gamma * v[k]).eval();
        }
        // 1e-12 of the largest |y|: the same sums in another order over 60 samples of a stable
        // loop (round-off ~1e-15 a step, not amplified).
        XYT_COMPARE_NEAR(worst, 0.0, 0.0, 1e-12 * scale);
        const TransferFunction g = ppAxisTransfer(d);
        for (const double theta : {0.0, 0.3, 1.5, kPi}) {
            const Complex z = std::polar(1.0, theta);
            // 1e-11: a 7 x 7 solve against polynomial evaluation, both well conditioned on the
            // unit circle (every pole within |z| <= 0.2 of a loop that has |T| >= 0.8 there).
            QVERIFY(test::nearComplex(modelResponse(m, z), g(z), 1e-11));
        }
    }
}

// Closed form: with two samples of delay (B = b_2 z^-2 + b_3 z^-3) the axis' v -> y is
// B F / T, of relative degree 2, and so is L = kp G for identical axes: the leading numerator
// coefficient must be exactly 0, not the round-off of a difference of characteristic
// polynomials (which would put a spurious zero near infinity). L still matches B F / T on the
// unit circle within the evaluation bound of its polynomials (evaluationTolerance; measured
// 1.4e-11 at omega T = 2.5 where |G| is small), at least 1e-11.
void TstCoupledLineLoop::delayedRstAxisKeepsRelativeDegree() {
    const PolePlacementPreset p = *findPolePlacementPreset("x-axis");
    const PolePlacementDesign d = designPolePlacement(
        p.a, Polynomial::fromAscending({0.0, 0.0, 0.0421, 0.0628}), p.t, p.tsSeconds);
    QCOMPARE(d.delay, 2);
    const SampledAxisModel m = rstAxisModel(d);
    const CoupledLineLoop loop = coupledLineLoop(m, m, 0.4, gains(0.5, 0.0));
    QCOMPARE(loop.couplingLoop.relativeDegree(), 2);
    const TransferFunction g = ppAxisTransfer(d);
    for (const double theta : {0.1, 1.0, 2.5}) {
        const Complex z = std::polar(1.0, theta);
        const double tol = std::max(1e-11, evaluationTolerance(loop.couplingLoop, z));
        QVERIFY2(test::nearComplex(loop.couplingLoop(z), 0.5 * g(z), tol),
                 qPrintable(QStringLiteral("theta %1, tol %2").arg(theta).arg(tol)));
    }
}

void TstCoupledLineLoop::identicalAxesSplitIntoTangentAndNormal_data() {
    QTest::addColumn<double>("theta");
    QTest::addColumn<double>("kp");
    QTest::addColumn<double>("ki");
    for (const double theta : {0.0, 0.3, kPi / 4.0, kPi / 2.0, 2.5}) {
        const QByteArray t = QByteArray::number(theta, 'g', 4);
        QTest::newRow(("P, theta " + t).constData()) << theta << 1.0 << 0.0;
        QTest::newRow(("PI, theta " + t).constData()) << theta << 0.05 << 0.5;
    }
}

// Closed form by symmetry: with identical axes the coordinates along and across the line
// decouple. Along the line (tangent) the coupling does not act: the axis' own poles, here
// e^{p T} of the Guillemin-Truxal closed loop. Across it (normal) the loop is the scalar
// C(z) G(z), whose closed-loop poles are the roots of Dc D + Nc N (G = N/D by c2dZoh, C of the
// law). Independent of theta.
void TstCoupledLineLoop::identicalAxesSplitIntoTangentAndNormal() {
    QFETCH(double, theta);
    QFETCH(double, kp);
    QFETCH(double, ki);
    const CrossCoupling c = gains(kp, ki);
    const SampledAxisModel axis = gtAxis("lower-base");
    const CoupledLineLoop loop = coupledLineLoop(axis, axis, theta, c);
    const TransferFunction g = gtAxisTransfer("lower-base");
    Polynomial nc, dc;
    couplingPolynomials(c, kGtPeriod, nc, dc);
    std::vector<Complex> expected = gtSampledPoles("lower-base");
    const std::vector<Complex> normal = (dc * g.den() + nc * g.num()).roots();
    expected.insert(expected.end(), normal.begin(), normal.end());
    // 1e-9 relative: roots of a quintic and eigenvalues of a 9 x 9 matrix; the closest pair
    // (0.99993 and 1) is 7e-5 apart, measured agreement ~1e-11.
    compareRootSets(loop.poles, expected, 1e-9);
    // Invariant: the poles are sorted by modulus and the radius is the last one's.
    for (std::size_t i = 1; i < loop.poles.size(); ++i)
        QVERIFY(std::abs(loop.poles[i - 1]) <= std::abs(loop.poles[i]));
    QCOMPARE(loop.spectralRadius, std::abs(loop.poles.back()));
    // Equal denominators are summed over one: L = C (Cx^2 + Cy^2) G = C G, of degree 4 (+1).
    QCOMPARE(loop.couplingLoop.den().degree(), 4 + (ki > 0.0 ? 1 : 0));
}

void TstCoupledLineLoop::differentAxesMatchTransferDeterminant_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<double>("theta");
    QTest::addColumn<double>("kp");
    QTest::addColumn<double>("ki");
    QTest::newRow("GT lower/upper, P, theta 0.3") << QStringLiteral("gt") << 0.3 << 1.0 << 0.0;
    QTest::newRow("GT lower/upper, P, theta 2.2") << QStringLiteral("gt") << 2.2 << 1.0 << 0.0;
    QTest::newRow("GT lower/upper, PI, theta 0.3") << QStringLiteral("gt") << 0.3 << 0.05 << 0.5;
    QTest::newRow("GT lower/upper, unstable P") << QStringLiteral("gt") << 0.785 << 20.0 << 0.0;
    QTest::newRow("RST x/y, PI, theta 0.7") << QStringLiteral("pp") << 0.7 << 1.0 << 1.0;
    QTest::newRow("RST x/y, P, theta -1") << QStringLiteral("pp") << -1.0 << 0.5 << 0.0;
    QTest::newRow("RST x/y, unstable PI") << QStringLiteral("pp") << 0.7 << 12.0 << 12.0;
}

// Independent path: the closed-loop polynomial from transfer functions,
// det = Dx Dy Dc + Nc (Cx^2 Nx Dy + Cy^2 Ny Dx), with G from c2dZoh (GT) or B F / (A F + B G)
// (RST), against the characteristic polynomial of the coupled poles. Coefficients, because the
// roots near z = 1 (GT) and at z = 0 (RST) are clustered and ill conditioned as roots.
// Invariant too: couplingLoop's D + N is the same polynomial (no axis left out here).
void TstCoupledLineLoop::differentAxesMatchTransferDeterminant() {
    QFETCH(QString, kind);
    QFETCH(double, theta);
    QFETCH(double, kp);
    QFETCH(double, ki);
    const CrossCoupling c = gains(kp, ki);
    const bool gt = kind == "gt";
    const PolePlacementDesign dx = ppDesign("x-axis"), dy = ppDesign("y-axis");
    const SampledAxisModel x = gt ? gtAxis("lower-base") : rstAxisModel(dx);
    const SampledAxisModel y = gt ? gtAxis("upper-base") : rstAxisModel(dy);
    const TransferFunction gx = gt ? gtAxisTransfer("lower-base") : ppAxisTransfer(dx);
    const TransferFunction gy = gt ? gtAxisTransfer("upper-base") : ppAxisTransfer(dy);
    const CoupledLineLoop loop = coupledLineLoop(x, y, theta, c);
    // The state count: both axes plus the integral when ki > 0.
    QCOMPARE(loop.poles.size(),
             static_cast<std::size_t>(x.phi.rows() + y.phi.rows() + (ki > 0.0 ? 1 : 0)));
    const Polynomial actual = Polynomial::fromRoots(loop.poles);
    Polynomial expected = transferDeterminant(gx, gy, theta, c);
    // The RST transfer functions have fewer poles than states (the histories' extra poles at
    // z = 0 cancel in B F / T): pad with those zeros.
    const int missing = actual.degree() - expected.degree();
    QVERIFY(missing >= 0);
    expected = expected * zPower(missing);
    // 1e-9 of the largest coefficient: polynomial products of degree up to 15 and
    // characteristic polynomials from eigenvalues (measured ~1e-11 for the stable rows, 1e-9 for
    // the unstable GT row whose coefficients reach 1e3).
    test::comparePolynomials(actual, expected, 1e-9);
    const Polynomial closed = (loop.couplingLoop.den() + loop.couplingLoop.num()).monic();
    const int merged = actual.degree() - closed.degree();
    if (merged == 0) {
        test::comparePolynomials(closed, expected, 1e-9);
    } else {
        // The RST designs share T, so both axes' closed loops have the denominator
        // z^6 (z - 0.2): L was summed over it once (the header's bookkeeping), and the whole
        // polynomial is D + N times that denominator (det = D (D Dc + Nc (Cx^2 Nx + Cy^2 Ny))).
        test::comparePolynomials(gx.den(), gy.den(), 1e-12);
        test::comparePolynomials(closed * gx.den() * zPower(merged - gx.den().degree()), expected,
                                 1e-9);
    }
    // The margins' own verdict (the roots of D + N) agrees where the dominant pole is clear of
    // the circle by 1e-3: the GT rows keep poles within 1e-5 of z = 1, where the roots of a
    // degree-9 polynomial scatter by up to 2e-4 (measured).
    if (std::abs(loop.spectralRadius - 1.0) > 1e-3)
        QCOMPARE(loop.margins.closedLoopStable, loop.stable);
    // The loop broken at each axis' input (the other axis and the coupling closed): 1 + L has
    // the coupled loop's characteristic polynomial too, L_x = C Cx^2 Gx / (1 + C Cy^2 Gy) having
    // the denominator Dx (Dc Dy + Nc Cy^2 Ny): D + N is det itself, over all the states.
    for (const std::optional<AxisBrokenLoop>* broken : {&loop.brokenAtX, &loop.brokenAtY}) {
        QVERIFY(broken->has_value());
        const Polynomial atAxis = ((*broken)->loop.den() + (*broken)->loop.num()).monic();
        const int pad = actual.degree() - atAxis.degree();
        QVERIFY(pad >= 0);
        test::comparePolynomials(atAxis * zPower(pad), expected, 1e-9);
        // Its margins from the state-space grid against stabilityMargins of its polynomials
        // where those are well conditioned (the RST rows: poles well inside the circle):
        // crossings refined to 1e-13 against Newton-refined roots, 1e-6 degree and dB.
        if (!gt && loop.stable) {
            const StabilityMargins m = stabilityMargins((*broken)->loop);
            QVERIFY2(std::abs((*broken)->phaseMarginDeg - m.phaseMarginDeg) < 1e-6 ||
                         (std::isinf(m.phaseMarginDeg) && std::isinf((*broken)->phaseMarginDeg)),
                     qPrintable(
                         QString("%1 vs %2").arg((*broken)->phaseMarginDeg).arg(m.phaseMarginDeg)));
            QVERIFY2(
                std::abs((*broken)->gainMarginDb - m.gainMarginDb) < 1e-6 ||
                    (std::isinf(m.gainMarginDb) && std::isinf((*broken)->gainMarginDb)),
                qPrintable(QString("%1 vs %2").arg((*broken)->gainMarginDb).arg(m.gainMarginDb)));
        }
    }
}

// Independent path: couplingLoop against C(z) (Cx^2 Gx(z) + Cy^2 Gy(z)) evaluated from the
// partial-fraction ZOH (GT) or B F / T (RST), on the unit circle. Near omega = 0 the GT axes'
// poles at 1 - 1e-5 make L's polynomials ill conditioned at z = e^{j omega T} (|D(z)| ~ 1e-15
// against coefficients ~20), which the header states: the tolerance is that evaluation bound
// (evaluationTolerance), at least 1e-10.
void TstCoupledLineLoop::couplingLoopMatchesAxisTransfers() {
    const double theta = 0.9;
    const double cx = -std::sin(theta), cy = std::cos(theta);
    struct Case {
        SampledAxisModel x, y;
        std::function<Complex(Complex)> gx, gy;
    };
    const PolePlacementDesign dx = ppDesign("x-axis"), dy = ppDesign("y-axis");
    const std::vector<Case> cases = {
        {gtAxis("lower-base"), gtAxis("upper-base"),
         [](Complex z) { return gtAxisResponse("lower-base", z); },
         [](Complex z) { return gtAxisResponse("upper-base", z); }},
        {rstAxisModel(dx), rstAxisModel(dy), [&dx](Complex z) { return ppAxisTransfer(dx)(z); },
         [&dy](Complex z) { return ppAxisTransfer(dy)(z); }},
    };
    for (const Case& k : cases) {
        const double ts = k.x.periodSeconds;
        const CrossCoupling c = gains(0.4, 2.0);
        const CoupledLineLoop loop = coupledLineLoop(k.x, k.y, theta, c);
        QCOMPARE(loop.couplingLoop.tsSeconds(), ts);
        for (const double w : {1e-3, 0.05, 0.2, 0.4, 1.3, 2.9, kPi}) {
            const Complex z = std::polar(1.0, w);
            const Complex cz = c.kp + c.ki * ts * z / (z - 1.0);
            const Complex expected = cz * (cx * cx * k.gx(z) + cy * cy * k.gy(z));
            const double tol = std::max(1e-10, evaluationTolerance(loop.couplingLoop, z));
            QVERIFY2(test::nearComplex(loop.couplingLoop(z), expected, tol),
                     qPrintable(QStringLiteral("omega T = %1, tol %2").arg(w).arg(tol)));
        }
    }
}

// Invariant (bookkeeping): at theta = 0 the x axis gets no coupling (Cx = -sin 0 = 0) and at
// theta = pi/2 the y axis gets Cy = cos(pi/2) ~ 6e-17: that axis is left out of couplingLoop,
// so the coupled characteristic polynomial is that axis' denominator times L's D + N. And
// stabilityMargins runs on the smaller loop without complaint.
void TstCoupledLineLoop::axisLeftOutAtRightAngles() {
    const TransferFunction gl = gtAxisTransfer("lower-base"), gu = gtAxisTransfer("upper-base");
    for (const double theta : {0.0, kPi / 2.0}) {
        const CoupledLineLoop loop =
            coupledLineLoop(gtAxis("lower-base"), gtAxis("upper-base"), theta, gains(1.0, 0.0));
        const TransferFunction& outside = theta == 0.0 ? gl : gu;
        QCOMPARE(loop.couplingLoop.den().degree(), 4); // the other axis alone
        const Polynomial closed = (loop.couplingLoop.den() + loop.couplingLoop.num()).monic();
        // 1e-9 of the largest coefficient, as in differentAxesMatchTransferDeterminant.
        test::comparePolynomials(Polynomial::fromRoots(loop.poles), closed * outside.den(), 1e-9);
        QVERIFY(loop.stable);
        QVERIFY(loop.margins.closedLoopStable);
        QVERIFY(std::isfinite(loop.margins.gainMarginFactor));
        QVERIFY(loop.diskMargin > 0.0);
    }
}

// Closed form: with kp = ki = 0 nothing couples the axes, so the poles are each axis' own:
// e^{p T} of both Guillemin-Truxal designs (spectral mapping). couplingLoop is the zero gain,
// the margins are left default, the disk margin 0 (documented: no loop).
void TstCoupledLineLoop::couplingOffGivesEachAxisPoles() {
    const CoupledLineLoop loop =
        coupledLineLoop(gtAxis("lower-base"), gtAxis("upper-base"), 0.6, CrossCoupling{});
    std::vector<Complex> expected = gtSampledPoles("lower-base");
    const std::vector<Complex> upper = gtSampledPoles("upper-base");
    expected.insert(expected.end(), upper.begin(), upper.end());
    // 1e-11 as in continuousAxisMatchesZohOfClosedAxis.
    compareRootSets(loop.poles, expected, 1e-11);
    QVERIFY(loop.stable); // every e^{p T} with Re p < 0, the slowest 1 - 1.4e-5
    QVERIFY(loop.couplingLoop.num().isZero());
    QCOMPARE(loop.couplingLoop.tsSeconds(), kGtPeriod);
    QVERIFY(loop.margins.gainMargins.empty() && std::isinf(loop.margins.gainMarginFactor));
    QCOMPARE(loop.diskMargin, 0.0);
}

// Closed form: a Guillemin-Truxal axis has a PI, whose integrator rejects a constant input: the
// v -> y transfer P/(1 + P K) vanishes at s = 0, and the ZOH keeps that DC gain, so G(1) = 0
// exactly. The coupling's own integrator pole z = 1 is then not moved by any gain: the coupled
// loop keeps an eigenvalue at z = 1 (a continuum of equilibria where the axes' integrators and
// the coupling's share a constant voltage). It must read as not stable despite round-off, and as
// bounded: that mode leaves eps at zero (the contour never sees it), every other pole is inside
// the circle, and the loop broken at the coupling (where G(1) = 0 cancels C's pole) has a disk
// margin.
void TstCoupledLineLoop::integralAgainstPiAxesLeavesPoleAtOne() {
    const CoupledLineLoop loop =
        coupledLineLoop(gtAxis("lower-base"), gtAxis("upper-base"), 0.4, gains(0.05, 0.5));
    // 1e-12: the eigenvalue round-off of a 9 x 9 matrix of norm ~1 (about 1e-15), well inside
    // the stability tolerance of the same size.
    XYT_COMPARE_NEAR(loop.spectralRadius, 1.0, 0.0, 1e-12);
    QVERIFY(!loop.stable);
    QVERIFY(loop.hiddenIntegralMode);
    QVERIFY(loop.bounded);
    QVERIFY(std::abs(loop.poles[loop.poles.size() - 2]) < 1.0 - 1e-12);
    QVERIFY(loop.diskMargin > 0.0 && loop.diskMargin < 2.0);
    // Without the integral the same axes are stable outright: nothing hidden.
    const CoupledLineLoop proportional =
        coupledLineLoop(gtAxis("lower-base"), gtAxis("upper-base"), 0.4, gains(0.05, 0.0));
    QVERIFY(proportional.stable && proportional.bounded && !proportional.hiddenIntegralMode);
}

// Invariant: the free response of the law, run step by step (freeResponseNorms, not the
// library's matrix), decays as rho^k with rho the spectral radius. With the RST axes the
// dominant pole (0.98988) is real and the next is 0.46: after 60 samples its share is
// (0.46/0.99)^60 < 1e-19, so (||x_K|| / ||x_60||)^(1/(K - 60)) equals rho to round-off: 1e-9.
void TstCoupledLineLoop::freeResponseDecaysAtSpectralRadius() {
    const SampledAxisModel x = rstAxisModel(ppDesign("x-axis"));
    const SampledAxisModel y = rstAxisModel(ppDesign("y-axis"));
    const CrossCoupling c = gains(1.0, 1.0);
    const CoupledLineLoop loop = coupledLineLoop(x, y, 0.7, c);
    QVERIFY(loop.stable);
    QCOMPARE(loop.poles.back().imag(), 0.0);
    QVERIFY(std::abs(loop.poles[loop.poles.size() - 2]) < 0.5);
    const int k0 = 60, k1 = 1060;
    const std::vector<double> norms = freeResponseNorms(x, y, 0.7, c, k1 + 1);
    const double rate = std::pow(norms[k1] / norms[k0], 1.0 / (k1 - k0));
    XYT_COMPARE_NEAR(rate, loop.spectralRadius, 1e-9, 0.0);
    QVERIFY(norms[k1] < 1e-3 * norms[0]);
}

// Invariant between two computations: scaling the whole coupling (kp and ki) by g scales L by
// g, so the coupled loop must turn unstable as g crosses the gain margin of stabilityMargins.
// Beyond it the step-by-step run grows at the spectral radius: the dominant pair there is
// complex (|z| = 1.145 near 90 degrees), so the norm is taken as the largest of 16 consecutive
// samples (a few periods) and the exponent compared within 2% (the bounded oscillation over
// 400 samples changes the log-rate by at most ln(2)/400, 0.5% of ln 1.145).
void TstCoupledLineLoop::gainBeyondMarginDestabilizes() {
    const SampledAxisModel x = rstAxisModel(ppDesign("x-axis"));
    const SampledAxisModel y = rstAxisModel(ppDesign("y-axis"));
    const CoupledLineLoop nominal = coupledLineLoop(x, y, 0.7, gains(1.0, 1.0));
    const double gm = nominal.margins.upperGainMarginFactor;
    QVERIFY(std::isfinite(gm) && gm > 1.0);
    QVERIFY(coupledLineLoop(x, y, 0.7, gains(gm * (1 - 1e-6), gm * (1 - 1e-6))).stable);
    const CoupledLineLoop beyond =
        coupledLineLoop(x, y, 0.7, gains(gm * (1 + 1e-6), gm * (1 + 1e-6)));
    QVERIFY(!beyond.stable);
    // 1e-5: the gain margin factor is exact to ~1e-12; 1e-6 of gain moves the crossing pole
    // by ~1e-6 in modulus.
    XYT_COMPARE_NEAR(beyond.spectralRadius, 1.0, 0.0, 1e-5);

    const CrossCoupling big = gains(12.0, 12.0);
    const CoupledLineLoop unstable = coupledLineLoop(x, y, 0.7, big);
    QVERIFY(!unstable.stable);
    QCOMPARE(unstable.diskMargin, 0.0);
    QVERIFY(unstable.spectralRadius > 1.1);
    const int k0 = 100, k1 = 500;
    const std::vector<double> norms = freeResponseNorms(x, y, 0.7, big, k1 + 1);
    const auto windowMax = [&norms](int k) {
        return *std::max_element(norms.begin() + k - 15, norms.begin() + k + 1);
    };
    QVERIFY(norms[k1] > 1e6 * norms[0]);
    const double logRate = std::log(windowMax(k1) / windowMax(k0)) / (k1 - k0);
    XYT_COMPARE_NEAR(logRate, std::log(unstable.spectralRadius), 0.02, 0.0);
}

void TstCoupledLineLoop::diskMarginScalarClosedForm_data() {
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("k");
    QTest::newRow("a 0.5, k 0.3") << 0.5 << 0.3;
    QTest::newRow("a 0.9, k 0.5") << 0.9 << 0.5;
    QTest::newRow("a -0.5, k 0.2") << -0.5 << 0.2;
    QTest::newRow("a 0.95, k 0.05") << 0.95 << 0.05;
    QTest::newRow("a 0.5, k 1.6 (unstable)") << 0.5 << 1.6;
}

// Closed form derived here: identical one-state axes G = 1/(z - a) and a P coupling k give
// L = k (Cx^2 + Cy^2)/(z - a) = k/(z - a) (any theta), closed-loop pole a - k. Then
// (1 - L)/(2 (1 + L)) = (z - (a + k)) / (2 (z - (a - k))), and |z - p|^2/|z - q|^2 =
// (1 + p^2 - 2 p cos w)/(1 + q^2 - 2 q cos w) is monotonic in cos w, so its maximum is at
// w = 0 or pi: alpha = 2 / max(|1 - a - k|/|1 - a + k|, |1 + a + k|/|1 + a - k|).
// For a = 0.5, k = 0.3 the maximum is at z = -1 on the real axis, where the disk's upper gain
// (1 + alpha/2)/(1 - alpha/2) must equal the exact gain margin (1 + a)/k = 5 (pole a - g k at
// -1), which stabilityMargins gives too.
void TstCoupledLineLoop::diskMarginScalarClosedForm() {
    QFETCH(double, a);
    QFETCH(double, k);
    const SampledAxisModel axis = firstOrderAxis(a);
    const CoupledLineLoop loop = coupledLineLoop(axis, axis, 1.0, gains(k, 0.0));
    const bool stable = std::abs(a - k) < 1.0;
    QCOMPARE(loop.stable, stable);
    // The poles: a (tangent) and a - k (normal); 1e-14 for 2 x 2 eigenvalues of order 1.
    compareRootSets(loop.poles, {Complex(a), Complex(a - k)}, 1e-14);
    if (!stable) {
        QCOMPARE(loop.diskMargin, 0.0);
        return;
    }
    const double alpha = 2.0 / std::max(std::abs(1.0 - a - k) / std::abs(1.0 - a + k),
                                        std::abs(1.0 + a + k) / std::abs(1.0 + a - k));
    // 1e-12: the peak sits at a grid end (omega = 0 or pi/T), which the grid holds exactly.
    XYT_COMPARE_NEAR(loop.diskMargin, alpha, 1e-12, 0.0);
    XYT_COMPARE_NEAR(loop.diskPhaseMarginDeg, 2.0 * std::atan(alpha / 2.0) * 180.0 / kPi, 1e-12,
                     0.0);
    if (alpha < 2.0)
        XYT_COMPARE_NEAR(loop.diskGainMarginDb,
                         20.0 * std::log10((1.0 + alpha / 2.0) / (1.0 - alpha / 2.0)), 1e-12, 0.0);
    else
        QVERIFY(std::isinf(loop.diskGainMarginDb));
    if (a == 0.5 && k == 0.3) {
        XYT_COMPARE_NEAR(std::pow(10.0, loop.diskGainMarginDb / 20.0), 5.0, 1e-12, 0.0);
        XYT_COMPARE_NEAR(loop.margins.upperGainMarginFactor, 5.0, 1e-12, 0.0);
    }
}

// Independent computation: |(1 - L)/(1 + L)| = |S'| with S' = 1/(1 + L'), L' = 2L/(1 - L)
// (D' = D - N, N' = 2N, so D' + N' = D + N and D' = D - N), so alpha = 2 / Ms(L'), the peak
// sensitivity stabilityMargins finds from the roots of a polynomial, not on a grid. And a
// brute-force dense grid never exceeds the peak found.
void TstCoupledLineLoop::diskMarginEqualsSensitivityPeakOfTransformedLoop() {
    struct Case {
        const char* name;
        SampledAxisModel x, y;
        double theta;
        CrossCoupling c;
    };
    const std::vector<Case> cases = {
        {"GT P", gtAxis("lower-base"), gtAxis("upper-base"), 0.3, gains(1.0, 0.0)},
        {"GT P strong", gtAxis("lower-base"), gtAxis("upper-base"), 2.0, gains(2.5, 0.0)},
        {"RST PI", rstAxisModel(ppDesign("x-axis")), rstAxisModel(ppDesign("y-axis")), 0.7,
         gains(1.0, 1.0)},
        {"RST PI strong", rstAxisModel(ppDesign("x-axis")), rstAxisModel(ppDesign("y-axis")), -0.4,
         gains(5.0, 3.0)},
    };
    for (const Case& k : cases) {
        const CoupledLineLoop loop = coupledLineLoop(k.x, k.y, k.theta, k.c);
        QVERIFY2(loop.stable, k.name);
        const TransferFunction& l = loop.couplingLoop;
        const StabilityMargins transformed =
            stabilityMargins(TransferFunction(2.0 * l.num(), l.den() - l.num(), l.tsSeconds()));
        // 1e-6: stabilityMargins finds a flat peak's frequency from a polynomial root to about
        // sqrt(eps) relative only (its own test allows 1e-7 there), which leaves its value low by
        // up to ~1e-7 (measured 1.4e-7 on the "GT P strong" row, its frequency 6e-5 off the
        // peak that the dense grid below finds).
        XYT_COMPARE_NEAR(loop.diskMargin, 2.0 / transformed.peakSensitivity, 1e-6, 0.0);
        // A brute-force grid of 100 001 frequencies, linear in omega, evaluated from the
        // state-space models as the library does: its maximum is a lower bound of the peak, so
        // it must not exceed the refined peak beyond the solves' round-off (1e-11), and comes
        // within 1e-7 of it (a spacing of pi/1e5 in omega T off a peak of curvature below
        // ~1e3, measured ~2e-10).
        const double cx = -std::sin(k.theta), cy = std::cos(k.theta);
        double dense = 0.0;
        for (int i = 0; i <= 100000; ++i) {
            const Complex z = std::polar(1.0, kPi * i / 100000.0);
            const Complex g = cx * cx * modelResponse(k.x, z) + cy * cy * modelResponse(k.y, z);
            const Complex lz = (k.c.kp + k.c.ki * l.tsSeconds() * z / (z - 1.0)) * g;
            dense = std::max(dense, std::abs((1.0 - lz) / (2.0 * (1.0 + lz))));
        }
        QVERIFY2(dense <= (1.0 + 1e-11) / loop.diskMargin, k.name);
        XYT_COMPARE_NEAR(dense, 1.0 / loop.diskMargin, 1e-7, 0.0);
        // The disk's gain range lies inside the exact one (a disk is a subset of all gain
        // changes): (1 + alpha/2)/(1 - alpha/2) <= the upper gain margin, up to 1e-9.
        if (loop.diskMargin < 2.0)
            QVERIFY2(std::pow(10.0, loop.diskGainMarginDb / 20.0) <=
                         loop.margins.upperGainMarginFactor * (1.0 + 1e-9),
                     k.name);
    }
}

// Refusals, each naming its field (errors.h): the coupling's gains first
// (validateCrossCoupling with "cross_coupling"), then the models, the periods and theta.
void TstCoupledLineLoop::refusals() {
    const SampledAxisModel a = gtAxis("lower-base");
    const SampledAxisModel other = gtAxis("upper-base", kGtPeriod * (1.0 + 1e-9));
    const SampledAxisModel close = gtAxis("upper-base", kGtPeriod * (1.0 + 1e-13));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, other, 0.0, gains(1.0, 0.0)); }),
             QStringLiteral("period"));
    // Within 1e-12 relative: the same period.
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, close, 0.0, gains(1.0, 0.0)); }),
             QStringLiteral("<no exception>"));
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, other, 0.0, gains(-1.0, 0.0)); }),
             QStringLiteral("cross_coupling.kp"));
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, a, 0.0, gains(1.0, nan)); }),
             QStringLiteral("cross_coupling.ki"));
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, a, nan, gains(1.0, 0.0)); }),
             QStringLiteral("theta"));
    SampledAxisModel broken = a;
    broken.gamma = Eigen::VectorXd::Ones(2);
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(a, broken, 0.0, gains(1.0, 0.0)); }),
             QStringLiteral("y_axis"));
    SampledAxisModel undefined = a;
    undefined.periodSeconds = 0.0;
    QCOMPARE(test::invalidInputField([&] { coupledLineLoop(undefined, a, 0.0, gains(1.0, 0.0)); }),
             QStringLiteral("period"));

    const GtPreset p = *findGtPreset("lower-base");
    const TransferFunction plant = p.plant.transferFunction();
    const TransferFunction pi = gtDesign("lower-base").controller;
    QCOMPARE(
        test::invalidInputField([&] { continuousAxisModel(c2dZoh(plant, 0.01), pi, 0.001, 0.01); }),
        QStringLiteral("plant"));
    QCOMPARE(test::invalidInputField([&] {
                 continuousAxisModel(TransferFunction::fromDescending({1.0, 1.0}, {1.0, 2.0}), pi,
                                     0.001, 0.01);
             }),
             QStringLiteral("plant")); // proper, not strictly
    QCOMPARE(test::invalidInputField([&] {
                 continuousAxisModel(
                     plant, TransferFunction::fromDescending({1.0, 0.0, 1.0}, {1.0}), 0.001, 0.01);
             }),
             QStringLiteral("controller"));
    for (const double period : {0.0, -0.01, nan})
        QCOMPARE(test::invalidInputField([&] { continuousAxisModel(plant, pi, 0.001, period); }),
                 QStringLiteral("period"));
    for (const double unit : {0.0, -1.0, nan})
        QCOMPARE(test::invalidInputField([&] { continuousAxisModel(plant, pi, unit, 0.01); }),
                 QStringLiteral("model_unit_scale"));

    PolePlacementDesign d = ppDesign("x-axis");
    d.tsSeconds = 0.0;
    QCOMPARE(test::invalidInputField([&] { rstAxisModel(d); }), QStringLiteral("ts"));
    d = ppDesign("x-axis");
    d.b = Polynomial::fromAscending({0.1, 0.0421});
    QCOMPARE(test::invalidInputField([&] { rstAxisModel(d); }), QStringLiteral("b"));
}

QTEST_APPLESS_MAIN(TstCoupledLineLoop)
#include "tst_coupled_line_loop.moc"
