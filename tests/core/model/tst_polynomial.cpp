// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/errors.h"
#include "core/model/polynomial.h"
#include "tests/support/tolerance.h"

#include <QTest>

using xyt::Polynomial;
using Complex = std::complex<double>;

class TstPolynomial : public QObject {
    Q_OBJECT
private slots:
    void constructionTrimsAndOrders();
    void arithmetic();
    void evaluation();
    void rootsClosedForm_data();
    void rootsClosedForm();
    void rootsResidualOnRandomPolynomials();
    void rootsOfPaperPolynomials();
    void divisionIdentity();
    void rejectsNaN();
    void toStringReadsAsTyped();
};

void TstPolynomial::constructionTrimsAndOrders() {
    const Polynomial p = Polynomial::fromDescending({0.0, 1.0, 125.3, 3665.0, 0.0});
    QCOMPARE(p.degree(), 3);
    QCOMPARE(p.coefficient(3), 1.0);
    QCOMPARE(p.coefficient(0), 0.0);
    QCOMPARE(p.ascending(), (std::vector<double>{0.0, 3665.0, 125.3, 1.0}));
    QCOMPARE(p.descending(), (std::vector<double>{1.0, 125.3, 3665.0, 0.0}));
    QVERIFY(Polynomial().isZero());
    QVERIFY(Polynomial::fromAscending({0.0, 0.0}).isZero());
}

void TstPolynomial::arithmetic() {
    const Polynomial a = Polynomial::fromDescending({1.0, 2.0});  // s + 2
    const Polynomial b = Polynomial::fromDescending({1.0, -3.0}); // s - 3
    QCOMPARE((a * b).descending(), (std::vector<double>{1.0, -1.0, -6.0}));
    QCOMPARE((a + b).descending(), (std::vector<double>{2.0, -1.0}));
    QVERIFY((a - a).isZero());
    QCOMPARE((2.0 * a).descending(), (std::vector<double>{2.0, 4.0}));
    QCOMPARE(a.reversed(2).ascending(), (std::vector<double>{0.0, 1.0, 2.0}));
}

void TstPolynomial::evaluation() {
    const Polynomial p = Polynomial::fromDescending({1.0, 125.3, 3665.0, 0.0});
    // Closed form: p(2) = 8 + 125.3*4 + 3665*2.
    XYT_COMPARE_NEAR(p(2.0), 8.0 + 501.2 + 7330.0, 1e-15, 0.0);
    const Complex v = p(Complex(0.0, 1.0)); // -j - 125.3 + 3665 j
    XYT_COMPARE_NEAR(v.real(), -125.3, 1e-15, 0.0);
    XYT_COMPARE_NEAR(v.imag(), 3664.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(p.derivative()(1.0), 3.0 + 250.6 + 3665.0, 1e-15, 0.0);
}

void TstPolynomial::rootsClosedForm_data() {
    QTest::addColumn<QList<double>>("rootsRe");
    QTest::addColumn<QList<double>>("rootsIm");
    QTest::newRow("real distinct") << QList<double>{-3.0, -1.0, 2.0} << QList<double>{0, 0, 0};
    QTest::newRow("complex pair and zero")
        << QList<double>{-1.0, -1.0, 0.0} << QList<double>{-2.0, 2.0, 0.0};
    QTest::newRow("widely scaled")
        << QList<double>{-1000.0, -1.0, -0.001} << QList<double>{0, 0, 0};
    QTest::newRow("quartic unit circle")
        << QList<double>{0.0, 0.0, 0.6, 0.6} << QList<double>{-1.0, 1.0, -0.8, 0.8};
}

void TstPolynomial::rootsClosedForm() {
    // Closed form: the roots of fromRoots(r) are r; tolerance 1e-9 relative to max(|r|, 1) as
    // the issue requires for well-conditioned inputs.
    QFETCH(QList<double>, rootsRe);
    QFETCH(QList<double>, rootsIm);
    std::vector<Complex> expected;
    for (qsizetype i = 0; i < rootsRe.size(); ++i)
        expected.emplace_back(rootsRe[i], rootsIm[i]);
    auto got = Polynomial::fromRoots(expected, 2.5).roots();
    xyt::sortRoots(got);
    xyt::sortRoots(expected);
    QCOMPARE(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        QVERIFY2(
            xyt::test::nearComplex(got[i], expected[i], 1e-9, 1e-9),
            qPrintable(QString("root %1: got %2%3j").arg(i).arg(got[i].real()).arg(got[i].imag())));
}

void TstPolynomial::rootsResidualOnRandomPolynomials() {
    // Invariant: |p(r)| / (sum |c_i| |r|^i) is at round-off level for every computed root
    // (backward error); 1e-12 leaves room for degree-10 accumulation.
    std::srand(12345);
    for (int trial = 0; trial < 200; ++trial) {
        const int degree = 1 + trial % 10;
        std::vector<double> c(static_cast<std::size_t>(degree) + 1);
        for (double& v : c)
            v = (std::rand() / double(RAND_MAX)) * 2.0 - 1.0;
        c.back() = 1.0 + std::abs(c.back());
        const Polynomial p = Polynomial::fromAscending(c);
        const auto roots = p.roots();
        QCOMPARE(int(roots.size()), degree);
        for (const Complex& r : roots) {
            double scale = 0.0;
            for (int i = 0; i <= degree; ++i)
                scale += std::abs(c[std::size_t(i)]) * std::pow(std::abs(r), i);
            QVERIFY2(std::abs(p(r)) <= 1e-12 * scale, qPrintable(QString("trial %1").arg(trial)));
        }
    }
}

void TstPolynomial::rootsOfPaperPolynomials() {
    // Patrick, Ishak and Adnan Eq. 2: B_c(z^-1) = 1 + 1.4917 z^-1 - 1.0784 z^-2, i.e. z^2 + 1.4917
    // z - 1.0784. Quadratic formula: z = (-1.4917 +- sqrt(1.4917^2 + 4 * 1.0784)) / 2 = 0.53266,
    // -2.02436. The paper prints -0.5327 for the first root: a sign misprint (the product of the
    // roots must be -1.0784, which -0.5327 * -2.0244 = +1.0784 is not).
    auto r = Polynomial::fromAscending({-1.0784, 1.4917, 1.0}).roots();
    xyt::sortRoots(r);
    const double disc = std::sqrt(1.4917 * 1.4917 + 4.0 * 1.0784);
    XYT_COMPARE_NEAR(r[0].real(), (-1.4917 - disc) / 2.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(r[1].real(), (-1.4917 + disc) / 2.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(r[1].real(), 0.5327, 0.0, 5e-5); // 4 printed digits
    XYT_COMPARE_NEAR(r[0].real(), -2.0244, 0.0, 5e-5);
}

void TstPolynomial::divisionIdentity() {
    // Invariant: a = q b + r with deg r < deg b.
    const Polynomial a = Polynomial::fromDescending({3.0, -2.0, 5.0, 7.0, -1.0});
    const Polynomial b = Polynomial::fromDescending({2.0, 0.5, -1.0});
    Polynomial q, r;
    Polynomial::divide(a, b, q, r);
    QVERIFY(r.degree() < b.degree());
    const Polynomial back = q * b + r;
    for (int i = 0; i <= a.degree(); ++i)
        XYT_COMPARE_NEAR(back.coefficient(i), a.coefficient(i), 1e-14, 1e-14);
}

void TstPolynomial::rejectsNaN() {
    try {
        Polynomial::fromDescending({1.0, std::nan("")}, "den");
        QFAIL("NaN accepted");
    } catch (const xyt::InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), QString("den[1]"));
    }
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput, Polynomial().roots());
}

void TstPolynomial::toStringReadsAsTyped() {
    QCOMPARE(
        QString::fromStdString(Polynomial::fromDescending({1.0, 125.3, 3665.0, 0.0}).toString()),
        QString("s^3 + 125.3 s^2 + 3665 s"));
    QCOMPARE(QString::fromStdString(Polynomial::fromAscending({1.0, -0.2}).toString("z")),
             QString("-0.2 z + 1"));
}

QTEST_APPLESS_MAIN(TstPolynomial)
#include "tst_polynomial.moc"
