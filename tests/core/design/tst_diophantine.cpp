// SPDX-License-Identifier: GPL-3.0-or-later
// Diophantine solve A F + B G = T and the RST pole-placement design of Patrick, Ishak and Adnan
// Sec. 5.
#include "core/design/diophantine.h"
#include "core/design/pole_placement.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using xyt::Polynomial;

namespace {

Polynomial poly(std::vector<double> c) {
    return Polynomial::fromAscending(std::move(c));
}

std::vector<double> toVector(const QJsonArray& a) {
    std::vector<double> v;
    for (const auto& x : a)
        v.push_back(x.toDouble());
    return v;
}

void compareCoefficients(const Polynomial& actual, const std::vector<double>& expected,
                         double relTol, double absTol) {
    QCOMPARE(actual.degree() + 1, static_cast<int>(expected.size()));
    for (std::size_t i = 0; i < expected.size(); ++i)
        XYT_COMPARE_NEAR(actual.coefficient(static_cast<int>(i)), expected[i], relTol, absTol);
}

} // namespace

class TstDiophantine : public QObject {
    Q_OBJECT
private slots:
    void paperDesign_data();
    void paperDesign();
    void paperPrintedControllerResidual_data();
    void paperPrintedControllerResidual();
    void paperZeros_data();
    void paperZeros();
    void randomPlantsMatchIndependentSolve();
    void higherOrderTargetRaisesDegreeOfF();
    void commonRootIsAnError();
    void nearCommonRootWarns();
    void nonMonicAIsNormalized();
    void invalidInput_data();
    void invalidInput();
};

void TstDiophantine::paperDesign_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<std::vector<double>>("f");
    QTest::addColumn<std::vector<double>>("g");
    QTest::addColumn<double>("kf");
    // Expected F and G: an independent numpy.linalg.lstsq solve of the convolution-matrix form
    // of A F + B G = T (the method of tests/data/gen_pp_zpetc.py), printed with 17 digits.
    // Kf = T(1)/B(1) (paper Eq. 7, Kf = sum T / sum B).
    // X axis: the paper's Eq. 9 prints Kf = 13.4251, F = 1 + 0.9331 z^-1 - 0.0657 z^-2,
    // G = 12.4613 + 0.9537 z^-1; these are WRONG (they leave a residual of 0.217 in
    // A F + B G - T, see paperPrintedControllerResidual). Correct: Kf = 0.8/0.0595 = 13.4454
    // (paper 0.0203 low), f2 = +0.0720 (paper -0.0657).
    QTest::newRow("x-axis (Eq. 1, 9)")
        << "x-axis" << std::vector<double>{1.0, 0.93631022836115441, 0.071970436540917365}
        << std::vector<double>{12.391681036552121, 1.0435713298433054} << 0.8 / 0.0595;
    // Y axis: Eq. 10 prints Kf = 9.0509 (correct 0.8/0.0884 = 9.04977, 0.0011 high),
    // F = 1 + 0.7284 z^-1 - 0.0879 z^-2, G = 15.0910 - 6.0346 z^-1: close, but off by up to
    // 3e-3 in g0, beyond the 4 printed decimals.
    QTest::newRow("y-axis (Eq. 3, 10)")
        << "y-axis" << std::vector<double>{1.0, 0.72790003440297124, -0.088117029536019437}
        << std::vector<double>{15.088067204461028, -6.0327285743540289} << 0.8 / 0.0884;
}

void TstDiophantine::paperDesign() {
    QFETCH(QString, preset);
    QFETCH(std::vector<double>, f);
    QFETCH(std::vector<double>, g);
    QFETCH(double, kf);
    const auto p = xyt::findPolePlacementPreset(preset.toStdString());
    QVERIFY(p);
    const xyt::PolePlacementDesign d = xyt::designPolePlacement(p->a, p->b, p->t, p->tsSeconds);
    // Sylvester condition number < 100 for both axes: 1e-12 relative is ~1e4 round-offs.
    compareCoefficients(d.f, f, 1e-12, 1e-14);
    compareCoefficients(d.g, g, 1e-12, 1e-14);
    XYT_COMPARE_NEAR(d.kf, kf, 1e-14, 0.0);
    QCOMPARE(d.delay, 1);
    // The equation itself: coefficients of order 1..10, residual at round-off level.
    QVERIFY2(d.residual < 1e-13, qPrintable(QString::number(d.residual)));
    QVERIFY(d.warnings.empty());
    // Invariant: the closed loop Kf B / T has the poles of T (z = 0.2) and unity DC gain.
    const xyt::TransferFunction cl = d.closedLoop();
    XYT_COMPARE_NEAR(cl.dcGain(), 1.0, 1e-13, 0.0);
    compareCoefficients(d.closedLoopDen, {1.0, -0.2}, 0.0, 0.0);
}

void TstDiophantine::paperPrintedControllerResidual_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<std::vector<double>>("f");
    QTest::addColumn<std::vector<double>>("g");
    QTest::addColumn<double>("residual");
    // max |A F + B G - T| of the PRINTED F, G (hand-checkable expansion; numpy gives the same):
    // x axis 0.21733967 at z^-3; y axis 6.032e-4 at z^-1. Rounding F and G to 4 decimals can
    // leave at most 5e-5 * (sum |a_i| + sum |b_i|) = 5e-5 * 3.43 = 1.7e-4: the x-axis F/G are
    // misprinted, the y-axis ones slightly off (3.5x the rounding bound).
    QTest::newRow("x-axis Eq. 9 printed") << "x-axis" << std::vector<double>{1.0, 0.9331, -0.0657}
                                          << std::vector<double>{12.4613, 0.9537} << 0.21733967;
    QTest::newRow("y-axis Eq. 10 printed") << "y-axis" << std::vector<double>{1.0, 0.7284, -0.0879}
                                           << std::vector<double>{15.0910, -6.0346} << 6.032e-4;
}

void TstDiophantine::paperPrintedControllerResidual() {
    QFETCH(QString, preset);
    QFETCH(std::vector<double>, f);
    QFETCH(std::vector<double>, g);
    QFETCH(double, residual);
    const auto p = xyt::findPolePlacementPreset(preset.toStdString());
    const double r = (p->a * poly(f) + p->b * poly(g) - p->t).maxAbsCoefficient();
    // The expected residuals are quoted with 4-5 significant digits.
    XYT_COMPARE_NEAR(r, residual, 1e-3, 0.0);
    // Against the correct solution's residual (< 1e-13): the printed values fail Eq. 8.
    QVERIFY(r > 1.7e-4);
}

void TstDiophantine::paperZeros_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<double>("nmp");
    QTest::addColumn<double>("mp");
    // numpy.roots of B(z^-1)/z^-1 (17 digits). Paper Sec. 2.1 prints the x-axis zeros as
    // z = -0.5327 and -2.0244: the first sign is wrong, z^2 + 1.4917 z - 1.0784 (Eq. 2) has the
    // roots +0.5327 and -2.0244 (product -1.0784 < 0: opposite signs). Sec. 2.2 (y axis,
    // 0.1053 and -1.8070) is right.
    QTest::newRow("x-axis Sec. 2.1") << "x-axis" << -2.0243841653913899 << 0.53269770458378884;
    QTest::newRow("y-axis Sec. 2.2") << "y-axis" << -1.807037662228741 << 0.10533311677419542;
}

void TstDiophantine::paperZeros() {
    QFETCH(QString, preset);
    QFETCH(double, nmp);
    QFETCH(double, mp);
    const auto p = xyt::findPolePlacementPreset(preset.toStdString());
    const auto d = xyt::designPolePlacement(p->a, p->b, p->t, p->tsSeconds);
    QCOMPARE(d.plantZeros.size(), std::size_t(2));
    // Sorted by real part; simple real roots: 1e-12 relative is round-off of the eigen solve.
    XYT_COMPARE_NEAR(d.plantZeros[0].real(), nmp, 1e-12, 0.0);
    XYT_COMPARE_NEAR(d.plantZeros[1].real(), mp, 1e-12, 0.0);
    XYT_COMPARE_NEAR(d.plantZeros[0].imag(), 0.0, 0.0, 1e-14);
}

void TstDiophantine::randomPlantsMatchIndependentSolve() {
    QFile file(QStringLiteral(XYT_SOURCE_DIR "/tests/data/pp_diophantine_random.json"));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    const QJsonArray cases = QJsonDocument::fromJson(file.readAll()).object()["cases"].toArray();
    QCOMPARE(cases.size(), 40);
    for (const auto& c : cases) {
        const QJsonObject o = c.toObject();
        const Polynomial a = poly(toVector(o["a"].toArray()));
        const Polynomial b = poly(toVector(o["b"].toArray()));
        const Polynomial t = poly(toVector(o["t"].toArray()));
        const xyt::DiophantineSolution s = xyt::solveDiophantine(a, b, t);
        // The generator keeps poles and zeros >= 0.05 apart, so the systems are well posed;
        // the tolerance scales with the condition number (round-off ~ cond * 1e-16, with a
        // factor 1e3 for both solvers' own errors).
        const double tol = std::max(1e-12, s.conditionNumber * 1e-13);
        const double scale = std::max(s.f.maxAbsCoefficient(), s.g.maxAbsCoefficient());
        compareCoefficients(s.f, toVector(o["f"].toArray()), 0.0, tol * scale);
        const auto g = toVector(o["g"].toArray());
        for (std::size_t i = 0; i < g.size(); ++i)
            XYT_COMPARE_NEAR(s.g.coefficient(static_cast<int>(i)), g[i], 0.0, tol * scale);
        QVERIFY2(s.residual < tol * scale, qPrintable(QString::number(s.residual)));
        // Degree invariant: deg G = na - 1 (minimal solution).
        QVERIFY(s.g.degree() <= std::max(a.degree() - 1, 0));
    }
}

void TstDiophantine::higherOrderTargetRaisesDegreeOfF() {
    // T of degree 5 > na + nb - 1 = 4 (x axis): nf = nt - na = 3 and the equation still holds.
    const auto p = *xyt::findPolePlacementPreset("x-axis");
    const Polynomial t = Polynomial::fromRoots({0.1, 0.2, 0.3, -0.4, 0.5}).reversed(5);
    const auto d = xyt::designPolePlacement(p.a, p.b, t, p.tsSeconds);
    QCOMPARE(d.f.degree(), 3);
    QCOMPARE(d.g.degree(), 1);
    QVERIFY2(d.residual < 1e-13, qPrintable(QString::number(d.residual)));
    // Invariant: F monic (B(0) = 0, A(0) = T(0) = 1).
    XYT_COMPARE_NEAR(d.f.coefficient(0), 1.0, 0.0, 1e-14);
}

void TstDiophantine::commonRootIsAnError() {
    // A = (1 - 0.5 z^-1)(1 - 0.9 z^-1), B = 0.1 z^-1 (1 - 0.5 z^-1): common root z = 0.5.
    const Polynomial a = poly({1.0, -1.4, 0.45});
    const Polynomial b = poly({0.0, 0.1, -0.05});
    try {
        xyt::solveDiophantine(a, b, poly({1.0, -0.2}));
        QFAIL("expected InvalidInput");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(e.field(), std::string("b"));
        QVERIFY2(std::string(e.what()).find("z = 0.5 ") != std::string::npos, e.what());
        // The reason carries its code and the root as an argument, for the translation.
        QCOMPARE(e.reasonDiagnostic().code, std::string("design_common_factor_root"));
        QCOMPARE(e.reasonDiagnostic().args.size(), std::size_t(2));
        QCOMPARE(e.reasonDiagnostic().args[0].text, std::string("0.5"));
        QCOMPARE(e.reason(), "shares the root z = 0.5 with A (common factor of A and B): "
                             "A F + B G = T has no solution (Sylvester condition number " +
                                 e.reasonDiagnostic().args[1].text + ")");
    }
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput,
                             xyt::designPolePlacement(a, b, poly({1.0, -0.2}), 0.07));
}

void TstDiophantine::nearCommonRootWarns() {
    // Zero at 0.501 next to the pole 0.5: condition number ~1.3e4 (numpy.linalg.cond of the
    // same scaled matrix), above kNearCommonFactorCondition = 1e4, below the error limit.
    const Polynomial a = poly({1.0, -1.4, 0.45});
    const Polynomial b = poly({0.0, 1.0, -0.501});
    const auto s = xyt::solveDiophantine(a, b, poly({1.0, -0.2}));
    QCOMPARE(s.warnings.size(), std::size_t(1));
    QVERIFY2(s.warnings[0].text.find("condition number") != std::string::npos,
             s.warnings[0].text.c_str());
    QVERIFY(s.conditionNumber > xyt::kNearCommonFactorCondition);
    // Still a valid solution: the residual is at round-off times the condition number.
    QVERIFY2(s.residual < 1e-10, qPrintable(QString::number(s.residual)));
}

void TstDiophantine::nonMonicAIsNormalized() {
    // 2 A y = 2 B u is the same plant: the design must equal the x-axis one, plus a warning.
    const auto p = *xyt::findPolePlacementPreset("x-axis");
    const auto ref = xyt::designPolePlacement(p.a, p.b, p.t, p.tsSeconds);
    const auto d = xyt::designPolePlacement(2.0 * p.a, 2.0 * p.b, p.t, p.tsSeconds);
    QCOMPARE(d.warnings.size(), std::size_t(1));
    // The warning is coded, A(0) its argument.
    QCOMPARE(d.warnings[0].code, std::string("design_a0_normalized"));
    QCOMPARE(d.warnings[0].args.at(0).text, std::string("2"));
    QCOMPARE(d.warnings[0].text,
             std::string("A(0) = 2: A and B divided by it so that A is monic (same plant)"));
    // Division by 2 is exact in binary, so the normalized inputs are bit-identical.
    QVERIFY(d.a == ref.a);
    QVERIFY(d.b == ref.b);
    XYT_COMPARE_NEAR(d.kf, ref.kf, 0.0, 0.0);
}

void TstDiophantine::invalidInput_data() {
    QTest::addColumn<std::vector<double>>("a");
    QTest::addColumn<std::vector<double>>("b");
    QTest::addColumn<std::vector<double>>("t");
    QTest::addColumn<double>("ts");
    QTest::addColumn<QString>("field");
    const std::vector<double> a{1.0, -1.658, 0.6583}, b{0.0, 0.0421, 0.0628, -0.0454}, t{1.0, -0.2};
    QTest::newRow("no delay") << a << std::vector<double>{0.1, 0.0421} << t << 0.07 << "b";
    QTest::newRow("T(0) != 1") << a << b << std::vector<double>{2.0, -0.2} << 0.07 << "t";
    QTest::newRow("unstable T") << a << b << std::vector<double>{1.0, -1.5} << 0.07 << "t";
    QTest::newRow("A(0) = 0") << std::vector<double>{0.0, 1.0} << b << t << 0.07 << "a";
    QTest::newRow("zero B") << a << std::vector<double>{0.0} << t << 0.07 << "b";
    QTest::newRow("B(1) = 0") << a << std::vector<double>{0.0, 1.0, -1.0} << t << 0.07 << "b";
    QTest::newRow("ts = 0") << a << b << t << 0.0 << "ts";
    QTest::newRow("ts NaN") << a << b << t << std::nan("") << "ts";
}

void TstDiophantine::invalidInput() {
    QFETCH(std::vector<double>, a);
    QFETCH(std::vector<double>, b);
    QFETCH(std::vector<double>, t);
    QFETCH(double, ts);
    QFETCH(QString, field);
    try {
        xyt::designPolePlacement(poly(a), poly(b), poly(t), ts);
        QFAIL("expected InvalidInput");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), field);
    }
}

QTEST_APPLESS_MAIN(TstDiophantine)
#include "tst_diophantine.moc"
