// SPDX-License-Identifier: GPL-3.0-or-later
// Tracking metrics and step-response figures against closed forms and scipy
// (tests/data/gt_stepinfo.csv, see tests/data/README.md).
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/simulation/metrics.h"
#include "tests/support/core_checks.h"
#include "tests/support/reference_data.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>

using xyt::SimulationResult;
using xyt::TransferFunction;

namespace {
/// A run with t = k dt and the given error; r chosen so that travel = rMax - rMin.
SimulationResult runWithError(const std::vector<double>& e, double dt) {
    SimulationResult run;
    run.dtSeconds = dt;
    for (std::size_t k = 0; k < e.size(); ++k) {
        run.t.push_back(double(k) * dt);
        run.e.push_back(e[k]);
        run.r.push_back(0.0);
        run.y.push_back(-e[k]);
        run.u.push_back(0.0);
        run.clipped.push_back(false);
    }
    return run;
}
} // namespace

class TstMetrics : public QObject {
    Q_OBJECT
private slots:
    void rmsOfASine();
    void itaeOfARampError();
    void maxErrorPercentAndSaturation();
    void firstOrderSettling_data();
    void firstOrderSettling();
    void secondOrderOvershoot_data();
    void secondOrderOvershoot();
    void gtClosedLoopsAgainstScipy_data();
    void gtClosedLoopsAgainstScipy();
    void unstableIsReportedNotThrown();
    void errorsNameTheField();
};

void TstMetrics::rmsOfASine() {
    // Closed form: over one full period sampled at N >= 3 equally spaced points,
    // sum sin^2 = N/2 exactly, so RMS = A/sqrt(2). Round-off of 1000 terms: 1e-13.
    const int n = 1000;
    std::vector<double> v(n);
    for (int k = 0; k < n; ++k)
        v[std::size_t(k)] = 3.0 * std::sin(2.0 * std::numbers::pi * k / n + 0.4);
    XYT_COMPARE_NEAR(xyt::rootMeanSquare(v), 3.0 / std::sqrt(2.0), 1e-13, 0.0);
    QCOMPARE(xyt::rootMeanSquare({}), 0.0);
    XYT_COMPARE_NEAR(xyt::rootMeanSquare({-2.0, 2.0}), 2.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(xyt::trackingMetrics(runWithError(v, 0.1)).rmse, 3.0 / std::sqrt(2.0), 1e-13,
                     0.0);
}

void TstMetrics::itaeOfARampError() {
    // e(t) = -2 t on [0, T] (sign must not matter): ITAE = int t |e| = 2 T^3/3. The trapezoid
    // rule on t^2 with step h is exact plus T h^2/6 (its closed-form error for a quadratic), so
    // the expected value is 2 (T^3/3 + T h^2/6); summation round-off 1e-12.
    const double h = 0.01, T = 10.0;
    std::vector<double> e;
    for (int k = 0; k <= 1000; ++k)
        e.push_back(-2.0 * k * h);
    const xyt::TrackingMetrics m = xyt::trackingMetrics(runWithError(e, h));
    XYT_COMPARE_NEAR(m.itae, 2.0 * (T * T * T / 3.0 + T * h * h / 6.0), 1e-12, 0.0);
    XYT_COMPARE_NEAR(m.maxAbsError, 20.0, 1e-15, 0.0);
}

void TstMetrics::maxErrorPercentAndSaturation() {
    // Definitions (core/simulation/metrics.h): travel = max r - min r, pct = 100 max|e| / travel,
    // saturated time = clipped samples * dt.
    SimulationResult run;
    run.dtSeconds = 0.05;
    run.t = {0.0, 0.05, 0.1, 0.15, 0.2};
    run.r = {10.0, 20.0, 40.0, 50.0, 50.0};
    run.y = {10.0, 19.0, 37.0, 50.5, 50.0};
    run.e = {0.0, 1.0, 3.0, -0.5, 0.0};
    run.u = {0.1, 2.5, -2.5, -1.0, 0.0};
    run.clipped = {false, true, true, false, false};
    const xyt::TrackingMetrics m = xyt::trackingMetrics(run);
    XYT_COMPARE_NEAR(m.maxAbsError, 3.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(m.maxAbsErrorPct, 100.0 * 3.0 / 40.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(m.maxAbsU, 2.5, 0.0, 0.0);
    QVERIFY(m.saturated);
    XYT_COMPARE_NEAR(m.saturatedTimeSeconds, 2 * 0.05, 1e-15, 0.0);
    // A constant reference has no travel: the percentage is 0, not a division by zero.
    run.r.assign(5, 7.0);
    run.clipped.assign(5, false);
    const xyt::TrackingMetrics flat = xyt::trackingMetrics(run);
    QCOMPARE(flat.maxAbsErrorPct, 0.0);
    QVERIFY(!flat.saturated);
    QCOMPARE(flat.saturatedTimeSeconds, 0.0);
}

void TstMetrics::firstOrderSettling_data() {
    QTest::addColumn<double>("tau");
    QTest::newRow("tau 1 s") << 1.0;
    QTest::newRow("tau 0.02 s") << 0.02;
    QTest::newRow("tau 150 s") << 150.0;
}

void TstMetrics::firstOrderSettling() {
    // Closed form: 1 - e^{-t/tau} enters the 2 % band for good at t = tau ln(50); no overshoot.
    // The settling instant is interpolated by a cubic Hermite polynomial between samples
    // 12 tau/4000 apart: error O((dt/tau)^4) ~ 1e-10; tolerance 1e-8 relative.
    QFETCH(double, tau);
    const TransferFunction g = TransferFunction::fromDescending({2.0 / tau}, {1.0, 1.0 / tau});
    const xyt::StepCharacteristics s = xyt::stepCharacteristics(g);
    QVERIFY(s.stable);
    XYT_COMPARE_NEAR(s.finalValue, 2.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(s.settlingTimeSeconds, tau * std::log(50.0), 1e-8, 0.0);
    QCOMPARE(s.overshootPct, 0.0);
    // A 5 % band: tau ln(20).
    XYT_COMPARE_NEAR(xyt::stepCharacteristics(g, 0.05).settlingTimeSeconds, tau * std::log(20.0),
                     1e-8, 0.0);
}

void TstMetrics::secondOrderOvershoot_data() {
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("wn");
    QTest::newRow("zeta 0.2, wn 1") << 0.2 << 1.0;
    QTest::newRow("zeta 0.5, wn 3") << 0.5 << 3.0;
    QTest::newRow("zeta 0.7, wn 0.1") << 0.7 << 0.1;
}

void TstMetrics::secondOrderOvershoot() {
    // Closed forms for wn^2/(s^2 + 2 zeta wn s + wn^2): overshoot 100 exp(-pi zeta/sqrt(1-zeta^2)),
    // peak time pi/wd, wd = wn sqrt(1 - zeta^2). The peak is the largest sample, dt = 12/(zeta wn)
    // /4000 apart: its value is low by at most (wd dt)^2/8 of the peak height, i.e. a relative
    // overshoot error (wd dt)^2/8 (1 + OS)/OS (2.4e-5 at zeta 0.5): tolerance twice that bound;
    // the peak time is within dt/2 of pi/wd.
    QFETCH(double, zeta);
    QFETCH(double, wn);
    const TransferFunction g =
        TransferFunction::fromDescending({wn * wn}, {1.0, 2.0 * zeta * wn, wn * wn});
    const xyt::StepCharacteristics s = xyt::stepCharacteristics(g);
    const double wd = wn * std::sqrt(1.0 - zeta * zeta);
    const double os = std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
    const double dt = 12.0 / (zeta * wn) / 4000.0;
    const double relTol = 2.0 * (wd * dt) * (wd * dt) / 8.0 * (1.0 + os) / os;
    QVERIFY(s.stable);
    XYT_COMPARE_NEAR(s.overshootPct, 100.0 * os, relTol, 0.0);
    XYT_COMPARE_NEAR(s.peakTimeSeconds, std::numbers::pi / wd, 0.0, dt / 2.0 + 1e-12);
    // Invariant: settling lies between the peak and the 2 % envelope bound -ln(0.02 sqrt(1-z^2))
    // /(zeta wn) (the response is inside the envelope, so it settles no later than that).
    QVERIFY(s.settlingTimeSeconds > s.peakTimeSeconds);
    QVERIFY(s.settlingTimeSeconds <= -std::log(0.02 * std::sqrt(1.0 - zeta * zeta)) / (zeta * wn));
}

void TstMetrics::gtClosedLoopsAgainstScipy_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<int>("samples");
    QTest::addColumn<double>("settling");
    QTest::addColumn<double>("overshoot");
    QTest::addColumn<double>("peakTime");
    const xyt::test::CsvTable table = xyt::test::readCsv("gt_stepinfo.csv");
    QVERIFY2(table.rows.size() == 2, "tests/data/gt_stepinfo.csv: expected 2 rows");
    for (std::size_t i = 0; i < table.rows.size(); ++i)
        for (const int samples : {4000, 400000})
            QTest::newRow(qPrintable(
                QString("scipy residues: %1, %2 samples").arg(table.rows[i][0]).arg(samples)))
                << table.rows[i][0] << samples << table.number(i, "settling_time")
                << table.number(i, "overshoot_pct") << table.number(i, "peak_time");
}

void TstMetrics::gtClosedLoopsAgainstScipy() {
    // scipy: exact partial-fraction step response, settling refined by brentq, peak by bounded
    // minimization. stepCharacteristics samples 12 slowest time constants: with the default 4000
    // samples that is dt = 0.44 s (lower base, slowest pole -0.0069) and 2.2 s (upper base,
    // -0.00137), while the loops also have poles at -45 ... -80 rad/s and settle in ~5 s. So the
    // default settling time comes from a Hermite interpolation across a 2.2 s gap: measured
    // 8.6e-4 relative error (3.7 ms) for the upper base; 1e-3 relative. With 400000 samples
    // (dt 22 ms) it converges to scipy: 1e-8. The peak is flat: overshoot 1e-3 relative, peak
    // time within one sample.
    QFETCH(QString, preset);
    QFETCH(int, samples);
    QFETCH(double, settling);
    QFETCH(double, overshoot);
    QFETCH(double, peakTime);
    const auto p = xyt::findGtPreset(preset.toStdString());
    const xyt::GtDesign d = xyt::designGuilleminTruxal(p->plant, p->omegaNRadPerSec, p->kp);
    const xyt::StepCharacteristics s = xyt::stepCharacteristics(d.closedLoop, 0.02, samples);
    QVERIFY(s.stable);
    XYT_COMPARE_NEAR(s.finalValue, 1.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(s.settlingTimeSeconds, settling, samples == 4000 ? 1e-3 : 1e-8, 0.0);
    XYT_COMPARE_NEAR(s.overshootPct, overshoot, 1e-3, 0.0);
    double slowest = 1e300;
    for (const auto& pole : d.closedLoopPoles)
        slowest = std::min(slowest, -pole.real());
    XYT_COMPARE_NEAR(s.peakTimeSeconds, peakTime, 0.0, 12.0 / slowest / samples);
}

void TstMetrics::unstableIsReportedNotThrown() {
    // s^2 - s + 1 has poles in the right half plane: stable == false, no exception.
    const TransferFunction g = TransferFunction::fromDescending({1.0}, {1.0, -1.0, 1.0});
    QVERIFY(!xyt::stepCharacteristics(g).stable);
    // An integrator (marginal) is not stable either.
    QVERIFY(!xyt::stepCharacteristics(TransferFunction::fromDescending({1.0}, {1.0, 0.0})).stable);
}

void TstMetrics::errorsNameTheField() {
    using xyt::test::invalidInputField;
    const TransferFunction g = TransferFunction::fromDescending({1.0}, {1.0, 1.0});
    QCOMPARE(invalidInputField([&] { xyt::stepCharacteristics(g, 0.0); }), QString("band"));
    QCOMPARE(invalidInputField([&] { xyt::stepCharacteristics(g, 1.0); }), QString("band"));
    QCOMPARE(invalidInputField([&] { xyt::stepCharacteristics(g, std::nan("")); }),
             QString("band"));
    QCOMPARE(invalidInputField([&] { xyt::stepCharacteristics(g, 0.02, 10); }), QString("samples"));
    QCOMPARE(invalidInputField([] {
                 xyt::stepCharacteristics(TransferFunction::fromDescending({1.0, 0.0}, {1.0}));
             }),
             QString("system"));
    QCOMPARE(invalidInputField([] { xyt::trackingMetrics(SimulationResult{}); }),
             QString("result"));
    SimulationResult bad = runWithError({1.0, 2.0}, 0.1);
    bad.u.pop_back();
    QCOMPARE(invalidInputField([&] { xyt::trackingMetrics(bad); }), QString("result"));
}

QTEST_APPLESS_MAIN(TstMetrics)
#include "tst_metrics.moc"
