// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/errors.h"
#include "core/analysis/parameter_locus.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

using namespace xyt;
using Complex = std::complex<double>;

class TstParameterLocus : public QObject {
    Q_OBJECT
private slots:
    void sweepValuesLinearAndLog();
    void gtSweepPolesSatisfyEq7_data();
    void gtSweepPolesSatisfyEq7();
    void branchesAreContinuous();
    void invalidSweepThrows();
};

void TstParameterLocus::sweepValuesLinearAndLog() {
    ParameterSweep s{1.0, 100.0, 3, true};
    const auto log = sweepValues(s);
    QCOMPARE(log.size(), std::size_t(3));
    // Geometric spacing: 1, sqrt(100) = 10, 100.
    XYT_COMPARE_NEAR(log[0], 1.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(log[1], 10.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(log[2], 100.0, 0.0, 0.0);
    s.logSpacing = false;
    const auto lin = sweepValues(s);
    XYT_COMPARE_NEAR(lin[1], 50.5, 1e-15, 0.0);
}

void TstParameterLocus::gtSweepPolesSatisfyEq7_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<bool>("sweepOmega");
    QTest::addColumn<bool>("logSpacing");
    QTest::newRow("lower base, wn 0.5..8, kp 30") << "lower-base" << true << false;
    QTest::newRow("lower base, kp 1..1000 log, wn 2") << "lower-base" << false << true;
    QTest::newRow("upper base, wn 0.2..5 log, kp 30") << "upper-base" << true << true;
    QTest::newRow("upper base, kp 5..200, wn 1") << "upper-base" << false << false;
}

void TstParameterLocus::gtSweepPolesSatisfyEq7() {
    // Every point is a root of the GT closed-loop characteristic polynomial (paper 000 Eq. 7
    // with Eq. 15-18, psi2 = 0): s^4 + a1 s^3 + a2 s^2 + kp k0 s + wn^4. Vieta on it: the
    // poles sum to -a1 and multiply to wn^4 at every value (1e-9 relative: root round-off of
    // a polynomial whose coefficients span 1e-4..1e6).
    QFETCH(QString, preset);
    QFETCH(bool, sweepOmega);
    QFETCH(bool, logSpacing);
    const GtPreset p = *findGtPreset(preset.toStdString());
    ParameterSweep s;
    s.logSpacing = logSpacing;
    s.count = 40;
    if (sweepOmega) {
        s.from = p.omegaNRadPerSec / 4.0;
        s.to = p.omegaNRadPerSec * 4.0;
    } else {
        s.from = logSpacing ? 1.0 : 5.0;
        s.to = logSpacing ? 1000.0 : 200.0;
    }
    const double fixed = sweepOmega ? p.kp : p.omegaNRadPerSec;
    const ParameterLocus locus = gtParameterLocus(
        p.plant, sweepOmega ? GtSweptParameter::OmegaN : GtSweptParameter::Kp, s, fixed);
    QCOMPARE(QString::fromStdString(locus.parameterName), sweepOmega ? "wn" : "kp");
    QCOMPARE(locus.branches.size(), std::size_t(4));
    QVERIFY(locus.values.size() >= 40); // base samples plus refinements
    QCOMPARE(locus.values.front(), s.from);
    QCOMPARE(locus.values.back(), s.to);
    for (std::size_t i = 0; i < locus.values.size(); ++i) {
        const double wn = sweepOmega ? locus.values[i] : fixed;
        const double kp = sweepOmega ? fixed : locus.values[i];
        if (i > 0)
            QVERIFY(locus.values[i] > locus.values[i - 1]);
        const Polynomial cl = Polynomial::fromDescending(
            {1.0, p.plant.a1, p.plant.a2, kp * p.plant.k0, std::pow(wn, 4)});
        Complex sum(0.0), product(1.0);
        for (const auto& branch : locus.branches) {
            const Complex r = branch[i];
            sum += r;
            product *= r;
            QVERIFY(std::abs(cl(r)) <= 1e-12 * (std::abs(r) * std::abs(r) * std::abs(r) * std::abs(r) +
                                                 p.plant.a1 * std::pow(std::abs(r), 3) +
                                                 p.plant.a2 * std::abs(r) * std::abs(r) +
                                                 kp * p.plant.k0 * std::abs(r) + std::pow(wn, 4)));
        }
        XYT_COMPARE_NEAR(sum.real(), -p.plant.a1, 1e-9, 0.0);
        XYT_COMPARE_NEAR(product.real(), std::pow(wn, 4), 1e-9, 0.0);
    }
}

void TstParameterLocus::branchesAreContinuous() {
    // With refinement the largest jump of a pole between consecutive values is at most the
    // bound maxStepFraction * extent of all base poles, unless the depth limit was hit; with
    // 6 bisections of 100 base intervals that limit is not reached on this smooth sweep.
    const GtPreset p = *findGtPreset("lower-base");
    ParameterSweep s{0.5, 8.0, 100, false};
    const ParameterLocus locus = gtParameterLocus(p.plant, GtSweptParameter::OmegaN, s, 30.0);
    double reMin = 1e300, reMax = -1e300, imAbs = 0.0;
    for (const auto& b : locus.branches)
        for (const Complex& r : b) {
            reMin = std::min(reMin, r.real());
            reMax = std::max(reMax, r.real());
            imAbs = std::max(imAbs, std::abs(r.imag()));
        }
    const double bound = s.maxStepFraction * std::max(reMax - reMin, 2.0 * imAbs);
    for (const auto& b : locus.branches)
        for (std::size_t i = 1; i < b.size(); ++i)
            QVERIFY2(std::abs(b[i] - b[i - 1]) <= bound * (1.0 + 1e-12),
                     qPrintable(QStringLiteral("jump %1 at wn = %2").arg(std::abs(b[i] - b[i - 1])).arg(locus.values[i])));
}

void TstParameterLocus::invalidSweepThrows() {
    const GtPreset p = *findGtPreset("lower-base");
    auto fieldOf = [&](ParameterSweep s, GtSweptParameter which, double fixed) -> std::string {
        try {
            gtParameterLocus(p.plant, which, s, fixed);
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return "no exception";
    };
    QCOMPARE(fieldOf({0.0, 2.0, 10, false}, GtSweptParameter::OmegaN, 30.0), std::string("wn"));
    QCOMPARE(fieldOf({1.0, 2.0, 10, false}, GtSweptParameter::OmegaN, -1.0), std::string("kp"));
    QCOMPARE(fieldOf({1.0, 2.0, 1, false}, GtSweptParameter::Kp, 2.0), std::string("count"));
    QCOMPARE(fieldOf({1.0, 1.0, 10, false}, GtSweptParameter::Kp, 2.0), std::string("to"));
}

QTEST_APPLESS_MAIN(TstParameterLocus)
#include "tst_parameter_locus.moc"
