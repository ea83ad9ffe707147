// SPDX-License-Identifier: GPL-3.0-or-later
// PI/PID gains from a target crossover and phase margin (core/design/pid_tuning.h), checked
// against the loop L(j w) = C(j w) G(j w) / u evaluated here with std::complex, its crossover
// found here by bisection: the invariant of the design is that the target holds on L.
#include "core/design/pid_tuning.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/polynomial.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <complex>
#include <limits>

using xyt::PidStructure;
using xyt::PidTuningResult;
using xyt::PidTuningStatus;
using xyt::ThirdOrderPlant;

using xyt::kInf;
using xyt::kNaN;
using xyt::kPi;

namespace {

// Braga et al. Eq. 2 (lower base) and Eq. 1 (upper base), in metres per volt; millimetre gains.
const ThirdOrderPlant kLower{77.8, 125.3, 3665.0};
constexpr double kMetresPerMm = 0.001;

/// L(j w) from its definition: (P + I/(j w) + D j w) / u * k0 / ((j w)^3 + a1 (j w)^2 + a2 j w).
std::complex<double> loop(const ThirdOrderPlant& g, double u, const PidTuningResult& r, double w) {
    const std::complex<double> s(0.0, w);
    return (r.p + r.i / s + r.d * s) / u * g.k0 / (s * s * s + g.a1 * s * s + g.a2 * s);
}

/// The gain crossover by bisection on log|L(j w)| over [lo, hi], which must bracket one sign
/// change; run until the midpoint no longer differs from an end (full double precision).
double crossoverByBisection(const ThirdOrderPlant& g, double u, const PidTuningResult& r, double lo,
                            double hi) {
    const auto f = [&](double w) { return std::log(std::abs(loop(g, u, r, w))); };
    if (!(f(lo) > 0.0 && f(hi) < 0.0))
        return kNaN;
    for (;;) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            return mid;
        (f(mid) > 0.0 ? lo : hi) = mid;
    }
}
} // namespace

class TstPidTuning : public QObject {
    Q_OBJECT
private slots:
    void targetIsMetOnTheLoop_data();
    void targetIsMetOnTheLoop();
    void unreachableTargetGivesAStatus_data();
    void unreachableTargetGivesAStatus();
    void unrepresentableGainsGiveAStatus();
    void badInputsNameTheField_data();
    void badInputsNameTheField();
};

void TstPidTuning::targetIsMetOnTheLoop_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<bool>("pid");
    QTest::addColumn<double>("wc");
    QTest::addColumn<double>("pm");
    // Rows reachable by construction: phi_c = PM - 90 + atan2(a1 wc, a2 - wc^2) is -35.2 deg
    // (lower base, 5 rad/s, 45 deg), -20.2 (5, 60), -7.5 (20, 45), -56.1 (2, 30), and -22.9 on
    // the upper base (5, 45); the PID rows add +7.5 (20, 60) and +44.5 (60, 45, near
    // w180 = sqrt(a2) = 60.5) that a PI cannot give.
    for (const bool pid : {false, true}) {
        const char* s = pid ? "PID" : "PI";
        QTest::newRow(qPrintable(QString("Braga et al. lower base, %1, 5 rad/s, 45 deg").arg(s)))
            << 77.8 << 125.3 << 3665.0 << pid << 5.0 << 45.0;
        QTest::newRow(qPrintable(QString("Braga et al. lower base, %1, 5 rad/s, 60 deg").arg(s)))
            << 77.8 << 125.3 << 3665.0 << pid << 5.0 << 60.0;
        QTest::newRow(qPrintable(QString("Braga et al. lower base, %1, 20 rad/s, 45 deg").arg(s)))
            << 77.8 << 125.3 << 3665.0 << pid << 20.0 << 45.0;
        QTest::newRow(qPrintable(QString("Braga et al. lower base, %1, 2 rad/s, 30 deg").arg(s)))
            << 77.8 << 125.3 << 3665.0 << pid << 2.0 << 30.0;
        QTest::newRow(qPrintable(QString("Braga et al. upper base, %1, 5 rad/s, 45 deg").arg(s)))
            << 24.44 << 68.18 << 863.0 << pid << 5.0 << 45.0;
    }
    QTest::newRow("Braga et al. lower base, PID, 20 rad/s, 60 deg")
        << 77.8 << 125.3 << 3665.0 << true << 20.0 << 60.0;
    QTest::newRow("Braga et al. lower base, PID, 60 rad/s, 45 deg")
        << 77.8 << 125.3 << 3665.0 << true << 60.0 << 45.0;
}

void TstPidTuning::targetIsMetOnTheLoop() {
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(bool, pid);
    QFETCH(double, wc);
    QFETCH(double, pm);
    const ThirdOrderPlant g{k0, a1, a2};
    const double u = kMetresPerMm;
    const PidTuningResult r =
        xyt::tunePidForMargin(g, u, pid ? PidStructure::Pid : PidStructure::Pi, wc, pm);
    QVERIFY2(r.ok(), r.reason.text.c_str());
    QVERIFY(r.reason.text.empty());
    QVERIFY(r.p > 0.0 && r.i > 0.0);
    if (pid) {
        // The stated third condition Ti = 4 Td, i.e. (P/I) = 4 (D/P): P^2 = 4 I D. Three
        // products of the result, rounding once each: 1e-14 relative.
        XYT_COMPARE_NEAR(r.p * r.p, 4.0 * r.i * r.d, 1e-14, 0.0);
        XYT_COMPARE_NEAR(r.tiSeconds, 4.0 * r.tdSeconds, 1e-15, 0.0);
        QVERIFY(r.d > 0.0);
    } else {
        QCOMPARE(r.d, 0.0); // PI: D is exactly zero, not computed
    }

    // Invariant of the design, on L evaluated here: |L(j wc)| = 1 and 180 + arg L(j wc) = PM.
    // The gains are closed forms of a few trigonometric functions (round-off ~1e-15 relative),
    // so 1e-12 leaves a thousandfold margin and is far inside the 1e-6 the design asks.
    const std::complex<double> lAtWc = loop(g, u, r, wc);
    XYT_COMPARE_NEAR(std::abs(lAtWc), 1.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(180.0 + std::arg(lAtWc) * 180.0 / kPi, pm, 0.0, 1e-10);

    // The crossover found here by bisection. Both plants have a1^2 > 2 a2, so |G| falls
    // monotonically, and so does |C G| for both structures (the PI's |C| falls; the PID's is
    // P (1 + 4 Td^2 w^2)/(4 Td w), whose log-slope stays below the 2/w of the plant's
    // integrator and poles): one sign change of log|L| on [wc/100, 100 wc]. Bisection to full
    // precision, log|L| with round-off 1e-15 and slope ~ 1/wc: 1e-12 relative.
    const double wBisect = crossoverByBisection(g, u, r, wc / 100.0, wc * 100.0);
    XYT_COMPARE_NEAR(wBisect, wc, 1e-12, 0.0);
    // The result's own check-back (roots of the crossover quartic, polished) agrees, and the
    // phase margin it recomputes too: same round-off argument.
    QCOMPARE(r.gainCrossoverCount, 1);
    XYT_COMPARE_NEAR(r.achievedCrossoverRadPerSec, wc, 1e-12, 0.0);
    XYT_COMPARE_NEAR(r.achievedCrossoverRadPerSec, wBisect, 1e-12, 0.0);
    XYT_COMPARE_NEAR(r.achievedPhaseMarginDeg, pm, 0.0, 1e-10);
    XYT_COMPARE_NEAR(180.0 + std::arg(loop(g, u, r, wBisect)) * 180.0 / kPi, pm, 0.0, 1e-9);

    // Closed-loop stability against the roots of u s^2 (s^2 + a1 s + a2) + k0 (D s^2 + P s + I)
    // (an independent route: Polynomial::roots instead of the result's Routh-Hurwitz test).
    const xyt::Polynomial cl =
        xyt::Polynomial::fromDescending({u, u * a1, u * a2 + k0 * r.d, k0 * r.p, k0 * r.i});
    bool stable = true;
    for (const auto& root : cl.roots())
        stable = stable && root.real() < 0.0;
    QCOMPARE(r.closedLoopStable, stable);
    QVERIFY(r.closedLoopStable); // a positive margin at the only crossover of a stable plant
    QVERIFY(r.warnings.empty());
}

void TstPidTuning::unreachableTargetGivesAStatus_data() {
    QTest::addColumn<bool>("pid");
    QTest::addColumn<double>("wc");
    QTest::addColumn<double>("pm");
    // phi_c = PM - 90 + atan2(a1 wc, a2 - wc^2) on the lower base:
    QTest::newRow("PI, PM 100 deg at 5 rad/s: phi_c = +19.8 > 0") << false << 5.0 << 100.0;
    QTest::newRow("PI, PM 60 deg at 20 rad/s: phi_c = +7.5 > 0") << false << 20.0 << 60.0;
    QTest::newRow("PI, PM 179 deg at 500 rad/s: phi_c = +254.7") << false << 500.0 << 179.0;
    QTest::newRow("PID, PM 170 deg at 60 rad/s: phi_c = +169.5 > 90") << true << 60.0 << 170.0;
    QTest::newRow("PID, PM 80 deg at 100 rad/s: phi_c = +106.8 > 90") << true << 100.0 << 80.0;
}

void TstPidTuning::unreachableTargetGivesAStatus() {
    QFETCH(bool, pid);
    QFETCH(double, wc);
    QFETCH(double, pm);
    PidTuningResult r;
    try {
        r = xyt::tunePidForMargin(kLower, kMetresPerMm, pid ? PidStructure::Pid : PidStructure::Pi,
                                  wc, pm);
    } catch (const std::exception& e) {
        QFAIL(e.what()); // a slider can ask for it: a status, never a throw
    }
    QVERIFY(!r.ok());
    QCOMPARE(r.status, PidTuningStatus::PhaseOutOfReach);
    QVERIFY(!r.reason.text.empty());
    QVERIFY(r.reason.text.find("deg") != std::string::npos);
    // A coded reason (the workbench translates it): the crossover is its first argument.
    QCOMPARE(r.reason.code,
             std::string(pid ? "design_pid_phase_out_of_reach" : "design_pid_pi_phase_too_high"));
    QCOMPARE(r.reason.args.size(), std::size_t(4));
    QVERIFY2(r.reason.text.rfind((pid ? "a PID with Ti = 4 Td gives a phase between -90 and 90 "
                                        "deg at "
                                      : "a PI gives a phase between -90 and 0 deg at ") +
                                     r.reason.args[0].text + " rad/s (plant phase ",
                                 0) == 0,
             r.reason.text.c_str());
    QCOMPARE(r.p, 0.0);
    QCOMPARE(r.i, 0.0);
    QCOMPARE(r.d, 0.0);
    QVERIFY(std::isnan(r.achievedCrossoverRadPerSec));
    // The required phase is reported all the same; it is past the structure's upper bound.
    QVERIFY(r.requiredControllerPhaseDeg > (pid ? 90.0 : 0.0));
}

void TstPidTuning::unrepresentableGainsGiveAStatus() {
    // |C(j wc)| = u wc |a2 - wc^2 + j a1 wc| / k0 ~ u a2 wc / k0 underflows for wc = 1e-200 rad/s
    // (wc^3 = 0 in double precision) while the phase (-45 deg) is within reach: a status, with
    // no gains, rather than P = 0 or NaN handed on.
    for (const PidStructure s : {PidStructure::Pi, PidStructure::Pid}) {
        const PidTuningResult r = xyt::tunePidForMargin(kLower, kMetresPerMm, s, 1e-200, 45.0);
        QCOMPARE(r.status, PidTuningStatus::GainsOutOfRange);
        QVERIFY(!r.reason.text.empty());
        QCOMPARE(r.p, 0.0);
        QCOMPARE(r.i, 0.0);
        QCOMPARE(r.d, 0.0);
    }
}

void TstPidTuning::badInputsNameTheField_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("wc");
    QTest::addColumn<double>("pm");
    QTest::addColumn<QString>("field");
    QTest::newRow("crossover 0") << 77.8 << 125.3 << 3665.0 << 0.001 << 0.0 << 45.0 << "crossover";
    QTest::newRow("crossover < 0")
        << 77.8 << 125.3 << 3665.0 << 0.001 << -5.0 << 45.0 << "crossover";
    QTest::newRow("crossover NaN")
        << 77.8 << 125.3 << 3665.0 << 0.001 << kNaN << 45.0 << "crossover";
    QTest::newRow("crossover inf")
        << 77.8 << 125.3 << 3665.0 << 0.001 << kInf << 45.0 << "crossover";
    QTest::newRow("phase margin 0")
        << 77.8 << 125.3 << 3665.0 << 0.001 << 5.0 << 0.0 << "phase_margin";
    QTest::newRow("phase margin < 0")
        << 77.8 << 125.3 << 3665.0 << 0.001 << 5.0 << -10.0 << "phase_margin";
    QTest::newRow("phase margin NaN")
        << 77.8 << 125.3 << 3665.0 << 0.001 << 5.0 << kNaN << "phase_margin";
    QTest::newRow("scale 0") << 77.8 << 125.3 << 3665.0 << 0.0 << 5.0 << 45.0 << "model_unit_scale";
    QTest::newRow("scale inf") << 77.8 << 125.3 << 3665.0 << kInf << 5.0 << 45.0
                               << "model_unit_scale";
    QTest::newRow("k0 0") << 0.0 << 125.3 << 3665.0 << 0.001 << 5.0 << 45.0 << "k0";
    QTest::newRow("k0 < 0") << -77.8 << 125.3 << 3665.0 << 0.001 << 5.0 << 45.0 << "k0";
    QTest::newRow("a1 NaN") << 77.8 << kNaN << 3665.0 << 0.001 << 5.0 << 45.0 << "a1";
    QTest::newRow("a1 0") << 77.8 << 0.0 << 3665.0 << 0.001 << 5.0 << 45.0 << "a1";
    QTest::newRow("a2 < 0") << 77.8 << 125.3 << -3665.0 << 0.001 << 5.0 << 45.0 << "a2";
    QTest::newRow("a2 inf") << 77.8 << 125.3 << kInf << 0.001 << 5.0 << 45.0 << "a2";
}

void TstPidTuning::badInputsNameTheField() {
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, scale);
    QFETCH(double, wc);
    QFETCH(double, pm);
    QFETCH(QString, field);
    for (const PidStructure s : {PidStructure::Pi, PidStructure::Pid})
        QCOMPARE(xyt::test::invalidInputField([&] {
                     xyt::tunePidForMargin({k0, a1, a2}, scale, s, wc, pm);
                 }),
                 field);
}

QTEST_APPLESS_MAIN(TstPidTuning)
#include "tst_pid_tuning.moc"
