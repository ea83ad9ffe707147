// SPDX-License-Identifier: GPL-3.0-or-later
// TransferFunction: interconnections, poles and zeros, DC gain and frequency response against
// closed forms; the z^-1 form round trip; errors that name the field.
#include "core/model/errors.h"
#include "core/model/transfer_function.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using xyt::Polynomial;
using xyt::TransferFunction;
using Complex = std::complex<double>;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TransferFunction tf(const std::vector<double>& num, const std::vector<double>& den) {
    return TransferFunction::fromDescending(num, den);
}

/// Coefficients descending, compared to 1e-14 of the largest (a few products and sums).
void compareDescending(const Polynomial& p, const std::vector<double>& expected) {
    xyt::test::comparePolynomials(p, Polynomial::fromDescending(expected), 1e-14);
}
} // namespace

class TstTransferFunction : public QObject {
    Q_OBJECT
private slots:
    void normalizedToMonicDenominator();
    void seriesAndParallelClosedForms();
    void feedbackClosedForms_data();
    void feedbackClosedForms();
    void polesAndZeros();
    void dcGain_data();
    void dcGain();
    void zInverseRoundTrip_data();
    void zInverseRoundTrip();
    void frequencyResponseClosedForms_data();
    void frequencyResponseClosedForms();
    void stability_data();
    void stability();
    void errorsNameTheField();
};

void TstTransferFunction::normalizedToMonicDenominator() {
    // (2 s + 4)/(2 s^2 + 6 s + 8) is stored as (s + 2)/(s^2 + 3 s + 4): a division by 2, exact.
    const TransferFunction g = tf({2.0, 4.0}, {2.0, 6.0, 8.0});
    QCOMPARE(g.num().descending(), (std::vector<double>{1.0, 2.0}));
    QCOMPARE(g.den().descending(), (std::vector<double>{1.0, 3.0, 4.0}));
    QCOMPARE(g.relativeDegree(), 1);
    QVERIFY(g.isStrictlyProper());
    QVERIFY(!g.isDiscrete());
    QVERIFY(!tf({1.0, 0.0, 0.0}, {1.0, 1.0}).isProper());
}

void TstTransferFunction::seriesAndParallelClosedForms() {
    const TransferFunction a = tf({1.0, 1.0}, {1.0, 2.0}); // (s+1)/(s+2)
    const TransferFunction b = tf({3.0}, {1.0, 1.0, 1.0}); // 3/(s^2+s+1)
    // Closed form: 3 (s+1) / ((s+2)(s^2+s+1)) = (3 s + 3)/(s^3 + 3 s^2 + 3 s + 2).
    const TransferFunction s = xyt::series(a, b);
    compareDescending(s.num(), {3.0, 3.0});
    compareDescending(s.den(), {1.0, 3.0, 3.0, 2.0});
    // 1/(s+1) + 1/(s+2) = (2 s + 3)/(s^2 + 3 s + 2).
    const TransferFunction p = xyt::parallel(tf({1.0}, {1.0, 1.0}), tf({1.0}, {1.0, 2.0}));
    compareDescending(p.num(), {2.0, 3.0});
    compareDescending(p.den(), {1.0, 3.0, 2.0});
}

void TstTransferFunction::feedbackClosedForms_data() {
    QTest::addColumn<int>("sign");
    QTest::addColumn<bool>("withSensor");
    QTest::addColumn<QList<double>>("num");
    QTest::addColumn<QList<double>>("den");
    // g = 5/(s(s+3)); unity negative feedback: 5/(s^2 + 3 s + 5).
    QTest::newRow("unity negative")
        << -1 << false << QList<double>{5.0} << QList<double>{1.0, 3.0, 5.0};
    // Positive feedback: 5/(s^2 + 3 s - 5).
    QTest::newRow("unity positive")
        << 1 << false << QList<double>{5.0} << QList<double>{1.0, 3.0, -5.0};
    // Sensor h = 2/(s+4): 5 (s+4)/(s(s+3)(s+4) + 10) = (5 s + 20)/(s^3 + 7 s^2 + 12 s + 10).
    QTest::newRow("sensor negative")
        << -1 << true << QList<double>{5.0, 20.0} << QList<double>{1.0, 7.0, 12.0, 10.0};
}

void TstTransferFunction::feedbackClosedForms() {
    QFETCH(int, sign);
    QFETCH(bool, withSensor);
    QFETCH(QList<double>, num);
    QFETCH(QList<double>, den);
    const TransferFunction g = tf({5.0}, {1.0, 3.0, 0.0});
    const TransferFunction h = withSensor ? tf({2.0}, {1.0, 4.0}) : TransferFunction();
    const TransferFunction t = xyt::feedback(g, h, sign);
    compareDescending(t.num(), {num.begin(), num.end()});
    compareDescending(t.den(), {den.begin(), den.end()});
}

void TstTransferFunction::polesAndZeros() {
    // (s+1)(s-2) / ((s+3)(s^2+2s+5)): zeros -1, 2; poles -3, -1 -+ 2j (closed form).
    const TransferFunction g(Polynomial::fromRoots({-1.0, 2.0}, 4.0),
                             Polynomial::fromRoots({-3.0, Complex(-1, -2), Complex(-1, 2)}));
    const auto z = g.zeros();
    const auto p = g.poles();
    QCOMPARE(z.size(), std::size_t(2));
    QCOMPARE(p.size(), std::size_t(3));
    // Well-conditioned simple roots: 1e-12 absolute (the polynomial solver's accuracy).
    QVERIFY(xyt::test::nearComplex(z[0], -1.0, 0.0, 1e-12));
    QVERIFY(xyt::test::nearComplex(z[1], 2.0, 0.0, 1e-12));
    QVERIFY(xyt::test::nearComplex(p[0], -3.0, 0.0, 1e-12));
    QVERIFY(xyt::test::nearComplex(p[1], Complex(-1, -2), 0.0, 1e-12));
    QVERIFY(xyt::test::nearComplex(p[2], Complex(-1, 2), 0.0, 1e-12));
    // A constant numerator has no zeros; an integrator has a pole at exactly 0.
    QVERIFY(tf({3.0}, {1.0, 1.0}).zeros().empty());
    QCOMPARE(tf({1.0}, {1.0, 0.0}).poles().front(), Complex(0.0, 0.0));
}

void TstTransferFunction::dcGain_data() {
    QTest::addColumn<QList<double>>("num");
    QTest::addColumn<QList<double>>("den");
    QTest::addColumn<double>("ts");
    QTest::addColumn<double>("expected");
    // Closed forms: N(0)/D(0), or N(1)/D(1) for discrete systems.
    QTest::newRow("second order 3/(s^2+3s+2)")
        << QList<double>{3.0} << QList<double>{1, 3, 2} << 0.0 << 1.5;
    QTest::newRow("integrator 1/s") << QList<double>{1.0} << QList<double>{1, 0} << 0.0 << kInf;
    QTest::newRow("negative integrator -2/(s^2+s)")
        << QList<double>{-2.0} << QList<double>{1, 1, 0} << 0.0 << -kInf;
    QTest::newRow("common factor s/(s(s+2))")
        << QList<double>{1, 0} << QList<double>{1, 2, 0} << 0.0 << 0.5;
    QTest::newRow("double common factor s^2(s+1)/(s^2(s+4))")
        << QList<double>{1, 1, 0, 0} << QList<double>{1, 4, 0, 0} << 0.0 << 0.25;
    QTest::newRow("differentiator s/(s+1)")
        << QList<double>{1, 0} << QList<double>{1, 1} << 0.0 << 0.0;
    QTest::newRow("discrete 0.5/(z-0.5)")
        << QList<double>{0.5} << QList<double>{1, -0.5} << 0.1 << 1.0;
    QTest::newRow("discrete integrator 0.1/(z-1)")
        << QList<double>{0.1} << QList<double>{1, -1} << 0.1 << kInf;
    // Regression: D(1) = 1 - 1.2 + 0.2 evaluates to 5.6e-17, not 0, so dcGain used to skip the
    // cancellation of (z - 1) and return 0 here (and a huge finite number for the next row).
    QTest::newRow("discrete common factor (z-1)/((z-1)(z-0.2))")
        << QList<double>{1, -1} << QList<double>{1, -1.2, 0.2} << 0.1 << 1.25;
    QTest::newRow("discrete pole at 1 with inexact coefficients 1/((z-1)(z-0.2))")
        << QList<double>{1} << QList<double>{1, -1.2, 0.2} << 0.1 << kInf;
}

void TstTransferFunction::dcGain() {
    QFETCH(QList<double>, num);
    QFETCH(QList<double>, den);
    QFETCH(double, ts);
    QFETCH(double, expected);
    const TransferFunction g(Polynomial::fromDescending({num.begin(), num.end()}),
                             Polynomial::fromDescending({den.begin(), den.end()}), ts);
    XYT_COMPARE_NEAR(g.dcGain(), expected, 1e-14, 1e-15);
}

void TstTransferFunction::zInverseRoundTrip_data() {
    QTest::addColumn<QList<double>>("numQ");
    QTest::addColumn<QList<double>>("denQ");
    QTest::addColumn<QList<double>>("numZ"); // expected, descending powers of z
    QTest::addColumn<QList<double>>("denZ");
    // (0.5 z^-1 + 0.25 z^-2)/(1 - 1.5 z^-1 + 0.7 z^-2) = (0.5 z + 0.25)/(z^2 - 1.5 z + 0.7).
    QTest::newRow("same degree") << QList<double>{0, 0.5, 0.25} << QList<double>{1, -1.5, 0.7}
                                 << QList<double>{0.5, 0.25} << QList<double>{1, -1.5, 0.7};
    // z^-2/(1 - 0.5 z^-1) = 1/(z^2 - 0.5 z): the numerator sets the degree.
    QTest::newRow("delay longer than den") << QList<double>{0, 0, 1} << QList<double>{1, -0.5}
                                           << QList<double>{1.0} << QList<double>{1, -0.5, 0};
    // As Patrick, Ishak and Adnan write them, biproper: (2 + z^-1)/(2 - z^-1) = (z + 0.5)/(z - 0.5)
    // after normalizing.
    QTest::newRow("biproper, den[0] != 1") << QList<double>{2, 1} << QList<double>{2, -1}
                                           << QList<double>{1, 0.5} << QList<double>{1, -0.5};
}

void TstTransferFunction::zInverseRoundTrip() {
    QFETCH(QList<double>, numQ);
    QFETCH(QList<double>, denQ);
    QFETCH(QList<double>, numZ);
    QFETCH(QList<double>, denZ);
    const Polynomial nq = Polynomial::fromAscending({numQ.begin(), numQ.end()});
    const Polynomial dq = Polynomial::fromAscending({denQ.begin(), denQ.end()});
    const TransferFunction g = TransferFunction::fromZInverse(nq, dq, 0.07);
    QVERIFY(g.isDiscrete());
    QCOMPARE(g.tsSeconds(), 0.07);
    compareDescending(g.num(), {numZ.begin(), numZ.end()});
    compareDescending(g.den(), {denZ.begin(), denZ.end()});
    // Invariant: back to z^-1 gives the typed polynomials divided by den[0].
    const double d0 = denQ.front();
    const Polynomial nBack = g.numZInverse(), dBack = g.denZInverse();
    for (int i = 0; i <= std::max(nq.degree(), nBack.degree()); ++i)
        XYT_COMPARE_NEAR(nBack.coefficient(i), nq.coefficient(i) / d0, 1e-15, 0.0);
    for (int i = 0; i <= std::max(dq.degree(), dBack.degree()); ++i)
        XYT_COMPARE_NEAR(dBack.coefficient(i), dq.coefficient(i) / d0, 1e-15, 0.0);
    // Same value at a test point: N(1/z)/D(1/z) == G(z) (closed form of the substitution).
    const Complex z(0.3, 1.1);
    const Complex direct = nq(1.0 / z) / dq(1.0 / z);
    QVERIFY(xyt::test::nearComplex(g(z), direct, 1e-14));
}

void TstTransferFunction::frequencyResponseClosedForms_data() {
    QTest::addColumn<double>("omega");
    QTest::newRow("w = 0.1") << 0.1;
    QTest::newRow("w = 2") << 2.0;
    QTest::newRow("w = 40") << 40.0;
}

void TstTransferFunction::frequencyResponseClosedForms() {
    QFETCH(double, omega);
    // First order a/(s + a): |G| = a/sqrt(a^2 + w^2), arg G = -atan(w/a).
    const double a = 3.0;
    const Complex g1 = tf({a}, {1.0, a}).frequencyResponse(omega);
    XYT_COMPARE_NEAR(std::abs(g1), a / std::hypot(a, omega), 1e-14, 0.0);
    XYT_COMPARE_NEAR(std::arg(g1), -std::atan(omega / a), 1e-14, 0.0);
    // Integrator 1/s: -j/w.
    const Complex gi = tf({1.0}, {1.0, 0.0}).frequencyResponse(omega);
    QVERIFY(xyt::test::nearComplex(gi, Complex(0.0, -1.0 / omega), 1e-15));
    // Discrete 1/(z - 0.5) at z = e^{j w Ts}, Ts = 0.07.
    const double ts = 0.07;
    const TransferFunction gd(Polynomial::constant(1.0), Polynomial::fromAscending({-0.5, 1.0}),
                              ts);
    const Complex expected = 1.0 / (std::polar(1.0, omega * ts) - 0.5);
    QVERIFY(xyt::test::nearComplex(gd.frequencyResponse(omega), expected, 1e-15));
}

void TstTransferFunction::stability_data() {
    QTest::addColumn<QList<double>>("den");
    QTest::addColumn<double>("ts");
    QTest::addColumn<bool>("stable");
    QTest::newRow("s^2 + 3 s + 2") << QList<double>{1, 3, 2} << 0.0 << true;
    QTest::newRow("integrator s (marginal is not stable)") << QList<double>{1, 0} << 0.0 << false;
    QTest::newRow("s^2 + 3 s - 5") << QList<double>{1, 3, -5} << 0.0 << false;
    QTest::newRow("z - 0.9") << QList<double>{1, -0.9} << 0.1 << true;
    QTest::newRow("z + 1.1") << QList<double>{1, 1.1} << 0.1 << false;
    QTest::newRow("z - 2 but continuous: s - 2") << QList<double>{1, -2} << 0.0 << false;
    QTest::newRow("z + 0.5 (would be stable as s + 0.5 too)")
        << QList<double>{1, 0.5} << 0.1 << true;
}

void TstTransferFunction::stability() {
    QFETCH(QList<double>, den);
    QFETCH(double, ts);
    QFETCH(bool, stable);
    QCOMPARE(TransferFunction(Polynomial::constant(1.0),
                              Polynomial::fromDescending({den.begin(), den.end()}), ts)
                 .isStable(),
             stable);
}

void TstTransferFunction::errorsNameTheField() {
    QCOMPARE(xyt::test::invalidInputField(
                 [] { TransferFunction(Polynomial::constant(1.0), Polynomial()); }),
             QString("den"));
    QCOMPARE(xyt::test::invalidInputField([] {
                 TransferFunction(Polynomial::constant(1.0), Polynomial::constant(1.0), -0.1);
             }),
             QString("ts"));
    QCOMPARE(xyt::test::invalidInputField([] {
                 TransferFunction(Polynomial::constant(1.0), Polynomial::constant(1.0), kNaN);
             }),
             QString("ts"));
    QCOMPARE(xyt::test::invalidInputField([] { tf({1.0, kNaN}, {1.0, 1.0}); }), QString("num[1]"));
    QCOMPARE(xyt::test::invalidInputField([] { tf({1.0}, {1.0, kInf}); }), QString("den[1]"));
    QCOMPARE(xyt::test::invalidInputField([] { tf({1.0}, {0.0, 0.0}); }), QString("den"));
    const Polynomial one = Polynomial::constant(1.0);
    QCOMPARE(xyt::test::invalidInputField([&] {
                 TransferFunction::fromZInverse(one, Polynomial::fromAscending({0.0, 1.0}), 0.1);
             }),
             QString("den"));
    QCOMPARE(xyt::test::invalidInputField([&] { TransferFunction::fromZInverse(one, one, 0.0); }),
             QString("ts"));
    QCOMPARE(xyt::test::invalidInputField(
                 [&] { TransferFunction::fromZInverse(one, Polynomial(), 0.1); }),
             QString("den"));
    QCOMPARE(xyt::test::invalidInputField([] {
                 tf({1.0}, {1.0, 1.0}).numZInverse();
             }),
             QString("ts"));
    const TransferFunction d1(one, Polynomial::fromAscending({-0.5, 1.0}), 0.1);
    const TransferFunction d2(one, Polynomial::fromAscending({-0.5, 1.0}), 0.2);
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::series(d1, d2); }), QString("ts"));
    QCOMPARE(xyt::test::invalidInputField([&] {
                 xyt::parallel(d1, tf({1.0}, {1.0, 1.0}));
             }),
             QString("ts"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::feedback(d1, d1, 0); }), QString("sign"));
    // An improper discrete system has no causal z^-1 form.
    const TransferFunction improper(Polynomial::fromAscending({0.0, 0.0, 1.0}),
                                    Polynomial::fromAscending({-0.5, 1.0}), 0.1);
    QCOMPARE(xyt::test::invalidInputField([&] { improper.numZInverse(); }), QString("num"));
}

QTEST_APPLESS_MAIN(TstTransferFunction)
#include "tst_transfer_function.moc"
