// SPDX-License-Identifier: GPL-3.0-or-later
// Trajectories of Braga et al.: the cubic point-to-point polynomial (Eq. 4-6) and the sinusoids of
// the circle contour (Eq. 23-24).
#include "core/model/errors.h"
#include "core/simulation/trajectory.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <Eigen/Dense>
#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using xyt::CubicTrajectory;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Braga et al. Eq. 5 as it must read: rows P(t0), P'(t0), P(tf), P'(tf).
Eigen::Matrix4d eq5Corrected(double t0, double tf) {
    Eigen::Matrix4d m;
    m << 1, t0, t0 * t0, t0 * t0 * t0, //
        0, 1, 2 * t0, 3 * t0 * t0,     //
        1, tf, tf * tf, tf * tf * tf,  //
        0, 1, 2 * tf, 3 * tf * tf;
    return m;
}

double evalAbsolute(const std::array<double, 4>& p, double t) {
    return p[0] + t * (p[1] + t * (p[2] + t * p[3]));
}
double evalAbsoluteSlope(const std::array<double, 4>& p, double t) {
    return p[1] + t * (2.0 * p[2] + t * 3.0 * p[3]);
}
} // namespace

class TstTrajectory : public QObject {
    Q_OBJECT
private slots:
    void paperEq6();
    void printedEq5IsSingular();
    void boundaryConditions_data();
    void boundaryConditions();
    void holdsOutsideTheInterval();
    void sinusoidAndRampIn();
    void circleIdentities();
    void sampleTimesLimits();
    void errorsNameTheField();
    void sampleLimitFollowsMemory();
    void positionsBeyondTheBoundAreRefused();
};

void TstTrajectory::paperEq6() {
    // Eq. 6: P(t) = 0.10650887 t^2 - 0.000546199 t^3 for 0 -> 600 in 130 s with v0 = vf = 0.
    // Closed form p2 = 3 D / T^2 = 1800/16900, p3 = -2 D / T^3 = -1200/2197000.
    const CubicTrajectory c(0.0, 600.0, 0.0, 130.0);
    const auto p = c.coefficients();
    XYT_COMPARE_NEAR(p[0], 0.0, 0.0, 1e-15);
    XYT_COMPARE_NEAR(p[1], 0.0, 0.0, 1e-15);
    XYT_COMPARE_NEAR(p[2], 1800.0 / 16900.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(p[3], -1200.0 / 2197000.0, 1e-15, 0.0);
    // Against the printed digits: p3 = -0.000546199362... rounds to the printed -0.000546199
    // (half a unit of the last digit). p2 = 0.1065088757... is printed 0.10650887, truncated, not
    // rounded (0.10650888): off by 5.7e-9, so only within one unit of the last printed digit.
    XYT_COMPARE_NEAR(p[3], -0.000546199, 0.0, 0.5e-9);
    XYT_COMPARE_NEAR(p[2], 0.10650887, 0.0, 1e-8);
    QVERIFY(std::abs(p[2] - 0.10650887) >
            0.5e-8); // the truncation is real, see tests/data/README.md
    // Peak velocity at mid-travel 1.5 D/T = 6.923 mm/s (closed form of the cubic).
    XYT_COMPARE_NEAR(c.velocity(65.0), 1.5 * 600.0 / 130.0, 1e-14, 0.0);
}

void TstTrajectory::printedEq5IsSingular() {
    // Braga et al. print row 2 of Eq. 5 as [0 t0 2t0 3t0^2] and row 4 as [0 1 2tf 3tf]. With the
    // paper's own t0 = 0 the printed row 2 is all zeros, so the printed matrix is singular and
    // cannot give Eq. 6: a misprint (the derivative row is [0 1 2t0 3t0^2], and 3tf^2 in row 4).
    const double t0 = 0.0, tf = 130.0;
    Eigen::Matrix4d printed;
    printed << 1, t0, t0 * t0, t0 * t0 * t0, 0, t0, 2 * t0, 3 * t0 * t0, 1, tf, tf * tf,
        tf * tf * tf, 0, 1, 2 * tf, 3 * tf;
    QCOMPARE(Eigen::FullPivLU<Eigen::Matrix4d>(printed).rank(), 3);
    QCOMPARE(Eigen::FullPivLU<Eigen::Matrix4d>(eq5Corrected(t0, tf)).rank(), 4);
}

void TstTrajectory::boundaryConditions_data() {
    QTest::addColumn<double>("x0");
    QTest::addColumn<double>("xf");
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("tf");
    QTest::addColumn<double>("v0");
    QTest::addColumn<double>("vf");
    QTest::newRow("Braga et al. Eq. 6: 0 -> 600 in 130 s")
        << 0.0 << 600.0 << 0.0 << 130.0 << 0.0 << 0.0;
    QTest::newRow("t0 != 0, v0, vf != 0") << 25.0 << -40.0 << 12.5 << 47.0 << 1.5 << -0.75;
    QTest::newRow("late start t0 = 200") << -10.0 << 300.0 << 200.0 << 330.0 << 0.0 << 2.0;
    QTest::newRow("negative t0, short") << 5.0 << 5.5 << -1.0 << 0.25 << -3.0 << 0.0;
}

void TstTrajectory::boundaryConditions() {
    QFETCH(double, x0);
    QFETCH(double, xf);
    QFETCH(double, t0);
    QFETCH(double, tf);
    QFETCH(double, v0);
    QFETCH(double, vf);
    const CubicTrajectory c(x0, xf, t0, tf, v0, vf);
    // Invariant: the four conditions of Eq. 5 hold (local-time evaluation: 1e-13 relative to the
    // sizes involved).
    const double scale = std::abs(x0) + std::abs(xf) + (std::abs(v0) + std::abs(vf)) * (tf - t0);
    XYT_COMPARE_NEAR(c.position(t0), x0, 0.0, 1e-13 * scale);
    XYT_COMPARE_NEAR(c.position(tf), xf, 0.0, 1e-13 * scale);
    const double vScale = scale / (tf - t0);
    XYT_COMPARE_NEAR(c.velocity(t0), v0, 0.0, 1e-13 * vScale);
    XYT_COMPARE_NEAR(c.velocity(tf), vf, 0.0, 1e-13 * vScale);
    // The absolute-time coefficients of Eq. 4 satisfy them too. Their evaluation at t ~ 330
    // cancels terms of size |p3| t^3: tolerance from the sum of the terms' magnitudes.
    const auto p = c.coefficients();
    for (const double t : {t0, tf}) {
        const double termSize = std::abs(p[0]) + std::abs(p[1] * t) + std::abs(p[2] * t * t) +
                                std::abs(p[3] * t * t * t);
        XYT_COMPARE_NEAR(evalAbsolute(p, t), c.position(t), 0.0, 64 * kEps * termSize);
        XYT_COMPARE_NEAR(evalAbsoluteSlope(p, t), c.velocity(t), 0.0,
                         64 * kEps * termSize / std::max(std::abs(t), 1.0) * 3.0);
    }
    // Independent check: Eq. 5 (corrected) solved with Eigen's full-pivot LU. The matrix's
    // condition number kappa grows like tf^6; the solve is accurate to ~kappa eps relative to
    // the largest coefficient, so the tolerance is 10 kappa eps of it.
    const Eigen::Matrix4d m = eq5Corrected(t0, tf);
    const Eigen::Vector4d sol = m.fullPivLu().solve(Eigen::Vector4d(x0, v0, xf, vf));
    Eigen::JacobiSVD<Eigen::Matrix4d> svd(m);
    const double kappa = svd.singularValues()(0) / svd.singularValues()(3);
    const double pMax = sol.cwiseAbs().maxCoeff();
    for (int i = 0; i < 4; ++i)
        XYT_COMPARE_NEAR(p[std::size_t(i)], sol(i), 0.0, 10.0 * kappa * kEps * pMax);
}

void TstTrajectory::holdsOutsideTheInterval() {
    // Before t0 the reference holds x0, after tf it holds xf, with zero velocity (by definition).
    const CubicTrajectory c(1.0, 2.0, 10.0, 20.0, 0.5, 0.5);
    QCOMPARE(c.position(-5.0), 1.0);
    QCOMPARE(c.position(25.0), 2.0);
    QCOMPARE(c.velocity(5.0), 0.0);
    QCOMPARE(c.velocity(21.0), 0.0);
    QCOMPARE(c.t0(), 10.0);
    QCOMPARE(c.tf(), 20.0);
}

void TstTrajectory::sinusoidAndRampIn() {
    xyt::Sinusoid s;
    s.amplitude = 25.0;
    s.omegaRadPerSec = 0.06;
    s.phaseRad = 0.3;
    s.offset = 4.0;
    // No ramp: offset + A sin(w t + phase) (definition).
    for (const double t : {0.0, 10.0, 77.7})
        XYT_COMPARE_NEAR(s.value(t), 4.0 + 25.0 * std::sin(0.06 * t + 0.3), 1e-15, 1e-14);
    // Ramp-in over 10 s: the envelope is t/10 until 10 s, 1 after, 0 before 0.
    s.rampInSeconds = 10.0;
    XYT_COMPARE_NEAR(s.value(5.0), 4.0 + 0.5 * 25.0 * std::sin(0.06 * 5.0 + 0.3), 1e-15, 1e-14);
    XYT_COMPARE_NEAR(s.value(0.0), 4.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(s.value(-1.0), 4.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(s.value(12.0), 4.0 + 25.0 * std::sin(0.06 * 12.0 + 0.3), 1e-15, 1e-14);
    // Continuous at the end of the ramp.
    XYT_COMPARE_NEAR(s.value(10.0 - 1e-9), s.value(10.0), 0.0, 1e-8);
}

void TstTrajectory::circleIdentities() {
    // Braga et al. Eq. 23-24: x = 25 sin(0.06 t), y = 25 cos(0.06 t).
    xyt::Circle c;
    QCOMPARE(c.radius, 25.0);
    QCOMPARE(c.omegaRadPerSec, 0.06);
    XYT_COMPARE_NEAR(c.periodSeconds(), 2.0 * std::numbers::pi / 0.06, 1e-15, 0.0);
    for (const double t : {0.0, 13.0, 52.36, 100.0}) {
        const double x = c.xAxis().value(t), y = c.yAxis().value(t);
        XYT_COMPARE_NEAR(x, 25.0 * std::sin(0.06 * t), 1e-15, 1e-14);
        XYT_COMPARE_NEAR(y, 25.0 * std::cos(0.06 * t), 1e-15, 1e-14);
        XYT_COMPARE_NEAR(std::hypot(x, y), 25.0, 1e-15, 0.0); // on the circle
    }
    // Shifted centre and a ramp-in: the radius grows as R t/Tr, then stays R.
    c.centreX = 100.0;
    c.centreY = -50.0;
    c.rampInSeconds = 20.0;
    auto radius = [&](double t) {
        return std::hypot(c.xAxis().value(t) - 100.0, c.yAxis().value(t) + 50.0);
    };
    XYT_COMPARE_NEAR(radius(5.0), 25.0 * 5.0 / 20.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(radius(60.0), 25.0, 1e-14, 0.0);
}

void TstTrajectory::sampleTimesLimits() {
    // n = floor(duration/dt + 1e-9) + 1: 130 s at 0.01 s gives 13001 samples ending at 130 s.
    const auto t = xyt::sampleTimes(130.0, 0.01);
    QCOMPARE(t.size(), std::size_t(13001));
    XYT_COMPARE_NEAR(t.back(), 130.0, 1e-15, 0.0);
    QCOMPARE(t.front(), 0.0);
    QCOMPARE(xyt::sampleTimes(0.0, 0.01).size(), std::size_t(1));
    QCOMPARE(xyt::sampleTimes(0.3, 0.1).size(), std::size_t(4)); // 0.3/0.1 = 2.9999999999999996
    // A duration whose samples do not fit: kMaxSamples + 1 samples are refused, naming duration.
    const double tooLong = static_cast<double>(xyt::kMaxSamples) * 0.01;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::sampleTimes(tooLong, 0.01); }),
             QString("duration"));
    QCOMPARE(xyt::test::invalidInputField([] { xyt::sampleTimes(1e300, 1e-300); }),
             QString("duration"));
    QCOMPARE(xyt::test::invalidInputField([] { xyt::sampleTimes(10.0, 0.0); }), QString("dt"));
    QCOMPARE(xyt::test::invalidInputField([] { xyt::sampleTimes(10.0, -0.01); }), QString("dt"));
    QCOMPARE(xyt::test::invalidInputField([] { xyt::sampleTimes(-1.0, 0.01); }),
             QString("duration"));
    QCOMPARE(xyt::test::invalidInputField([] { xyt::sampleTimes(std::nan(""), 0.01); }),
             QString("duration"));
    QCOMPARE(xyt::test::invalidInputField(
                 [] { xyt::sampleTimes(10.0, std::numeric_limits<double>::infinity()); }),
             QString("dt"));
}

void TstTrajectory::errorsNameTheField() {
    const double nan = std::nan("");
    QCOMPARE(xyt::test::invalidInputField([] { CubicTrajectory(0.0, 1.0, 5.0, 5.0); }),
             QString("tf"));
    QCOMPARE(xyt::test::invalidInputField([] { CubicTrajectory(0.0, 1.0, 5.0, 1.0); }),
             QString("tf"));
    QCOMPARE(xyt::test::invalidInputField([&] { CubicTrajectory(nan, 1.0, 0.0, 1.0); }),
             QString("x0"));
    QCOMPARE(xyt::test::invalidInputField([&] { CubicTrajectory(0.0, nan, 0.0, 1.0); }),
             QString("xf"));
    QCOMPARE(xyt::test::invalidInputField([&] { CubicTrajectory(0.0, 1.0, nan, 1.0); }),
             QString("t0"));
    QCOMPARE(xyt::test::invalidInputField([&] { CubicTrajectory(0.0, 1.0, 0.0, 1.0, nan); }),
             QString("v0"));
    QCOMPARE(
        xyt::test::invalidInputField([&] { CubicTrajectory(0.0, 1.0, 0.0, 1.0, 0.0, HUGE_VAL); }),
        QString("vf"));
    xyt::Sinusoid s;
    s.rampInSeconds = -1.0;
    QCOMPARE(xyt::test::invalidInputField([&] { s.validate(); }), QString("ramp_in"));
    s.rampInSeconds = 0.0;
    s.amplitude = nan;
    QCOMPARE(xyt::test::invalidInputField([&] { s.validate(); }), QString("amplitude"));
    xyt::Circle c;
    c.omegaRadPerSec = 0.0;
    QCOMPARE(xyt::test::invalidInputField([&] { c.periodSeconds(); }), QString("omega"));
}

void TstTrajectory::sampleLimitFollowsMemory() {
    // Closed form (core/trajectory.h): floor(0.25 * memory / 256 B), at most 20 million.
    QCOMPARE(xyt::sampleLimitForMemory(4e9), std::size_t(3906250));
    QCOMPARE(xyt::sampleLimitForMemory(1024.0 * 1024 * 1024), std::size_t(1048576));
    QCOMPARE(xyt::sampleLimitForMemory(64e9), xyt::kMaxSamples); // 62.5 million capped
    QCOMPARE(xyt::sampleLimitForMemory(0.0), xyt::kMaxSamples);  // unknown memory
    QCOMPARE(xyt::sampleLimitForMemory(std::nan("")), xyt::kMaxSamples);
    QVERIFY(xyt::sampleLimit() <= xyt::kMaxSamples);
    QVERIFY(xyt::sampleLimit() == xyt::sampleLimitForMemory(xyt::physicalMemoryBytes()));
}

void TstTrajectory::positionsBeyondTheBoundAreRefused() {
    // xf = 1e308 overflowed the reference ("reference: sample 1 is not a finite
    // number"); amplitude 1e308 gave null metrics beside finite ones. kMaxPositionMm = 1e9.
    QCOMPARE(xyt::test::invalidInputField([] { CubicTrajectory(0.0, 1e308, 0.0, 130.0); }),
             QString("xf"));
    QCOMPARE(xyt::test::invalidInputField([] { CubicTrajectory(-2e9, 0.0, 0.0, 130.0); }),
             QString("x0"));
    QCOMPARE(xyt::test::invalidInputField([] { CubicTrajectory(0.0, 1.0, 0.0, 130.0, 1e10); }),
             QString("v0"));
    const CubicTrajectory atBound(-1e9, 1e9, 0.0, 130.0); // the bound itself is accepted
    QCOMPARE(atBound.position(130.0), 1e9);
    xyt::Sinusoid s;
    s.amplitude = 1e308;
    QCOMPARE(xyt::test::invalidInputField([&] { s.validate(); }), QString("amplitude"));
    s.amplitude = 25.0;
    s.offset = -1e300;
    QCOMPARE(xyt::test::invalidInputField([&] { s.validate(); }), QString("offset"));
}

QTEST_APPLESS_MAIN(TstTrajectory)
#include "tst_trajectory.moc"
