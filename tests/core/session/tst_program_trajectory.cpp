// SPDX-License-Identifier: GPL-3.0-or-later
// A G-code program as a session's trajectory: its run time, its references, the
// session paths its refusals name, and its evaluation. The expected times and positions are the
// closed form of a trapezoidal move along a straight line (accelerate at a to v = F, cruise,
// decelerate: t = L / v + v / a when L >= v^2 / a).
#include "core/contour/ballbar_circles.h"
#include "core/contour/feed_profile.h"
#include "core/model/errors.h"
#include "core/session/contour_run.h"
#include "core/session/export_text.h"
#include "core/session/program_trajectory.h"
#include "core/session/session_evaluation.h"
#include "tests/support/ballbar_program.h"
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
    void ballbarProgramCirclesAreFound_data();
    void ballbarProgramCirclesAreFound();
    void ballbarFiguresOfAKnownRadialDeviation_data();
    void ballbarFiguresOfAKnownRadialDeviation();
    void ballbarProgramIsEvaluated();
    void programIsReadAndPlannedOncePerChange();
    void programsCompareByContent();
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

void TstProgramTrajectory::ballbarProgramCirclesAreFound_data() {
    // Segments [begin, end) of each circle; -1: none.
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("firstEnd");
    QTest::addColumn<int>("opposite");
    QTest::addColumn<int>("oppositeEnd");
    QTest::addColumn<QString>("note"); // a part of the note, empty: no note
    const int cw = int(test::kBallbarClockwiseSegment),
              ccw = int(test::kBallbarCounterClockwiseSegment);
    QTest::newRow("clockwise and counter-clockwise with feed-in arcs")
        << QString(test::kBallbarProgram) << cw << cw + 1 << ccw << ccw + 1 << QString();
    QTest::newRow("one direction with a feed-in arc")
        << QString("G0 X15 Y0\nG2 X25 Y0 I5 J0 F120\nG2 X25 Y0 I-25 J0\n") << 2 << 3 << -1 << -1
        << QString(
               "the program runs its full circle (line 3) one way only: no circular hysteresis H");
    QTest::newRow("two clockwise circles")
        << QString("G0 X25 Y0\nG2 X25 Y0 I-25 J0 F120\nG2 X25 Y0 I-25 J0\n") << 1 << 2 << -1 << -1
        << QString("none of the program's 2 full circles runs the circle of line 2 the other way");
    QTest::newRow("the other way on another radius")
        << QString("G0 X25 Y0\nG2 X25 Y0 I-25 J0 F120\nG1 X26\nG3 X26 Y0 I-26 J0\n") << 1 << 2 << -1
        << -1 << QString("none of the program's 2 full circles");
    QTest::newRow("three circles")
        << QString(test::kBallbarProgram) + "G1 X25 Y0\nG2 X25 Y0 I-25 J0\n"
        << cw << cw + 1 << ccw << ccw + 1
        << QString("the program holds 3 full circles: the figures are those of line 4 and line 7");
    QTest::newRow("no full circle")
        << QString("G1 X10 F600\nG2 X20 Y0 I5 J0\n") << -1 << -1 << -1 << -1 << QString();
    // Full circles written as consecutive arcs on one centre and radius, turning one way.
    QTest::newRow("semicircles clockwise, quadrants counter-clockwise")
        << QString(test::kBallbarArcsProgram) << int(test::kBallbarArcsClockwiseBegin)
        << int(test::kBallbarArcsClockwiseEnd) << int(test::kBallbarArcsCounterClockwiseBegin)
        << int(test::kBallbarArcsCounterClockwiseEnd) << QString();
    QTest::newRow("a one-arc circle paired with quadrants the other way")
        << QString("G0 X25 Y0\nG2 X25 Y0 I-25 J0 F120\nG3 X0 Y25 I-25 J0\nG3 X-25 Y0 I0 J-25\n"
                   "G3 X0 Y-25 I25 J0\nG3 X25 Y0 I0 J25\n")
        << 1 << 2 << 2 << 6 << QString();
    QTest::newRow("three quadrants are no circle")
        << QString("G0 X25 Y0\nG3 X0 Y25 I-25 J0 F120\nG3 X-25 Y0 I0 J-25\nG3 X0 Y-25 I25 J0\nG1 "
                   "X25 Y0\n")
        << -1 << -1 << -1 << -1 << QString();
    // Four quadrants whose last ends one unit of the last digit (0.001 mm) past or short of the
    // start (within the reader's end tolerance of 0.002 mm): 4e-5 rad off one turn.
    QTest::newRow("quadrants ending 0.001 mm past the start are no circle")
        << QString("G0 X25 Y0\nG3 X0 Y25 I-25 J0 F120\nG3 X-25 Y0 I0 J-25\nG3 X0 Y-25 I25 J0\nG3 "
                   "X25 Y0.001 I0 J25\n")
        << -1 << -1 << -1 << -1 << QString();
    QTest::newRow("quadrants ending 0.001 mm short of the start are no circle")
        << QString("G0 X25 Y0\nG3 X0 Y25 I-25 J0 F120\nG3 X-25 Y0 I0 J-25\nG3 X0 Y-25 I25 J0\nG3 "
                   "X25 Y-0.001 I0 J25\n")
        << -1 << -1 << -1 << -1 << QString();
    // Two clockwise semicircles of radius 25 about (0, 0) and (-50, 0): an S whose sweeps add up
    // to one turn, but no circle.
    QTest::newRow("arcs on different centres are not joined")
        << QString("G0 X25 Y0\nG2 X-25 Y0 I-25 J0 F120\nG2 X-75 Y0 I-25 J0\n") << -1 << -1 << -1
        << -1 << QString();
    QTest::newRow("a semicircle and back is no circle")
        << QString("G0 X25 Y0\nG2 X-25 Y0 I-25 J0 F120\nG3 X25 Y0 I25 J0\n") << -1 << -1 << -1 << -1
        << QString();
    QTest::newRow("a rapid between semicircles ends the run")
        << QString(
               "G0 X25 Y0\nG2 X-25 Y0 I-25 J0 F120\nG0 X-25 Y0.5\nG0 X-25 Y0\nG2 X25 Y0 I25 J0\n")
        << -1 << -1 << -1 << -1 << QString();
    // More than a turn in a run: the circle is the first whole turn, the rest a new run.
    QTest::newRow("five quadrants: the first four")
        << QString("G0 X25 Y0\nG3 X0 Y25 I-25 J0 F120\nG3 X-25 Y0 I0 J-25\nG3 X0 Y-25 I25 J0\n"
                   "G3 X25 Y0 I0 J25\nG3 X0 Y25 I-25 J0\n")
        << 1 << 5 << -1 << -1
        << QString("the program runs its full circle (lines 2-5) one way only");
    QTest::newRow("a quarter on the circle, then a full-circle arc: the full-circle arc")
        << QString("G0 X25 Y0\nG3 X0 Y25 I-25 J0 F120\nG3 X0 Y25 I0 J-25\n") << 2 << 3 << -1 << -1
        << QString("the program runs its full circle (line 3) one way only");
    QTest::newRow("a semicircle, then three 2 pi / 3 arcs: the turn after the semicircle")
        << QString("G0 X25 Y0\nG2 X-25 Y0 I-25 J0 F120\nG2 X12.5 Y21.650635094610966 I25 J0\n"
                   "G2 X12.5 Y-21.650635094610966 I-12.5 J-21.650635094610966\n"
                   "G2 X-25 Y0 I-12.5 J21.650635094610966\n")
        << 2 << 5 << -1 << -1 << QString("(lines 3-5)");
    QTest::newRow("eight quadrants: two circles one way")
        << QString("G0 X25 Y0\nG2 X0 Y-25 I-25 J0 F120\nG2 X-25 Y0 I0 J25\nG2 X0 Y25 I25 J0\nG2 "
                   "X25 Y0 I0 J-25\n"
                   "G2 X0 Y-25 I-25 J0\nG2 X-25 Y0 I0 J25\nG2 X0 Y25 I25 J0\nG2 X25 Y0 I0 J-25\n")
        << 1 << 5 << -1 << -1
        << QString(
               "none of the program's 2 full circles runs the circle of lines 2-5 the other way");
}

void TstProgramTrajectory::ballbarProgramCirclesAreFound() {
    QFETCH(QString, program);
    QFETCH(int, first);
    QFETCH(int, firstEnd);
    QFETCH(int, opposite);
    QFETCH(int, oppositeEnd);
    QFETCH(QString, note);
    const BallbarCircles c = findBallbarCircles(readGcode(program.toStdString()));
    QCOMPARE(c.first ? int(c.first->begin) : -1, first);
    QCOMPARE(c.first ? int(c.first->end) : -1, firstEnd);
    QCOMPARE(c.opposite ? int(c.opposite->begin) : -1, opposite);
    QCOMPARE(c.opposite ? int(c.opposite->end) : -1, oppositeEnd);
    QVERIFY2(note.isEmpty() ? c.note.text.empty() : QString::fromStdString(c.note).contains(note),
             c.note.text.c_str());
}

void TstProgramTrajectory::ballbarFiguresOfAKnownRadialDeviation_data() {
    // The circles' segments [begin, end) and the lines of their first arcs.
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("cwBegin");
    QTest::addColumn<int>("cwEnd");
    QTest::addColumn<int>("ccwBegin");
    QTest::addColumn<int>("ccwEnd");
    QTest::addColumn<int>("cwLine");
    QTest::addColumn<int>("ccwLine");
    const int cw = int(test::kBallbarClockwiseSegment),
              ccw = int(test::kBallbarCounterClockwiseSegment);
    QTest::newRow("each circle one arc")
        << QString(test::kBallbarProgram) << cw << cw + 1 << ccw << ccw + 1
        << int(test::kBallbarClockwiseLine) << int(test::kBallbarCounterClockwiseLine);
    QTest::newRow("semicircles and quadrants")
        << QString(test::kBallbarArcsProgram) << int(test::kBallbarArcsClockwiseBegin)
        << int(test::kBallbarArcsClockwiseEnd) << int(test::kBallbarArcsCounterClockwiseBegin)
        << int(test::kBallbarArcsCounterClockwiseEnd) << int(test::kBallbarArcsClockwiseLine)
        << int(test::kBallbarArcsCounterClockwiseLine);
}

void TstProgramTrajectory::ballbarFiguresOfAKnownRadialDeviation() {
    // The traced points moved radially off the programmed circle: the clockwise run at
    // R + a, the counter-clockwise run at R - b (concentric). Closed forms: each run is a
    // circle about the nominal centre, so G = 0 for each; F max = F min = +a (clockwise) and -b
    // (counter-clockwise); H = a + b and G(b) = a + b (the radii differ by a + b at every angle).
    // Written as one arc or as several per circle, the runs are the same circles.
    QFETCH(QString, program);
    QFETCH(int, cwBegin);
    QFETCH(int, cwEnd);
    QFETCH(int, ccwBegin);
    QFETCH(int, ccwEnd);
    QFETCH(int, cwLine);
    QFETCH(int, ccwLine);
    const double a = 0.004, b = 0.0015, radius = test::kBallbarRadiusMm;
    const GcodeProgram read = readGcode(program.toStdString());
    ContourTrace trace;
    FeedProfileOptions options;
    options.dtSeconds = 0.01;
    trace.profile = planFeedProfile(read, options);
    trace.x = trace.profile.x;
    trace.y = trace.profile.y;
    // The points each run must hold, in time order.
    std::vector<double> cwX, cwY, ccwX, ccwY;
    for (std::size_t k = 0; k < trace.x.size(); ++k) {
        const int segment = int(trace.profile.segment[k]);
        const bool cw = segment >= cwBegin && segment < cwEnd;
        if (!cw && !(segment >= ccwBegin && segment < ccwEnd)) {
            trace.y[k] +=
                1.0; // the feed-in and feed-out arcs: far off, and left out of the figures
            continue;
        }
        const double r = std::hypot(trace.x[k], trace.y[k]);
        const double scale = (radius + (cw ? a : -b)) / r;
        trace.x[k] *= scale;
        trace.y[k] *= scale;
        (cw ? cwX : ccwX).push_back(trace.x[k]);
        (cw ? cwY : ccwY).push_back(trace.y[k]);
    }
    QVERIFY(cwX.size() > 1000 && ccwX.size() > 1000);
    std::vector<Diagnostic> warnings;
    const auto testResult = ballbarTestOfProgram(read, trace, Iso230Options{}, warnings);
    QVERIFY(testResult);
    QVERIFY(warnings.empty());
    QVERIFY(testResult->fromProgram && testResult->clockwise);
    QCOMPARE(int(testResult->line), cwLine);
    QCOMPARE(int(testResult->reverseLine), ccwLine);
    QVERIFY(testResult->x == cwX && testResult->y == cwY);
    QVERIFY(testResult->reverseX == ccwX && testResult->reverseY == ccwY);
    const Iso230Circular& iso = testResult->iso;
    XYT_COMPARE_NEAR(iso.circularDeviationG, 0.0, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.radialDeviationFMax, a, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.radialDeviationFMin, a, 0.0, 1e-10);
    QVERIFY(iso.hysteresisH && iso.bidirectionalG && testResult->reverseIso);
    // H and G(b) are taken about the least-squares centre of both runs together, which the
    // runs' unequal samples per angle (the feed-in ends, the feed-out starts) move off the
    // nominal centre by about 0.01 mm: that changes them only at second order, below 1e-9 mm.
    XYT_COMPARE_NEAR(*iso.hysteresisH, a + b, 0.0, 1e-9);
    XYT_COMPARE_NEAR(*iso.bidirectionalG, a + b, 0.0, 1e-9);
    XYT_COMPARE_NEAR(testResult->reverseIso->circularDeviationG, 0.0, 0.0, 1e-10);
    XYT_COMPARE_NEAR(testResult->reverseIso->radialDeviationFMax, -b, 0.0, 1e-10);
    XYT_COMPARE_NEAR(testResult->reverseIso->radialDeviationFMin, -b, 0.0, 1e-10);
}

void TstProgramTrajectory::ballbarProgramIsEvaluated() {
    // The program as a session's trajectory: before, a program with more than one feed move
    // had no ISO 230-4 figures at all, and nothing said why.
    Session s = Session::paperDefault();
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "ballbar.nc";
    s.trajectory.gcode.program = test::kBallbarProgram;
    const SessionEvaluation e = evaluateSession(s);
    QVERIFY2(e.program, e.programError.text.c_str());
    QVERIFY(e.program->circular);
    const ContourCircularTest& c = *e.program->circular;
    QVERIFY(c.fromProgram && c.clockwise);
    QCOMPARE(c.nominal.radius, test::kBallbarRadiusMm);
    // The figures are iso230Circular's of the program's own traced points on each circle.
    std::vector<double> x, y, rx, ry;
    for (std::size_t k = 0; k < e.program->trace.x.size(); ++k) {
        const std::size_t segment = e.program->trace.profile.segment[k];
        if (segment == test::kBallbarClockwiseSegment)
            x.push_back(e.program->trace.x[k]), y.push_back(e.program->trace.y[k]);
        if (segment == test::kBallbarCounterClockwiseSegment)
            rx.push_back(e.program->trace.x[k]), ry.push_back(e.program->trace.y[k]);
    }
    const Iso230Circular both = iso230Circular(x, y, rx, ry, c.nominal);
    const Iso230Circular reverse = iso230Circular(rx, ry, c.nominal);
    QCOMPARE(c.iso.circularDeviationG, both.circularDeviationG);
    QVERIFY(c.iso.hysteresisH && c.reverseIso);
    QCOMPARE(*c.iso.hysteresisH, *both.hysteresisH);
    QCOMPARE(c.reverseIso->circularDeviationG, reverse.circularDeviationG);
    QVERIFY(c.iso.circularDeviationG > 0.0 && *c.iso.hysteresisH > 0.0);
}

void TstProgramTrajectory::programIsReadAndPlannedOncePerChange() {
    // The session's program is read once per text and its profile planned once per set of
    // planning options (ProgramState), however many evaluations, copies and edits of other fields
    // follow. Each evaluation used to read the text five times (the run time, both axes'
    // references, the contour run, the path) and plan it four.
    Session s = Session::paperDefault();
    s.trajectory = straightMove();
    s.trajectory.dtSeconds = 0.01;
    const std::shared_ptr<const ProgramState> state = s.trajectory.gcode.program.state();
    QVERIFY(state);
    QCOMPARE(state->reads.load(), 0);
    const SessionEvaluation first = evaluateSession(s);
    QVERIFY2(first.axes[0].ok, first.axes[0].error.text.c_str());
    QVERIFY(first.program && first.programPath);
    // One read; two plans: the run time (without samples) and the sampled profile.
    QCOMPARE(state->reads.load(), 1);
    QCOMPARE(state->plans.load(), 2);
    for (int i = 0; i < 3; ++i) {
        const SessionEvaluation again = evaluateSession(s);
        QVERIFY(again.programPath == first.programPath); // the one shared path, not a copy
        QCOMPARE(again.program->contour.maxAbs, first.program->contour.maxAbs);
    }
    (void)summarizeProgram(s.trajectory);
    (void)s.trajectory.effectiveDurationSeconds();
    (void)chooseRunDuration(s);
    QCOMPARE(state->reads.load(), 1);
    QCOMPARE(state->plans.load(), 2);
    // An edit of the design keeps the program (a session copy shares it).
    Session edited = s;
    edited.axes[0].gt.kp = 40.0;
    QVERIFY(edited.trajectory.gcode.program.state() == state);
    QVERIFY(evaluateSession(edited).axes[0].ok);
    QCOMPARE(state->reads.load(), 1);
    QCOMPARE(state->plans.load(), 2);
    // A planning option is a new plan (sampled and not) of the same read program; going back
    // to the previous options finds their plans kept.
    edited.trajectory.gcode.feedScale = 0.5;
    QVERIFY(evaluateSession(edited).axes[1].ok);
    QCOMPARE(state->reads.load(), 1);
    QCOMPARE(state->plans.load(), 4);
    edited.trajectory.gcode.feedScale = 1.0;
    QVERIFY(evaluateSession(edited).axes[1].ok);
    QCOMPARE(state->plans.load(), 4);
    // The trapezoid's closed form still holds on the shared profile: 10/10 + 10/100 s.
    XYT_COMPARE_NEAR(programRunSeconds(edited.trajectory), 1.1, 1e-12, 0.0);
    // A new text is read once, itself; the old state is untouched.
    edited.trajectory.gcode.program = "G21 G90\nG1 X20 Y0 F600\n";
    const std::shared_ptr<const ProgramState> next = edited.trajectory.gcode.program.state();
    QVERIFY(next != state);
    QVERIFY(evaluateSession(edited).axes[0].ok);
    QVERIFY(evaluateSession(edited).axes[0].ok);
    QCOMPARE(next->reads.load(), 1);
    QCOMPARE(next->plans.load(), 2);
    QCOMPARE(state->reads.load(), 1);
    XYT_COMPARE_NEAR(programRunSeconds(edited.trajectory), 20.0 / 10.0 + 10.0 / 100.0, 1e-12, 0.0);
    // An unreadable text is read once too, and refused the same way each time.
    edited.trajectory.gcode.program = "G1 X1 F60\nG5\n";
    for (int i = 0; i < 3; ++i) {
        const SessionEvaluation e = evaluateSession(edited);
        QVERIFY(!e.axes[0].ok);
        QCOMPARE(QString::fromStdString(e.axes[0].errorField), QString("trajectory.gcode.program"));
    }
    QCOMPARE(edited.trajectory.gcode.program.state()->reads.load(), 1);
}

void TstProgramTrajectory::programsCompareByContent() {
    // Equality is the text's, whatever the sharing: equal texts set apart are equal, texts of
    // the same size that differ (one character, the last one) are not, in a program and in a
    // whole session.
    const std::string text = "G21 G90\nG1 X10 Y0 F600\n";
    std::string other = text;
    other[other.size() - 2] = '1'; // "F601"
    const ProgramText a(text), b(text), c(other);
    QVERIFY(a.state() != b.state());
    QVERIFY(a == b);
    QCOMPARE(a.size(), c.size());
    QVERIFY(!(a == c));
    QVERIFY(ProgramText() == ProgramText(""));
    QVERIFY(!(ProgramText() == a));
    QCOMPARE(a.str(), text);
    Session s = Session::paperDefault();
    s.trajectory = straightMove();
    Session t = s;
    QVERIFY(s == t);
    t.trajectory.gcode.program = other;
    QVERIFY(!(s == t));
    t.trajectory.gcode.program = std::string(text); // the same text again, a new state
    QVERIFY(s == t);
    QVERIFY(s.trajectory.gcode.program.state() != t.trajectory.gcode.program.state());
}

QTEST_APPLESS_MAIN(TstProgramTrajectory)
#include "tst_program_trajectory.moc"
