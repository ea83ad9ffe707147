// SPDX-License-Identifier: GPL-3.0-or-later
// Robustness to plant-model mismatch. Sources of the expected values: the session's
// own evaluation (zero uncertainty), a direct simulation of the perturbed loop (ZPETC with a
// wrong B), the closed-form steady-state error of a first-order pole-placement loop whose gain
// is uniformly distributed (Kolmogorov-Smirnov at a fixed seed), and invariants (bit-identical
// results for any thread count; nested envelopes for nested ranges).
#include "core/design/pole_placement.h"
#include "core/model/errors.h"
#include "core/session/robustness_problem.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/metrics.h"
#include "core/study/robustness.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace xyt;

namespace {

std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

RobustnessOptions options(int samples, std::uint64_t seed = 1, bool corners = true) {
    RobustnessOptions o;
    o.samples = samples;
    o.seed = seed;
    o.corners = corners;
    return o;
}

Session ppSession() {
    Session s;
    s.axes[0].method =
        DesignMethod::PolePlacementZpetc;       // Patrick, Ishak and Adnan's x axis, ZPETC on
    s.trajectory.kind = TrajectoryKind::Circle; // 30 mm at 0.1 rad/s in Patrick, Ishak and Adnan
    s.trajectory.radius = 30.0;
    s.trajectory.omegaRadPerSec = 0.1;
    s.trajectory.rampInSeconds = 0.0;
    return s;
}

/// Every number of every run and of the statistics, bit for bit.
std::vector<std::uint64_t> fingerprint(const RobustnessResult& r) {
    std::vector<std::uint64_t> f;
    for (const PlantRun& p : r.runs) {
        for (double v : p.values)
            f.push_back(bits(v));
        f.insert(f.end(),
                 {bits(p.tracking.rmse), bits(p.tracking.maxAbsError), bits(p.tracking.maxAbsU),
                  bits(p.tracking.itae), bits(p.step.settlingTimeSeconds), p.stable, p.meetsSpec});
    }
    for (const Distribution& d : {r.rmse, r.maxAbsError, r.maxAbsU})
        f.insert(f.end(),
                 {bits(d.min), bits(d.p05), bits(d.p50), bits(d.p95), bits(d.max), bits(d.mean)});
    for (const SignalEnvelope* e : {&r.output, &r.error, &r.command})
        for (const std::vector<double>* v : {&e->min, &e->p05, &e->p50, &e->p95, &e->max})
            for (double x : *v)
                f.push_back(bits(x));
    f.push_back(bits(r.fractionMeetingSpec));
    return f;
}

/// Sum over time of the envelope's width max - min.
double width(const SignalEnvelope& e) {
    double w = 0.0;
    for (std::size_t k = 0; k < e.min.size(); ++k)
        w += e.max[k] - e.min[k];
    return w;
}

} // namespace

class TstRobustness : public QObject {
    Q_OBJECT
private slots:
    void zeroUncertaintyIsTheNominal_data();
    void zeroUncertaintyIsTheNominal();
    void deterministicAcrossThreadCounts();
    void widerRangesNeverNarrowTheEnvelope();
    void zpetcImprovementFallsWithAWrongB();
    void zpetcSensitivityCurve();
    void steadyStateErrorDistributionIsAnalytic();
    void unstablePlantsAreListedNotAveraged();
    void badInputsAreNamed();
};

void TstRobustness::zeroUncertaintyIsTheNominal_data() {
    QTest::addColumn<bool>("discrete");
    QTest::newRow("Guillemin-Truxal, cubic") << false;
    QTest::newRow("pole placement + ZPETC, circle") << true;
}

void TstRobustness::zeroUncertaintyIsTheNominal() {
    QFETCH(bool, discrete);
    const Session s = discrete ? ppSession() : Session{};
    const RobustnessProblem problem = sessionRobustnessProblem(s, 0);
    RobustnessOptions o;
    o.samples = 12;
    const RobustnessResult r = analyzeRobustness(problem, o);
    QCOMPARE(r.runs.size(), std::size_t(13)); // 12 draws and the one corner of an empty box
    // The session's own evaluation of the axis is the nominal run.
    const AxisEvaluation eval = evaluateAxis(s, 0);
    QCOMPARE(bits(r.nominal.tracking.rmse), bits(eval.metrics.rmse));
    QCOMPARE(bits(r.nominal.tracking.maxAbsError), bits(eval.metrics.maxAbsError));
    QCOMPARE(bits(r.nominal.tracking.maxAbsU), bits(eval.metrics.maxAbsU));
    if (discrete)
        QCOMPARE(bits(r.nominal.rmseWithoutFf), bits(eval.rmseWithoutFf));
    for (const PlantRun& p : r.runs) {
        QCOMPARE(bits(p.tracking.rmse), bits(r.nominal.tracking.rmse));
        QCOMPARE(bits(p.tracking.itae), bits(r.nominal.tracking.itae));
        QCOMPARE(p.meetsSpec, r.nominal.meetsSpec);
    }
    QCOMPARE(bits(r.rmse.min), bits(r.rmse.max));
    QCOMPARE(r.output.min, r.output.max);
    QCOMPARE(r.output.nominal, r.output.max); // the nominal run at the envelope's instants
    // One bin holding every run (all values equal).
    const Histogram h = histogram(figureValues(r, RobustnessFigure::Rmse), 20);
    QCOMPARE(h.counts, std::vector<int>{13});
    QVERIFY(r.unstable.empty());
}

void TstRobustness::deterministicAcrossThreadCounts() {
    RobustnessProblem problem = sessionRobustnessProblem(Session{}, 0);
    setRelativeRange(problem.parameters, "k0", 0.2);
    setRelativeRange(problem.parameters, "a1", 0.1);
    RobustnessOptions o;
    o.samples = 24;
    o.seed = 7;
    std::vector<std::vector<std::uint64_t>> prints;
    for (int threads : {1, 2, 3}) {
        o.threads = threads;
        const RobustnessResult r = analyzeRobustness(problem, o);
        QCOMPARE(r.threadsUsed, threads);
        QCOMPARE(r.runs.size(), std::size_t(24 + 4)); // 2 uncertain parameters: 4 corners
        prints.push_back(fingerprint(r));
    }
    QCOMPARE(prints[1], prints[0]);
    QCOMPARE(prints[2], prints[0]);
    o.seed = 8; // another seed, other plants
    QVERIFY(fingerprint(analyzeRobustness(problem, o)) != prints[0]);
}

void TstRobustness::widerRangesNeverNarrowTheEnvelope() {
    // Same seed: each plant moves farther from the nominal along the same direction as the
    // ranges widen (drawPlants), so the spread of the runs can only grow.
    RobustnessProblem base = sessionRobustnessProblem(Session{}, 0);
    setRelativeRange(base.parameters, "k0", 0.3);
    setRelativeRange(base.parameters, "a2", 0.2);
    RobustnessOptions o;
    o.samples = 30;
    double lastWidth = -1.0, lastRmseSpread = -1.0;
    for (double scale : {0.0, 0.25, 0.5, 1.0}) {
        RobustnessProblem p = base;
        p.parameters = scaledRanges(base.parameters, scale);
        const RobustnessResult r = analyzeRobustness(p, o);
        const double w = width(r.error);
        const double spread = r.rmse.max - r.rmse.min;
        QVERIFY2(w >= lastWidth,
                 qPrintable(QString("scale %1: width %2 < %3").arg(scale).arg(w).arg(lastWidth)));
        QVERIFY2(spread >= lastRmseSpread, qPrintable(QString("scale %1").arg(scale)));
        lastWidth = w;
        lastRmseSpread = spread;
    }
    QVERIFY(lastWidth > 0.0);
    // The histogram of the widest case counts every stable run once, in bins of equal width
    // spanning the distribution's min and max.
    RobustnessProblem p = base;
    const RobustnessResult r = analyzeRobustness(p, o);
    const Histogram h = histogram(figureValues(r, RobustnessFigure::MaxAbsU), 7);
    int total = 0;
    for (int c : h.counts)
        total += c;
    QCOMPARE(total, r.maxAbsU.count);
    QCOMPARE(h.edges.front(), r.maxAbsU.min);
    QCOMPARE(h.edges.back(), r.maxAbsU.max);
}

void TstRobustness::zpetcImprovementFallsWithAWrongB() {
    RobustnessProblem problem = sessionRobustnessProblem(ppSession(), 0);
    const RobustnessResult exact = analyzeRobustness(problem, options(0));
    const AxisEvaluation eval = evaluateAxis(ppSession(), 0);
    const double nominalImprovement =
        1.0 - exact.nominal.tracking.rmse / exact.nominal.rmseWithoutFf;
    XYT_COMPARE_NEAR(100.0 * nominalImprovement, eval.improvementPct, 1e-12, 0.0);
    // B 20 % off in b1 (the corners: b1 at 0.8 and 1.2 times the model's).
    setRelativeRange(problem.parameters, "b1", 0.2);
    RobustnessOptions o;
    o.samples = 0;
    const RobustnessResult wrong = analyzeRobustness(problem, o);
    QCOMPARE(wrong.runs.size(), std::size_t(2));
    for (const PlantRun& p : wrong.runs) {
        QVERIFY(p.stable && p.finite);
        const double improvement = 1.0 - p.tracking.rmse / p.rmseWithoutFf;
        QVERIFY2(improvement < nominalImprovement, qPrintable(QString("b1 = %1: %2 >= %3")
                                                                  .arg(p.values[2])
                                                                  .arg(improvement)
                                                                  .arg(nominalImprovement)));
        // The reported RMSE is that of a direct simulation of the mismatched plant under the
        // nominal RST law and the nominal ZPETC.
        PolePlacementDesign plant = *problem.loop;
        std::vector<double> b = plant.b.ascending();
        b[1] = p.values[2];
        plant.b = Polynomial::fromAscending(b);
        const DiscreteRun run =
            simulateZpetcLoop(plant, *problem.zpetc, problem.reference, problem.samples);
        double sum = 0.0;
        for (std::size_t k = 0; k < problem.samples; ++k)
            sum += (problem.reference[k] - run.y[k]) * (problem.reference[k] - run.y[k]);
        XYT_COMPARE_NEAR(p.tracking.rmse, std::sqrt(sum / static_cast<double>(problem.samples)),
                         1e-12, 0.0);
    }
    QCOMPARE(problem.parameters[2].name, std::string("b1"));
}

void TstRobustness::zpetcSensitivityCurve() {
    // Patrick, Ishak and Adnan: ZPETC is sensitive to mismatch. At scale 0 the curve's improvement
    // is the nominal one (the session's evaluation); as B moves away it falls; each point is
    // analyzeRobustness at that scale (same seed).
    RobustnessProblem problem = sessionRobustnessProblem(ppSession(), 0);
    for (const char* b : {"b1", "b2", "b3"})
        setRelativeRange(problem.parameters, b, 0.3);
    const RobustnessOptions o = options(20, 3, false);
    const std::vector<ZpetcSensitivityPoint> curve = zpetcSensitivity(problem, {0.0, 0.5, 1.0}, o);
    QCOMPARE(curve.size(), std::size_t(3));
    XYT_COMPARE_NEAR(curve[0].medianImprovementPct, evaluateAxis(ppSession(), 0).improvementPct,
                     1e-12, 0.0);
    QVERIFY(curve[1].medianImprovementPct < curve[0].medianImprovementPct);
    QVERIFY(curve[2].medianImprovementPct < curve[1].medianImprovementPct);
    RobustnessProblem half = problem;
    half.parameters = scaledRanges(problem.parameters, 0.5);
    const RobustnessResult direct = analyzeRobustness(half, o);
    QCOMPARE(bits(curve[1].rmseWithFf.p50), bits(direct.rmse.p50));
    QCOMPARE(bits(curve[1].rmseWithoutFf.p50), bits(direct.rmseWithoutFf.p50));
    const std::string field = [&] {
        try {
            zpetcSensitivity(sessionRobustnessProblem(Session{}, 0), {1.0});
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return std::string();
    }();
    QCOMPARE(field, std::string("problem"));
}

void TstRobustness::steadyStateErrorDistributionIsAnalytic() {
    // A = 1 - a z^-1, B = b z^-1, T = 1 + t1 z^-1: F = 1, G = (t1 + a)/b, Kf = (1 + t1)/b. With
    // the true gain beta b the loop's step settles at (1 + t1) beta / ((1 - a) + beta (t1 + a)),
    // so e_ss(beta) = (1 - a)(1 - beta) / ((1 - a) + beta (t1 + a)), decreasing in beta, and for
    // beta uniform on [1 - rho, 1 + rho]: P(e_ss <= e) = (1 + rho - beta(e)) / (2 rho) with
    // beta(e) = (1 - a)(1 - e) / ((1 - a) + e (t1 + a)).
    const double a = 0.8, b = 0.5, t1 = -0.5, rho = 0.5;
    RobustnessProblem p;
    p.loop = designPolePlacement(Polynomial::fromAscending({1.0, -a}),
                                 Polynomial::fromAscending({0.0, b}),
                                 Polynomial::fromAscending({1.0, t1}), 1.0);
    p.parameters = {{"a1", -a, 0.0}, {"b1", b, rho}};
    p.samples = 200; // the closed-loop pole 0.8 - 0.3 beta is 0.35..0.65: 0.65^200 ~ 1e-37
    p.reference.assign(p.samples, 1.0);
    p.move = PointToPointMove{0.0, 1.0, 0.0};
    p.spec.umaxVolts = 1e9;
    RobustnessOptions o;
    o.samples = 400;
    o.seed = 2026;
    o.corners = false;
    const RobustnessResult r = analyzeRobustness(p, o);
    std::vector<double> e;
    for (const PlantRun& run : r.runs) {
        QVERIFY(run.stable && run.move);
        e.push_back(run.move->finalErrorMm);
    }
    std::sort(e.begin(), e.end());
    const auto cdf = [&](double x) {
        const double beta = (1.0 - a) * (1.0 - x) / ((1.0 - a) + x * (t1 + a));
        return std::clamp((1.0 + rho - beta) / (2.0 * rho), 0.0, 1.0);
    };
    double d = 0.0; // Kolmogorov-Smirnov statistic
    const double n = static_cast<double>(e.size());
    for (std::size_t i = 0; i < e.size(); ++i)
        d = std::max({d, std::abs(static_cast<double>(i + 1) / n - cdf(e[i])),
                      std::abs(static_cast<double>(i) / n - cdf(e[i]))});
    // Critical value at the 1 % level for n = 400: 1.628 / sqrt(n) = 0.0814.
    QVERIFY2(d < 1.628 / std::sqrt(n), qPrintable(QString("D = %1").arg(d)));
}

void TstRobustness::unstablePlantsAreListedNotAveraged() {
    // The same first-order loop: G = (t1 + a)/b = 0.6, so with the true gain beta b the
    // closed-loop pole is a - beta b G = 0.8 - 0.3 beta, outside the unit circle for beta > 6.
    const double a = 0.8, b = 0.5, t1 = -0.5;
    RobustnessProblem p;
    p.loop = designPolePlacement(Polynomial::fromAscending({1.0, -a}),
                                 Polynomial::fromAscending({0.0, b}),
                                 Polynomial::fromAscending({1.0, t1}), 1.0);
    p.parameters = {{"a1", -a, 0.0}, {"b1", b, 0.9}};
    p.samples = 50;
    p.reference.assign(p.samples, 1.0);
    p.spec.umaxVolts = 1e9;
    RobustnessOptions o;
    o.samples = 100;
    const RobustnessResult r = analyzeRobustness(p, o); // beta in [0.1, 1.9]: all stable
    QVERIFY(r.unstable.empty());
    QCOMPARE(r.rmse.count, 102);
    p.parameters[1].relative = 0.0;
    p.parameters[1].nominal = 8.0 * b; // pole 0.8 - 2.4 = -1.6
    const RobustnessResult bad = analyzeRobustness(p, options(5, 1, false));
    QCOMPARE(bad.unstable.size(), std::size_t(5));
    QCOMPARE(bad.rmse.count, 0);
    QVERIFY(!bad.worst);
    QCOMPARE(bad.fractionMeetingSpec, 0.0);
    QVERIFY(!bad.warnings.empty());
}

void TstRobustness::badInputsAreNamed() {
    RobustnessProblem p = sessionRobustnessProblem(Session{}, 0);
    const auto field = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return {};
    };
    QCOMPARE(field([&] { setRelativeRange(p.parameters, "k0", 1.0); }), std::string("range.k0"));
    QCOMPARE(field([&] { setRelativeRange(p.parameters, "k0", -0.1); }), std::string("range.k0"));
    QCOMPARE(field([&] { setRelativeRange(p.parameters, "b1", 0.1); }), std::string("range"));
    QCOMPARE(field([&] { analyzeRobustness(p, options(-1)); }), std::string("samples"));
    RobustnessOptions o;
    o.envelopePoints = 1;
    QCOMPARE(field([&] { analyzeRobustness(p, o); }), std::string("envelope_points"));
    QCOMPARE(field([&] { sessionRobustnessProblem(Session{}, 2); }), std::string("axis"));
    RobustnessProblem both = p;
    both.loop = sessionRobustnessProblem(ppSession(), 0).loop;
    QCOMPARE(field([&] { analyzeRobustness(both, options(1)); }), std::string("problem"));
}

QTEST_APPLESS_MAIN(TstRobustness)
#include "tst_robustness.moc"
