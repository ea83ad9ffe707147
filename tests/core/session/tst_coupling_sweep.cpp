// SPDX-License-Identifier: GPL-3.0-or-later
// The sweep of the cross-coupling's gains over the contour error (core/session/coupling_sweep.h):
// every cell is the contour run of its gains run alone, bit for bit (runProgramContour,
// runCoupledTrajectory); (0, 0) is the uncoupled run; a line where the coupled loop is unstable
// refuses its cell naming the line, as the run alone does; the rule of the best cell on cells
// built by hand; a cancelled sweep stops and says so; one and two threads give the same cells;
// bad grids are refused by name.
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/coupling_sweep.h"
#include "core/session/program_trajectory.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"

#include <QFile>
#include <QTest>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

using namespace xyt;

namespace {

/// Braga et al.'s check circle: 25 mm, 90 mm/min, counter-clockwise from rest at the origin.
constexpr const char* kPaperCircle = "F90\nG3 X0 Y0 I-25 J0\n";

std::string example(const char* name) {
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/resources/examples/") + QLatin1String(name));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll().toStdString();
}

/// xytune-cli contour --gcode's options: --max-accel 100, dt 1 ms.
ContourRunOptions cliOptions() {
    ContourRunOptions o;
    o.profile.maxAccelMmPerS2 = 100.0;
    o.profile.dtSeconds = 0.001;
    return o;
}

Session withGains(Session s, const CrossCoupling& c) {
    s.crossCoupling = c;
    return s;
}

/// Equal bit for bit (NaN equal to the same NaN): what "the same code into its own slot" gives.
bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool sameCell(const CouplingSweepCell& a, const CouplingSweepCell& b) {
    return a.coupling == b.coupling && a.status == b.status && a.message == b.message &&
           sameBits(a.maxAbsMm, b.maxAbsMm) && sameBits(a.rmsMm, b.rmsMm) &&
           sameBits(a.spectralRadius, b.spectralRadius) && sameBits(a.diskMargin, b.diskMargin) &&
           a.warning == b.warning && a.saturated == b.saturated;
}

bool anyClipped(const SimulationResult& r) {
    return std::find(r.clipped.begin(), r.clipped.end(), true) != r.clipped.end();
}

/// A hand-made Ok cell for the rule of the best.
CouplingSweepCell okCell(double maxAbs, double rms, bool saturated = false,
                         const std::string& warning = "") {
    CouplingSweepCell c;
    c.status = CouplingCellStatus::Ok;
    c.maxAbsMm = maxAbs;
    c.rmsMm = rms;
    c.saturated = saturated;
    c.warning = warning;
    return c;
}

} // namespace

class TstCouplingSweep : public QObject {
    Q_OBJECT

private slots:
    /// Source: the run alone. Each cell of a program's sweep holds the figures of
    /// runProgramContour with that cell's gains (bit for bit: the same code on the same
    /// profile); its loop is that run's CouplingStability::worst, its saturation the runs'
    /// clipped flags. The square's kp 3 is refused on its lines (see the next test), kp 0.3
    /// saturates (xytune-cli contour --ccc-sweep on the example).
    void eachProgramCellIsItsRunAlone() {
        const Session session = Session::paperDefault();
        const GcodeProgram program = readGcode(example("square_sharp_corners.nc"));
        const ContourRunOptions options = cliOptions();
        const CouplingSweepGrid grid{{0.0, 0.1, 0.3, 3.0}, {0.0, 0.1}};
        const CouplingSweepResult sweep = sweepProgramCoupling(session, program, options, grid);
        QCOMPARE(sweep.cells.size(), std::size_t(8));
        QVERIFY(!sweep.cancelled);
        QCOMPARE(sweep.cellsRun, std::size_t(8));
        bool sawSaturated = false, sawUnstable = false;
        for (std::size_t i = 0; i < grid.kpVoltsPerMm.size(); ++i)
            for (std::size_t j = 0; j < grid.kiVoltsPerMmSecond.size(); ++j) {
                const CouplingSweepCell& cell = sweep.cell(i, j);
                const CrossCoupling gains{grid.kpVoltsPerMm[i], grid.kiVoltsPerMmSecond[j],
                                          session.crossCoupling.estimate};
                QCOMPARE(cell.coupling, gains);
                try {
                    const ContourRun alone =
                        runProgramContour(withGains(session, gains), program, options);
                    QCOMPARE(cell.status, CouplingCellStatus::Ok);
                    QVERIFY(sameBits(cell.maxAbsMm, alone.contour.maxAbs));
                    QVERIFY(sameBits(cell.rmsMm, alone.contour.rms));
                    QCOMPARE(cell.saturated,
                             anyClipped(alone.trace.axes[0]) || anyClipped(alone.trace.axes[1]));
                    sawSaturated = sawSaturated || cell.saturated;
                    if (gains.active()) {
                        QVERIFY(alone.couplingStability.has_value());
                        QVERIFY(sameBits(cell.spectralRadius,
                                         alone.couplingStability->worst.spectralRadius));
                        QVERIFY(
                            sameBits(cell.diskMargin, alone.couplingStability->worst.diskMargin));
                        QCOMPARE(cell.warning, alone.couplingStability->warning);
                    } else {
                        QVERIFY(std::isnan(cell.spectralRadius)); // no coupled loop
                    }
                } catch (const InvalidInput& e) {
                    QCOMPARE(cell.status, CouplingCellStatus::Unstable);
                    QCOMPARE(cell.message.text, std::string(e.what()));
                    sawUnstable = true;
                }
            }
        QVERIFY(sawSaturated);
        QVERIFY(sawUnstable);
    }

    /// Source: the uncoupled run. Gains 0 and 0 switch the coupling off (CrossCoupling), so the
    /// (0, 0) cell and the independent axes' figure are runProgramContour with the coupling off,
    /// and the independent runs of a coupled run (ContourRun::independent) are the same.
    void zeroGainsAreTheUncoupledRun() {
        const Session session = Session::paperDefault();
        const GcodeProgram program = readGcode(kPaperCircle);
        const ContourRunOptions options = cliOptions();
        const CouplingSweepResult sweep =
            sweepProgramCoupling(session, program, options, {{0.0, 0.1}, {0.0, 1.0}});
        const ContourRun off = runProgramContour(session, program, options);
        QVERIFY(!off.couplingStability.has_value());
        for (const CouplingSweepCell* cell : {&sweep.cell(0, 0), &sweep.independent}) {
            QCOMPARE(cell->status, CouplingCellStatus::Ok);
            QVERIFY(sameBits(cell->maxAbsMm, off.contour.maxAbs));
            QVERIFY(sameBits(cell->rmsMm, off.contour.rms));
        }
        QVERIFY(sameCell(sweep.cell(0, 0), sweep.independent));
        const ContourRun coupled =
            runProgramContour(withGains(session, {0.1, 1.0}), program, options);
        QVERIFY(coupled.independent.has_value());
        QVERIFY(sameBits(sweep.independent.maxAbsMm, coupled.independent->contour.maxAbs));
        // The figures of the issue (xytune-cli contour on the paper circle): 0.523 mm uncoupled,
        // 0.0012 mm with kp 0.1 and ki 1.
        QVERIFY(std::abs(sweep.independent.maxAbsMm - 0.523) < 0.0005);
        QVERIFY(std::abs(sweep.cell(1, 1).maxAbsMm - 0.00124) < 0.00001);
        // Source: the rule. kp 0.1, ki 1 is the grid's only cell below 0.1 mm.
        QCOMPARE(sweep.best, std::optional<std::size_t>(sweep.cellIndex(1, 1)));
        QCOMPARE(sweep.bestBasis, CouplingBestBasis::Robust);
    }

    /// Source: checkCouplingStability's refusal. kp 3 with the paper's PIs is unstable on the
    /// square's lines; the cell is refused with the run's own message, which names the line.
    void anUnstableCellIsRefusedNamingTheLine() {
        const Session session = Session::paperDefault();
        const GcodeProgram program = readGcode(example("square_sharp_corners.nc"));
        const CouplingSweepResult sweep =
            sweepProgramCoupling(session, program, cliOptions(), {{3.0}, {0.0}});
        const CouplingSweepCell& cell = sweep.cell(0, 0);
        QCOMPARE(cell.status, CouplingCellStatus::Unstable);
        QVERIFY2(cell.message.text.rfind(
                     "cross_coupling: the coupled loop is unstable on program line ", 0) == 0,
                 cell.message.text.c_str());
        QVERIFY(std::isnan(cell.maxAbsMm));
        QVERIFY(!sweep.best.has_value()); // no Ok cell: no best (the independent is not a cell)
        QCOMPARE(sweep.independent.status, CouplingCellStatus::Ok);
    }

    /// Source: the run alone. The session's circle (not a program): each cell is
    /// runCoupledTrajectory on the evaluated axes' references, the (0, 0) cell its independent
    /// half (identical in every coupled run).
    void eachTrajectoryCellIsItsRunAlone() {
        Session session = Session::paperDefault();
        session.trajectory.kind = TrajectoryKind::Circle;
        const SessionEvaluation ev = evaluateSession(session);
        QVERIFY(ev.axes[0].ok && ev.axes[1].ok);
        const CouplingSweepGrid grid{{0.0, 0.1, 1.0}, {0.0, 1.0}};
        const CouplingSweepResult sweep = sweepSessionCoupling(session, ev, grid);
        for (std::size_t i = 0; i < grid.kpVoltsPerMm.size(); ++i)
            for (std::size_t j = 0; j < grid.kiVoltsPerMmSecond.size(); ++j) {
                const CouplingSweepCell& cell = sweep.cell(i, j);
                const CrossCoupling gains{grid.kpVoltsPerMm[i], grid.kiVoltsPerMmSecond[j],
                                          session.crossCoupling.estimate};
                if (!gains.active())
                    continue;
                const CoupledTrajectoryRun alone =
                    runCoupledTrajectory(withGains(session, gains), ev.axes[0].run, ev.axes[1].run);
                QCOMPARE(cell.status, CouplingCellStatus::Ok);
                QVERIFY(sameBits(cell.maxAbsMm, alone.coupledError.maxAbs));
                QVERIFY(sameBits(cell.rmsMm, alone.coupledError.rms));
                QVERIFY(sameBits(cell.spectralRadius, alone.stability.worst.spectralRadius));
                QVERIFY(sameBits(cell.diskMargin, alone.stability.worst.diskMargin));
                QCOMPARE(cell.saturated,
                         anyClipped(alone.coupled[0]) || anyClipped(alone.coupled[1]));
                QVERIFY(sameBits(sweep.cell(0, 0).maxAbsMm, alone.independentError.maxAbs));
                QVERIFY(sameBits(sweep.cell(0, 0).rmsMm, alone.independentError.rms));
            }
        // The point-to-point move (the diagonal): kp 100 is refused on "the move", named.
        Session move = Session::paperDefault();
        const SessionEvaluation evMove = evaluateSession(move);
        const CouplingSweepResult moveSweep =
            sweepSessionCoupling(move, evMove, {{0.1, 100.0}, {0.0}});
        QCOMPARE(moveSweep.cell(0, 0).status, CouplingCellStatus::Ok);
        QCOMPARE(moveSweep.cell(1, 0).status, CouplingCellStatus::Unstable);
        QVERIFY2(moveSweep.cell(1, 0).message.text.find("unstable on the move") !=
                     std::string::npos,
                 moveSweep.cell(1, 0).message.text.c_str());
        // The session's evaluation with the coupling on shows the same figures.
        Session coupled = withGains(session, {0.1, 1.0, session.crossCoupling.estimate});
        const SessionEvaluation evCoupled = evaluateSession(coupled);
        QVERIFY(evCoupled.coupledTrajectory != nullptr);
        QVERIFY(
            sameBits(sweep.cell(1, 1).maxAbsMm, evCoupled.coupledTrajectory->coupledError.maxAbs));
    }

    /// Source: runSessionProgram. A G-code session's sweep runs its program as the evaluation
    /// does (its options, its shared profile): the cell of the session's gains is the
    /// evaluation's contour run.
    void aProgramSessionIsSweptAsItIsEvaluated() {
        Session session = Session::paperDefault();
        session.trajectory.kind = TrajectoryKind::Gcode;
        session.trajectory.gcode.program = ProgramText(kPaperCircle);
        session.trajectory.dtSeconds = 0.01;
        session.crossCoupling = {0.1, 1.0, ContourEstimateKind::Circular};
        const SessionEvaluation ev = evaluateSession(session);
        QVERIFY2(ev.program != nullptr, ev.programError.text.c_str());
        const CouplingSweepResult sweep = sweepSessionCoupling(session, ev, {{0.0, 0.1}, {1.0}});
        QCOMPARE(sweep.cell(1, 0).status, CouplingCellStatus::Ok);
        QVERIFY(sameBits(sweep.cell(1, 0).maxAbsMm, ev.program->contour.maxAbs));
        QVERIFY(ev.program->independent.has_value());
        QVERIFY(sameBits(sweep.independent.maxAbsMm, ev.program->independent->contour.maxAbs));
    }

    /// Source: kBestCouplingRule on cells built by hand.
    void theBestFollowsItsRule() {
        CouplingBestBasis basis = CouplingBestBasis::Saturating;
        // The smallest error inside the limit with the loop stable everywhere, not the smallest.
        std::vector<CouplingSweepCell> cells{okCell(1.0, 0.5), okCell(0.1, 0.1, true),
                                             okCell(0.2, 0.1, false, "frozen loop unstable"),
                                             okCell(0.5, 0.2)};
        QCOMPARE(bestCouplingCell(cells, basis), std::optional<std::size_t>(3));
        QCOMPARE(basis, CouplingBestBasis::Robust);
        // Refused and failed cells never count, whatever their figures.
        cells.push_back(okCell(0.01, 0.01));
        cells.back().status = CouplingCellStatus::Failed;
        QCOMPARE(bestCouplingCell(cells, basis), std::optional<std::size_t>(3));
        // Ties: the smaller RMS, then the first in grid order.
        cells = {okCell(0.5, 0.3), okCell(0.5, 0.2), okCell(0.5, 0.2)};
        QCOMPARE(bestCouplingCell(cells, basis), std::optional<std::size_t>(1));
        // No robust cell: the best inside the limit, said so.
        cells = {okCell(0.1, 0.1, true), okCell(0.3, 0.1, false, "w"),
                 okCell(0.2, 0.1, false, "w")};
        QCOMPARE(bestCouplingCell(cells, basis), std::optional<std::size_t>(2));
        QCOMPARE(basis, CouplingBestBasis::WithinLimit);
        // Every cell saturates: the best among them, said so.
        cells = {okCell(0.3, 0.1, true), okCell(0.2, 0.1, true, "w")};
        QCOMPARE(bestCouplingCell(cells, basis), std::optional<std::size_t>(1));
        QCOMPARE(basis, CouplingBestBasis::Saturating);
        // None ran.
        cells = {CouplingSweepCell{}};
        QVERIFY(!bestCouplingCell(cells, basis).has_value());
    }

    /// Source: CouplingSweepOptions::progress. Cancelling at the first report (after the
    /// independent axes) runs no cell: the result says cancelled, holds the independent figure
    /// and the (0, 0) cell it gives, and the others stay NotRun. A later cancel keeps what ran.
    void cancelStopsEarlyAndSaysSo() {
        const Session session = Session::paperDefault();
        const GcodeProgram program = readGcode(example("square_sharp_corners.nc"));
        CouplingSweepOptions options;
        options.threads = 1;
        int reports = 0;
        options.progress = [&](double fraction) {
            ++reports;
            return !(fraction > 0.0); // cancels at the first report
        };
        const CouplingSweepGrid grid = defaultCouplingSweepGrid();
        const CouplingSweepResult sweep =
            sweepProgramCoupling(session, program, cliOptions(), grid, options);
        QVERIFY(sweep.cancelled);
        QCOMPARE(reports, 1);
        QCOMPARE(sweep.cellsRun, std::size_t(1)); // (0, 0): the independent run itself
        QCOMPARE(sweep.cell(0, 0).status, CouplingCellStatus::Ok);
        QCOMPARE(sweep.cell(0, 1).status, CouplingCellStatus::NotRun);
        QCOMPARE(sweep.best, std::optional<std::size_t>(0));

        // Cancelled once some cells ran (the reports come every 20 ms on the calling thread, a
        // cell takes about as long): fewer than all, each one as in a full sweep.
        options.progress = [](double fraction) { return fraction < 0.2; };
        const CouplingSweepResult partial =
            sweepProgramCoupling(session, program, cliOptions(), grid, options);
        QVERIFY(partial.cancelled);
        QVERIFY(partial.cellsRun < partial.cells.size());
        const CouplingSweepResult full = sweepProgramCoupling(session, program, cliOptions(), grid);
        for (std::size_t i = 0; i < partial.cells.size(); ++i)
            if (partial.cells[i].status != CouplingCellStatus::NotRun)
                QVERIFY(sameCell(partial.cells[i], full.cells[i]));
    }

    /// Source: parallelRuns' contract (each item by the same code into its own slot). One and
    /// two threads give the same cells, bit for bit, and the same best.
    void threadCountsGiveIdenticalResults() {
        const Session session = Session::paperDefault();
        const GcodeProgram program = readGcode(example("star.nc"));
        const CouplingSweepGrid grid{{0.0, 0.03, 0.1, 3.0}, {0.0, 0.1, 1.0}};
        CouplingSweepOptions one, two;
        one.threads = 1;
        two.threads = 2;
        const CouplingSweepResult a =
            sweepProgramCoupling(session, program, cliOptions(), grid, one);
        const CouplingSweepResult b =
            sweepProgramCoupling(session, program, cliOptions(), grid, two);
        QCOMPARE(a.threadsUsed, 1);
        QCOMPARE(b.threadsUsed, 2);
        QCOMPARE(a.cells.size(), b.cells.size());
        for (std::size_t i = 0; i < a.cells.size(); ++i)
            QVERIFY2(sameCell(a.cells[i], b.cells[i]), qPrintable(QString::number(i)));
        QVERIFY(sameCell(a.independent, b.independent));
        QCOMPARE(a.best, b.best);
        QCOMPARE(a.bestBasis, b.bestBasis);
    }

    /// Source: normalizedCouplingSweepGrid's contract. Each refusal names its list; the pairs
    /// are counted after repeated values are dropped; the lists come back ascending.
    void badGridsAreRefusedByName_data() {
        QTest::addColumn<std::vector<double>>("kp");
        QTest::addColumn<std::vector<double>>("ki");
        QTest::addColumn<QString>("field");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        std::vector<double> twenty(20), twentyOne(21);
        std::iota(twenty.begin(), twenty.end(), 0.0);
        std::iota(twentyOne.begin(), twentyOne.end(), 0.0);
        QTest::newRow("kp empty") << std::vector<double>{} << std::vector<double>{0.0} << "kp";
        QTest::newRow("ki empty") << std::vector<double>{0.0} << std::vector<double>{} << "ki";
        QTest::newRow("kp negative")
            << std::vector<double>{0.1, -0.1} << std::vector<double>{0.0} << "kp";
        QTest::newRow("kp nan") << std::vector<double>{nan} << std::vector<double>{0.0} << "kp";
        QTest::newRow("ki inf") << std::vector<double>{0.0} << std::vector<double>{inf} << "ki";
        QTest::newRow("ki negative zero is zero, -1 is not")
            << std::vector<double>{0.0} << std::vector<double>{-0.0, -1.0} << "ki";
        QTest::newRow("21 x 20 pairs") << twentyOne << twenty << "grid";
    }
    void badGridsAreRefusedByName() {
        QFETCH(std::vector<double>, kp);
        QFETCH(std::vector<double>, ki);
        QFETCH(QString, field);
        try {
            normalizedCouplingSweepGrid({kp, ki});
            QFAIL("not refused");
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), field);
        }
        // The sweeps refuse it before they run anything.
        const Session session = Session::paperDefault();
        QVERIFY_THROWS_EXCEPTION(
            InvalidInput,
            sweepProgramCoupling(session, readGcode(kPaperCircle), cliOptions(), {kp, ki}));
    }

    /// Source: normalizedCouplingSweepGrid's contract: ascending, repeats dropped; 20 x 20 is
    /// the largest square grid allowed (400 pairs).
    void gridsAreNormalized() {
        const CouplingSweepGrid g = normalizedCouplingSweepGrid({{1.0, 0.1, 1.0, 0.0}, {3.0, 0.0}});
        QCOMPARE(g.kpVoltsPerMm, (std::vector<double>{0.0, 0.1, 1.0}));
        QCOMPARE(g.kiVoltsPerMmSecond, (std::vector<double>{0.0, 3.0}));
        QVERIFY(twentyByTwentyIsAllowed());
        const CouplingSweepGrid d = defaultCouplingSweepGrid();
        QCOMPARE(normalizedCouplingSweepGrid(d), d); // the default is normal already
        QCOMPARE(d.kpVoltsPerMm.size() * d.kiVoltsPerMmSecond.size(), std::size_t(30));
    }

    /// Source: sameCouplingSweepInputs' contract. The swept gains and the snapshots do not make
    /// a sweep stale; anything a run reads (the limit, an axis, the trajectory, the estimate,
    /// the in-position window that sets an automatic move's length) does.
    void whatMakesASweepStale() {
        const Session a = Session::paperDefault();
        Session b = a;
        b.crossCoupling.kp = 0.3;
        b.crossCoupling.ki = 1.0;
        b.snapshots.push_back(a.snapshot("kept"));
        QVERIFY(sameCouplingSweepInputs(a, b));
        for (int change = 0; change < 5; ++change) {
            Session c = a;
            if (change == 0)
                c.umaxVolts = 5.0;
            else if (change == 1)
                c.axes[1].gt.kp = 31.0;
            else if (change == 2)
                c.trajectory.kind = TrajectoryKind::Circle;
            else if (change == 3)
                c.crossCoupling.estimate = ContourEstimateKind::Linear;
            else
                c.spec.inPositionWindowMm *= 2.0;
            QVERIFY2(!sameCouplingSweepInputs(a, c), qPrintable(QString::number(change)));
        }
    }

private:
    /// 20 x 20 = 400 pairs is allowed (kMaxCouplingSweepCells).
    static bool twentyByTwentyIsAllowed() {
        std::vector<double> twenty;
        for (int i = 0; i < 20; ++i)
            twenty.push_back(0.1 * i);
        try {
            return normalizedCouplingSweepGrid({twenty, twenty}).kpVoltsPerMm.size() == 20;
        } catch (const InvalidInput&) {
            return false;
        }
    }
};

QTEST_APPLESS_MAIN(TstCouplingSweep)
#include "tst_coupling_sweep.moc"
