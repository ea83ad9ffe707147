// SPDX-License-Identifier: GPL-3.0-or-later
// Koren's cross-coupled controller on a program's contour run (runProgramContour with
// Session::crossCoupling on): the contour-error estimates against the exact distance, the loops
// advanced sample by sample against the batch runs, the coupling's off switch, the symmetry of
// identical axes on the diagonal, and Braga et al.'s circle of the issue.
#include "core/contour/gcode_reader.h"
#include "core/design/cross_coupling.h"
#include "core/model/errors.h"
#include "core/session/axis_run.h"
#include "core/session/contour_run.h"
#include "core/session/design_method_module.h"
#include "core/session/program_trajectory.h"
#include "core/session/robustness_problem.h"
#include "core/session/session.h"
#include "core/study/contour_robustness.h"
#include "tests/support/reference_data.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace xyt;

namespace {

/// Braga et al.'s check circle: 25 mm, 90 mm/min, counter-clockwise from rest at the origin.
constexpr const char* kPaperCircle = "F90\nG3 X0 Y0 I-25 J0\n";

ContourRunOptions contourOptions(double dt = 0.001) {
    ContourRunOptions o;
    o.profile.maxAccelMmPerS2 = 100.0; // xytune-cli contour --gcode's default
    o.profile.dtSeconds = dt;
    return o;
}

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        m = std::max(m, std::abs(a[k] - b[k]));
    return m;
}

double maxAbs(const std::vector<double>& a) {
    double m = 0.0;
    for (double v : a)
        m = std::max(m, std::abs(v));
    return m;
}

/// Axis @p i of @p session along the program's x (i = 0) or y reference: the batch run and the
/// stepped one with no extra voltage.
std::pair<SimulationResult, SimulationResult> batchAndStepped(const Session& session, int i,
                                                              const FeedProfile& p) {
    const DesignMethodModule& m =
        designMethodModule(session.axes[static_cast<std::size_t>(i)].method);
    const std::vector<double>& r = i == 0 ? p.x : p.y;
    SimulationResult batch = m.tracePath(session, i, p.t, r, p.dtSeconds).run;
    std::unique_ptr<SteppedLoop> loop = m.steppedPath(session, i, p.t, r, p.dtSeconds);
    while (loop->index() < loop->samples())
        loop->advance(0.0);
    return {std::move(batch), loop->takeResult()};
}

FeedProfile paperCircleProfile() {
    const GcodeProgram program = readGcode(kPaperCircle);
    FeedProfileOptions o = contourOptions().profile;
    return planFeedProfile(program.path, programFeeds(program, 1.0), o);
}

} // namespace

class TstCrossCoupledContour : public QObject {
    Q_OBJECT

private slots:
    /// On a straight line the tangent estimate is the exact signed distance (a projection on
    /// the normal): equal to round-off, 1e-12 of the error's size.
    void theLinearEstimateIsExactOnLines() {
        std::mt19937_64 rng(31);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int trial = 0; trial < 200; ++trial) {
            const double theta = 3.2 * u(rng), ex = u(rng), ey = u(rng);
            const double rx = 100.0 * u(rng), ry = 100.0 * u(rng);
            const double s = std::sin(theta), c = std::cos(theta);
            // The table at r - e; its distance right of the line through r along (c, s).
            const double x = rx - ex, y = ry - ey;
            const double rightOfLine = (x - rx) * s - (y - ry) * c;
            QVERIFY(std::abs(linearContourEstimate(ex, ey, theta).value - rightOfLine) <= 1e-12);
            QVERIFY(std::abs(exactContourErrorNearReference(rx, ry, theta, 0.0, x, y) -
                             rightOfLine) <= 1e-12);
        }
    }

    /// On a circle of radius R the exact error is |y - c| - R (counter-clockwise: the table
    /// outside is right of travel). Taylor: the linear estimate misses kappa tau^2 / 2, second
    /// order in |e|; the circular one's residue is third order. Halving e divides the first's
    /// error by 4 and the second's by 8: checked to 5 % and 10 % at |e| = 0.4 .. 0.05 mm on
    /// R = 25 mm (the next terms are |e|/R = 1.6 % smaller).
    void theCircularEstimateIsOneOrderBetterOnCircles() {
        const double radius = 25.0;
        for (const double sign : {1.0, -1.0}) { // counter-clockwise, clockwise
            const double kappa = sign / radius;
            const double theta = 0.7, dir = 2.1; // travel direction; the error's direction
            const double s = std::sin(theta), c = std::cos(theta);
            const double rx = 3.0, ry = -4.0;
            const double cx = rx - s / kappa, cy = ry + c / kappa; // the centre, left for CCW
            std::vector<double> linear, circular;
            for (const double h : {0.4, 0.2, 0.1, 0.05}) {
                const double ex = h * std::cos(dir), ey = h * std::sin(dir);
                const double x = rx - ex, y = ry - ey;
                const double rho = std::hypot(x - cx, y - cy);
                const double exact = sign > 0.0 ? rho - radius : radius - rho;
                QVERIFY(std::abs(exactContourErrorNearReference(rx, ry, theta, kappa, x, y) -
                                 exact) <= 1e-13);
                linear.push_back(linearContourEstimate(ex, ey, theta).value - exact);
                circular.push_back(circularContourEstimate(ex, ey, theta, kappa).value - exact);
            }
            for (std::size_t i = 0; i + 1 < linear.size(); ++i) {
                QVERIFY2(std::abs(linear[i] / linear[i + 1] / 4.0 - 1.0) < 0.05,
                         qPrintable(QString::number(linear[i] / linear[i + 1])));
                QVERIFY2(std::abs(circular[i] / circular[i + 1] / 8.0 - 1.0) < 0.1,
                         qPrintable(QString::number(circular[i] / circular[i + 1])));
            }
        }
    }

    /// The coupling gains are the estimate's gradient: checked by central differences (step
    /// 1e-6 mm: truncation 1e-12, round-off 1e-10 relative).
    void theCouplingGainsAreTheEstimatesGradient() {
        const double theta = -2.3, kappa = -0.04, ex = 0.3, ey = -0.2, h = 1e-6;
        const ContourEstimate e = circularContourEstimate(ex, ey, theta, kappa);
        const double dx = (circularContourEstimate(ex + h, ey, theta, kappa).value -
                           circularContourEstimate(ex - h, ey, theta, kappa).value) /
                          (2 * h);
        const double dy = (circularContourEstimate(ex, ey + h, theta, kappa).value -
                           circularContourEstimate(ex, ey - h, theta, kappa).value) /
                          (2 * h);
        QVERIFY(std::abs(e.gainX - dx) < 1e-8);
        QVERIFY(std::abs(e.gainY - dy) < 1e-8);
        const ContourEstimate l = linearContourEstimate(ex, ey, theta);
        QCOMPARE(l.gainX, -std::sin(theta));
        QCOMPARE(l.gainY, std::cos(theta));
    }

    /// Each method's loop advanced sample by sample with no coupling voltage is its batch run:
    /// the table with friction and the pole-placement loop are the same arithmetic (bit for bit);
    /// the linear continuous loop carries the command's input column always and forms the
    /// products in another order (round-off: 1e-12 of the largest output).
    void theSteppedLoopsAreTheBatchRuns() {
        const FeedProfile p = paperCircleProfile();
        Session s = Session::paperDefault();
        for (int i = 0; i < 2; ++i) {
            const auto [batch, stepped] = batchAndStepped(s, i, p);
            QCOMPARE(stepped.y.size(), batch.y.size());
            QVERIFY(maxAbsDifference(stepped.y, batch.y) <= 1e-12 * maxAbs(batch.y));
            QVERIFY(maxAbsDifference(stepped.u, batch.u) <= 1e-12 * (1.0 + maxAbs(batch.u)));
        }
        s.axes[0].friction.coulombVolts = 0.05;
        s.axes[1].friction.backlashMm = 0.01;
        for (int i = 0; i < 2; ++i) {
            const auto [batch, stepped] = batchAndStepped(s, i, p);
            QVERIFY(stepped.y == batch.y);
            QVERIFY(stepped.u == batch.u);
            QVERIFY(stepped.sliding == batch.sliding);
        }
        Session pp = Session::paperDefault();
        for (AxisSettings& a : pp.axes)
            a.method = DesignMethod::PolePlacementZpetc;
        for (const bool zpetc : {true, false}) {
            for (AxisSettings& a : pp.axes)
                a.pp.zpetcEnabled = zpetc;
            for (int i = 0; i < 2; ++i) {
                const auto [batch, stepped] = batchAndStepped(pp, i, p);
                QVERIFY(stepped.t == batch.t);
                QVERIFY(stepped.y == batch.y);
                QVERIFY(stepped.u == batch.u);
                QVERIFY(stepped.clipped == batch.clipped);
            }
        }
        Session pid = Session::paperDefault();
        for (AxisSettings& a : pid.axes)
            a.method = DesignMethod::PidFeedforward;
        for (int i = 0; i < 2; ++i) {
            const auto [batch, stepped] = batchAndStepped(pid, i, p);
            QVERIFY(maxAbsDifference(stepped.y, batch.y) <= 1e-12 * maxAbs(batch.y));
        }
    }

    /// Gains at zero switch the coupling off: the run is the uncoupled one bit for bit, with no
    /// coupling signals and no comparison run.
    void zeroGainsAreTheUncoupledRunBitForBit() {
        const GcodeProgram program = readGcode(kPaperCircle);
        Session off = Session::paperDefault();
        off.crossCoupling.estimate = ContourEstimateKind::Linear;
        const ContourRun a = runProgramContour(Session::paperDefault(), program, contourOptions());
        const ContourRun b = runProgramContour(off, program, contourOptions());
        QVERIFY(a.trace.x == b.trace.x);
        QVERIFY(a.trace.y == b.trace.y);
        QVERIFY(a.contour.error == b.contour.error);
        QVERIFY(!b.trace.coupling && !b.independent);
    }

    /// Identical axes along the 45-degree diagonal: both errors are equal at every sample, so
    /// the contour error is zero by symmetry and so is the estimate, up to sin(pi/4) and
    /// cos(pi/4) differing in their last bit (1e-16 of the axis error, a few mm): the coupling
    /// changes neither the trace nor the contour error beyond 1e-9 mm.
    void identicalAxesOnTheDiagonalAreUnchanged() {
        Session s = Session::paperDefault();
        s.axes[1].gt = s.axes[0].gt;
        const GcodeProgram program = readGcode("G1 X100 Y100 F600\n");
        const ContourRun plain = runProgramContour(s, program, contourOptions(0.01));
        s.crossCoupling.kp = 1.0;
        s.crossCoupling.ki = 1.0;
        const ContourRun coupled = runProgramContour(s, program, contourOptions(0.01));
        QVERIFY(coupled.trace.coupling.has_value());
        QVERIFY(plain.trace.x == plain.trace.y);      // the symmetry itself
        QVERIFY(maxAbs(plain.trace.axes[0].e) > 1.0); // the axes lag by millimetres
        QVERIFY(maxAbsDifference(coupled.trace.x, plain.trace.x) <= 1e-9);
        QVERIFY(maxAbsDifference(coupled.trace.y, plain.trace.y) <= 1e-9);
        QVERIFY(coupled.contour.maxAbs <= plain.contour.maxAbs + 1e-9);
        QVERIFY(plain.contour.maxAbs <= 1e-12);
    }

    /// Braga et al.'s bases as X and Y under the paper's designs on the 25 mm circle at 90 mm/min
    /// from rest on the path: 0.523 mm of contour error with the axes independent (the issue's
    /// figure), at most half of it with the coupling at the same axis gains (kp 0.1 V/mm: 0.124
    /// mm; a PI, kp 0.1 and ki 1 V/(mm s): 0.0012 mm). The comparison run beside the coupled one
    /// is the independent run.
    void thePaperCircleHalvesItsContourError() {
        const GcodeProgram program = readGcode(kPaperCircle);
        const ContourRun plain =
            runProgramContour(Session::paperDefault(), program, contourOptions());
        QVERIFY2(std::abs(plain.contour.maxAbs - 0.523) < 0.001,
                 qPrintable(QString::number(plain.contour.maxAbs)));
        for (const auto estimate : {ContourEstimateKind::Linear, ContourEstimateKind::Circular})
            for (const auto [kp, ki] : {std::pair{0.1, 0.0}, std::pair{0.1, 1.0}}) {
                Session s = Session::paperDefault();
                s.crossCoupling = {kp, ki, estimate};
                const ContourRun coupled = runProgramContour(s, program, contourOptions());
                qInfo("kp %g ki %g %s: %.4g mm (independent axes %.4g mm)", kp, ki,
                      contourEstimateName(estimate), coupled.contour.maxAbs,
                      coupled.independent->contour.maxAbs);
                QVERIFY(coupled.contour.maxAbs <= 0.5 * plain.contour.maxAbs);
                QVERIFY(coupled.independent->contour.error == plain.contour.error);
                QVERIFY(coupled.circular && coupled.independent->iso);
                QCOMPARE(coupled.independent->iso->circularDeviationG,
                         plain.circular->iso.circularDeviationG);
            }
    }

    /// The same run simulated independently in SciPy (tests/data/gen_cross_coupling.py: each
    /// axis' closed loop discretized with scipy.linalg.expm, the law written again in Python):
    /// max and RMS contour error of every case to 1e-8 relative. Both are exact discretizations
    /// of one linear system; a one-ulp change of the step matrices moves these figures by 9e-11
    /// (the loops' slow poles at 1 - 7e-6 amplify it), so 1e-8 leaves a margin of 100.
    void thePaperCircleAgreesWithAnIndependentSimulation() {
        const test::CsvTable table = test::readCsv("cross_coupling_circle.csv");
        QCOMPARE(table.rows.size(), std::size_t{5});
        const GcodeProgram program = readGcode(kPaperCircle);
        for (std::size_t row = 0; row < table.rows.size(); ++row) {
            Session s = Session::paperDefault();
            const QString estimate = table.rows[row].at(table.column("estimate"));
            s.crossCoupling.kp = table.number(row, "kp");
            s.crossCoupling.ki = table.number(row, "ki");
            s.crossCoupling.estimate =
                estimate == "linear" ? ContourEstimateKind::Linear : ContourEstimateKind::Circular;
            ContourRunOptions o = contourOptions();
            o.compareIndependentAxes = false;
            const ContourRun run = runProgramContour(s, program, o);
            QCOMPARE(run.trace.coupling.has_value(), estimate != "none");
            const double max = table.number(row, "max_contour_error_mm");
            const double rms = table.number(row, "rms_contour_error_mm");
            QVERIFY2(
                std::abs(run.contour.maxAbs - max) <= 1e-8 * max,
                qPrintable(QString("%1: %2 vs %3").arg(estimate).arg(run.contour.maxAbs).arg(max)));
            QVERIFY2(
                std::abs(run.contour.rms - rms) <= 1e-8 * rms,
                qPrintable(QString("%1: %2 vs %3").arg(estimate).arg(run.contour.rms).arg(rms)));
        }
    }

    /// The robustness analysis of the contour runs every pair of plants cross-coupled: its
    /// nominal pair is the session's coupled contour run (the same runs on the same time base:
    /// equal to the bit), and a drawn pair moves it.
    void theContourRobustnessRunsCoupled() {
        Session s = Session::paperDefault();
        s.trajectory.kind = TrajectoryKind::Gcode;
        s.trajectory.gcode.program = kPaperCircle;
        s.trajectory.gcode.maxAccelMmPerS2 = 100.0;
        s.crossCoupling = {0.1, 1.0, ContourEstimateKind::Circular};
        ContourRobustnessProblem problem = sessionContourRobustnessProblem(s);
        QVERIFY(problem.coupling.has_value());
        RobustnessOptions options;
        options.samples = 0;
        options.corners = false;
        const ContourRobustnessResult coupled = analyzeContourRobustness(problem, options);
        ContourRunOptions runOptions = programRunOptions(s.trajectory);
        runOptions.compareIndependentAxes = false;
        const ContourRun run = runProgramContour(s, readGcode(kPaperCircle), runOptions);
        QCOMPARE(coupled.nominal.maxAbsContourError, run.contour.maxAbs);
        QCOMPARE(coupled.nominal.rmsContourError, run.contour.rms);
        problem.coupling.reset();
        const ContourRobustnessResult alone = analyzeContourRobustness(problem, options);
        QVERIFY(coupled.nominal.maxAbsContourError < 0.5 * alone.nominal.maxAbsContourError);
        // A plant 10 % slower on x: the pair still runs coupled and its error differs.
        problem = sessionContourRobustnessProblem(s);
        for (UncertainParameter& q : problem.x.parameters)
            if (q.name == "k0")
                q.relative = 0.1;
        options.corners = true;
        const ContourRobustnessResult drawn = analyzeContourRobustness(problem, options);
        QCOMPARE(drawn.runs.size(), std::size_t{2});
        for (const JointPlantRun& r : drawn.runs) {
            QVERIFY(r.stable && r.finite);
            QVERIFY(r.maxAbsContourError != coupled.nominal.maxAbsContourError);
        }
    }

    /// The comparison runs beside a coupled one: the independent axes (the session's design)
    /// and, for axes with a feedforward, the feedback alone: each is runProgramContour of that
    /// session uncoupled, bit for bit. The paper's PIs have no feedforward: no second run.
    void theComparisonRunsAreTheirSessionsRuns() {
        const GcodeProgram program = readGcode("F300\nG2 X0 Y0 I0 J15\n");
        Session pp = Session::paperDefault();
        for (AxisSettings& a : pp.axes)
            a.method = DesignMethod::PolePlacementZpetc;
        pp.crossCoupling = {3.0, 1.0, ContourEstimateKind::Circular};
        const ContourRun coupled = runProgramContour(pp, program, contourOptions(0.01));
        QVERIFY(coupled.independent && coupled.feedbackOnly);
        Session alone = pp;
        alone.crossCoupling = {};
        const ContourRun design = runProgramContour(alone, program, contourOptions(0.01));
        QVERIFY(coupled.independent->contour.error == design.contour.error);
        for (AxisSettings& a : alone.axes)
            a.pp.zpetcEnabled = false;
        const ContourRun feedback = runProgramContour(alone, program, contourOptions(0.01));
        QVERIFY(coupled.feedbackOnly->contour.error == feedback.contour.error);
        QCOMPARE(coupled.feedbackOnly->iso->circularDeviationG,
                 feedback.circular->iso.circularDeviationG);
        // The ZPETC already tracks: the feedback alone is far worse, the coupling no worse.
        QVERIFY(feedback.contour.maxAbs > 10.0 * design.contour.maxAbs);
        qInfo("pole placement on a 15 mm circle at F300: feedback alone %.4g mm, ZPETC %.4g mm, "
              "ZPETC and coupling %.4g mm",
              feedback.contour.maxAbs, design.contour.maxAbs, coupled.contour.maxAbs);
        Session gt = Session::paperDefault();
        gt.crossCoupling = {0.1, 0.0, ContourEstimateKind::Circular};
        QVERIFY(!runProgramContour(gt, program, contourOptions(0.01)).feedbackOnly);
    }

    /// Refusals name the field: a negative or non-finite gain, and axes at two periods.
    void badCouplingsAreRefusedByName() {
        const GcodeProgram program = readGcode(kPaperCircle);
        Session s = Session::paperDefault();
        s.crossCoupling.kp = -1.0;
        try {
            runProgramContour(s, program, contourOptions());
            QFAIL("a negative gain ran");
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), QStringLiteral("cross_coupling.kp"));
        }
        s.crossCoupling.kp = 0.1;
        s.crossCoupling.ki = std::nan("");
        try {
            runProgramContour(s, program, contourOptions());
            QFAIL("a NaN gain ran");
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), QStringLiteral("cross_coupling.ki"));
        }
        s.crossCoupling.ki = 0.0;
        s.axes[1].method = DesignMethod::PolePlacementZpetc; // at 70 ms beside 1 ms
        try {
            runProgramContour(s, program, contourOptions());
            QFAIL("axes at two periods ran coupled");
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), QStringLiteral("cross_coupling"));
            QVERIFY(QString::fromStdString(e.reason()).contains("0.07 s"));
        }
    }
};

QTEST_GUILESS_MAIN(TstCrossCoupledContour)
#include "tst_cross_coupled_contour.moc"
