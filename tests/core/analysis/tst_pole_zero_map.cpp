// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/damping_grid.h"
#include "core/analysis/pole_zero_map.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace xyt;
using Complex = std::complex<double>;

class TstPoleZeroMap : public QObject {
    Q_OBJECT
private slots:
    void gtSetsMatchClosedForms_data();
    void gtSetsMatchClosedForms();
    void xAxisArxModelZeros();
    void dampingOfClosedForms_data();
    void dampingOfClosedForms();
    void sPlaneGridLinesHaveTheirZetaAndOmega();
    void zPlaneGridIsTheImageOfTheSPlaneGrid();
    void niceFrequencies();
    void invalidGridThrows();
};

void TstPoleZeroMap::gtSetsMatchClosedForms_data() {
    QTest::addColumn<QString>("preset");
    QTest::newRow("lower-base") << "lower-base";
    QTest::newRow("upper-base") << "upper-base";
}

void TstPoleZeroMap::gtSetsMatchClosedForms() {
    QFETCH(QString, preset);
    const GtPreset p = *findGtPreset(preset.toStdString());
    const GtDesign d = designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp);
    const auto sets = gtPoleZeroSets(d);
    QCOMPARE(sets.size(), std::size_t(5));
    const char* names[] = {"plant", "controller", "open loop", "closed loop", "reference model"};
    for (std::size_t i = 0; i < 5; ++i)
        QCOMPARE(sets[i].name, std::string(names[i]));
    // Plant k0/(s(s^2 + a1 s + a2)), Eq. 9: poles -a1/2 -+ sqrt(a1^2/4 - a2), 0; no zeros.
    const double disc = std::sqrt(p.plant.a1 * p.plant.a1 / 4.0 - p.plant.a2);
    QCOMPARE(sets[0].poles.size(), std::size_t(3));
    QVERIFY(sets[0].zeros.empty());
    XYT_COMPARE_NEAR(sets[0].poles[0].real(), -p.plant.a1 / 2.0 - disc, 1e-12, 0.0);
    XYT_COMPARE_NEAR(sets[0].poles[1].real(), -p.plant.a1 / 2.0 + disc, 1e-12, 0.0);
    XYT_COMPARE_NEAR(sets[0].poles[2].real(), 0.0, 0.0, 1e-12);
    // Controller kp + ki/s (Eq. 16): pole 0, zero -psi1 = -wn^4/(kp k0) (Eq. 11).
    const double psi1 = std::pow(p.omegaNRadPerSec, 4) / (p.kp * p.plant.k0);
    XYT_COMPARE_NEAR(sets[1].zeros.at(0).real(), -psi1, 1e-12, 0.0);
    XYT_COMPARE_NEAR(sets[1].poles.at(0).real(), 0.0, 0.0, 0.0);
    // Open loop: the double pole at 0 plus the plant's, the controller's zero.
    QCOMPARE(sets[2].poles.size(), std::size_t(4));
    QCOMPARE(sets[2].zeros.size(), std::size_t(1));
    // Closed loop = reference model (the design matches Eq. 10 to Eq. 7 exactly): the same
    // poles (two computations of one polynomial's roots: 1e-9 of the largest magnitude) and
    // the zero -psi1 (Eq. 7 numerator f3 wn^3 s + wn^4).
    QCOMPARE(sets[3].poles.size(), std::size_t(4));
    for (std::size_t i = 0; i < 4; ++i)
        QVERIFY(std::abs(sets[3].poles[i] - sets[4].poles[i]) <= 1e-9 * std::abs(sets[4].poles[0]));
    XYT_COMPARE_NEAR(sets[4].zeros.at(0).real(), -psi1, 1e-12, 0.0);
    XYT_COMPARE_NEAR(sets[3].zeros.at(0).real(), -psi1, 1e-12, 0.0);
}

void TstPoleZeroMap::xAxisArxModelZeros() {
    // Patrick, Ishak and Adnan Eq. 1-2: B = 0.0421 z^-1 + 0.0628 z^-2 - 0.0454 z^-3, zeros of
    // 0.0421 z^2 + 0.0628 z - 0.0454 by the quadratic formula: (-0.0628 +- sqrt(0.0628^2 +
    // 4*0.0421*0.0454))/(2*0.0421) = 0.53266 and -2.02437. The paper prints "z = -0.5327 and
    // z = -2.0244": the sign of the first zero is a misprint (its Eq. 2 polynomial
    // 1 + 1.4917 z^-1 - 1.0784 z^-2 has roots +0.5327 and -2.0244 too). Poles: 0 (the delay)
    // and 0.829 -+ sqrt(0.829^2 - 0.6583).
    const TransferFunction tf =
        TransferFunction::fromZInverse(Polynomial::fromAscending({0.0, 0.0421, 0.0628, -0.0454}),
                                       Polynomial::fromAscending({1.0, -1.6580, 0.6583}), 0.07);
    const PoleZeroSet set = poleZeroSet("x-axis plant", tf);
    QCOMPARE(set.tsSeconds, 0.07);
    const double root = std::sqrt(0.0628 * 0.0628 + 4.0 * 0.0421 * 0.0454);
    QCOMPARE(set.zeros.size(), std::size_t(2));
    XYT_COMPARE_NEAR(set.zeros[0].real(), (-0.0628 - root) / (2.0 * 0.0421), 1e-13, 0.0);
    XYT_COMPARE_NEAR(set.zeros[1].real(), (-0.0628 + root) / (2.0 * 0.0421), 1e-13, 0.0);
    XYT_COMPARE_NEAR(set.zeros[1].real(), 0.5327, 0.0, 5e-5); // the printed magnitude, 4 decimals
    const double poleDisc = std::sqrt(0.829 * 0.829 - 0.6583);
    QCOMPARE(set.poles.size(), std::size_t(3));
    XYT_COMPARE_NEAR(set.poles[0].real(), 0.0, 0.0, 1e-15);
    XYT_COMPARE_NEAR(set.poles[1].real(), 0.829 - poleDisc, 1e-13, 0.0);
    XYT_COMPARE_NEAR(set.poles[2].real(), 0.829 + poleDisc, 1e-13, 0.0);
}

void TstPoleZeroMap::dampingOfClosedForms_data() {
    QTest::addColumn<double>("re");
    QTest::addColumn<double>("im");
    QTest::addColumn<double>("ts");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("omega");
    // s = -1 + j: |s| = sqrt 2, zeta = 1/sqrt 2.
    QTest::newRow("s -1+j") << -1.0 << 1.0 << 0.0 << 1.0 / std::sqrt(2.0) << std::sqrt(2.0);
    // z = exp((-1 + j) 0.1): the same pole through s = ln(z)/Ts.
    const Complex z = std::exp(Complex(-1.0, 1.0) * 0.1);
    QTest::newRow("z exp((-1+j)0.1)")
        << z.real() << z.imag() << 0.1 << 1.0 / std::sqrt(2.0) << std::sqrt(2.0);
    // Integrator s = 0: zeta 1, omega 0 (convention); z = 1 is the same pole.
    QTest::newRow("s 0") << 0.0 << 0.0 << 0.0 << 1.0 << 0.0;
    QTest::newRow("z 1") << 1.0 << 0.0 << 0.07 << 1.0 << 0.0;
    // z = -1: s = j pi/Ts, undamped at the Nyquist frequency.
    QTest::newRow("z -1") << -1.0 << 0.0 << 0.1 << 0.0 << std::numbers::pi / 0.1;
    // Unstable s = 2: zeta = -1.
    QTest::newRow("s 2") << 2.0 << 0.0 << 0.0 << -1.0 << 2.0;
}

void TstPoleZeroMap::dampingOfClosedForms() {
    QFETCH(double, re);
    QFETCH(double, im);
    QFETCH(double, ts);
    QFETCH(double, zeta);
    QFETCH(double, omega);
    const DampingAndFrequency d = dampingOf(Complex(re, im), ts);
    XYT_COMPARE_NEAR(d.zeta, zeta, 1e-14, 1e-15); // exp/log round trip: a few ulps
    XYT_COMPARE_NEAR(d.omegaNRadPerSec, omega, 1e-14, 1e-14);
}

void TstPoleZeroMap::sPlaneGridLinesHaveTheirZetaAndOmega() {
    const DampingGrid g = sPlaneDampingGrid(defaultGridZetas(), {1.0, 2.0, 5.0}, 10.0, 31);
    QCOMPARE(g.dampingLines.size(), std::size_t(11));
    QCOMPARE(g.frequencyLines.size(), std::size_t(3));
    for (const GridLine& line : g.dampingLines)
        for (const Complex& s : line.points)
            if (std::abs(s) > 0.0) // the origin has no damping ratio
                XYT_COMPARE_NEAR(dampingOf(s).zeta, line.value, 1e-14, 1e-15);
    for (const GridLine& line : g.frequencyLines) {
        QCOMPARE(line.points.size(), std::size_t(61)); // 31 per half, the real-axis point shared
        for (const Complex& s : line.points) {
            XYT_COMPARE_NEAR(std::abs(s), line.value, 1e-14, 0.0);
            QVERIFY(s.real() <= 1e-12 * line.value); // left half plane
        }
    }
}

void TstPoleZeroMap::zPlaneGridIsTheImageOfTheSPlaneGrid() {
    // z = exp(s Ts): back through s = ln(z)/Ts every point has the zeta / omega_n of its line,
    // and lies in the closed unit disk (Re s <= 0).
    const double ts = 0.07;
    const DampingGrid g =
        zPlaneDampingGrid(defaultGridZetas(), defaultZGridFrequencies(ts), ts, 41);
    QCOMPARE(g.dampingLines.size(), std::size_t(11));
    QCOMPARE(g.frequencyLines.size(), std::size_t(10));
    for (const GridLine& line : g.dampingLines)
        for (const Complex& z : line.points) {
            QVERIFY(std::abs(z) <= 1.0 + 1e-15);
            // Skip z = 1 (omega 0) and the Nyquist ends, where ln(z) may take the other
            // branch of the logarithm.
            const Complex s = std::log(z) / ts;
            if (std::abs(z - 1.0) < 1e-12 || std::abs(s.imag()) > 0.999 * std::numbers::pi / ts)
                continue;
            XYT_COMPARE_NEAR(dampingOf(z, ts).zeta, line.value, 1e-9, 1e-12);
        }
    for (const GridLine& line : g.frequencyLines)
        for (const Complex& z : line.points) {
            QVERIFY(std::abs(z) <= 1.0 + 1e-15);
            if (std::abs(std::arg(z)) > 0.999 * std::numbers::pi)
                continue;
            XYT_COMPARE_NEAR(dampingOf(z, ts).omegaNRadPerSec, line.value, 1e-12, 0.0);
        }
}

void TstPoleZeroMap::niceFrequencies() {
    // The 1-2-5 sequence below 100: the top three are 20, 50, 100.
    QCOMPARE(niceGridFrequencies(100.0, 3), (std::vector<double>{20.0, 50.0, 100.0}));
    const auto w = niceGridFrequencies(7.0, 4);
    QCOMPARE(w.size(), std::size_t(4));
    XYT_COMPARE_NEAR(w.back(), 5.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(w.front(), 0.5, 1e-15, 0.0);
}

void TstPoleZeroMap::invalidGridThrows() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, sPlaneDampingGrid({1.5}, {1.0}, 10.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, sPlaneDampingGrid({0.5}, {-1.0}, 10.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, zPlaneDampingGrid({0.5}, {100.0}, 0.1)); // > pi/Ts
    QVERIFY_THROWS_EXCEPTION(InvalidInput, zPlaneDampingGrid({0.5}, {1.0}, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, dampingOf(Complex(std::nan(""), 0.0)));
}

QTEST_APPLESS_MAIN(TstPoleZeroMap)
#include "tst_pole_zero_map.moc"
