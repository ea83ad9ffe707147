// SPDX-License-Identifier: GPL-3.0-or-later
// CLI contract of xytune-cli contour --gcode: the figures printed are those of the
// core (runProgramContour on the default session, computed here again), the CSV holds the time
// series, and bad arguments or programs exit 2 naming the argument, file, line and column.
#include "core/contour/gcode_reader.h"
#include "core/session/contour_run.h"
#include "core/session/coupling_sweep.h"
#include "core/session/session.h"
#include "tests/support/ballbar_program.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <utility>

namespace {

QString example(const char* name) {
    return QStringLiteral(XYT_SOURCE_DIR "/resources/examples/") + QLatin1String(name);
}

xyt::GcodeProgram readExample(const char* name) {
    QFile f(example(name));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return xyt::readGcode(f.readAll().toStdString());
}

} // namespace

class TstCliContour : public QObject {
    Q_OBJECT
private slots:
    void circleMatchesTheCore_data();
    void circleMatchesTheCore();
    void squareCornersAndCsv();
    void ballbarProgramGivesBothDirections();
    void crossCouplingMatchesTheCore();
    void presetCrossCoupling();
    void couplingSweepMatchesTheCore();
    void couplingSweepDefaultGrid();
    void badInput_data();
    void badInput();
};

void TstCliContour::circleMatchesTheCore_data() {
    QTest::addColumn<QString>("method");
    QTest::newRow("guillemin-truxal") << "guillemin-truxal";
    QTest::newRow("pole-placement-zpetc") << "pole-placement-zpetc";
}

void TstCliContour::circleMatchesTheCore() {
    QFETCH(QString, method);
    // Patrick, Ishak and Adnan's 30 mm circle with the default session's axes, --max-accel 50.
    const auto run = xyt::test::runCli(
        {"contour", "--gcode", example("circle_30mm.nc"), "--max-accel", "50", "--method", method});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"profile", "x_axis", "y_axis", "contour_error", "iso230_4", "warnings"})
        QVERIFY2(o.contains(key), key);
    // The same run in the core: the JSON prints 17 digits, so the figures agree to 1e-15.
    xyt::Session session = xyt::Session::paperDefault();
    for (auto& axis : session.axes)
        axis.method = method == "guillemin-truxal" ? xyt::DesignMethod::GuilleminTruxal
                                                   : xyt::DesignMethod::PolePlacementZpetc;
    xyt::ContourRunOptions options;
    options.profile.maxAccelMmPerS2 = 50.0;
    const auto core = xyt::runProgramContour(session, readExample("circle_30mm.nc"), options);
    const QJsonObject ce = o["contour_error"].toObject();
    XYT_COMPARE_NEAR(ce["max"].toDouble(), core.contour.maxAbs, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ce["rms"].toDouble(), core.contour.rms, 1e-15, 0.0);
    QCOMPARE(ce["samples"].toInteger(), qint64(core.contour.measuredSamples));
    QVERIFY(core.circular.has_value());
    const QJsonObject iso = o["iso230_4"].toObject();
    XYT_COMPARE_NEAR(iso["G"].toDouble(), core.circular->iso.circularDeviationG, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["F_max"].toDouble(), core.circular->iso.radialDeviationFMax, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["F_min"].toDouble(), core.circular->iso.radialDeviationFMin, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["H"].toDouble(), *core.circular->iso.hysteresisH, 1e-15, 0.0);
    QCOMPARE(iso["direction"].toString(), QStringLiteral("clockwise"));
    QCOMPARE(iso["nominal"].toObject()["radius"].toDouble(), 30.0);
    QCOMPARE(iso["reversal_spikes"].toArray().size(), 4);
    // The profile: a rapid of 30 mm, then the circle at 3 mm/s; the program end M30 does not warn.
    XYT_COMPARE_NEAR(o["length"].toDouble(), 30.0 + 60.0 * 3.14159265358979323846, 1e-15, 0.0);
    QCOMPARE(o["profile"].toObject()["samples"].toInteger(), qint64(core.trace.profile.t.size()));
    for (const QJsonValue& w : o["warnings"].toArray())
        QVERIFY2(!w.toString().contains("M30"), qPrintable(w.toString()));
    QCOMPARE(o["x_axis"].toObject()["method"].toString(), method);
}

void TstCliContour::ballbarProgramGivesBothDirections() {
    // A ballbar program as machine shops write it (feed-in arc, clockwise circle, feed-out and
    // feed-in arcs, counter-clockwise circle): before, "iso230_4" was null and nothing said why.
    QTemporaryDir dir;
    const QString path = dir.filePath("ballbar.nc");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(xyt::test::kBallbarProgram);
    f.close();
    const auto run = xyt::test::runCli({"contour", "--gcode", path, "--dt", "0.002"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject iso = run.json()["iso230_4"].toObject();
    QVERIFY2(!iso.isEmpty(), run.out.constData());
    // The core's figures of the same run (the JSON prints 17 digits).
    xyt::ContourRunOptions options;
    options.profile.dtSeconds = 0.002;
    options.profile.maxAccelMmPerS2 = 100.0; // the CLI's default
    const auto core = xyt::runProgramContour(xyt::Session::paperDefault(),
                                             xyt::readGcode(xyt::test::kBallbarProgram), options);
    QVERIFY(core.circular && core.circular->reverseIso && core.circular->iso.hysteresisH);
    QCOMPARE(iso["runs"].toString(), QStringLiteral("program"));
    QCOMPARE(iso["direction"].toString(), QStringLiteral("clockwise"));
    QCOMPARE(iso["line"].toInteger(), qint64(xyt::test::kBallbarClockwiseLine));
    QCOMPARE(iso["reverse_line"].toInteger(), qint64(xyt::test::kBallbarCounterClockwiseLine));
    XYT_COMPARE_NEAR(iso["G"].toDouble(), core.circular->iso.circularDeviationG, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["G_reverse"].toDouble(), core.circular->reverseIso->circularDeviationG,
                     1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["F_max"].toDouble(), core.circular->iso.radialDeviationFMax, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["F_min_reverse"].toDouble(),
                     core.circular->reverseIso->radialDeviationFMin, 1e-15, 0.0);
    XYT_COMPARE_NEAR(iso["H"].toDouble(), *core.circular->iso.hysteresisH, 1e-15, 0.0);
    QCOMPARE(iso["nominal"].toObject()["radius"].toDouble(), xyt::test::kBallbarRadiusMm);
    // The same test with the circles written as semicircles and quadrants: the same path and
    // profile, so the same figures up to round-off; before, no circle was found in it at all.
    QFile arcs(dir.filePath("ballbar_arcs.nc"));
    QVERIFY(arcs.open(QIODevice::WriteOnly));
    arcs.write(xyt::test::kBallbarArcsProgram);
    arcs.close();
    const auto arcsRun =
        xyt::test::runCli({"contour", "--gcode", arcs.fileName(), "--dt", "0.002"});
    QCOMPARE(arcsRun.exitCode, 0);
    const QJsonObject arcsIso = arcsRun.json()["iso230_4"].toObject();
    QVERIFY2(!arcsIso.isEmpty(), arcsRun.out.constData());
    QCOMPARE(arcsIso["runs"].toString(), QStringLiteral("program"));
    QCOMPARE(arcsIso["line"].toInteger(), qint64(xyt::test::kBallbarArcsClockwiseLine));
    QCOMPARE(arcsIso["reverse_line"].toInteger(),
             qint64(xyt::test::kBallbarArcsCounterClockwiseLine));
    for (const char* figure : {"G", "G_reverse", "F_max", "F_min", "F_max_reverse", "F_min_reverse",
                               "H", "G_bidirectional"}) {
        QVERIFY2(arcsIso[figure].isDouble(), figure);
        XYT_COMPARE_NEAR(arcsIso[figure].toDouble(), iso[figure].toDouble(), 1e-9, 0.0);
    }
    // One direction only: G and F, no H, and the warnings say why.
    QFile one(dir.filePath("one_way.nc"));
    QVERIFY(one.open(QIODevice::WriteOnly));
    one.write("G0 X15 Y0\nG2 X25 Y0 I5 J0 F120\nG2 X25 Y0 I-25 J0\n");
    one.close();
    const auto oneWay = xyt::test::runCli({"contour", "--gcode", one.fileName(), "--dt", "0.002"});
    QCOMPARE(oneWay.exitCode, 0);
    const QJsonObject oneIso = oneWay.json()["iso230_4"].toObject();
    QVERIFY(oneIso["G"].isDouble() && oneIso["H"].isNull() && oneIso["G_reverse"].isNull());
    QVERIFY2(oneWay.json()["warnings"].toArray().contains(QStringLiteral(
                 "ISO 230-4: the program runs its full circle (line 3) one way only: no circular "
                 "hysteresis H, which needs a clockwise and a counter-clockwise run of the same "
                 "circle")),
             oneWay.out.constData());
}

void TstCliContour::squareCornersAndCsv() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("square.csv");
    const auto run =
        xyt::test::runCli({"contour", "--gcode", example("square_sharp_corners.nc"), "--method",
                           "pole-placement-zpetc", "--dt", "0.002", "--csv", csv});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    // Three inner corners of 90 degrees: the profile stops at each; each side alone takes
    // 40/10 + 10/100 s at the default --max-accel 100 (trapezoid closed form): 16.4 s in all.
    QCOMPARE(o["profile"].toObject()["sharp_corners"].toInt(), 3);
    XYT_COMPARE_NEAR(o["profile"].toObject()["duration"].toDouble(), 16.4, 1e-13, 0.0);
    const QJsonArray corners = o["contour_error"].toObject()["corners"].toArray();
    QCOMPARE(corners.size(), 3);
    QCOMPARE(corners[1].toObject()["x"].toDouble(), 40.0);
    QCOMPARE(corners[1].toObject()["y"].toDouble(), 40.0);
    QVERIFY(o["iso230_4"].isNull());
    // The CSV: a header and one row per sample (16.4 s at 2 ms: 8201), the last at the end.
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.first(), QByteArray("t,s,v,x_ref,y_ref,x,y,contour_error"));
    QCOMPARE(lines.size(), 8202);
    QCOMPARE(qint64(lines.size() - 1), o["profile"].toObject()["samples"].toInteger());
    const QList<QByteArray> last = lines.last().split(',');
    QCOMPARE(last.size(), 8);
    XYT_COMPARE_NEAR(last[1].toDouble(), 160.0, 1e-9, 0.0); // s at the end: the perimeter
    XYT_COMPARE_NEAR(last[3].toDouble(), 0.0, 0.0, 1e-9);   // back at the origin
    XYT_COMPARE_NEAR(last[4].toDouble(), 0.0, 0.0, 1e-9);
}

void TstCliContour::crossCouplingMatchesTheCore() {
    // The square under the paper's PIs with Koren's coupling: the figures are those of
    // runProgramContour with Session::crossCoupling set, computed here again; the independent
    // axes' contour error is the plain run's.
    const auto run =
        xyt::test::runCli({"contour", "--gcode", example("square_sharp_corners.nc"), "--ccc-kp",
                           "0.1", "--ccc-ki", "0.5", "--ccc-estimate", "linear"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    xyt::Session s = xyt::Session::paperDefault();
    s.crossCoupling = {0.1, 0.5, xyt::ContourEstimateKind::Linear};
    xyt::ContourRunOptions options;
    options.profile.maxAccelMmPerS2 = 100.0; // the CLI's default
    options.profile.dtSeconds = 0.001;
    const xyt::ContourRun core =
        xyt::runProgramContour(s, readExample("square_sharp_corners.nc"), options);
    // JSON numbers are printed with 17 significant digits: the same doubles.
    QCOMPARE(o["contour_error"].toObject()["max"].toDouble(), core.contour.maxAbs);
    const QJsonObject c = o["cross_coupling"].toObject();
    QCOMPARE(c["kp"].toDouble(), 0.1);
    QCOMPARE(c["estimate"].toString(), QStringLiteral("linear"));
    QCOMPARE(c["independent_axes"].toObject()["contour_error"].toObject()["max"].toDouble(),
             core.independent->contour.maxAbs);
    const QJsonObject line = c["line_loop"].toObject();
    QCOMPARE(line["spectral_radius"].toDouble(), core.couplingStability->worst.spectralRadius);
    QCOMPARE(line["lines_checked"].toInt(), 2);     // the square's lines at 0 and 90 degrees
    QCOMPARE(line["frozen_directions"].toInt(), 0); // no arc
    QCOMPARE(line["poles"].toArray().size(),
             static_cast<qsizetype>(core.couplingStability->worst.poles.size()));
    // Off: no cross_coupling block.
    const auto plain =
        xyt::test::runCli({"contour", "--gcode", example("square_sharp_corners.nc")});
    QVERIFY(plain.json()["cross_coupling"].isNull());
}

void TstCliContour::presetCrossCoupling() {
    // The paper-zpetc pair on its circle: the coupled block runs the session's two
    // pole-placement axes, coupled and independent (both from rest at r(0)).
    const auto run = xyt::test::runCli({"contour", "--ccc-kp", "3", "--ccc-ki", "1"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject c = run.json()["cross_coupling"].toObject();
    const double coupled = c["contour_error"].toObject()["max"].toDouble();
    const double alone =
        c["independent_axes"].toObject()["contour_error"].toObject()["max"].toDouble();
    QVERIFY(coupled > 0.0 && alone > 0.0);
    QVERIFY(coupled <= alone); // the ZPETC axes are near-perfect; the coupling does not hurt
    QCOMPARE(c["line_loop"].toObject()["period"].toDouble(), 0.07);
}

void TstCliContour::couplingSweepMatchesTheCore() {
    // The square under the paper's PIs, its coupling's gains swept on a 3 x 2 grid given out of
    // order: every cell is the core's sweepProgramCoupling on the same program and options,
    // computed here again (17 digits: the same doubles), kp 3 refused on the square's line 7
    // with the core's message; the best is the core's.
    const auto run =
        xyt::test::runCli({"contour", "--gcode", example("square_sharp_corners.nc"), "--ccc-sweep",
                           "--ccc-sweep-kp", "3,0,0.1", "--ccc-sweep-ki", "0.1, 0"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    QVERIFY(o["cross_coupling"].isNull()); // the run itself is uncoupled (no --ccc-kp)
    const QJsonObject sweep = o["cross_coupling_sweep"].toObject();
    xyt::ContourRunOptions options;
    options.profile.maxAccelMmPerS2 = 100.0; // the CLI's default
    options.profile.dtSeconds = 0.001;
    const xyt::CouplingSweepResult core = xyt::sweepProgramCoupling(
        xyt::Session::paperDefault(), readExample("square_sharp_corners.nc"), options,
        {{0.0, 0.1, 3.0}, {0.0, 0.1}});
    QCOMPARE(sweep["grid"].toObject()["kp"].toArray(), (QJsonArray{0, 0.1, 3}));
    QCOMPARE(sweep["grid"].toObject()["ki"].toArray(), (QJsonArray{0, 0.1}));
    QCOMPARE(sweep["estimate"].toString(), QStringLiteral("circular"));
    const QJsonArray cells = sweep["cells"].toArray();
    QCOMPARE(cells.size(), qsizetype(6));
    for (qsizetype i = 0; i < cells.size(); ++i) {
        const QJsonObject c = cells[i].toObject();
        const xyt::CouplingSweepCell& expected = core.cells[static_cast<std::size_t>(i)];
        QCOMPARE(c["kp"].toDouble(), expected.coupling.kp);
        QCOMPARE(c["ki"].toDouble(), expected.coupling.ki);
        QCOMPARE(c["status"].toString(),
                 QString::fromUtf8(xyt::couplingCellStatusName(expected.status)));
        if (expected.status == xyt::CouplingCellStatus::Ok) {
            QCOMPARE(c["contour_error"].toObject()["max"].toDouble(), expected.maxAbsMm);
            QCOMPARE(c["contour_error"].toObject()["rms"].toDouble(), expected.rmsMm);
            QCOMPARE(c["saturated"].toBool(), expected.saturated);
            if (expected.coupling.active())
                QCOMPARE(c["spectral_radius"].toDouble(), expected.spectralRadius);
            else
                QVERIFY(c["spectral_radius"].isNull()); // no coupled loop at (0, 0)
        } else {
            QCOMPARE(c["message"].toString(), QString::fromStdString(expected.message));
            QVERIFY(c["contour_error"].isNull());
        }
    }
    QCOMPARE(cells[4].toObject()["status"].toString(), QStringLiteral("unstable"));
    QVERIFY(cells[4].toObject()["message"].toString().contains("unstable on program line 7"));
    // (0, 0) is the independent axes' run, which is the plain run's contour error.
    const QJsonObject alone = sweep["independent_axes"].toObject();
    QCOMPARE(alone["contour_error"].toObject()["max"].toDouble(), core.independent.maxAbsMm);
    QCOMPARE(alone["contour_error"].toObject()["max"].toDouble(),
             o["contour_error"].toObject()["max"].toDouble());
    QVERIFY(core.best.has_value());
    const QJsonObject best = sweep["best"].toObject();
    QCOMPARE(best["index"].toInteger(), qint64(*core.best));
    QCOMPARE(best["among"].toString(), QStringLiteral("robust"));
    QCOMPARE(sweep["rule"].toString(), QString::fromUtf8(xyt::kBestCouplingRule));
    QCOMPARE(sweep["cancelled"].toBool(), false);
}

void TstCliContour::couplingSweepDefaultGrid() {
    // --ccc-sweep alone sweeps defaultCouplingSweepGrid (30 pairs) with the --ccc-estimate;
    // the run itself keeps its --ccc-kp.
    const auto run = xyt::test::runCli({"contour", "--gcode", example("star.nc"), "--ccc-sweep",
                                        "--ccc-kp", "0.03", "--ccc-estimate", "linear"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    const QJsonObject sweep = o["cross_coupling_sweep"].toObject();
    const xyt::CouplingSweepGrid grid = xyt::defaultCouplingSweepGrid();
    const QJsonObject g = sweep["grid"].toObject();
    QCOMPARE(g["kp"].toArray().size(), static_cast<qsizetype>(grid.kpVoltsPerMm.size()));
    QCOMPARE(g["ki"].toArray().size(), static_cast<qsizetype>(grid.kiVoltsPerMmSecond.size()));
    for (std::size_t i = 0; i < grid.kpVoltsPerMm.size(); ++i)
        QCOMPARE(g["kp"].toArray()[static_cast<qsizetype>(i)].toDouble(), grid.kpVoltsPerMm[i]);
    QCOMPARE(sweep["cells"].toArray().size(), qsizetype(30));
    QCOMPARE(sweep["estimate"].toString(), QStringLiteral("linear"));
    // The cell of the run's own gains (kp 0.03, ki 0: index 1 * 5 + 0) is the run.
    const QJsonObject own = sweep["cells"].toArray()[5].toObject();
    QCOMPARE(own["kp"].toDouble(), 0.03);
    QCOMPARE(own["ki"].toDouble(), 0.0);
    QCOMPARE(own["contour_error"].toObject()["max"].toDouble(),
             o["contour_error"].toObject()["max"].toDouble());
    QCOMPARE(sweep["independent_axes"].toObject()["contour_error"].toObject()["max"].toDouble(),
             o["cross_coupling"]
                 .toObject()["independent_axes"]
                 .toObject()["contour_error"]
                 .toObject()["max"]
                 .toDouble());
}

void TstCliContour::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message"); // a part of the one stderr line
    const QString star = example("star.nc");
    QTest::newRow("missing file") << QStringList{"--gcode", "/nonexistent/part.nc"}
                                  << "--gcode: cannot read /nonexistent/part.nc";
    QTest::newRow("bad program") << QStringList{"--gcode", "BAD"}
                                 << "--gcode: BAD: line 2: unknown word Q3 at column 7";
    QTest::newRow("accel") << QStringList{"--gcode", star, "--max-accel", "0"}
                           << "--max-accel: must be greater than zero";
    QTest::newRow("jerk") << QStringList{"--gcode", star, "--max-jerk", "-1"} << "--max-jerk:";
    QTest::newRow("feed scale") << QStringList{"--gcode", star, "--feed-scale", "-2"}
                                << "--feed-scale:";
    QTest::newRow("too many samples")
        << QStringList{"--gcode", star, "--dt", "1e-9"} << "--dt: the program needs at least";
    // A program that cannot be planned is refused by the option that makes it so, never a crash
    // (a jerk of 1e-200 used to end the peak-speed bisection at 0 and read a piece that was never
    // written). MOVE is "G0 X5\nG1 F600 X10": 5 mm of rapid, 5 mm at 10 mm/s. The times are the
    // planner's closed-form lower bounds (feed_profile.h) over the path's 10 mm, against the
    // 2e7 samples at dt 0.001 s (2e4 s).
    QTest::newRow("jerk 1e-200")
        << QStringList{"--gcode", "MOVE", "--max-jerk", "1e-200"}
        << "--max-jerk: 1e-200 mm/s^3 needs at least 3.17e+67 s to move the path's 10 mm";
    QTest::newRow("jerk 1e-300") << QStringList{"--gcode", "MOVE", "--max-jerk", "1e-300"}
                                 << "--max-jerk: 1e-300 mm/s^3 needs at least 6.84e+100 s";
    QTest::newRow("jerk subnormal") << QStringList{"--gcode", "MOVE", "--max-jerk", "5e-324"}
                                    << "--max-jerk: 4.94066e-324 mm/s^3 needs at least 4.02e+108 s";
    QTest::newRow("jerk huge")
        << QStringList{"--gcode", "MOVE", "--max-jerk", "1e300"}
        << "--max-jerk: 1e+300 mm/s^3 is outside the planner's range [1e-100, 1e+100]";
    QTest::newRow("accel tiny") << QStringList{"--gcode", "MOVE", "--max-accel", "1e-300"}
                                << "--max-accel: 1e-300 mm/s^2 needs at least 6.32e+150 s";
    QTest::newRow("accel huge") << QStringList{"--gcode", "MOVE", "--max-accel", "1e300"}
                                << "--max-accel: 1e+300 mm/s^2 is outside";
    QTest::newRow("feed scale tiny")
        << QStringList{"--gcode", "MOVE", "--feed-scale", "1e-300"}
        << "--feed-scale: 1e-300 makes the feed of line 2 (10 mm/s) 1e-299 mm/s";
    QTest::newRow("feed scale slow")
        << QStringList{"--gcode", "MOVE", "--feed-scale", "1e-5"}
        << "--feed-scale: the program needs at least 5e+04 s at 1e-05 times its feeds";
    QTest::newRow("feed scale huge") << QStringList{"--gcode", "MOVE", "--feed-scale", "1e300"}
                                     << "--feed-scale: 1e+300 makes the feed";
    QTest::newRow("rapid feed huge")
        << QStringList{"--gcode", "MOVE", "--rapid-feed", "1e300"}
        << "--rapid-feed: 1e+300 mm/min is outside the planner's range";
    QTest::newRow("rapid feed tiny") << QStringList{"--gcode", "MOVE", "--rapid-feed", "1e-300"}
                                     << "--rapid-feed: 1e-300 mm/min is outside";
    QTest::newRow("rapid feed slow") << QStringList{"--gcode", "MOVE", "--rapid-feed", "1e-3"}
                                     << "--rapid-feed: running the rapids needs at least 3e+05 s";
    QTest::newRow("dt subnormal") << QStringList{"--gcode", "MOVE", "--dt", "5e-324"}
                                  << "--dt: the program needs at least 0.5 s";
    QTest::newRow("corner angle huge") << QStringList{"--gcode", "MOVE", "--corner-angle", "1e300"}
                                       << "--corner-angle: must be in [0, 180)";
    QTest::newRow("method") << QStringList{"--gcode", star, "--method", "pid"}
                            << "--method: must be";
    QTest::newRow("preset option")
        << QStringList{"--gcode", star, "--radius", "5"} << "--radius: is not an option";
    QTest::newRow("negative coupling gain") << QStringList{"--gcode", star, "--ccc-kp", "-0.1"}
                                            << "--ccc-kp: must be a finite number >= 0";
    QTest::newRow("coupling gain nan") << QStringList{"--gcode", star, "--ccc-ki", "nan"}
                                       << "--ccc-ki: 'nan' is not a finite number";
    QTest::newRow("coupling estimate")
        << QStringList{"--gcode", star, "--ccc-kp", "1", "--ccc-estimate", "parabolic"}
        << "--ccc-estimate: must be linear or circular";
    // The coupled loop of the paper's PIs is unstable for this gain on MOVE's feed line
    // (program line 2, along x: spectral radius 1.048); the G0 rapid is not coupled.
    QTest::newRow("unstable line")
        << QStringList{"--gcode", "MOVE", "--ccc-kp", "100"}
        << "cross_coupling: the coupled loop is unstable on program line 2 (direction 0 deg)";
    QTest::newRow("sweep list not a number")
        << QStringList{"--gcode", star, "--ccc-sweep", "--ccc-sweep-kp", "0,0.1,x"}
        << "--ccc-sweep-kp: 'x' is not a number";
    QTest::newRow("sweep list empty")
        << QStringList{"--gcode", star, "--ccc-sweep", "--ccc-sweep-ki", ""}
        << "--ccc-sweep-ki: '' is not a number";
    QTest::newRow("sweep gain negative")
        << QStringList{"--gcode", star, "--ccc-sweep", "--ccc-sweep-ki", "0,-1"}
        << "--ccc-sweep-ki: -1 is not a finite gain >= 0";
    QTest::newRow("sweep gain infinite")
        << QStringList{"--gcode", star, "--ccc-sweep", "--ccc-sweep-kp", "inf"}
        << "--ccc-sweep-kp: inf is not a finite gain >= 0";
    QTest::newRow("sweep too many pairs")
        << QStringList{"--gcode",
                       star,
                       "--ccc-sweep",
                       "--ccc-sweep-kp",
                       "0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20",
                       "--ccc-sweep-ki",
                       "0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19"}
        << "--ccc-sweep-kp: with --ccc-sweep-ki: 21 values of kp and 20 of ki make 420 pairs: "
           "at most 400";
    QTest::newRow("sweep list without the flag")
        << QStringList{"--gcode", star, "--ccc-sweep-kp", "0,1"}
        << "--ccc-sweep-kp: needs --ccc-sweep";
    QTest::newRow("sweep flag with a value")
        << QStringList{"--gcode", star, "--ccc-sweep=1"} << "--ccc-sweep: takes no value";
    QTest::newRow("sweep on the preset")
        << QStringList{"--ccc-sweep"} << "--ccc-sweep: is not an option of this command";
    QTest::newRow("preset margin with coupling")
        << QStringList{"--ccc-kp", "1", "--margin", "0.1"} << "--margin: cannot go with";
    QTest::newRow("unwritable csv")
        << QStringList{"--gcode", star, "--csv", "/nonexistent/x.csv"} << "--csv: cannot write";
}

void TstCliContour::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QTemporaryDir dir;
    // BAD: an unknown word on line 2; MOVE: a rapid then a feed move (see the rows).
    for (const auto& [name, text] :
         {std::pair{QStringLiteral("BAD"), QByteArray("G0 X1\nG1 X1 Q3 F10\n")},
          std::pair{QStringLiteral("MOVE"), QByteArray("G0 X5\nG1 F600 X10\n")}}) {
        const QString path = dir.filePath(name + ".nc");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
        f.close();
        args.replaceInStrings(name, path);
        message.replace(name, path);
    }
    const auto run = xyt::test::runCli(QStringList{"contour"} + args);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    const QString err = QString::fromUtf8(run.err).trimmed();
    QVERIFY2(err.startsWith("xytune-cli contour: " + message), qPrintable(err));
    QVERIFY(!err.contains('\n'));
}

QTEST_APPLESS_MAIN(TstCliContour)
#include "tst_cli_contour.moc"
