// SPDX-License-Identifier: GPL-3.0-or-later
// CLI contract of xytune-cli robustness: the figures printed are the core's
// (analyzeRobustness of the session's axes, computed here again with the same ranges and seed),
// the CSV holds one row per plant; with --contour the joint XY figures are
// analyzeContourRobustness's; bad arguments exit 2 naming the argument.
#include "core/session/robustness_problem.h"
#include "core/session/session.h"
#include "core/study/contour_robustness.h"
#include "tests/support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace xyt;

class TstCliRobustness : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void figuresAreTheCores();
    void sensitivityCurveIsTheCores();
    void contourFiguresAreTheCores();
    void badInput_data();
    void badInput();

private:
    QTemporaryDir dir_;
    QString session_;
};

void TstCliRobustness::initTestCase() {
    QVERIFY(dir_.isValid());
    session_ = dir_.filePath("session.json");
    const auto made = test::runCli({"new", "-o", session_});
    QCOMPARE(made.exitCode, 0);
}

void TstCliRobustness::figuresAreTheCores() {
    const QString csv = dir_.filePath("runs.csv");
    const auto run =
        test::runCli({"robustness", session_, "--samples", "20", "--seed", "5", "--range", "k0=10%",
                      "--range", "y.a2=0.05", "--threads", "2", "--csv", csv});
    QCOMPARE(run.exitCode, 0);
    const QJsonArray axes = run.json().value("axes").toArray();
    QCOMPARE(axes.size(), 2);
    const Session s = Session::paperDefault();
    for (int axis = 0; axis < 2; ++axis) {
        RobustnessProblem p = sessionRobustnessProblem(s, axis);
        setRelativeRange(p.parameters, "k0", 0.1);
        if (axis == 1)
            setRelativeRange(p.parameters, "a2", 0.05);
        RobustnessOptions o;
        o.samples = 20;
        o.seed = 5;
        const RobustnessResult r = analyzeRobustness(p, o);
        const QJsonObject a = axes[axis].toObject();
        QCOMPARE(a.value("corners").toInt(), axis == 0 ? 2 : 4);
        const QJsonObject rmse = a.value("statistics").toObject().value("rmse").toObject();
        // JSON prints the shortest decimal that reads back as the same double: exact.
        QCOMPARE(rmse.value("p50").toDouble(), r.rmse.p50);
        QCOMPARE(rmse.value("max").toDouble(), r.rmse.max);
        QCOMPARE(rmse.value("count").toInt(), r.rmse.count);
        QCOMPARE(a.value("fraction_meeting_spec").toDouble(), r.fractionMeetingSpec);
        QCOMPARE(a.value("worst").toObject().value("index").toInt(), static_cast<int>(*r.worst));
        QCOMPARE(a.value("nominal").toObject().value("rmse").toDouble(), r.nominal.tracking.rmse);
    }
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + 22 + 24); // header, x: 20 + 2 corners, y: 20 + 4
    QVERIFY(lines[0].startsWith("axis,index,kind,x.k0,x.a1,x.a2,y.k0,y.a1,y.a2,stable"));
}

void TstCliRobustness::sensitivityCurveIsTheCores() {
    // x on Patrick, Ishak and Adnan's pole placement + ZPETC: session file written here.
    Session s = Session::paperDefault();
    s.axes[0].method = DesignMethod::PolePlacementZpetc;
    s.trajectory.kind = TrajectoryKind::Circle;
    const QString path = dir_.filePath("pp.json");
    {
        const auto made = test::runCli({"new", "-o", path});
        QCOMPARE(made.exitCode, 0);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray text = f.readAll();
        f.close();
        const QByteArray gt = "\"method\": \"guillemin-truxal\""; // the first: axis x
        const qsizetype at = text.indexOf(gt);
        QVERIFY(at >= 0);
        text.replace(at, gt.size(), "\"method\": \"pole-placement-zpetc\"");
        text.replace("\"kind\": \"cubic\"", "\"kind\": \"circle\"");
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
    }
    const auto run = test::runCli({"robustness", path, "--axis", "x", "--samples", "10", "--range",
                                   "b1=20%", "--sensitivity"});
    QCOMPARE(run.exitCode, 0);
    const QJsonArray curve =
        run.json().value("axes").toArray()[0].toObject().value("zpetc_sensitivity").toArray();
    QCOMPARE(curve.size(), 5);
    RobustnessProblem p = sessionRobustnessProblem(s, 0);
    setRelativeRange(p.parameters, "b1", 0.2);
    RobustnessOptions o;
    o.samples = 10;
    const auto expected = zpetcSensitivity(p, {0.0, 0.25, 0.5, 0.75, 1.0}, o);
    for (int i = 0; i < 5; ++i) {
        const QJsonObject point = curve[i].toObject();
        QCOMPARE(point.value("rmse_with_ff").toObject().value("p50").toDouble(),
                 expected[static_cast<std::size_t>(i)].rmseWithFf.p50);
        QCOMPARE(point.value("median_improvement_pct").toDouble(),
                 expected[static_cast<std::size_t>(i)].medianImprovementPct);
    }
}

void TstCliRobustness::contourFiguresAreTheCores() {
    // Braga et al.'s bases on the circle: the session file of `new` with the circle chosen.
    const QString path = dir_.filePath("circle.json");
    QVERIFY(QFile::copy(session_, path));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QByteArray text = f.readAll();
        text.replace("\"kind\": \"cubic\"", "\"kind\": \"circle\"");
        QVERIFY(f.resize(0));
        f.write(text);
    }
    const QString csv = dir_.filePath("pairs.csv");
    const auto run = test::runCli({"robustness", path, "--contour", "--samples", "6", "--seed", "2",
                                   "--range", "k0=10%", "--range", "x.a1=5%", "--csv", csv});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject xy = run.json().value("xy").toObject();
    Session s = Session::paperDefault();
    s.trajectory.kind = TrajectoryKind::Circle;
    ContourRobustnessProblem p = sessionContourRobustnessProblem(s);
    setRelativeRange(p.x.parameters, "k0", 0.1);
    setRelativeRange(p.x.parameters, "a1", 0.05);
    setRelativeRange(p.y.parameters, "k0", 0.1);
    RobustnessOptions o;
    o.samples = 6;
    o.seed = 2;
    const ContourRobustnessResult r = analyzeContourRobustness(p, o);
    QCOMPARE(xy.value("contour").toString(), QString("circle"));
    QCOMPARE(xy.value("pairs").toInt(), 6 + 8); // 3 uncertain parameters: 8 corners
    const QJsonObject maxAbs =
        xy.value("statistics").toObject().value("max_abs_contour_error").toObject();
    QCOMPARE(maxAbs.value("p95").toDouble(),
             r.maxAbsContourError.p95); // shortest round-trip decimal: exact
    QCOMPARE(maxAbs.value("max").toDouble(), r.maxAbsContourError.max);
    QCOMPARE(xy.value("nominal").toObject().value("max_abs_contour_error").toDouble(),
             r.nominal.maxAbsContourError);
    QCOMPARE(xy.value("worst").toObject().value("index").toInt(), static_cast<int>(*r.worst));
    QVERIFY(xy.value("worst").toObject().value("parameters").toObject().contains("y.k0"));
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines[0].endsWith(",max_abs_contour_error,rms_contour_error"));
    QCOMPARE(lines.filter(QRegularExpression("^xy,")).size(), 14);
}

void TstCliRobustness::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("named");
    QTest::newRow("unknown parameter") << QStringList{"--range", "q0=10%"} << "--range";
    QTest::newRow("range of 100 %") << QStringList{"--range", "k0=100%"} << "--range";
    QTest::newRow("range not a number") << QStringList{"--range", "k0=ten%"} << "--range";
    QTest::newRow("b1 on a GT session") << QStringList{"--range", "x.b1=5%"} << "--range";
    QTest::newRow("negative samples") << QStringList{"--samples", "-3"} << "--samples";
    QTest::newRow("fractional seed") << QStringList{"--seed", "1.5"} << "--seed";
    QTest::newRow("bad axis") << QStringList{"--axis", "z"} << "--axis";
    QTest::newRow("unknown option")
        << QStringList{"--from-identifcation"} << "--from-identifcation";
    QTest::newRow("not identified")
        << QStringList{"--from-identification"} << "axes[0].model_origin";
    QTest::newRow("ranges and identification")
        << QStringList{"--from-identification", "--range", "k0=5%"} << "--range";
    QTest::newRow("contour of a cubic move") << QStringList{"--contour"} << "--contour";
    QTest::newRow("contour of one axis") << QStringList{"--contour", "--axis", "x"} << "--contour";
}

void TstCliRobustness::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, named);
    const auto run = test::runCli(QStringList{"robustness", session_} + args);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(named.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
    const auto noSession = test::runCli({"robustness", "--samples", "3"});
    QCOMPARE(noSession.exitCode, 2);
    QVERIFY(noSession.err.contains("SESSION"));
}

QTEST_MAIN(TstCliRobustness)
#include "tst_cli_robustness.moc"
