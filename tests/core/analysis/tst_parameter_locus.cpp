// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/parameter_locus.h"
#include "core/model/errors.h"
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
    void stabilityChangesMatchRouth();
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
    // Every point is a root of the GT closed-loop characteristic polynomial (Braga et al. Eq. 7
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
            QVERIFY(std::abs(cl(r)) <=
                    1e-12 * (std::abs(r) * std::abs(r) * std::abs(r) * std::abs(r) +
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
                     qPrintable(QStringLiteral("jump %1 at wn = %2")
                                    .arg(std::abs(b[i] - b[i - 1]))
                                    .arg(locus.values[i])));
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

void TstParameterLocus::stabilityChangesMatchRouth() {
    // The GT closed loop s^4 + a s^3 + b s^2 + c s + d (c = kp k0, d = wn^4; Braga et al. Eq. 7,
    // 15-18) is Hurwitz iff a, b, c, d > 0, ab - c > 0 and c (ab - c) - a^2 d > 0 (Routh).
    // Lower base of Braga et al.: a = 125.3, b = 3665, k0 = 77.8.
    const ThirdOrderPlant plant{77.8, 125.3, 3665.0};
    const double a = plant.a1, b = plant.a2;
    { // wn sweeps at kp = 30: one change, unstable above wn* = (c (ab - c) / a^2)^(1/4).
        const double c = 30.0 * plant.k0;
        const double wnStar = std::pow(c * (a * b - c) / (a * a), 0.25);
        const ParameterLocus l =
            gtParameterLocus(plant, GtSweptParameter::OmegaN, {0.2, 20.0, 100, true}, 30.0);
        QCOMPARE(l.stabilityChanges.size(), std::size_t(1));
        // Bisection to 1e-13 relative; the root finder's error on the crossing pole's real
        // part (~1e-15 of |p| ~ 10) moves the boundary by far less than 1e-9.
        XYT_COMPARE_NEAR(l.stabilityChanges[0].value, wnStar, 1e-9, 0.0);
        QVERIFY(l.stabilityChanges[0].becomesUnstable);
        // The crossing pole is on the imaginary axis at omega^2 = c / a (Routh auxiliary row).
        XYT_COMPARE_NEAR(l.stabilityChanges[0].pole.imag(), std::sqrt(c / a), 1e-6, 0.0);
        XYT_COMPARE_NEAR(l.stabilityChanges[0].pole.real(), 0.0, 0.0, 1e-6);
        // Swept downwards the same boundary is found, with the same sense (stable below).
        const ParameterLocus down =
            gtParameterLocus(plant, GtSweptParameter::OmegaN, {20.0, 0.2, 100, true}, 30.0);
        QCOMPARE(down.stabilityChanges.size(), std::size_t(1));
        XYT_COMPARE_NEAR(down.stabilityChanges[0].value, wnStar, 1e-9, 0.0);
        QVERIFY(down.stabilityChanges[0].becomesUnstable);
    }
    { // kp sweeps at wn = 10: stable for c between the roots of c^2 - ab c + a^2 d = 0.
        const double d = 1e4;
        const double disc = std::sqrt(a * a * b * b - 4.0 * a * a * d);
        const double kp1 = 0.5 * (a * b - disc) / plant.k0, kp2 = 0.5 * (a * b + disc) / plant.k0;
        const ParameterLocus l =
            gtParameterLocus(plant, GtSweptParameter::Kp, {0.1 * kp1, 2.0 * kp2, 200, true}, 10.0);
        QCOMPARE(l.stabilityChanges.size(), std::size_t(2));
        XYT_COMPARE_NEAR(l.stabilityChanges[0].value, kp1, 1e-9, 0.0);
        QVERIFY(!l.stabilityChanges[0].becomesUnstable);
        XYT_COMPARE_NEAR(l.stabilityChanges[1].value, kp2, 1e-9, 0.0);
        QVERIFY(l.stabilityChanges[1].becomesUnstable);
    }
    { // Invariant: a sweep that stays stable reports no change.
        const ParameterLocus l =
            gtParameterLocus(plant, GtSweptParameter::OmegaN, {0.2, 5.0, 50, true}, 30.0);
        QVERIFY(l.stabilityChanges.empty());
    }
}

QTEST_APPLESS_MAIN(TstParameterLocus)
#include "tst_parameter_locus.moc"
