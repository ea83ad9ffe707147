// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/simulation/metrics.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"
#include "core/study/design_sweep.h"
#include "core/study/sweep_diagnosis.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QTest>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

using namespace xyt;

namespace {

/// The lower base of Braga et al. (Eq. 2) on a cubic 0 -> 600 mm in @p tf seconds, dt 0.01.
DesignProblem lowerBaseCubic(double tf = 130.0, double maxOvershootPct = 0.0) {
    const GtPreset lower = *findGtPreset("lower-base");
    const CubicTrajectory cubic(0.0, 600.0, 0.0, tf);
    DesignProblem p;
    p.plant = lower.plant;
    p.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
    p.dtSeconds = 0.01;
    p.reference = sampled([&](double t) { return cubic.position(t); }, sampleTimes(tf, 0.01));
    p.spec.maxOvershootPct = maxOvershootPct;
    return p;
}

SweepAxis logAxis(double lo, double hi, int n) {
    return {lo, hi, n, true};
}

std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

/// Every number of a point, bit for bit.
std::vector<std::uint64_t> fingerprint(const DesignPoint& p) {
    const TrackingMetrics& m = p.tracking;
    const StepCharacteristics& s = p.step;
    return {bits(p.wn),
            bits(p.kp),
            bits(p.ki),
            p.stable,
            p.feasible,
            p.computed,
            bits(m.rmse),
            bits(m.maxAbsError),
            bits(m.maxAbsErrorPct),
            bits(m.maxAbsU),
            m.saturated,
            bits(m.saturatedTimeSeconds),
            bits(m.itae),
            bits(s.settlingTimeSeconds),
            bits(s.overshootPct),
            bits(s.peakTimeSeconds),
            bits(p.phaseMarginDeg),
            bits(p.gainMarginDb)};
}

} // namespace

class TstDesignSweep : public QObject {
    Q_OBJECT
private slots:
    void axisValues_data();
    void axisValues();
    void badAxisThrows_data();
    void badAxisThrows();
    void fastPathMatchesFullSimulation_data();
    void fastPathMatchesFullSimulation();
    void stepFiguresMatchAnalytic_data();
    void stepFiguresMatchAnalytic();
    void handCheckedFeasibility_data();
    void handCheckedFeasibility();
    void everyGtDesignOvershoots();
    void bestIsArgminOverFeasible_data();
    void bestIsArgminOverFeasible();
    void refinementImprovesAndStaysFeasible();
    void deterministicAcrossThreadCounts();
    void badBatchWidthNamed();
    void progressIsMonotoneOnCallingThread();
    void cancellationStopsEarly();
    void marginsAreTheLoopsAndJudgedByTheMinima();
};

void TstDesignSweep::axisValues_data() {
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<int>("n");
    QTest::addColumn<bool>("log");
    QTest::addColumn<QList<double>>("expected");
    // Closed forms: linear lo + (hi - lo) i / (n - 1); log lo (hi / lo)^(i / (n - 1)).
    QTest::newRow("linear 1..3") << 1.0 << 3.0 << 3 << false << QList<double>{1, 2, 3};
    QTest::newRow("linear 0.5..2 x4") << 0.5 << 2.0 << 4 << false << QList<double>{0.5, 1, 1.5, 2};
    QTest::newRow("log decades") << 1.0 << 1000.0 << 4 << true << QList<double>{1, 10, 100, 1000};
    QTest::newRow("log 2..8 x3") << 2.0 << 8.0 << 3 << true << QList<double>{2, 4, 8};
    QTest::newRow("single value") << 2.0 << 5.0 << 1 << false << QList<double>{2};
    QTest::newRow("min == max") << 3.0 << 3.0 << 3 << true << QList<double>{3, 3, 3};
}

void TstDesignSweep::axisValues() {
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(int, n);
    QFETCH(bool, log);
    QFETCH(QList<double>, expected);
    const std::vector<double> v = SweepAxis{lo, hi, n, log}.values();
    QCOMPARE(v.size(), static_cast<std::size_t>(expected.size()));
    for (qsizetype i = 0; i < expected.size(); ++i)
        XYT_COMPARE_NEAR(v[static_cast<std::size_t>(i)], expected[i], 1e-14, 0.0); // pow round-off
    QCOMPARE(bits(v.front()), bits(lo)); // the ends are exact
    if (n > 1)
        QCOMPARE(bits(v.back()), bits(hi));
}

void TstDesignSweep::badAxisThrows_data() {
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<int>("n");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("min > max") << 2.0 << 1.0 << 3;
    QTest::newRow("n = 0") << 1.0 << 2.0 << 0;
    QTest::newRow("n = 501") << 1.0 << 2.0 << 501;
    QTest::newRow("zero min") << 0.0 << 2.0 << 3;
    QTest::newRow("negative") << -2.0 << -1.0 << 3;
    QTest::newRow("NaN") << nan << 2.0 << 3;
}

void TstDesignSweep::badAxisThrows() {
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(int, n);
    try {
        SweepAxis{lo, hi, n, false}.values("wn");
        QFAIL("no exception");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.field(), std::string("wn"));
    }
}

void TstDesignSweep::fastPathMatchesFullSimulation_data() {
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::addColumn<double>("tf");
    QTest::addColumn<bool>("saturates");
    QTest::addColumn<bool>("stable");
    // The cubic in 130 s needs 0.33 V; in 10 s its peak speed of 90 mm/s needs ~4.2 V.
    QTest::newRow("paper design, linear") << 2.0 << 30.0 << 130.0 << false << true;
    QTest::newRow("fast slow corner, linear") << 5.0 << 200.0 << 130.0 << false << true;
    QTest::newRow("paper design, saturated") << 2.0 << 30.0 << 10.0 << true << true;
    QTest::newRow("high gain, saturated") << 3.0 << 500.0 << 10.0 << true << true;
    // Routh: unstable when wn^4 > kp k0 (a1 a2 - kp k0) / a1^2 = 6.79e4 for kp 30: wn 20.
    QTest::newRow("unstable, saturated") << 20.0 << 30.0 << 130.0 << true << false;
}

void TstDesignSweep::fastPathMatchesFullSimulation() {
    QFETCH(double, wn);
    QFETCH(double, kp);
    QFETCH(double, tf);
    QFETCH(bool, saturates);
    QFETCH(bool, stable);
    const DesignProblem problem = lowerBaseCubic(tf);
    const DesignPoint fast = DesignEvaluator(problem).evaluate(wn, kp);

    // The full computation: design, simulateLoop with every signal stored, trackingMetrics.
    const GtDesign d = designGuilleminTruxal(problem.plant, wn, kp);
    LoopSimulationOptions o;
    o.dtSeconds = problem.dtSeconds;
    o.umaxVolts = problem.spec.umaxVolts;
    o.modelUnitsPerPositionUnit = problem.modelUnitsPerPositionUnit;
    const auto run =
        simulateLoop(problem.plant.transferFunction(), d.controller, problem.reference, o);
    const TrackingMetrics full = trackingMetrics(run);
    const StepCharacteristics step = stepCharacteristics(d.closedLoop);

    QCOMPARE(fast.stable, stable);
    QCOMPARE(fast.tracking.saturated, saturates);
    QCOMPARE(full.saturated, saturates);
    QVERIFY(fast.metricsFinite);
    // The batched kernel does per design what simulateLoop and trackingMetrics do, in the same
    // order (tracking_batch.h): equal bit for bit.
    QCOMPARE(bits(fast.tracking.itae), bits(full.itae));
    QCOMPARE(bits(fast.tracking.rmse), bits(full.rmse));
    QCOMPARE(bits(fast.tracking.maxAbsError), bits(full.maxAbsError));
    QCOMPARE(bits(fast.tracking.maxAbsErrorPct), bits(full.maxAbsErrorPct));
    QCOMPARE(bits(fast.tracking.maxAbsU), bits(full.maxAbsU));
    QCOMPARE(bits(fast.tracking.saturatedTimeSeconds), bits(full.saturatedTimeSeconds));
    QCOMPARE(fast.step.stable, step.stable);
    if (stable) {
        XYT_COMPARE_NEAR(fast.step.settlingTimeSeconds, step.settlingTimeSeconds, 1e-12, 0.0);
        XYT_COMPARE_NEAR(fast.step.overshootPct, step.overshootPct, 1e-12, 0.0);
    }
    XYT_COMPARE_NEAR(fast.ki, d.ki, 1e-15, 0.0);
    const SpecificationCheck c = checkSpecification(problem.spec, full, step);
    QCOMPARE(fast.check.allPassed(), c.allPassed());
    QCOMPARE(fast.check.noSaturation, c.noSaturation);
}

void TstDesignSweep::stepFiguresMatchAnalytic_data() {
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::addColumn<double>("settling");
    QTest::addColumn<double>("overshoot");
    // tests/data/design_sweep_step.csv: analytic partial-fraction step responses (scipy).
    // XYT_TEST_DATA_DIR expands to tests/core/data (CMAKE_CURRENT_SOURCE_DIR of the caller of
    // xyt_add_test), not tests/data, so the path is built from the source root.
    QFile f(QStringLiteral(XYT_SOURCE_DIR) + "/tests/data/design_sweep_step.csv");
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        qFatal("cannot open %s", qPrintable(f.fileName()));
    f.readLine();
    while (!f.atEnd()) {
        const QList<QByteArray> c = f.readLine().trimmed().split(',');
        if (c.size() != 4)
            continue;
        QTest::newRow(("wn " + c[0] + " kp " + c[1]).constData())
            << c[0].toDouble() << c[1].toDouble() << c[2].toDouble() << c[3].toDouble();
    }
}

void TstDesignSweep::stepFiguresMatchAnalytic() {
    // Regression: with one uniform grid over 12 slow time constants, wn 0.5 kp 30 gave a
    // settling time of 102.6 s (true 6.04 s) and failed the 100 s criterion.
    QFETCH(double, wn);
    QFETCH(double, kp);
    QFETCH(double, settling);
    QFETCH(double, overshoot);
    const DesignPoint p = DesignEvaluator(lowerBaseCubic()).evaluate(wn, kp);
    QVERIFY(p.step.stable);
    // Settling: Hermite interpolation inside one step (dt <= 3 t / 500), error O(dt^4): 1e-5.
    XYT_COMPARE_NEAR(p.step.settlingTimeSeconds, settling, 1e-5, 0.0);
    // Overshoot: the largest sample misses the true peak by O((dt / tau)^2): 1e-4 relative.
    XYT_COMPARE_NEAR(p.step.overshootPct, overshoot, 1e-4, 0.0);
}

void TstDesignSweep::handCheckedFeasibility_data() {
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::addColumn<double>("tf");
    QTest::addColumn<double>("maxOvershoot");
    QTest::addColumn<bool>("feasible");
    QTest::addColumn<QString>("failing");
    // Paper design: error 1.418 % < 2 %, 0.33 V, settling 5.46 s, overshoot 0.997 %.
    QTest::newRow("paper design, strict spec")
        << 2.0 << 30.0 << 130.0 << 0.0 << false << "overshoot";
    QTest::newRow("paper design, 1 % overshoot") << 2.0 << 30.0 << 130.0 << 1.0 << true << "";
    // The cubic in 10 s needs ~4.2 V > 2.5 V whatever the design.
    QTest::newRow("saturating trajectory") << 2.0 << 30.0 << 10.0 << 5.0 << false << "saturation";
    // wn 0.2 kp 5: slow loop, max error 10.6 % of the travel (lag of a type-2 loop on a cubic).
    QTest::newRow("slow design, error") << 0.2 << 5.0 << 130.0 << 1.0 << false << "error";
    QTest::newRow("unstable") << 20.0 << 30.0 << 130.0 << 5.0 << false << "stable";
}

void TstDesignSweep::handCheckedFeasibility() {
    QFETCH(double, wn);
    QFETCH(double, kp);
    QFETCH(double, tf);
    QFETCH(double, maxOvershoot);
    QFETCH(bool, feasible);
    QFETCH(QString, failing);
    const DesignPoint p = DesignEvaluator(lowerBaseCubic(tf, maxOvershoot)).evaluate(wn, kp);
    QCOMPARE(p.feasible, feasible);
    if (failing == "overshoot")
        QVERIFY(!p.check.overshoot && p.check.trackingError && p.check.noSaturation &&
                p.check.settlingTime);
    if (failing == "saturation")
        QVERIFY(!p.check.noSaturation && p.tracking.saturated);
    if (failing == "error")
        QVERIFY(!p.check.trackingError && p.tracking.maxAbsErrorPct > 2.0);
    if (failing == "stable")
        QVERIFY(!p.stable && !p.check.stable);
}

void TstDesignSweep::everyGtDesignOvershoots() {
    // Invariant: G_R is type 2, the step error integrates to E(0) = 0 and starts at 1, so every
    // stable design overshoots (Specification doc). So with the paper's strict 0 % no grid point
    // is feasible, and the sweep says so.
    SweepOptions o;
    const DesignSweepResult r =
        sweepDesignSpace(lowerBaseCubic(), logAxis(0.2, 10.0, 12), logAxis(2.0, 2000.0, 12), o);
    QVERIFY(r.stableCount > 0);
    for (const DesignPoint& p : r.points)
        if (p.stable)
            QVERIFY2(p.step.overshootPct > Specification::kOvershootRoundOffPct,
                     qPrintable(QString("wn %1 kp %2").arg(p.wn).arg(p.kp)));
    QCOMPARE(r.feasibleCount, 0);
    QVERIFY(!r.bestIndex);
    QVERIFY(!r.refined);
    QCOMPARE(r.warnings.size(), std::size_t(1));
}

void TstDesignSweep::bestIsArgminOverFeasible_data() {
    QTest::addColumn<int>("criterion");
    QTest::newRow("itae") << int(SweepCriterion::Itae);
    QTest::newRow("max_error") << int(SweepCriterion::MaxError);
    QTest::newRow("rmse") << int(SweepCriterion::Rmse);
    QTest::newRow("max_u") << int(SweepCriterion::MaxU);
    QTest::newRow("phase_margin (maximized)") << int(SweepCriterion::PhaseMargin);
    QTest::newRow("gain_margin (maximized)") << int(SweepCriterion::GainMargin);
}

void TstDesignSweep::bestIsArgminOverFeasible() {
    QFETCH(int, criterion);
    SweepOptions o;
    o.criterion = static_cast<SweepCriterion>(criterion);
    o.refine = false;
    const DesignSweepResult r = sweepDesignSpace(lowerBaseCubic(130.0, 1.0), logAxis(0.3, 4.0, 9),
                                                 logAxis(5.0, 300.0, 9), o);
    QVERIFY(r.feasibleCount > 0);
    QVERIFY(r.feasibleCount < 81); // the grid has infeasible points too
    QVERIFY(r.bestIndex.has_value());
    int feasible = 0;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const DesignPoint& p = r.points[i];
        QCOMPARE(r.feasibleMask[i], std::uint8_t(p.feasible));
        QCOMPARE(p.feasible, p.check.allPassed() && p.metricsFinite);
        if (!p.feasible)
            continue;
        ++feasible;
        // The best is a minimum over every feasible point (ties go to the lowest index).
        QVERIFY(criterionValue(r.points[*r.bestIndex], o.criterion) <=
                criterionValue(p, o.criterion));
        if (criterionMaximizes(o.criterion)) // ... which is the largest margin
            QVERIFY(criterionMetric(r.points[*r.bestIndex], o.criterion) >=
                    criterionMetric(p, o.criterion));
    }
    QCOMPARE(feasible, r.feasibleCount);
    QVERIFY(r.points[*r.bestIndex].feasible);
}

void TstDesignSweep::refinementImprovesAndStaysFeasible() {
    SweepOptions o;
    const SweepAxis wn = logAxis(0.3, 4.0, 9), kp = logAxis(5.0, 300.0, 9);
    const DesignSweepResult r = sweepDesignSpace(lowerBaseCubic(130.0, 1.0), wn, kp, o);
    QVERIFY(r.bestIndex && r.refined);
    const DesignPoint& best = r.points[*r.bestIndex];
    const DesignPoint& refined = r.refined->point;
    QVERIFY(refined.feasible);
    QVERIFY(criterionValue(refined, o.criterion) <= criterionValue(best, o.criterion));
    QCOMPARE(r.refined->improved,
             criterionValue(refined, o.criterion) < criterionValue(best, o.criterion));
    QVERIFY(refined.wn >= wn.minValue && refined.wn <= wn.maxValue);
    QVERIFY(refined.kp >= kp.minValue && refined.kp <= kp.maxValue);
    QVERIFY(r.refined->evaluations > 0 && r.refined->evaluations <= o.maxRefineEvaluations);
    // The refined point is what the evaluator says about its (wn, kp): no stale metrics.
    const DesignPoint again =
        DesignEvaluator(lowerBaseCubic(130.0, 1.0)).evaluate(refined.wn, refined.kp);
    QCOMPARE(fingerprint(again), fingerprint(refined));
}

void TstDesignSweep::deterministicAcrossThreadCounts() {
    // Includes saturated, unstable and feasible points (cubic in 20 s: some designs clip).
    const DesignProblem problem = lowerBaseCubic(20.0, 1.0);
    const SweepAxis wn = logAxis(0.3, 30.0, 11), kp = logAxis(2.0, 3000.0, 11);
    std::vector<DesignSweepResult> runs;
    for (int threads : {1, 2, 3})
        for (int width : {1, 4, 8}) {
            SweepOptions o;
            o.threads = threads;
            o.batchWidth = width;
            runs.push_back(sweepDesignSpace(problem, wn, kp, o));
            QCOMPARE(runs.back().threadsUsed, threads);
        }
    const DesignSweepResult& a = runs[0];
    int saturated = 0, unstable = 0;
    for (const DesignPoint& p : a.points) {
        saturated += p.tracking.saturated ? 1 : 0;
        unstable += p.stable ? 0 : 1;
    }
    QVERIFY(saturated > 0 && unstable > 0 && a.feasibleCount > 0);
    for (std::size_t k = 1; k < runs.size(); ++k) {
        const DesignSweepResult& b = runs[k];
        QCOMPARE(b.points.size(), a.points.size());
        for (std::size_t i = 0; i < a.points.size(); ++i)
            QCOMPARE(fingerprint(b.points[i]), fingerprint(a.points[i]));
        QCOMPARE(b.bestIndex, a.bestIndex);
        QVERIFY(a.refined && b.refined);
        QCOMPARE(fingerprint(b.refined->point), fingerprint(a.refined->point));
    }
}

void TstDesignSweep::badBatchWidthNamed() {
    SweepOptions o;
    o.batchWidth = 3;
    try {
        sweepDesignSpace(lowerBaseCubic(10.0), logAxis(1.0, 2.0, 2), logAxis(10.0, 20.0, 2), o);
        QFAIL("a batch width of 3 was accepted");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.field(), std::string("batch_width"));
        QCOMPARE(e.reasonDiagnostic().code, std::string("sim_batch_width"));
        QCOMPARE(e.reason(), std::string("must be 1, 2, 4 or 8"));
    }
    DesignProblem p = lowerBaseCubic(10.0);
    p.stepSamples = 99; // stepCharacteristics needs at least 100
    try {
        DesignEvaluator{p};
        QFAIL("99 step samples were accepted");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.field(), std::string("step_samples"));
        // A generic reason with its bounds as arguments.
        QCOMPARE(e.reasonDiagnostic().code, std::string("study_from_to"));
        QCOMPARE(e.reasonDiagnostic().args.at(0).text, std::string("100"));
        QCOMPARE(e.reasonDiagnostic().args.at(1).text, std::string("100000"));
        QCOMPARE(e.reason(), std::string("must be from 100 to 100000"));
    }
}

void TstDesignSweep::progressIsMonotoneOnCallingThread() {
    std::vector<double> seen;
    bool otherThread = false;
    const auto caller = std::this_thread::get_id();
    SweepOptions o;
    o.threads = 2;
    o.progress = [&](double f) {
        otherThread = otherThread || std::this_thread::get_id() != caller;
        seen.push_back(f);
        return true;
    };
    const DesignSweepResult r = sweepDesignSpace(lowerBaseCubic(130.0, 1.0), logAxis(0.3, 4.0, 20),
                                                 logAxis(5.0, 300.0, 20), o);
    QCOMPARE(r.status, SweepStatus::Completed);
    QVERIFY(!otherThread);
    QVERIFY(seen.size() >= 2);
    QCOMPARE(seen.front(), 0.0);
    QCOMPARE(seen.back(), 1.0);
    for (std::size_t i = 1; i < seen.size(); ++i)
        QVERIFY(seen[i] >= seen[i - 1]);
    for (std::size_t i = 0; i + 1 < seen.size(); ++i)
        QVERIFY(seen[i] < 1.0); // 1 only once everything, refinement included, is done
}

void TstDesignSweep::cancellationStopsEarly() {
    // Cancel at the first report after the start (about 20 ms in): 3600 points on 2 threads
    // take some 200 ms here, far longer.
    int calls = 0;
    SweepOptions o;
    o.threads = 2;
    o.progress = [&](double) { return ++calls < 2; };
    const DesignSweepResult r =
        sweepDesignSpace(lowerBaseCubic(), logAxis(0.3, 4.0, 60), logAxis(5.0, 300.0, 60), o);
    QCOMPARE(r.status, SweepStatus::Cancelled);
    QVERIFY(r.computedCount < 3600);
    QVERIFY(!r.refined);
    QVERIFY(!r.warnings.empty());
    QCOMPARE(calls, 2); // never called again after it said stop
    for (const DesignPoint& p : r.points)
        if (!p.computed)
            QVERIFY(!p.feasible && std::isinf(criterionValue(p, SweepCriterion::Itae)));
    // Cancelled before anything: no point computed.
    o.progress = [](double) { return false; };
    const DesignSweepResult none =
        sweepDesignSpace(lowerBaseCubic(), logAxis(0.3, 4.0, 5), logAxis(5.0, 300.0, 5), o);
    QCOMPARE(none.status, SweepStatus::Cancelled);
    QCOMPARE(none.computedCount, 0);
}

void TstDesignSweep::marginsAreTheLoopsAndJudgedByTheMinima() {
    // Every point carries the margins of its loop L = G_c G, as stabilityMargins of
    // gtLoopTransferFunctions gives them for the same design (the same computation, so equal
    // to the bit), and the margin minima judge them like every other limit.
    DesignProblem problem = lowerBaseCubic(130.0, 1.0);
    SweepOptions o;
    o.refine = false;
    const SweepAxis wn = logAxis(0.5, 4.0, 5), kp = logAxis(5.0, 300.0, 5);
    DesignSweepResult r = sweepDesignSpace(problem, wn, kp, o);
    double lo = INFINITY, hi = -INFINITY;
    for (const DesignPoint& p : r.points) {
        const GtDesign d = designGuilleminTruxal(problem.plant, p.wn, p.kp);
        const StabilityMargins m = stabilityMargins(gtLoopTransferFunctions(d).openLoop);
        QCOMPARE(bits(p.phaseMarginDeg), bits(m.phaseMarginDeg));
        QCOMPARE(bits(p.gainMarginDb), bits(m.gainMarginDb));
        QVERIFY(p.check.marginsApply);
        if (p.stable) {
            lo = std::min(lo, p.phaseMarginDeg);
            hi = std::max(hi, p.phaseMarginDeg);
        }
    }
    QVERIFY(lo < hi);
    // A phase-margin minimum between the grid's extremes: exactly the stable points below it
    // fail that criterion, after a rejudge and in a fresh sweep alike.
    Specification spec = problem.spec;
    spec.minPhaseMarginDeg = 0.5 * (lo + hi);
    rejudgeDesignSpace(r, spec);
    problem.spec = spec;
    const DesignSweepResult fresh = sweepDesignSpace(problem, wn, kp, o);
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const DesignPoint& p = r.points[i];
        QCOMPARE(p.check.phaseMargin, p.stable && p.phaseMarginDeg >= spec.minPhaseMarginDeg);
        QCOMPARE(fresh.points[i].check.phaseMargin, p.check.phaseMargin);
        QCOMPARE(fresh.points[i].feasible, p.feasible);
        if (!p.check.phaseMargin)
            QVERIFY(!p.feasible);
    }
    // A minimum no design meets: the diagnosis names the phase margin, quotes the largest one
    // found, and relaxes the minimum to (3 digits below) the least-violating design's margin.
    spec.minPhaseMarginDeg = 179.0;
    rejudgeDesignSpace(r, spec);
    QCOMPARE(r.feasibleCount, 0);
    const SweepDiagnosis diagnosis = diagnoseSweep(r, spec);
    const auto f = std::find_if(
        diagnosis.failingEverywhere.begin(), diagnosis.failingEverywhere.end(),
        [](const CriterionFailure& c) { return c.criterion == SpecCriterion::PhaseMargin; });
    QVERIFY(f != diagnosis.failingEverywhere.end());
    QCOMPARE(f->bestValue, hi);
    QCOMPARE(f->limit, 179.0);
    QVERIFY(diagnosis.relaxed.has_value()); // the least-violating design clips nothing here
    {
        const DesignPoint& least = r.points[*diagnosis.leastViolating];
        QVERIFY(diagnosis.relaxed->minPhaseMarginDeg <= least.phaseMarginDeg);
        QVERIFY(diagnosis.relaxed->minPhaseMarginDeg >= least.phaseMarginDeg * (1.0 - 1e-2));
        const SpecificationCheck again =
            checkSpecification(*diagnosis.relaxed, least.tracking, least.step, least.move,
                               LoopMarginFigures{least.phaseMarginDeg, least.gainMarginDb});
        QVERIFY(again.allPassed());
    }
}

QTEST_APPLESS_MAIN(TstDesignSweep)
#include "tst_design_sweep.moc"
