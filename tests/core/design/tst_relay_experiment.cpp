// SPDX-License-Identifier: GPL-3.0-or-later
// The relay experiment of Åström and Hägglund on Braga et al.'s motor bases
// (core/design/relay_experiment.h): the exact limit cycle against a long time simulation and
// against Tsypkin's Fourier series evaluated here, the describing-function estimate against its
// closed form and against the exact cycle, the ultimate-cycle rules against their formulas.
#include "core/design/relay_experiment.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <complex>
#include <limits>

using xyt::PidStructure;
using xyt::RelayDescribingFunction;
using xyt::RelayLimitCycle;
using xyt::RelaySimulation;
using xyt::RelaySimulationOptions;
using xyt::ThirdOrderPlant;
using xyt::UltimateCycleGains;
using xyt::UltimateCycleRule;

using xyt::kInf;
using xyt::kNaN;
using xyt::kPi;

namespace {

// Braga et al. Eq. 2 (lower base), in metres per volt; positions in mm.
const ThirdOrderPlant kLower{77.8, 125.3, 3665.0};
constexpr double kMetresPerMm = 0.001;

std::complex<double> plantAt(const ThirdOrderPlant& g, double w) {
    const std::complex<double> s(0.0, w);
    return g.k0 / (s * s * s + g.a1 * s * s + g.a2 * s);
}

// Tsypkin's series for the symmetric periodic response to the square wave u = +d on (0, h),
// -d on (h, 2h), u = (4d/pi) sum_{k odd} sin(k w t)/k with w = pi/h:
//   y(t) = (4d/pi) sum_{k odd} Im(G(j k w) e^{j k w t}) / k   (model units),
// the zero-mean solution, which is the symmetric one x(t + h) = -x(t). The terms fall as
// k0/(k w)^3/k, so 40001 odd harmonics leave a tail below 1e-14 of the first term.
double tsypkinY(const ThirdOrderPlant& g, double d, double w, double t) {
    double sum = 0.0;
    for (int k = 80001; k >= 1; k -= 2) // smallest terms first
        sum += std::imag(plantAt(g, k * w) * std::polar(1.0, k * w * t)) / k;
    return 4.0 * d / kPi * sum;
}
} // namespace

class TstRelayExperiment : public QObject {
    Q_OBJECT
private slots:
    void limitCycleAgainstLongSimulation_data();
    void limitCycleAgainstLongSimulation();
    void limitCycleAgainstTsypkinSeries_data();
    void limitCycleAgainstTsypkinSeries();
    void describingFunctionClosedForm();
    void describingFunctionAgainstExactCycle();
    void simulationFollowsTheRelayConvention();
    void ultimateCycleRules_data();
    void ultimateCycleRules();
    void badInputsNameTheField_data();
    void badInputsNameTheField();
};

void TstRelayExperiment::limitCycleAgainstLongSimulation_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<double>("d");
    QTest::newRow("Braga et al. lower base, 1 V") << 77.8 << 125.3 << 3665.0 << 1.0;
    QTest::newRow("Braga et al. lower base, 2.5 V") << 77.8 << 125.3 << 3665.0 << 2.5;
    QTest::newRow("Braga et al. upper base, 1 V") << 24.44 << 68.18 << 863.0 << 1.0;
}

void TstRelayExperiment::limitCycleAgainstLongSimulation() {
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, d);
    const ThirdOrderPlant g{k0, a1, a2};
    const RelayLimitCycle lc = xyt::relayLimitCycle(g, kMetresPerMm, d);
    QVERIFY2(lc.found, lc.status.text.c_str());
    XYT_COMPARE_NEAR(lc.periodSeconds, 2.0 * lc.halfPeriodSeconds, 0.0, 0.0);
    XYT_COMPARE_NEAR(lc.frequencyRadPerSec * lc.periodSeconds, 2.0 * kPi, 1e-15, 0.0);
    XYT_COMPARE_NEAR(lc.ultimateGainVoltsPerMm, 4.0 * d / (kPi * lc.amplitudeMm), 1e-15, 0.0);
    // The switch state: y = 0 (the switching condition, solved to round-off of x0's other
    // components, |y'| h ~ a), y falling, the peak inside the half period.
    XYT_COMPARE_NEAR(lc.switchState[0] / kMetresPerMm, 0.0, 0.0, 1e-12 * lc.amplitudeMm);
    QVERIFY(lc.switchState[1] < 0.0);
    QVERIFY(lc.peakTimeSeconds > 0.0 && lc.peakTimeSeconds < lc.halfPeriodSeconds);

    // A 40-period simulation from 0.01 mm at rest, 1000 steps a period. The transient shrinks
    // about fivefold a cycle (measured on the lower base: 2.5e-7 relative after 10 periods,
    // 4e-14 after 30), so after 40 only round-off remains: 4e4 exact ZOH steps, each rounding
    // ~1e-16, and switch instants to adjacent doubles. 1e-10 relative bounds that with margin
    // (the differences measured are below 1e-13).
    RelaySimulationOptions o;
    o.initialOffsetMm = 0.01;
    o.stepSeconds = lc.periodSeconds / 1000.0;
    o.durationSeconds = 40.0 * lc.periodSeconds;
    o.cyclesToMeasure = 3;
    const RelaySimulation sim = xyt::simulateRelayFeedback(g, kMetresPerMm, d, o);
    QVERIFY(sim.warnings.empty());
    QCOMPARE(sim.cyclesMeasured, 3);
    XYT_COMPARE_NEAR(sim.measuredPeriodSeconds, lc.periodSeconds, 1e-10, 0.0);
    XYT_COMPARE_NEAR(sim.measuredAmplitudeMm, lc.amplitudeMm, 1e-10, 0.0);
    // The last switch interval is the half period (same argument).
    const auto& sw = sim.switchTimesSeconds;
    QVERIFY(sw.size() > 70); // two switches a period, ~40 periods less the start-up
    XYT_COMPARE_NEAR(sw[sw.size() - 1] - sw[sw.size() - 2], lc.halfPeriodSeconds, 1e-10, 0.0);
}

void TstRelayExperiment::limitCycleAgainstTsypkinSeries_data() {
    limitCycleAgainstLongSimulation_data();
}

void TstRelayExperiment::limitCycleAgainstTsypkinSeries() {
    // An independent route to the same cycle: the half period is the root of the switching
    // condition y(0) = (4d/pi) sum_{k odd} Im G(j k w)/k = 0 (Tsypkin's locus crossing the real
    // axis), found here by bisection; the amplitude is max |y| of the series over (0, h), found
    // by golden-section search.
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, d);
    const ThirdOrderPlant g{k0, a1, a2};
    const RelayLimitCycle lc = xyt::relayLimitCycle(g, kMetresPerMm, d);
    QVERIFY2(lc.found, lc.status.text.c_str());

    // y(0) changes sign between w = sqrt(a2)/2 and 2 sqrt(a2) (the describing function's
    // w180 = sqrt(a2) is within a few percent of the true frequency).
    double lo = std::sqrt(a2) / 2.0, hi = 2.0 * std::sqrt(a2);
    const double yLo = tsypkinY(g, d, lo, 0.0);
    QVERIFY(yLo * tsypkinY(g, d, hi, 0.0) < 0.0);
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((tsypkinY(g, d, mid, 0.0) > 0.0) == (yLo > 0.0) ? lo : hi) = mid;
    }
    const double w = 0.5 * (lo + hi);
    // 60 halvings of a 4:1 bracket: 1e-18 relative; the series' tail (1e-14 of the first term)
    // and its summation round-off (~1e-16 per term, 4e4 terms, partly cancelling) move the root
    // by ~1e-12 relative at most (2e-14 measured): 1e-10 leaves margin.
    XYT_COMPARE_NEAR(lc.frequencyRadPerSec, w, 1e-10, 0.0);

    const double h = kPi / w;
    const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = 0.0, b = h;
    for (int i = 0; i < 100; ++i) { // y < 0 on (0, h) with one minimum: golden section on y
        const double c = b - phi * (b - a), e = a + phi * (b - a);
        if (tsypkinY(g, d, w, c) < tsypkinY(g, d, w, e))
            b = e;
        else
            a = c;
    }
    const double amplitudeMm = -tsypkinY(g, d, w, 0.5 * (a + b)) / kMetresPerMm;
    // y is stationary at the peak: comparing values, golden section can place t only to about
    // sqrt(eps) of h (1e-8 measured), which costs y nothing (the error enters squared); with the
    // series' round-off (~1e-14 relative) 1e-10 on the amplitude leaves margin (1e-13 measured).
    // The peak time itself is known here to that sqrt(eps) only: 1e-6.
    XYT_COMPARE_NEAR(lc.amplitudeMm, amplitudeMm, 1e-10, 0.0);
    XYT_COMPARE_NEAR(lc.peakTimeSeconds, 0.5 * (a + b), 1e-6, 0.0);
}

void TstRelayExperiment::describingFunctionClosedForm() {
    const double d = 1.5;
    const RelayDescribingFunction df = xyt::relayDescribingFunction(kLower, kMetresPerMm, d);
    // w180 = sqrt(a2) = sqrt(3665) = 60.539...: G(j w180) is real and negative there, with
    // |G| = k0/(a1 a2) (checked on G evaluated here; a few roundings: 1e-15 relative).
    XYT_COMPARE_NEAR(df.omega180RadPerSec, std::sqrt(3665.0), 1e-15, 0.0);
    const std::complex<double> g180 = plantAt(kLower, df.omega180RadPerSec);
    XYT_COMPARE_NEAR(g180.imag(), 0.0, 0.0, 1e-14 * std::abs(g180));
    QVERIFY(g180.real() < 0.0);
    XYT_COMPARE_NEAR(std::abs(g180), 77.8 / (125.3 * 3665.0), 1e-14, 0.0);
    // a = 4 d k0/(pi a1 a2) m, in mm; Ku = 4 d/(pi a) = u a1 a2/k0 V/mm; Tu = 2 pi/w180.
    XYT_COMPARE_NEAR(df.amplitudeMm, 4.0 * d * 77.8 / (kPi * 125.3 * 3665.0) / 0.001, 1e-15, 0.0);
    XYT_COMPARE_NEAR(df.ultimateGainVoltsPerMm, 0.001 * 125.3 * 3665.0 / 77.8, 1e-15, 0.0);
    XYT_COMPARE_NEAR(df.periodSeconds, 2.0 * kPi / std::sqrt(3665.0), 1e-15, 0.0);
    // Numbers: a = 0.32356 mm at 1.5 V, Ku = 5.9026 V/mm (the Routh bound 5903 of
    // tst_guillemin_truxal in V/m), Tu = 0.10379 s (printed to 5 digits: half a unit).
    XYT_COMPARE_NEAR(df.amplitudeMm, 0.32356, 0.0, 0.5e-5);
    XYT_COMPARE_NEAR(df.ultimateGainVoltsPerMm, 5.9026, 0.0, 0.5e-4);
    XYT_COMPARE_NEAR(df.periodSeconds, 0.10379, 0.0, 0.5e-5);
}

void TstRelayExperiment::describingFunctionAgainstExactCycle() {
    // The first-harmonic estimate against the exact cycle on the lower base. Differences found
    // (exact cycle: Tu = 0.1062323 s, a = 0.2234089 mm per volt of relay, Ku = 5.699143 V/mm):
    //   Tu: DF 2.30 % short, a: DF 3.45 % small, Ku: DF 3.57 % high.
    // The integrator and the poles at -46.5 and -78.8 rad/s (a1 = 125.3, a2 = 3665) make
    // |G(j 3w)| = |G(j w)|/14.4 at the cycle's w = 59.1 rad/s; with the square wave's 1/3 the
    // third harmonic of y is 1/43 of the first, which is why the estimate is this close.
    // Tolerance: the measured difference rounded up to the next quarter percent, so the test
    // fails if the estimate drifts (a wrong formula would be off by tens of percent).
    for (const double d : {1.0, 3.0}) { // h does not depend on d, a and Ku scale with it
        const RelayLimitCycle lc = xyt::relayLimitCycle(kLower, kMetresPerMm, d);
        const RelayDescribingFunction df = xyt::relayDescribingFunction(kLower, kMetresPerMm, d);
        QVERIFY(lc.found);
        XYT_COMPARE_NEAR(df.periodSeconds, lc.periodSeconds, 0.025, 0.0);
        XYT_COMPARE_NEAR(df.amplitudeMm, lc.amplitudeMm, 0.035, 0.0);
        XYT_COMPARE_NEAR(df.ultimateGainVoltsPerMm, lc.ultimateGainVoltsPerMm, 0.0375, 0.0);
        // And the exact numbers themselves (computed by this module, confirmed by the
        // simulation and the Tsypkin series above), to the 7 digits printed.
        XYT_COMPARE_NEAR(lc.periodSeconds, 0.1062323, 0.0, 0.5e-7);
        XYT_COMPARE_NEAR(lc.amplitudeMm / d, 0.2234089, 0.0, 0.5e-7);
        XYT_COMPARE_NEAR(lc.ultimateGainVoltsPerMm, 5.699143, 0.0, 0.5e-6);
    }
}

void TstRelayExperiment::simulationFollowsTheRelayConvention() {
    // u = d sign(e), e = r - y = -y: at every sample off a switch u and y have opposite signs;
    // each switch is recorded twice (old u, new u) at y = 0.
    const double d = 2.0;
    RelaySimulationOptions o;
    o.initialOffsetMm = -0.05;
    o.durationSeconds = 0.5;
    o.stepSeconds = 2e-4;
    const RelaySimulation s = xyt::simulateRelayFeedback(kLower, kMetresPerMm, d, o);
    QCOMPARE(s.tSeconds.size(), s.yMm.size());
    QCOMPARE(s.tSeconds.size(), s.uVolts.size());
    QCOMPARE(s.tSeconds.front(), 0.0);
    QCOMPARE(s.yMm.front(), -0.05);
    QCOMPARE(s.uVolts.front(), d); // y < 0 at the start: e > 0, u = +d
    XYT_COMPARE_NEAR(s.tSeconds.back(), 0.5, 1e-15, 0.0);
    // 0.5 s / 0.2 ms = 2500 step ends, plus t = 0, plus two samples a switch.
    QCOMPARE(s.tSeconds.size(), std::size_t(2501) + 2 * s.switchTimesSeconds.size());
    std::size_t switches = 0;
    for (std::size_t k = 1; k < s.tSeconds.size(); ++k) {
        QVERIFY(s.tSeconds[k] >= s.tSeconds[k - 1]);
        QVERIFY(std::abs(s.uVolts[k]) == d);
        if (s.uVolts[k] != s.uVolts[k - 1]) {
            // A switch: same instant, y at zero (to adjacent doubles of the instant:
            // |y'| eps t ~ 1e-15 mm), and e turned to the sign of the new u.
            QCOMPARE(s.tSeconds[k], s.tSeconds[k - 1]);
            QCOMPARE(s.tSeconds[k], s.switchTimesSeconds[switches]);
            XYT_COMPARE_NEAR(s.yMm[k], 0.0, 0.0, 1e-12);
            QVERIFY(-s.yMm[k] * s.uVolts[k] >= 0.0);
            ++switches;
        } else if (k + 1 < s.tSeconds.size() && s.uVolts[k + 1] == s.uVolts[k]) {
            QVERIFY2(s.uVolts[k] * s.yMm[k] < 0.0, qPrintable(QString::number(s.tSeconds[k])));
        }
    }
    QCOMPARE(switches, s.switchTimesSeconds.size());
    QVERIFY(switches > 6);
    // The extrema are where the relay has held one sign for a while: between switches, and
    // alternating in sign once the cycle is established.
    QCOMPARE(s.peakTimesSeconds.size(), s.peakValuesMm.size());
    QVERIFY(s.peakTimesSeconds.size() >= switches - 1);

    // A step of a tenth of the period is flagged.
    o.stepSeconds = 0.01;
    QVERIFY(!xyt::simulateRelayFeedback(kLower, kMetresPerMm, d, o).warnings.empty());
    // 0.07 s / 0.01 s rounds to 7.000000000000001: still 7 steps, the last ending at 0.07 s.
    o.durationSeconds = 0.07;
    const RelaySimulation seven = xyt::simulateRelayFeedback(kLower, kMetresPerMm, d, o);
    QCOMPARE(seven.tSeconds.size(), std::size_t(8) + 2 * seven.switchTimesSeconds.size());
    QCOMPARE(seven.tSeconds.back(), 0.07);
    // Too short to see two switches to +d: no measurement, a warning.
    o.stepSeconds = 1e-4;
    o.durationSeconds = 0.05;
    const RelaySimulation shortRun = xyt::simulateRelayFeedback(kLower, kMetresPerMm, d, o);
    QVERIFY(std::isnan(shortRun.measuredPeriodSeconds));
    QVERIFY(std::isnan(shortRun.measuredAmplitudeMm));
    QCOMPARE(shortRun.warnings.size(), std::size_t(1));
}

void TstRelayExperiment::ultimateCycleRules_data() {
    QTest::addColumn<int>("rule");
    QTest::addColumn<bool>("pid");
    QTest::addColumn<double>("p");
    QTest::addColumn<double>("ti");
    QTest::addColumn<double>("td");
    const double ku = 5.699143, tu = 0.1062323;
    const int zn = int(UltimateCycleRule::ZieglerNichols),
              tl = int(UltimateCycleRule::TyreusLuyben);
    // Ziegler and Nichols (1942), the ultimate-sensitivity method.
    QTest::newRow("Ziegler-Nichols PI") << zn << false << 0.45 * ku << tu / 1.2 << 0.0;
    QTest::newRow("Ziegler-Nichols PID") << zn << true << 0.6 * ku << tu / 2.0 << tu / 8.0;
    // Tyreus and Luyben (1992).
    QTest::newRow("Tyreus-Luyben PI") << tl << false << ku / 3.2 << 2.2 * tu << 0.0;
    QTest::newRow("Tyreus-Luyben PID") << tl << true << ku / 2.2 << 2.2 * tu << tu / 6.3;
}

void TstRelayExperiment::ultimateCycleRules() {
    QFETCH(int, rule);
    QFETCH(bool, pid);
    QFETCH(double, p);
    QFETCH(double, ti);
    QFETCH(double, td);
    const UltimateCycleGains g = xyt::ultimateCycleGains(
        5.699143, 0.1062323, UltimateCycleRule(rule), pid ? PidStructure::Pid : PidStructure::Pi);
    // The same one or two roundings as the rows: 1e-15 relative. LinuxCNC's I = P/Ti and
    // D = P Td (ideal parallel form, mm).
    XYT_COMPARE_NEAR(g.p, p, 1e-15, 0.0);
    XYT_COMPARE_NEAR(g.tiSeconds, ti, 1e-15, 0.0);
    XYT_COMPARE_NEAR(g.tdSeconds, td, 1e-15, 0.0);
    XYT_COMPARE_NEAR(g.i, p / ti, 1e-15, 0.0);
    XYT_COMPARE_NEAR(g.d, p * td, 1e-15, 0.0);
    if (!pid)
        QCOMPARE(g.d, 0.0);
}

void TstRelayExperiment::badInputsNameTheField_data() {
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("d");
    QTest::addColumn<QString>("field");
    QTest::newRow("relay amplitude 0") << 77.8 << 0.001 << 0.0 << "relay_amplitude";
    QTest::newRow("relay amplitude < 0") << 77.8 << 0.001 << -1.0 << "relay_amplitude";
    QTest::newRow("relay amplitude NaN") << 77.8 << 0.001 << kNaN << "relay_amplitude";
    QTest::newRow("relay amplitude inf") << 77.8 << 0.001 << kInf << "relay_amplitude";
    QTest::newRow("scale 0") << 77.8 << 0.0 << 1.0 << "model_unit_scale";
    QTest::newRow("scale NaN") << 77.8 << kNaN << 1.0 << "model_unit_scale";
    QTest::newRow("k0 < 0") << -77.8 << 0.001 << 1.0 << "k0";
    QTest::newRow("k0 NaN") << kNaN << 0.001 << 1.0 << "k0";
}

void TstRelayExperiment::badInputsNameTheField() {
    QFETCH(double, k0);
    QFETCH(double, scale);
    QFETCH(double, d);
    QFETCH(QString, field);
    const ThirdOrderPlant g{k0, 125.3, 3665.0};
    using xyt::test::invalidInputField;
    QCOMPARE(invalidInputField([&] { xyt::relayLimitCycle(g, scale, d); }), field);
    QCOMPARE(invalidInputField([&] { xyt::relayDescribingFunction(g, scale, d); }), field);
    QCOMPARE(invalidInputField([&] { xyt::simulateRelayFeedback(g, scale, d, {}); }), field);
    // The plant's other fields and the simulation's own settings.
    QCOMPARE(invalidInputField([&] {
                 xyt::relayLimitCycle({77.8, 0.0, 3665.0}, 0.001, 1.0);
             }),
             QString("a1"));
    QCOMPARE(invalidInputField([&] {
                 xyt::relayLimitCycle({77.8, 125.3, -1.0}, 0.001, 1.0);
             }),
             QString("a2"));
    const auto simField = [&](RelaySimulationOptions o) {
        return invalidInputField([&] { xyt::simulateRelayFeedback(kLower, 0.001, 1.0, o); });
    };
    RelaySimulationOptions o;
    o.initialOffsetMm = 0.0;
    QCOMPARE(simField(o), QString("initial_offset"));
    o = {};
    o.durationSeconds = kInf;
    QCOMPARE(simField(o), QString("duration"));
    o = {};
    o.stepSeconds = 0.0;
    QCOMPARE(simField(o), QString("step"));
    o = {};
    o.stepSeconds = 1e-9; // 2e9 steps over the default 2 s
    QCOMPARE(simField(o), QString("step"));
    o = {};
    o.cyclesToMeasure = 0;
    QCOMPARE(simField(o), QString("cycles_to_measure"));
    QCOMPARE(invalidInputField([&] {
                 xyt::ultimateCycleGains(0.0, 0.1, UltimateCycleRule::ZieglerNichols,
                                         PidStructure::Pi);
             }),
             QString("ultimate_gain"));
    QCOMPARE(invalidInputField([&] {
                 xyt::ultimateCycleGains(5.0, kNaN, UltimateCycleRule::TyreusLuyben,
                                         PidStructure::Pid);
             }),
             QString("ultimate_period"));
}

QTEST_APPLESS_MAIN(TstRelayExperiment)
#include "tst_relay_experiment.moc"
