// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

namespace {

const QStringList kLowerCubic = {"sweep", "--preset", "lower-base", "--trajectory", "cubic",
                                 "--xf",  "600",      "--tf",       "130"};

} // namespace

class TstCliSweep : public QObject {
    Q_OBJECT
private slots:
    void contractKeysAndCsv();
    void strictSpecHasNoBest();
    void bestOnTheEdgeIsWarned();
    void badGridExitsWithTwo_data();
    void badGridExitsWithTwo();
    void marginCriterionAndMinimum();
    void summaryWithoutPoints();
};

void TstCliSweep::contractKeysAndCsv() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("sweep.csv");
    const auto run = xyt::test::runCli(
        kLowerCubic + QStringList{"--wn", "0.5:4:4", "--kp", "10:200:5", "--log", "--max-overshoot",
                                  "1", "--csv", csv, "--threads", "2", "--points"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"best", "refined", "feasible_count", "points", "grid", "criterion",
                            "specification", "threads"})
        QVERIFY2(o.contains(key), key);
    QCOMPARE(o["criterion"].toString(), QString("itae"));
    QCOMPARE(o["threads"].toInt(), 2);
    const QJsonObject best = o["best"].toObject();
    for (const char* key : {"wn", "kp", "ki", "metrics"})
        QVERIFY2(best.contains(key), key);
    QVERIFY(best["feasible"].toBool());
    // ki = wn^4 / k0 (Braga et al. Eq. 11 and 16), k0 = 77.8.
    const double wn = best["wn"].toDouble();
    XYT_COMPARE_NEAR(best["ki"].toDouble(), wn * wn * wn * wn / 77.8, 1e-12, 0.0);
    const QJsonObject refined = o["refined"].toObject();
    for (const char* key : {"wn", "kp", "ki", "metrics"})
        QVERIFY2(refined.contains(key), key);
    QVERIFY(refined["metrics"].toObject()["itae"].toDouble() <=
            best["metrics"].toObject()["itae"].toDouble());
    // points[i_wn][i_kp]: 4 rows over wn, 5 columns over kp.
    const QJsonArray points = o["points"].toArray();
    QCOMPARE(points.size(), 4);
    int feasible = 0;
    for (qsizetype i = 0; i < points.size(); ++i) {
        const QJsonArray row = points[i].toArray();
        QCOMPARE(row.size(), 5);
        for (qsizetype j = 0; j < row.size(); ++j) {
            const QJsonObject p = row[j].toObject();
            // Grid values: log axes, closed form min (max/min)^(i/(n-1)).
            XYT_COMPARE_NEAR(p["wn"].toDouble(), 0.5 * std::pow(8.0, i / 3.0), 1e-14, 0.0);
            XYT_COMPARE_NEAR(p["kp"].toDouble(), 10.0 * std::pow(20.0, j / 4.0), 1e-14, 0.0);
            feasible += p["feasible"].toBool() ? 1 : 0;
        }
    }
    QCOMPARE(o["feasible_count"].toInt(), feasible);
    // The CSV: a header and one row per grid point, in the same order (wn outer, kp inner).
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.size(), 1 + 4 * 5);
    QVERIFY(lines[0].startsWith("i_wn,i_kp,wn,kp,ki,stable,feasible,"));
    QVERIFY(lines[0].contains("itae"));
    QVERIFY(lines[1 + 1 * 5 + 2].startsWith("1,2,"));
}

void TstCliSweep::strictSpecHasNoBest() {
    // Braga et al.'s strict "no overshoot": no type-2 design meets it (see
    // core/study/specification.h).
    const auto run = xyt::test::runCli(kLowerCubic +
                                       QStringList{"--wn", "1:3:3", "--kp", "10:50:3", "--points"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    QCOMPARE(o["feasible_count"].toInt(), 0);
    QVERIFY(o["best"].isNull());
    QVERIFY(o["refined"].isNull());
    // The warnings say which criterion fails everywhere and the best value the grid
    // reaches on it; the invariant checked here: it is the smallest step overshoot of all points.
    const QJsonArray warnings = o["warnings"].toArray();
    QCOMPARE(warnings.size(), 3);
    QCOMPARE(warnings[0].toString(), QString("no design of the grid meets the specification"));
    const QJsonObject diagnosis = o["diagnosis"].toObject();
    QVERIFY(diagnosis["none_feasible"].toBool());
    const QJsonArray failing = diagnosis["failing_everywhere"].toArray();
    QCOMPARE(failing.size(), qsizetype(1));
    QCOMPARE(failing[0].toObject()["criterion"].toString(), QString("overshoot"));
    double smallest = INFINITY;
    QJsonArray at;
    const QJsonArray rows = o["points"].toArray();
    for (qsizetype i = 0; i < rows.size(); ++i)
        for (qsizetype j = 0; j < rows[i].toArray().size(); ++j) {
            const double v =
                rows[i].toArray()[j].toObject()["metrics"].toObject()["overshoot_pct"].toDouble(
                    INFINITY);
            if (v < smallest) {
                smallest = v;
                at = QJsonArray{i, j};
            }
        }
    QCOMPARE(failing[0].toObject()["best_value"].toDouble(), smallest);
    QCOMPARE(failing[0].toObject()["best_index"].toArray(), at);
    QVERIFY2(warnings[1].toString().startsWith(
                 "the step overshoot limit (0 %) fails at every design of the "
                 "grid; the smallest step overshoot found is "),
             qPrintable(warnings[1].toString()));
    // The least-violating design (smallest total normalized violation) is that point here, and
    // it has not settled into 0.01 mm by the end of the run (its slow pole -psi1 = -wn^4/(k0 kp)
    // = -0.0026 rad/s): no relaxed limit makes it pass, and the warning says so.
    const QJsonObject least = diagnosis["least_violating"].toObject();
    QCOMPARE(least["index"].toArray(), at);
    const QJsonObject leastPoint = rows[at[0].toInt()].toArray()[at[1].toInt()].toObject();
    QCOMPARE(leastPoint["move_and_settle"].toObject()["settled"].toBool(true), false);
    QVERIFY(diagnosis["relaxed_specification"].isNull());
    QVERIFY2(warnings[2].toString().startsWith(
                 "least-violating design: wn = 1 rad/s, kp = 50 (point 2); "
                 "relaxing a limit does not make it pass"),
             qPrintable(warnings[2].toString()));
}

void TstCliSweep::bestOnTheEdgeIsWarned() {
    // The example: the best design's kp is the last grid value, 60.
    const auto run = xyt::test::runCli(
        kLowerCubic + QStringList{"--wn", "0.5:4:100", "--kp", "5:60:100", "--max-overshoot", "2"},
        600000);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    const QJsonArray index = o["best"].toObject()["index"].toArray();
    QCOMPARE(index[1].toInt(), 99);
    QCOMPARE(o["best"].toObject()["kp"].toDouble(), 60.0);
    QVERIFY(o["diagnosis"].toObject()["edges"].toObject()["kp_upper"].toBool());
    QVERIFY(!o["diagnosis"].toObject()["edges"].toObject()["kp_lower"].toBool());
    bool said = false;
    for (const QJsonValue& w : o["warnings"].toArray())
        said = said || w.toString() ==
                           "kp = 60 (the best design) is the upper end of the kp range 5..60: "
                           "the optimum may lie above; widen the kp range beyond 60";
    QVERIFY2(said, QJsonDocument(o["warnings"].toArray()).toJson().constData());
    // The settle criterion is judged on a run of tf + 2 x the settle limit (130 + 200 s).
    QCOMPARE(o["duration"].toDouble(), 330.0);
    QVERIFY(o["best"].toObject()["checks"].toObject()["settle"].toBool());
    const QJsonObject ms = o["best"].toObject()["move_and_settle"].toObject();
    QVERIFY(ms["settled"].toBool());
    QVERIFY(ms["settle_time"].toDouble() <= 100.0);
}

void TstCliSweep::badGridExitsWithTwo_data() {
    QTest::addColumn<QStringList>("grid");
    QTest::addColumn<QString>("argument");
    QTest::newRow("min > max") << QStringList{"--wn", "5:1:3", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("N = 0") << QStringList{"--wn", "1:5:3", "--kp", "1:2:0"} << "--kp";
    QTest::newRow("N = 501") << QStringList{"--wn", "1:5:501", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("not a number") << QStringList{"--wn", "1:x:3", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("N not whole") << QStringList{"--wn", "1:5:3", "--kp", "1:2:2.5"} << "--kp";
    QTest::newRow("two fields") << QStringList{"--wn", "1:5", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("zero with --log")
        << QStringList{"--wn", "1:5:3", "--kp", "0:2:3", "--log"} << "--kp";
    QTest::newRow("negative linear") << QStringList{"--wn", "-1:5:3", "--kp", "1:2:3"} << "--wn";
    QTest::newRow("missing --kp") << QStringList{"--wn", "1:5:3"} << "--kp";
    QTest::newRow("bad criterion")
        << QStringList{"--wn", "1:5:3", "--kp", "1:2:3", "--criterion", "iae"} << "--criterion";
    QTest::newRow("phase margin above 180")
        << QStringList{"--wn", "1:5:3", "--kp", "1:2:3", "--min-phase-margin", "200"}
        << "--min-phase-margin";
    QTest::newRow("negative gain margin")
        << QStringList{"--wn", "1:5:3", "--kp", "1:2:3", "--min-gain-margin", "-3"}
        << "--min-gain-margin";
    QTest::newRow("bad threads") << QStringList{"--wn", "1:5:3", "--kp", "1:2:3", "--threads", "0"}
                                 << "--threads";
}

void TstCliSweep::badGridExitsWithTwo() {
    QFETCH(QStringList, grid);
    QFETCH(QString, argument);
    const auto run = xyt::test::runCli(kLowerCubic + grid);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(argument.toUtf8()), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.out.isEmpty());
}

void TstCliSweep::marginCriterionAndMinimum() {
    // --criterion phase_margin picks the feasible design of the largest phase margin,
    // and --min-phase-margin makes every design below it infeasible. Each point's margin is the
    // core's (tst_design_sweep checks it against stabilityMargins); the CSV column equals it.
    QTemporaryDir dir;
    const QString csv = dir.filePath("sweep.csv");
    const QStringList grid = {"--wn",  "0.5:4:4",         "--kp", "10:200:4",
                              "--log", "--max-overshoot", "5"};
    const auto free = xyt::test::runCli(
        kLowerCubic + grid + QStringList{"--criterion", "phase_margin", "--csv", csv, "--points"});
    QCOMPARE(free.exitCode, 0);
    double lo = INFINITY, hi = -INFINITY;
    for (const QJsonValue& row : free.json()["points"].toArray())
        for (const QJsonValue& v : row.toArray()) {
            const QJsonObject p = v.toObject();
            QVERIFY(p["phase_margin"].isDouble() && p["gain_margin"].isDouble());
            if (p["feasible"].toBool()) {
                lo = std::min(lo, p["phase_margin"].toDouble());
                hi = std::max(hi, p["phase_margin"].toDouble());
            }
        }
    QVERIFY(lo < hi);
    const QJsonObject best = free.json()["best"].toObject();
    QCOMPARE(best["phase_margin"].toDouble(), hi);
    QCOMPARE(best["checks"].toObject()["phase_margin"].toBool(), true);
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    const int column = static_cast<int>(lines[0].split(',').indexOf("phase_margin"));
    QVERIFY(column > 0);
    QCOMPARE(lines[1].split(',')[column].toDouble(),
             free.json()["points"].toArray()[0].toArray()[0].toObject()["phase_margin"].toDouble());

    const double minimum = 0.5 * (lo + hi);
    const auto strict = xyt::test::runCli(
        kLowerCubic + grid +
        QStringList{"--min-phase-margin", QString::number(minimum, 'g', 17), "--points"});
    QCOMPARE(strict.exitCode, 0);
    QCOMPARE(strict.json()["specification"].toObject()["min_phase_margin"].toDouble(), minimum);
    int feasible = 0;
    for (const QJsonValue& row : strict.json()["points"].toArray())
        for (const QJsonValue& v : row.toArray()) {
            const QJsonObject p = v.toObject();
            if (p["feasible"].toBool()) {
                ++feasible;
                QVERIFY(p["phase_margin"].toDouble() >= minimum);
            }
        }
    QVERIFY(feasible > 0);
    QVERIFY(feasible < free.json()["feasible_count"].toInt());
}

void TstCliSweep::summaryWithoutPoints() {
    // A 100 x 100 grid wrote 13 MB of points by default. Without --points the summary alone: the
    // same best design, counts and diagnosis as with them (the same study), and no points.
    const QStringList grid = {"--wn",  "0.5:4:6",         "--kp", "10:200:6",
                              "--log", "--max-overshoot", "5"};
    const auto summary = xyt::test::runCli(kLowerCubic + grid);
    const auto full = xyt::test::runCli(kLowerCubic + grid + QStringList{"--points"});
    QCOMPARE(summary.exitCode, 0);
    QCOMPARE(full.exitCode, 0);
    QJsonObject withPoints = full.json();
    QCOMPARE(withPoints["points"].toArray().size(), 6);
    QVERIFY(!summary.json().contains("points"));
    withPoints.remove("points");
    withPoints.remove("threads"); // the cores free on the shared machine may differ
    QJsonObject without = summary.json();
    without.remove("threads");
    QCOMPARE(without, withPoints);
    QVERIFY(without["best"].isObject());
}

QTEST_APPLESS_MAIN(TstCliSweep)
#include "tst_cli_sweep.moc"
