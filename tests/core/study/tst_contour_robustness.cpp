// SPDX-License-Identifier: GPL-3.0-or-later
// The joint XY contour under plant-model mismatch. Sources of the expected values:
// the session's own evaluation (zero uncertainty: SessionEvaluation::contour for the circle,
// SessionEvaluation::program for a G-code program), the pair simulated directly (simulateLoop)
// and judged by the core's contour measures (circleContourError, contourError), and invariants
// (bit-identical results for any thread count; the XY band's base points lie on the circle with
// the outward unit radius as normal).
#include "core/model/errors.h"
#include "core/session/robustness_problem.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/contour_error.h"
#include "core/simulation/simulation.h"
#include "core/study/contour_robustness.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

using namespace xyt;

namespace {

std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

/// Braga et al.'s circle (both bases, Guillemin-Truxal) or Patrick, Ishak and Adnan's (x by pole
/// placement + ZPETC).
Session circleSession(bool mixed) {
    Session s;
    s.trajectory.kind = TrajectoryKind::Circle;
    if (mixed) {
        s.axes[0].method = DesignMethod::PolePlacementZpetc;
        s.trajectory.radius = 30.0;
        s.trajectory.omegaRadPerSec = 0.1;
        s.trajectory.rampInSeconds = 0.0;
    }
    return s;
}

Session programSession(const char* example) {
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/resources/examples/") + example);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read the example %s", example);
    Session s;
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = example;
    s.trajectory.gcode.program = f.readAll().toStdString();
    return s;
}

RobustnessOptions options(int samples, int threads = 0) {
    RobustnessOptions o;
    o.samples = samples;
    o.seed = 3;
    o.threads = threads;
    return o;
}

/// Axis @p axis of @p s (Guillemin-Truxal) simulated directly (simulateLoop) with its nominal
/// PI on the plant with parameters k0, a1, a2, following @p reference from rest at its start.
std::vector<double> directRun(const Session& s, const RobustnessProblem& a,
                              const std::vector<double>& values, std::size_t offset) {
    const ThirdOrderPlant plant{values[offset], values[offset + 1], values[offset + 2]};
    LoopSimulationOptions o;
    o.dtSeconds = a.dtSeconds;
    o.umaxVolts = s.umaxVolts;
    o.modelUnitsPerPositionUnit = a.modelUnitsPerPositionUnit;
    o.initialOutput = a.initialOutput;
    return simulateLoop(plant.transferFunction(), *a.controller, a.reference, o).y;
}

} // namespace

class TstContourRobustness : public QObject {
    Q_OBJECT
private slots:
    void zeroUncertaintyIsTheSessionsContour_data();
    void zeroUncertaintyIsTheSessionsContour();
    void eachPairIsADirectSimulation_data();
    void eachPairIsADirectSimulation();
    void deterministicAcrossThreadCounts();
    void bandGeometry();
    void badInputsAreNamed();
};

void TstContourRobustness::zeroUncertaintyIsTheSessionsContour_data() {
    QTest::addColumn<QString>("kind");
    QTest::newRow("Braga et al.'s circle, both Guillemin-Truxal") << "circle";
    QTest::newRow("Patrick, Ishak and Adnan's circle, x pole placement + ZPETC") << "mixed";
    QTest::newRow("G-code square with sharp corners") << "square_sharp_corners.nc";
    QTest::newRow("G-code engraving (rapids left out)") << "engraving_xy.nc";
}

void TstContourRobustness::zeroUncertaintyIsTheSessionsContour() {
    QFETCH(QString, kind);
    const bool program = kind.endsWith(".nc");
    const Session s =
        program ? programSession(kind.toUtf8().constData()) : circleSession(kind == "mixed");
    const ContourRobustnessProblem p = sessionContourRobustnessProblem(s);
    const ContourRobustnessResult r = analyzeContourRobustness(p, options(6));
    const SessionEvaluation eval = evaluateSession(s);
    const double maxAbs = program ? eval.program->contour.maxAbs : eval.contour->maxAbs;
    const double rms = program ? eval.program->contour.rms : eval.contour->rms;
    // The same runs judged the same way: bit for bit.
    QCOMPARE(bits(r.nominal.maxAbsContourError), bits(maxAbs));
    QCOMPARE(bits(r.nominal.rmsContourError), bits(rms));
    QCOMPARE(r.runs.size(), std::size_t(6 + 1)); // the one corner of an empty box
    for (const JointPlantRun& run : r.runs) {
        QVERIFY(run.stable && run.finite);
        QCOMPARE(bits(run.maxAbsContourError), bits(maxAbs));
    }
    QCOMPARE(bits(r.maxAbsContourError.min), bits(r.maxAbsContourError.max));
    QCOMPARE(r.error.min, r.error.max);
    QCOMPARE(r.error.nominal, r.error.p50);
    QVERIFY(r.unstable.empty());
}

void TstContourRobustness::eachPairIsADirectSimulation_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<double>("relative"); // each parameter's uncertainty
    QTest::addColumn<int>("samples");
    QTest::newRow("Braga et al.'s circle") << "circle" << 0.05 << 3;
    QTest::newRow("G-code star") << "star.nc" << 0.05 << 3;
    // Rapids are left out of the figures: a pair whose trace lies nearer a rapid than the
    // nominal trace did (or the other way) is judged on its own samples, not on the nominal's.
    QTest::newRow("G-code engraving (rapids left out)") << "engraving_xy.nc" << 0.3 << 8;
}

void TstContourRobustness::eachPairIsADirectSimulation() {
    QFETCH(QString, kind);
    QFETCH(double, relative);
    QFETCH(int, samples);
    const bool program = kind.endsWith(".nc");
    const Session s = program ? programSession(kind.toUtf8().constData()) : circleSession(false);
    ContourRobustnessProblem p = sessionContourRobustnessProblem(s);
    for (RobustnessProblem* a : {&p.x, &p.y})
        for (UncertainParameter& q : a->parameters)
            q.relative = relative;
    RobustnessOptions o = options(samples);
    o.corners = false;
    const ContourRobustnessResult r = analyzeContourRobustness(p, o);
    QCOMPARE(r.runs.size(), std::size_t(samples));
    QCOMPARE(r.parameterNames,
             (std::vector<std::string>{"x.k0", "x.a1", "x.a2", "y.k0", "y.a1", "y.a2"}));
    // A 5 % mismatch moves the contour: the pairs differ from the nominal and from each other.
    QVERIFY(r.maxAbsContourError.max > r.maxAbsContourError.min);
    for (const JointPlantRun& run : r.runs) {
        QVERIFY(run.maxAbsContourError != r.nominal.maxAbsContourError);
        // The same pair through the plain simulation and the contour measures of the core (both
        // Guillemin-Truxal axes run on the same grid as the judging time base).
        const std::vector<double> x = directRun(s, p.x, run.values, 0);
        const std::vector<double> y = directRun(s, p.y, run.values, 3);
        const auto [expectedMax, expectedRms] = [&] {
            if (program) {
                const ContourErrorResult c =
                    contourError(*p.geometry.path, p.geometry.t, x, y, p.geometry.pathOptions);
                return std::pair{c.maxAbs, c.rms};
            }
            const ContourError c = circleContourError(p.geometry.t, x, y, *p.geometry.circle);
            return std::pair{c.maxAbs, c.rms};
        }();
        QCOMPARE(bits(run.maxAbsContourError), bits(expectedMax));
        QCOMPARE(bits(run.rmsContourError), bits(expectedRms));
    }
}

void TstContourRobustness::deterministicAcrossThreadCounts() {
    ContourRobustnessProblem p = sessionContourRobustnessProblem(circleSession(true));
    for (RobustnessProblem* a : {&p.x, &p.y})
        for (UncertainParameter& q : a->parameters)
            q.relative = 0.1;
    std::vector<std::uint64_t> first;
    for (int threads : {1, 2, 3}) {
        RobustnessOptions o = options(10, threads);
        o.corners = false;
        const ContourRobustnessResult r = analyzeContourRobustness(p, o);
        QCOMPARE(r.threadsUsed, threads);
        std::vector<std::uint64_t> f;
        for (const JointPlantRun& run : r.runs)
            f.insert(f.end(), {bits(run.maxAbsContourError), bits(run.rmsContourError)});
        for (const std::vector<double>* v :
             {&r.error.min, &r.error.p05, &r.error.p50, &r.error.p95, &r.error.max})
            for (double x : *v)
                f.push_back(bits(x));
        f.push_back(bits(r.maxAbsContourError.mean));
        if (first.empty())
            first = f;
        QCOMPARE(f, first);
    }
}

void TstContourRobustness::bandGeometry() {
    const Session s = circleSession(false);
    const ContourRobustnessProblem p = sessionContourRobustnessProblem(s);
    RobustnessOptions o = options(2);
    o.envelopePoints = 50;
    const ContourRobustnessResult r = analyzeContourRobustness(p, o);
    QCOMPARE(r.base.size(), r.error.t.size());
    QCOMPARE(r.normal.size(), r.error.t.size());
    QVERIFY(r.error.t.size() >= 50 && r.error.t.size() <= 51);
    for (std::size_t j = 0; j < r.base.size(); ++j) {
        // On the programmed circle, with the outward unit radius as the normal (closed form).
        QVERIFY(xyt::test::near(std::hypot(r.base[j].x, r.base[j].y), s.trajectory.radius, 1e-12));
        QVERIFY(xyt::test::near(std::hypot(r.normal[j].x, r.normal[j].y), 1.0, 1e-12));
        QVERIFY(xyt::test::near(r.base[j].x * r.normal[j].y - r.base[j].y * r.normal[j].x, 0.0, 0.0,
                                1e-9));
        // Only samples after the ramp-in are judged.
        QVERIFY(r.error.t[j] >= s.trajectory.rampInSeconds);
    }
}

void TstContourRobustness::badInputsAreNamed() {
    const auto field = [](auto&& f) {
        try {
            f();
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return std::string("(no error)");
    };
    QCOMPARE(field([] { sessionContourRobustnessProblem(Session{}); }), std::string("trajectory"));
    ContourRobustnessProblem p = sessionContourRobustnessProblem(circleSession(false));
    ContourRobustnessProblem bad = p;
    bad.geometry.path =
        std::make_shared<const Path>(std::vector<PathSegment>{PathSegment::line({0, 0}, {1, 0})});
    QCOMPARE(field([&] { analyzeContourRobustness(bad); }), std::string("geometry"));
    bad = p;
    bad.geometry.t[3] = bad.geometry.t[2];
    QCOMPARE(field([&] { analyzeContourRobustness(bad); }), std::string("geometry"));
    bad = p;
    bad.y.parameters[0].relative = 1.5;
    QCOMPARE(field([&] { analyzeContourRobustness(bad); }), std::string("y.range.k0"));
    bad = p;
    bad.geometry.circle->rampInSeconds = 1e9;
    QCOMPARE(field([&] { analyzeContourRobustness(bad); }), std::string("geometry"));
}

QTEST_APPLESS_MAIN(TstContourRobustness)
#include "tst_contour_robustness.moc"
