// SPDX-License-Identifier: GPL-3.0-or-later
// The Guillemin-Truxal PI design of Braga et al. (Eq. 7-22) against its closed forms and the
// published numbers, after checking each published number against its own equation.
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <limits>

using xyt::GtDesign;
using xyt::Polynomial;
using xyt::ThirdOrderPlant;
using xyt::TransferFunction;
using xyt::test::comparePolynomials;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
} // namespace

class TstGuilleminTruxal : public QObject {
    Q_OBJECT
private slots:
    void closedForms_data();
    void closedForms();
    void closedLoopEqualsReferenceModel_data();
    void closedLoopEqualsReferenceModel();
    void paperEq10LeadLagClosedLoop();
    void paperLowerBaseEq19And20();
    void paperUpperBaseEq21And22();
    void presets();
    void unstableDesignIsFlaggedNotThrown();
    void unrepresentableWnOrKpIsRefusedNamingIt();
    void badInputsNameTheField_data();
    void badInputsNameTheField();
};

void TstGuilleminTruxal::closedForms_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::newRow("Braga et al. Sec. 3.1 lower base") << 77.8 << 125.3 << 3665.0 << 2.0 << 30.0;
    QTest::newRow("Braga et al. Sec. 3.2 upper base") << 24.44 << 68.18 << 863.0 << 1.0 << 30.0;
    QTest::newRow("generic, wn < 1") << 10.0 << 5.0 << 6.0 << 0.5 << 2.0;
    QTest::newRow("negative k0") << -3.0 << 4.0 << 2.0 << 1.5 << 0.7;
}

void TstGuilleminTruxal::closedForms() {
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, wn);
    QFETCH(double, kp);
    const GtDesign d = xyt::designGuilleminTruxal({k0, a1, a2}, wn, kp);
    // Closed forms of Braga et al.; one or two roundings each, so 1e-15 relative.
    const double tol = 1e-15;
    XYT_COMPARE_NEAR(d.f1, a1 / wn, tol, 0.0);                       // Eq. 17
    XYT_COMPARE_NEAR(d.f2, a2 / (wn * wn), tol, 0.0);                // Eq. 18
    XYT_COMPARE_NEAR(d.f3, kp * k0 / (wn * wn * wn), tol, 0.0);      // Eq. 15
    XYT_COMPARE_NEAR(d.psi1, std::pow(wn, 4) / (kp * k0), tol, 0.0); // Eq. 11
    XYT_COMPARE_NEAR(d.ki, kp * d.psi1, tol, 0.0);                   // Eq. 16
    QCOMPARE(d.psi2, 0.0); // Eq. 12 with Eq. 15: exactly zero, not computed
    XYT_COMPARE_NEAR(d.kp, kp, 0.0, 0.0);
    // Eq. 16: G_c(s) = kp + ki/s = (kp s + ki)/s.
    QCOMPARE(d.controller.num().degree(), 1);
    XYT_COMPARE_NEAR(d.controller.num().coefficient(1), kp, tol, 0.0);
    XYT_COMPARE_NEAR(d.controller.num().coefficient(0), d.ki, tol, 0.0);
    QCOMPARE(d.controller.den().descending(), (std::vector<double>{1.0, 0.0}));
    // Eq. 7 with s^2 (the paper prints "f2 wn^2 s"): ascending wn^4, f3 wn^3, f2 wn^2, f1 wn, 1.
    const std::vector<double> den{std::pow(wn, 4), d.f3 * std::pow(wn, 3), d.f2 * wn * wn,
                                  d.f1 * wn, 1.0};
    for (int i = 0; i <= 4; ++i)
        XYT_COMPARE_NEAR(d.referenceModel.den().coefficient(i), den[std::size_t(i)], 1e-14, 0.0);
    XYT_COMPARE_NEAR(d.referenceModel.num().coefficient(1), d.f3 * std::pow(wn, 3), 1e-14, 0.0);
    XYT_COMPARE_NEAR(d.referenceModel.num().coefficient(0), std::pow(wn, 4), 1e-14, 0.0);
    // f1 wn = a1 and f2 wn^2 = a2: the reference model keeps the plant's own s^3 and s^2 terms.
    XYT_COMPARE_NEAR(d.referenceModel.den().coefficient(3), a1, 1e-14, 0.0);
    XYT_COMPARE_NEAR(d.referenceModel.den().coefficient(2), a2, 1e-14, 0.0);
}

void TstGuilleminTruxal::closedLoopEqualsReferenceModel_data() {
    closedForms_data();
}

void TstGuilleminTruxal::closedLoopEqualsReferenceModel() {
    // Invariant (the point of the method, Eq. 3): feedback(G_c G) == G_R coefficient-wise. The
    // closed loop is a few products and sums of the inputs, so 1e-13 of the largest coefficient.
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, wn);
    QFETCH(double, kp);
    const GtDesign d = xyt::designGuilleminTruxal({k0, a1, a2}, wn, kp);
    comparePolynomials(d.closedLoop.num(), d.referenceModel.num(), 1e-13);
    comparePolynomials(d.closedLoop.den(), d.referenceModel.den(), 1e-13);
    // Type 2 (paper Sec. 3): 1 - G_R has a double zero at s = 0, so the ramp error vanishes.
    const Polynomial error = d.referenceModel.den() - d.referenceModel.num();
    XYT_COMPARE_NEAR(error.coefficient(0), 0.0, 0.0, 1e-13 * error.maxAbsCoefficient());
    XYT_COMPARE_NEAR(error.coefficient(1), 0.0, 0.0, 1e-13 * error.maxAbsCoefficient());
    // The open loop G_c G has the plant's integrator and the controller's: type 2.
    QCOMPARE(d.openLoop.den().coefficient(0), 0.0);
    QCOMPARE(d.openLoop.den().coefficient(1), 0.0);
    // The reported poles are the roots of the closed-loop denominator (residue invariant).
    QCOMPARE(d.closedLoopPoles.size(), std::size_t(4));
    for (const auto& p : d.closedLoopPoles) {
        double scale = 0.0;
        for (int i = 0; i <= 4; ++i)
            scale += std::abs(d.closedLoop.den().coefficient(i)) * std::pow(std::abs(p), i);
        QVERIFY(std::abs(d.closedLoop.den()(p)) <= 1e-12 * scale);
    }
}

void TstGuilleminTruxal::paperEq10LeadLagClosedLoop() {
    // Braga et al. Eq. 10 (checked by expanding s(s^2 + a1 s + a2)(s + psi2) + k k0 (s + psi1)):
    // feedback(k (s + psi1)/(s + psi2) G) for psi2 != 0.
    const double k = 2.5, psi1 = 0.3, psi2 = 4.0, k0 = 77.8, a1 = 125.3, a2 = 3665.0;
    const TransferFunction gc = TransferFunction::fromDescending({k, k * psi1}, {1.0, psi2});
    const TransferFunction t1 =
        xyt::feedback(xyt::series(gc, ThirdOrderPlant{k0, a1, a2}.transferFunction()));
    comparePolynomials(t1.den(),
                       Polynomial::fromDescending(
                           {1.0, a1 + psi2, a2 + psi2 * a1, psi2 * a2 + k * k0, k * k0 * psi1}),
                       1e-14);
    comparePolynomials(t1.num(), Polynomial::fromDescending({k * k0, k * k0 * psi1}), 1e-14);
}

void TstGuilleminTruxal::paperLowerBaseEq19And20() {
    const GtDesign d = xyt::designGuilleminTruxal({77.8, 125.3, 3665.0}, 2.0, 30.0);
    // Sec. 3.1 prints (garbled as "f1 = 62.65, 916.25 f2 = f3 = 291.75") f1 = 62.65,
    // f2 = 916.25, f3 = 291.75: all exact (125.3/2, 3665/4, 30*77.8/8), so round-off tolerance.
    XYT_COMPARE_NEAR(d.f1, 62.65, 1e-15, 0.0);
    XYT_COMPARE_NEAR(d.f2, 916.25, 1e-15, 0.0);
    XYT_COMPARE_NEAR(d.f3, 291.75, 1e-15, 0.0);
    // Eq. 19: (2334 s + 16)/(s^4 + 125.3 s^3 + 3665 s^2 + 2334 s + 16), exact values.
    comparePolynomials(d.referenceModel.num(), Polynomial::fromDescending({2334.0, 16.0}), 1e-15);
    comparePolynomials(d.referenceModel.den(),
                       Polynomial::fromDescending({1.0, 125.3, 3665.0, 2334.0, 16.0}), 1e-15);
    // Eq. 20: G_c = 30 + 0.20566/s. ki = 16/77.8 = 0.2056555..., printed to 5 digits: half a
    // unit of the last printed digit.
    XYT_COMPARE_NEAR(d.ki, 0.20566, 0.0, 0.5e-5);
    XYT_COMPARE_NEAR(d.kp, 30.0, 0.0, 0.0);
}

void TstGuilleminTruxal::paperUpperBaseEq21And22() {
    const GtDesign d = xyt::designGuilleminTruxal({24.44, 68.18, 863.0}, 1.0, 30.0);
    // Sec. 3.2 prints f1 = 64.18: a misprint. Eq. 17 gives a1/wn = 68.18/1 = 68.18 (off by 4).
    XYT_COMPARE_NEAR(d.f1, 68.18, 1e-15, 0.0);
    XYT_COMPARE_NEAR(d.f2, 863.0, 1e-15, 0.0); // printed 863: right
    XYT_COMPARE_NEAR(d.f3, 733.2, 1e-15, 0.0); // printed 733.2 = 30*24.44: right
    // Eq. 21 prints the s^3 coefficient 128.36 (= 2 * 64.18, as if f1 = 64.18 and wn = 2 of
    // the lower base): a misprint. f1 wn = 68.18, the plant's own a1 (Eq. 14 with psi2 = 0).
    // The other coefficients print right: 733.2 s + 1 over ... 863 s^2 + 733.2 s + 1.
    comparePolynomials(d.referenceModel.num(), Polynomial::fromDescending({733.2, 1.0}), 1e-15);
    comparePolynomials(d.referenceModel.den(),
                       Polynomial::fromDescending({1.0, 68.18, 863.0, 733.2, 1.0}), 1e-15);
    QVERIFY(std::abs(d.referenceModel.den().coefficient(3) - 128.36) > 60.0);
    // Eq. 22: G_c = 30 + 0.0409/s. ki = 1/24.44 = 0.040917..., printed to 4 decimals.
    XYT_COMPARE_NEAR(d.ki, 0.0409, 0.0, 0.5e-4);
}

void TstGuilleminTruxal::presets() {
    // The plants of Braga et al. Eq. 1 and 2 and the designs of Sec. 3.1 and 3.2, with the
    // volts-to-metres models driven by millimetre trajectories (0.001 m per mm).
    const auto lower = xyt::findGtPreset("lower-base");
    const auto upper = xyt::findGtPreset("upper-base");
    QVERIFY(lower && upper);
    QCOMPARE(lower->plant.k0, 77.8);
    QCOMPARE(lower->plant.a1, 125.3);
    QCOMPARE(lower->plant.a2, 3665.0);
    QCOMPARE(lower->omegaNRadPerSec, 2.0);
    QCOMPARE(lower->kp, 30.0);
    QCOMPARE(upper->plant.k0, 24.44);
    QCOMPARE(upper->plant.a1, 68.18);
    QCOMPARE(upper->plant.a2, 863.0);
    QCOMPARE(upper->omegaNRadPerSec, 1.0);
    QCOMPARE(upper->kp, 30.0);
    QCOMPARE(lower->modelUnitsPerPositionUnit, 0.001);
    QCOMPARE(upper->modelUnitsPerPositionUnit, 0.001);
    QVERIFY(!xyt::findGtPreset("middle-base"));
    QCOMPARE(xyt::gtPresets().size(), std::size_t(2));
    // Both paper designs are stable.
    for (const auto& p : xyt::gtPresets())
        QVERIFY(xyt::designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp).stable);
}

void TstGuilleminTruxal::unstableDesignIsFlaggedNotThrown() {
    // Routh-Hurwitz on s^4 + a1 s^3 + a2 s^2 + kp k0 s + wn^4: the s^1 row needs
    // a1 a2 > kp k0 (up to the small wn^4 term), i.e. kp < 125.3 * 3665 / 77.8 = 5903 for the
    // lower base. kp = 10000 breaks it; the design still returns, with stable == false and a
    // right-half-plane pole.
    GtDesign d;
    try {
        d = xyt::designGuilleminTruxal({77.8, 125.3, 3665.0}, 2.0, 10000.0);
    } catch (const std::exception& e) {
        QFAIL(e.what());
    }
    QVERIFY(!d.stable);
    bool rhp = false;
    for (const auto& p : d.closedLoopPoles)
        rhp = rhp || p.real() > 0.0;
    QVERIFY(rhp);
    // Just below the Routh bound it is stable again (kp = 5000).
    QVERIFY(xyt::designGuilleminTruxal({77.8, 125.3, 3665.0}, 2.0, 5000.0).stable);
}

void TstGuilleminTruxal::badInputsNameTheField_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::addColumn<QString>("field");
    QTest::newRow("wn = 0") << 77.8 << 125.3 << 3665.0 << 0.0 << 30.0 << "wn";
    QTest::newRow("wn < 0") << 77.8 << 125.3 << 3665.0 << -2.0 << 30.0 << "wn";
    QTest::newRow("wn NaN") << 77.8 << 125.3 << 3665.0 << kNaN << 30.0 << "wn";
    QTest::newRow("wn inf") << 77.8 << 125.3 << 3665.0 << kInf << 30.0 << "wn";
    QTest::newRow("kp = 0") << 77.8 << 125.3 << 3665.0 << 2.0 << 0.0 << "kp";
    QTest::newRow("kp < 0") << 77.8 << 125.3 << 3665.0 << 2.0 << -30.0 << "kp";
    QTest::newRow("kp NaN") << 77.8 << 125.3 << 3665.0 << 2.0 << kNaN << "kp";
    QTest::newRow("k0 = 0") << 0.0 << 125.3 << 3665.0 << 2.0 << 30.0 << "k0";
    QTest::newRow("k0 -inf") << -kInf << 125.3 << 3665.0 << 2.0 << 30.0 << "k0";
    QTest::newRow("a1 NaN") << 77.8 << kNaN << 3665.0 << 2.0 << 30.0 << "a1";
    QTest::newRow("a2 inf") << 77.8 << 125.3 << kInf << 2.0 << 30.0 << "a2";
}

void TstGuilleminTruxal::badInputsNameTheField() {
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, wn);
    QFETCH(double, kp);
    QFETCH(QString, field);
    QCOMPARE(xyt::test::invalidInputField([&] {
                 xyt::designGuilleminTruxal({k0, a1, a2}, wn, kp);
             }),
             field);
}

void TstGuilleminTruxal::unrepresentableWnOrKpIsRefusedNamingIt() {
    // wn = 1e300 made wn^4 overflow and the reference model's constructor reported
    // "den[2]: must be a number, got NaN". Bounds from the closed forms (Braga et al. Eq. 11-18):
    // wn^4 overflows above DBL_MAX^(1/4) = 1.34e77 rad/s, wn^2 underflows to 0 below ~1.5e-162.
    const ThirdOrderPlant lower{77.8, 125.3, 3665.0};
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::designGuilleminTruxal(lower, 1e300, 30.0); }),
             QString("wn"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::designGuilleminTruxal(lower, 2e77, 30.0); }),
             QString("wn"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::designGuilleminTruxal(lower, 1e-200, 30.0); }),
             QString("wn"));
    // psi1 = wn^4/(kp k0) underflows to 0 for kp = 1e308 (kp k0 overflows).
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::designGuilleminTruxal(lower, 2.0, 1e308); }),
             QString("kp"));
    // The same overflow of kp k0 from a plant gain of 1e308 with an ordinary kp: k0 is named.
    QCOMPARE(xyt::test::invalidInputField([&] {
                 xyt::designGuilleminTruxal({1e308, 125.3, 3665.0}, 30.0, 460.852);
             }),
             QString("k0"));
    // And psi1 = wn^4/(kp k0) overflowing for a plant gain of 1e-305: k0 again.
    QCOMPARE(xyt::test::invalidInputField([&] {
                 xyt::designGuilleminTruxal({1e-305, 125.3, 3665.0}, 30.0, 2.0);
             }),
             QString("k0"));
    // Still representable: wn = 1e70 (wn^4 = 1e280) gives finite coefficients.
    const GtDesign d = xyt::designGuilleminTruxal(lower, 1e70, 30.0);
    QVERIFY(std::isfinite(d.ki) && d.ki > 0.0);
}

QTEST_APPLESS_MAIN(TstGuilleminTruxal)
#include "tst_guillemin_truxal.moc"
