// SPDX-License-Identifier: GPL-3.0-or-later
// A G-code program as a session's trajectory (issue 13): its run time, its references, the
// session paths its refusals name, and its evaluation. The expected times and positions are the
// closed form of a trapezoidal move along a straight line (accelerate at a to v = F, cruise,
// decelerate: t = L / v + v / a when L >= v^2 / a).
#include "core/model/errors.h"
#include "core/session/export_text.h"
#include "core/session/program_trajectory.h"
#include "core/session/session_evaluation.h"
#include "tests/support/tolerance.h"

#include <QTest>

using namespace xyt;

class TstProgramTrajectory : public QObject {
    Q_OBJECT
private slots:
    void runTimeIsTheTrapezoidsClosedForm();
    void referencesFollowTheProfile();
    void refusalsNameTheSessionPath_data();
    void refusalsNameTheSessionPath();
    void evaluationRunsBothAxesAlongTheProgram();
    void octaveExportRefusesAProgram();
};

namespace {

/// A 10 mm move along x at F600 (10 mm/s) with 100 mm/s^2: 0.1 s up, 0.9 s cruise, 0.1 s down.
TrajectorySettings straightMove() {
    TrajectorySettings t;
    t.kind = TrajectoryKind::Gcode;
    t.gcode.fileName = "line.nc";
    t.gcode.program = "G21 G90\nG1 X10 Y0 F600\n";
    t.gcode.maxAccelMmPerS2 = 100.0;
    t.dtSeconds = 0.001;
    return t;
}

} // namespace

void TstProgramTrajectory::runTimeIsTheTrapezoidsClosedForm() {
    TrajectorySettings t = straightMove();
    XYT_COMPARE_NEAR(programRunSeconds(t), 10.0 / 10.0 + 10.0 / 100.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(t.effectiveDurationSeconds(), 1.1, 1e-12, 0.0);
    t.durationSeconds = 50.0; // not used by a program
    XYT_COMPARE_NEAR(t.effectiveDurationSeconds(), 1.1, 1e-12, 0.0);
    t.gcode.feedScale = 0.5; // 5 mm/s: 10 / 5 + 5 / 100
    XYT_COMPARE_NEAR(programRunSeconds(t), 2.05, 1e-12, 0.0);
    const ProgramSummary s = summarizeProgram(t);
    QCOMPARE(s.moves, std::size_t(1));
    QCOMPARE(s.lines, std::size_t(2));
    XYT_COMPARE_NEAR(s.lengthMm, 10.0, 1e-15, 0.0);
    QCOMPARE(s.corners, std::size_t(0));
    QVERIFY(!s.singleFullCircle);
    t.gcode.program = "G1 X1 F100\nG5\n";
    QCOMPARE(t.effectiveDurationSeconds(), 0.0); // unreadable: the evaluation names it
}

void TstProgramTrajectory::referencesFollowTheProfile() {
    const TrajectorySettings t = straightMove();
    const auto x = axisReference(t, 0);
    const auto y = axisReference(t, 1);
    // Linear between 1 ms samples: off the parabola by at most a dt^2 / 8 = 1.25e-5 mm.
    const double tol = 100.0 * 0.001 * 0.001 / 8.0 + 1e-12;
    XYT_COMPARE_NEAR(x(0.0), 0.0, 0.0, 1e-12);
    XYT_COMPARE_NEAR(x(0.05), 0.5 * 100.0 * 0.05 * 0.05, 0.0, tol);
    XYT_COMPARE_NEAR(x(0.55), 5.0, 0.0, tol);
    XYT_COMPARE_NEAR(x(1.1), 10.0, 0.0, 1e-12);
    XYT_COMPARE_NEAR(x(7.0), 10.0, 0.0, 1e-12); // held at the end
    for (double time : {0.0, 0.3, 1.0, 2.0})
        XYT_COMPARE_NEAR(y(time), 0.0, 0.0, 1e-15);
}

void TstProgramTrajectory::refusalsNameTheSessionPath_data() {
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("expectedField");
    QTest::addColumn<QString>("reasonStart");
    QTest::newRow("unknown word") << "program"
                                  << "G21\nG5 X1\n"
                                  << "trajectory.gcode.program"
                                  << "line 2: unknown word G5 at column 1";
    QTest::newRow("no motion") << "program"
                               << "G21\n"
                               << "trajectory.gcode.program"
                               << "";
    QTest::newRow("feed scale") << "feed_scale"
                                << "0"
                                << "trajectory.gcode.feed_scale"
                                << "";
    QTest::newRow("max accel") << "max_accel"
                               << "-1"
                               << "trajectory.gcode.max_accel"
                               << "";
    QTest::newRow("max jerk") << "max_jerk"
                              << "-1"
                              << "trajectory.gcode.max_jerk"
                              << "";
    // A jerk the samples cannot hold: 4 (L / 2J)^(1/3) over the program's length, named by its
    // session path (it ended the planner's bisection at 0 and crashed the reader).
    QTest::newRow("max jerk 1e-300") << "max_jerk"
                                     << "1e-300"
                                     << "trajectory.gcode.max_jerk"
                                     << "1e-300 mm/s^3 needs at least";
    QTest::newRow("dt") << "dt"
                        << "0"
                        << "trajectory.dt"
                        << "";
}

void TstProgramTrajectory::refusalsNameTheSessionPath() {
    QFETCH(QString, field);
    QFETCH(QString, value);
    QFETCH(QString, expectedField);
    QFETCH(QString, reasonStart);
    TrajectorySettings t = straightMove();
    if (field == "program")
        t.gcode.program = value.toStdString();
    else if (field == "feed_scale")
        t.gcode.feedScale = value.toDouble();
    else if (field == "max_accel")
        t.gcode.maxAccelMmPerS2 = value.toDouble();
    else if (field == "max_jerk")
        t.gcode.maxJerkMmPerS3 = value.toDouble();
    else
        t.dtSeconds = value.toDouble();
    // The run time does not depend on the step (programRunSeconds plans without sampling): a bad
    // dt is refused where the profile is sampled.
    for (int route = field == "dt" ? 1 : 0; route < 2; ++route) {
        try {
            if (route == 0)
                programRunSeconds(t);
            else
                axisReference(t, 0);
            QFAIL("not refused");
        } catch (const InvalidInput& e) {
            QCOMPARE(QString::fromStdString(e.field()), expectedField);
            QVERIFY2(QString::fromStdString(e.reason()).startsWith(reasonStart), e.what());
        }
    }
}

void TstProgramTrajectory::evaluationRunsBothAxesAlongTheProgram() {
    Session s = Session::paperDefault();
    s.trajectory = straightMove();
    const SessionEvaluation e = evaluateSession(s);
    XYT_COMPARE_NEAR(e.duration.seconds, 1.1, 1e-12, 0.0);
    QVERIFY(e.axes[0].ok && e.axes[1].ok);
    QVERIFY(e.program && e.programPath);
    XYT_COMPARE_NEAR(e.programPath->length(), 10.0, 1e-15, 0.0);
    // Each axis follows its coordinate of the profile; the contour run holds the same profile.
    const auto x = axisReference(s.trajectory, 0);
    for (std::size_t k = 0; k < e.axes[0].run.t.size(); k += 37)
        XYT_COMPARE_NEAR(e.axes[0].run.r[k], x(e.axes[0].run.t[k]), 1e-15, 1e-15);
    QCOMPARE(e.program->trace.profile.t.size(), e.axes[0].run.t.size());
    // The per-axis runs and the contour run are the same simulation of the same samples.
    for (std::size_t k = 0; k < e.axes[0].run.t.size(); k += 37)
        XYT_COMPARE_NEAR(e.program->trace.x[k], e.axes[0].run.y[k], 1e-12, 1e-12);
    // The presets have no program run.
    QVERIFY(!evaluateSession(Session::paperDefault()).program);
}

void TstProgramTrajectory::octaveExportRefusesAProgram() {
    Session s = Session::paperDefault();
    s.trajectory = straightMove();
    const SessionEvaluation e = evaluateSession(s);
    try {
        exportOctaveScript(s, e, ExportOptions{});
        QFAIL("not refused");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.field(), std::string("trajectory.kind"));
    }
}

QTEST_APPLESS_MAIN(TstProgramTrajectory)
#include "tst_program_trajectory.moc"
