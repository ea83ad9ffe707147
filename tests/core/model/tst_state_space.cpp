// SPDX-License-Identifier: GPL-3.0-or-later
// State-space realization and exact discretization: against the transfer function itself,
// scalar closed forms and Octave's c2d (tests/data/gt_zoh.csv, see tests/data/README.md).
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"
#include "tests/support/core_checks.h"
#include "tests/support/reference_data.h"
#include "tests/support/tolerance.h"

#include <Eigen/Dense>
#include <QTest>

#include <cmath>
#include <limits>

using xyt::Polynomial;
using xyt::TransferFunction;
using Complex = std::complex<double>;

namespace {
/// The systems of the reference file, by the names used there.
TransferFunction namedSystem(const QString& name) {
    const auto preset = xyt::findGtPreset(name.section(' ', 0, 0).toStdString());
    if (!preset)
        return {};
    if (name.endsWith("plant"))
        return preset->plant.transferFunction();
    return xyt::designGuilleminTruxal(preset->plant, preset->omegaNRadPerSec, preset->kp)
        .closedLoop;
}

Complex ssValue(const xyt::StateSpace& ss, Complex s) {
    const Eigen::Index n = ss.states();
    const Eigen::MatrixXcd m = s * Eigen::MatrixXcd::Identity(n, n) - ss.a.cast<Complex>();
    const Eigen::VectorXcd x = m.partialPivLu().solve(ss.b.cast<Complex>());
    return (ss.c.cast<Complex>() * x)(0) + ss.d(0, 0);
}
} // namespace

class TstStateSpace : public QObject {
    Q_OBJECT
private slots:
    void realizationReproducesTf_data();
    void realizationReproducesTf();
    void zohScalarClosedForm();
    void zohAgainstOctave_data();
    void zohAgainstOctave();
    void fohScalarClosedForm_data();
    void fohScalarClosedForm();
    void characteristicPolynomialOfKnownMatrix();
    void errorsNameTheField();
};

void TstStateSpace::realizationReproducesTf_data() {
    QTest::addColumn<QList<double>>("num");
    QTest::addColumn<QList<double>>("den");
    QTest::newRow("lower-base plant, Braga et al. Eq. 2")
        << QList<double>{77.8} << QList<double>{1, 125.3, 3665, 0};
    QTest::newRow("lower-base G_R, Eq. 19")
        << QList<double>{2334, 16} << QList<double>{1, 125.3, 3665, 2334, 16};
    QTest::newRow("biproper (2s^2+1)/(s^2+3s+2)")
        << QList<double>{2, 0, 1} << QList<double>{1, 3, 2};
    QTest::newRow("non-monic PI (30s+0.2)/(2s)") << QList<double>{30, 0.2} << QList<double>{2, 0};
    QTest::newRow("static gain 4") << QList<double>{4} << QList<double>{1};
}

void TstStateSpace::realizationReproducesTf() {
    // Invariant: C (sI - A)^-1 B + D == N(s)/D(s) at test points away from the poles. A solve of
    // a companion matrix of order <= 4: 1e-12 relative.
    QFETCH(QList<double>, num);
    QFETCH(QList<double>, den);
    const TransferFunction g =
        TransferFunction::fromDescending({num.begin(), num.end()}, {den.begin(), den.end()});
    const xyt::StateSpace ss = xyt::realize(g);
    QCOMPARE(ss.states(), Eigen::Index(g.den().degree()));
    for (const Complex s :
         {Complex(0.3, 0.0), Complex(-1.5, 2.0), Complex(0.0, 7.0), Complex(50.0, -20.0)})
        QVERIFY2(xyt::test::nearComplex(ssValue(ss, s), g(s), 1e-12),
                 qPrintable(QString("s = %1 + %2j").arg(s.real()).arg(s.imag())));
}

void TstStateSpace::zohScalarClosedForm() {
    // x' = -2 x + 3 u held over Ts: Phi = e^{-2 Ts}, Gamma = 3 (1 - e^{-2 Ts}) / 2; the
    // transfer function is Gamma/(z - Phi). expm of a 2x2: 1e-14 relative.
    const double ts = 0.07;
    const TransferFunction g = TransferFunction::fromDescending({3.0}, {1.0, 2.0});
    const xyt::StateSpace d = xyt::discretizeZoh(xyt::realize(g), ts);
    XYT_COMPARE_NEAR(d.a(0, 0), std::exp(-2.0 * ts), 1e-14, 0.0);
    XYT_COMPARE_NEAR((d.c * d.b)(0, 0), 1.5 * (1.0 - std::exp(-2.0 * ts)), 1e-14, 0.0);
    QCOMPARE(d.tsSeconds, ts);
    const TransferFunction gd = xyt::c2dZoh(g, ts);
    XYT_COMPARE_NEAR(gd.den().coefficient(0), -std::exp(-2.0 * ts), 1e-14, 0.0);
    XYT_COMPARE_NEAR(gd.num().coefficient(0), 1.5 * (1.0 - std::exp(-2.0 * ts)), 1e-13, 0.0);
    // ZOH keeps the DC gain: 1.5.
    XYT_COMPARE_NEAR(gd.dcGain(), 1.5, 1e-13, 0.0);
}

void TstStateSpace::zohAgainstOctave_data() {
    QTest::addColumn<QString>("system");
    QTest::addColumn<double>("ts");
    QTest::addColumn<QList<double>>("num");
    QTest::addColumn<QList<double>>("den");
    const xyt::test::CsvTable table = xyt::test::readCsv("gt_zoh.csv");
    QVERIFY2(table.rows.size() == 16, "tests/data/gt_zoh.csv: expected 16 rows");
    for (std::size_t i = 0; i + 1 < table.rows.size(); i += 2) {
        QList<double> num, den;
        for (const char* c : {"c0", "c1", "c2", "c3", "c4"}) {
            num << table.number(i, c);
            den << table.number(i + 1, c);
        }
        const QString name = table.rows[i][0];
        const double ts = table.number(i, "ts");
        QTest::newRow(qPrintable(QString("Octave c2d zoh: %1, Ts %2").arg(name).arg(ts)))
            << name << ts << num << den;
    }
}

void TstStateSpace::zohAgainstOctave() {
    QFETCH(QString, system);
    QFETCH(double, ts);
    QFETCH(QList<double>, num);
    QFETCH(QList<double>, den);
    const TransferFunction g = namedSystem(system);
    const TransferFunction gd = xyt::c2dZoh(g, ts);
    const Polynomial denRef = Polynomial::fromDescending({den.begin(), den.end()});
    const Polynomial numRef = Polynomial::fromDescending({num.begin(), num.end()});
    QCOMPARE(gd.den().degree(), denRef.degree());
    // Denominator: e^{p Ts} products, coefficients of order 1: 1e-11 absolute covers two
    // independent expm evaluations and the expansion of the characteristic polynomial.
    for (int i = 0; i <= denRef.degree(); ++i)
        XYT_COMPARE_NEAR(gd.den().coefficient(i), denRef.coefficient(i), 0.0, 1e-11);
    // Numerator: computed as a difference of characteristic polynomials of order-1 size, so its
    // absolute error is at the same 1e-11 scale although the coefficients are as small as 1e-6
    // (the Ts = 0.01 plants): compare its absolute error, plus the DC gain which checks the sum.
    for (int i = 0; i <= std::max(gd.num().degree(), numRef.degree()); ++i)
        XYT_COMPARE_NEAR(gd.num().coefficient(i), numRef.coefficient(i), 0.0, 1e-11);
    // Poles map to e^{p Ts} (closed form of ZOH).
    auto zPoles = gd.poles();
    std::vector<Complex> mapped;
    for (const Complex& p : g.poles())
        mapped.push_back(std::exp(p * ts));
    xyt::sortRoots(mapped);
    QCOMPARE(zPoles.size(), mapped.size());
    for (std::size_t i = 0; i < mapped.size(); ++i)
        QVERIFY(xyt::test::nearComplex(zPoles[i], mapped[i], 0.0, 1e-9));
    // ZOH preserves the DC gain: 1 for the GT closed loops (type 2), and the plants keep their
    // integrator (a pole at z = 1, infinite gain). N(1)/D(1) of the closed loops is
    // ill-conditioned: D(1) ~ 1e-8 is a sum of coefficients of size ~1, so its relative error is
    // eps sum|d_i| / |D(1)| (3.6e-7 for the upper base at Ts 0.01; Octave's own coefficients
    // give 0.99999992 there). Tolerance: 10 times that bound.
    if (system.endsWith("closed loop")) {
        double sumAbs = 0.0;
        for (double c : gd.den().ascending())
            sumAbs += std::abs(c);
        const double cond =
            std::numeric_limits<double>::epsilon() * sumAbs / std::abs(gd.den()(1.0));
        XYT_COMPARE_NEAR(gd.dcGain(), 1.0, 10.0 * cond, 0.0);
    } else {
        QVERIFY(std::isinf(gd.dcGain()));
    }
}

void TstStateSpace::fohScalarClosedForm_data() {
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("ts");
    QTest::newRow("stable a = -2, Ts 0.07") << -2.0 << 0.07;
    QTest::newRow("unstable a = 0.5, Ts 0.01") << 0.5 << 0.01;
    QTest::newRow("fast a = -125, Ts 0.1") << -125.0 << 0.1;
}

void TstStateSpace::fohScalarClosedForm() {
    // x' = a x + b u with u linear over the step: x(T) = e^{aT} x0 + gamma0 u0 + gamma1 slope,
    // gamma0 = b (e^{aT} - 1)/a, gamma1 = int_0^T e^{a(T-s)} b s ds = b (e^{aT} - 1 - aT)/a^2.
    // gamma1 is evaluated with expm1 to avoid cancellation; expm of a 3x3: 1e-12 relative.
    QFETCH(double, a);
    QFETCH(double, ts);
    const double b = 3.0;
    Eigen::MatrixXd am(1, 1), bm(1, 1);
    am << a;
    bm << b;
    const xyt::FohDiscretization foh = xyt::discretizeFoh(am, bm, ts);
    const double aT = a * ts;
    XYT_COMPARE_NEAR(foh.phi(0, 0), std::exp(aT), 1e-13, 0.0);
    XYT_COMPARE_NEAR(foh.gamma0(0, 0), b * std::expm1(aT) / a, 1e-12, 0.0);
    XYT_COMPARE_NEAR(foh.gamma1(0, 0), b * (std::expm1(aT) - aT) / (a * a), 1e-10, 0.0);
}

void TstStateSpace::characteristicPolynomialOfKnownMatrix() {
    // Upper triangular with eigenvalues 1, -2, 3: det(xI - M) = (x - 1)(x + 2)(x - 3)
    // = x^3 - 2 x^2 - 5 x + 6.
    Eigen::MatrixXd m(3, 3);
    m << 1, 4, -1, 0, -2, 7, 0, 0, 3;
    const Polynomial p = xyt::characteristicPolynomial(m);
    const std::vector<double> expected{6.0, -5.0, -2.0, 1.0};
    QCOMPARE(p.degree(), 3);
    for (int i = 0; i <= 3; ++i)
        XYT_COMPARE_NEAR(p.coefficient(i), expected[std::size_t(i)], 0.0, 1e-13);
    QCOMPARE(xyt::characteristicPolynomial(Eigen::MatrixXd(0, 0)).degree(), 0);
}

void TstStateSpace::errorsNameTheField() {
    const TransferFunction g = TransferFunction::fromDescending({1.0}, {1.0, 1.0});
    using xyt::test::invalidInputField;
    QCOMPARE(invalidInputField([] {
                 xyt::realize(TransferFunction::fromDescending({1.0, 0.0}, {1.0}));
             }),
             QString("num"));
    QCOMPARE(invalidInputField([&] { xyt::c2dZoh(g, 0.0); }), QString("ts"));
    QCOMPARE(invalidInputField([&] { xyt::c2dZoh(g, -0.01); }), QString("ts"));
    QCOMPARE(invalidInputField([&] { xyt::c2dZoh(g, std::nan("")); }), QString("ts"));
    QCOMPARE(invalidInputField([&] { xyt::c2dZoh(xyt::c2dZoh(g, 0.1), 0.1); }), QString("system"));
    QCOMPARE(invalidInputField(
                 [&] { xyt::discretizeZoh(xyt::discretizeZoh(xyt::realize(g), 0.1), 0.1); }),
             QString("system"));
    QCOMPARE(invalidInputField([] {
                 xyt::discretizeFoh(Eigen::MatrixXd::Zero(1, 1), Eigen::MatrixXd::Ones(1, 1), 0.0);
             }),
             QString("ts"));
    // Regression (fuzz_design, crash-stiff-discretization): the companion form of
    // s (s^2 + a1 s + a2) with a1 = 1e300 overflows exp()'s scaling and squaring; refused, never
    // a NaN step matrix.
    Eigen::MatrixXd stiff(3, 3);
    stiff << 0, 1, 0, 0, 0, 1, 0, -1e300, -1e300;
    QCOMPARE(
        invalidInputField([&] { xyt::discretizeFoh(stiff, Eigen::MatrixXd::Ones(3, 1), 0.01); }),
        QString("ts"));
}

QTEST_APPLESS_MAIN(TstStateSpace)
#include "tst_state_space.moc"
