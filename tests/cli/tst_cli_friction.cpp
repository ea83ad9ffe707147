// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI contract for the table's friction: the jog experiment (excite --signal jog) and its
// estimator (identify --structure friction) recover the friction of a synthetic table within
// their own standard deviations; simulate and contour --gcode report the friction, its
// stick-slip findings and what compensation buys; bad friction input exits 2 naming the option.
#include "core/contour/gcode_reader.h"
#include "core/session/contour_run.h"
#include "core/session/session.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cstddef>

namespace {

// Braga et al.'s lower base (Eq. 19, metres per volt) and the paper's model unit (m per mm).
constexpr double kK0 = 77.8, kA2 = 3665.0, kUnit = 0.001;

// The synthetic table of the jog experiment: Coulomb level (V) and viscous friction beyond the
// model's own damping (V per mm/s). With Fs = Fc (no Stribeck dip) the table slides at every
// speed once moving, so each cruise is steady sliding.
constexpr double kCoulombVolts = 0.02, kViscousVoltsPerMmPerS = 0.01;

const QStringList kCubicMove = {"simulate", "--preset",   "lower-base", "--trajectory",
                                "cubic",    "--xf",       "50",         "--tf",
                                "10",       "--duration", "20"};

// A 25 mm circle at F150 (2.5 mm/s), as a ballbar test runs it.
const QByteArray kCircle = "G21 G90 G17\nG0 X25 Y0\nG2 X25 Y0 I-25 J0 F150\n";

/// The run's JSON, after checking that it succeeded with nothing on stderr.
QJsonObject succeeded(const xyt::test::CliRun& run) {
    if (!run.finished || run.exitCode != 0 || !run.err.isEmpty())
        qWarning("exit %d: %s", run.exitCode, run.err.constData());
    return run.finished && run.exitCode == 0 && run.err.isEmpty() ? run.json() : QJsonObject();
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

/// Writes @p path as `xytune-cli new` does, with axis x changed by @p edit.
template <class Edit> bool writeSession(const QString& path, Edit edit) {
    if (xyt::test::runCli({"new", "-o", path}).exitCode != 0)
        return false;
    QJsonObject doc = QJsonDocument::fromJson(readAll(path)).object();
    QJsonArray axes = doc["axes"].toArray();
    QJsonObject x = axes[0].toObject();
    edit(x);
    axes[0] = x;
    doc["axes"] = axes;
    return writeAll(path, QJsonDocument(doc).toJson());
}

/// The session format's friction object (every field present, as the format requires).
QJsonObject frictionObject(double coulomb, double viscous) {
    return {{"coulomb", coulomb},
            {"static", 0.0},
            {"stribeck_velocity", 0.0},
            {"viscous", viscous},
            {"backlash", 0.0},
            {"amplifier_deadband", 0.0},
            {"electrical_pole", "faster"},
            {"compensation", QJsonObject{{"percent", 0.0}, {"band", 0.05}}}};
}

double isoG(const QJsonObject& contour) {
    return contour["iso230_4"].toObject()["G"].toDouble();
}

bool warns(const QJsonObject& o, const QString& text) {
    for (const QJsonValue& w : o["warnings"].toArray())
        if (w.toString().contains(text))
            return true;
    return false;
}

} // namespace

class TstCliFriction : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void jogExperimentRecoversCoulombAndViscous();
    void simulateReportsFrictionAndCompensation();
    void badInputExitsWithTwoNamingTheOption_data();
    void badInputExitsWithTwoNamingTheOption();
    void contourShowsReversalSpikesAndCompensation();

private:
    QTemporaryDir dir_;
    QString gcode_;
};

void TstCliFriction::initTestCase() {
    QVERIFY(dir_.isValid());
    gcode_ = dir_.filePath("circle.ngc");
    QVERIFY(writeAll(gcode_, kCircle));
}

void TstCliFriction::jogExperimentRecoversCoulombAndViscous() {
    // The axis that jogs: a PID tuned by `tune` for a 20 rad/s crossover and 60 degrees of phase
    // margin, without feedforward. Not the paper's Guillemin-Truxal PI: its velocity constant
    // k0 kp / a2 = 0.64 1/s (a 1.6 s lag) leaves the table at 3.6 mm/s of a 10 mm/s jog when
    // the 20 mm move ends, so no cruise is steady (measured: Fc 0.0150 +- 0.0027 V). Not the
    // pid-ff default (that PI plus the model's feedforward) either: its feedforward takes the
    // program's derivatives by central differences (PidFeedforwardMethod::tracePath), so the
    // command of the last two samples of each cruise already holds the next ramp, and the
    // estimator's steady part ends at the cruise's last sample: with the tuned PID and that
    // feedforward a noise-free log gives Fc 0.019895 V (0.5 % low; without those two samples
    // 0.0199999967 V).
    const auto tune = xyt::test::runCli(
        {"tune", "--preset", "lower-base", "--crossover", "20", "--phase-margin", "60"});
    const QJsonObject gains = succeeded(tune)["gains"].toObject();
    QVERIFY(gains["p"].isDouble() && gains["i"].isDouble() && gains["d"].isDouble());
    const QString session = dir_.filePath("jog.json");
    QVERIFY(writeSession(session, [&](QJsonObject& x) {
        x["method"] = "pid-ff";
        x["parameters"] = QJsonObject{{"p", gains["p"]}, {"i", gains["i"]}, {"d", gains["d"]},
                                      {"ff1", 0.0},      {"ff2", 0.0},      {"ff3", 0.0}};
        x["friction"] = frictionObject(kCoulombVolts, kViscousVoltsPerMmPerS);
    }));

    // Travel 40 mm rather than the default 20: the loop's slowest closed-loop poles (roots of
    // s^4 + a1 s^3 + (a2 + k0 D/u) s^2 + k0 P/u s + k0 I/u: -7.53 +- 10.74j 1/s) then decay by
    // e^(-7.53 x 1.95) = 4e-7 before the steady part (the second half of the 3.9 s cruise at
    // 10 mm/s) begins. At 20 mm they decay by e^(-7.2) = 8e-4 only, which left 1.1e-5 V of the
    // ramp's transient in the 10 mm/s points: a bias of -0.6 standard deviations on the
    // viscous slope over 60 seeds, for the check below to absorb.
    const QStringList jog = {"excite", "--signal",  "jog",   "--speeds", "2,4,6,8,10", "--travel",
                             "40",     "--respond", session, "--axis",   "x"};
    const QString noisyLog = dir_.filePath("jog_noisy.csv"), cleanLog = dir_.filePath("jog.csv");
    const QJsonObject excited = succeeded(xyt::test::runCli(
        jog + QStringList{"--noise-std", "0.001", "--seed", "7", "-o", noisyLog}));
    // jogReference: two cruises (out and back) per speed.
    QCOMPARE(excited["segments"].toArray().size(), 10);
    QVERIFY(!succeeded(xyt::test::runCli(jog + QStringList{"-o", cleanLog})).isEmpty());

    const QStringList identify = {"identify", "--structure", "friction", "--session",
                                  session,    "--axis",      "x",        "--data"};
    const QJsonObject noisy = succeeded(xyt::test::runCli(identify + QStringList{noisyLog}));
    const QJsonObject clean = succeeded(xyt::test::runCli(identify + QStringList{cleanLog}));
    QCOMPARE(noisy["structure"].toString(), QStringLiteral("friction"));
    const QJsonArray noisyPoints = noisy["points"].toArray(),
                     cleanPoints = clean["points"].toArray();
    QCOMPARE(noisyPoints.size(), 10); // one point per cruise (steadyJogPoints)
    QCOMPARE(cleanPoints.size(), 10);

    // The model's own slope a2/k0 per mm (identifyFrictionCurve's "model_slope"), one division
    // and one product apart from this expression: 1e-15.
    const double modelSlope = kA2 / kK0 * kUnit;
    XYT_COMPARE_NEAR(noisy["model_slope"].toDouble(), modelSlope, 1e-15, 0.0);
    // The excess is the fitted slope less the model's: the same two doubles (17 digits read
    // back exactly), the same subtraction.
    XYT_COMPARE_NEAR(noisy["viscous_beyond_model"].toDouble(),
                     noisy["viscous"].toDouble() - noisy["model_slope"].toDouble(), 0.0, 0.0);

    // The noise is added to the logged position after the run (runJogExperiment), so the loop
    // and its command are the noise-free run's: every point's mean command is the same double
    // in both logs. The noise enters the estimate only through the velocities (least-squares
    // slopes of the noisy positions), and the fit's standard deviations pool its scatter.
    for (qsizetype i = 0; i < noisyPoints.size(); ++i)
        XYT_COMPARE_NEAR(noisyPoints[i].toObject()["volts"].toDouble(),
                         cleanPoints[i].toObject()["volts"].toDouble(), 0.0, 0.0);
    const double coulombStd = noisy["coulomb_std"].toDouble();
    const double viscousStd = noisy["viscous_std"].toDouble();
    QVERIFY(coulombStd > 0.0 && viscousStd > 0.0);

    // The requirement: the Coulomb level and the viscous slope within 3 standard deviations of
    // the table's (the slope being the model's a2/k0 u plus the table's viscous friction, the
    // curve of friction_identification.h). With 8 degrees of freedom |t| > 3 has probability
    // 1.7 % (1 of 60 seeds measured); seed 7 gives Fc 0.0200035 +- 2.1e-6 V (+1.7 standard
    // deviations) and b 0.0571071 +- 3.1e-7 V per mm/s (-2.6). The excess over the model adds
    // the subtraction's rounding: 1e-15.
    const double trueSlope = modelSlope + kViscousVoltsPerMmPerS;
    XYT_COMPARE_NEAR(noisy["coulomb"].toDouble(), kCoulombVolts, 0.0, 3.0 * coulombStd);
    XYT_COMPARE_NEAR(noisy["viscous"].toDouble(), trueSlope, 0.0, 3.0 * viscousStd);
    XYT_COMPARE_NEAR(noisy["viscous_beyond_model"].toDouble(), kViscousVoltsPerMmPerS, 0.0,
                     3.0 * viscousStd + 1e-15);
    // The table has no Stribeck dip: the F-test keeps the straight line.
    QVERIFY(!noisy["stribeck"].toBool());

    // The experiment itself is unbiased at the scale of that noise: without noise the estimate
    // is within a tenth of the noisy run's standard deviation of the truth (a bias that small
    // moves the 3-sigma coverage by under 0.1 %), so the check above tests the statistics, not
    // a transient. Measured: 1.6e-8 V and 3.9e-9 V per mm/s off.
    XYT_COMPARE_NEAR(clean["coulomb"].toDouble(), kCoulombVolts, 0.0, 0.1 * coulombStd);
    XYT_COMPARE_NEAR(clean["viscous"].toDouble(), trueSlope, 0.0, 0.1 * viscousStd);
    // The loop holds a type-2 plant-and-PID (integrator in each), so in steady sliding the
    // table moves at the jog's speed; the transient's remainder (4e-7 of it, above) measured
    // 3.1e-8 relative at 10 mm/s: 1e-6.
    const double speeds[] = {2, -2, 4, -4, 6, -6, 8, -8, 10, -10};
    for (qsizetype i = 0; i < cleanPoints.size(); ++i)
        XYT_COMPARE_NEAR(cleanPoints[i].toObject()["velocity"].toDouble(),
                         speeds[static_cast<std::size_t>(i)], 1e-6, 0.0);
}

void TstCliFriction::simulateReportsFrictionAndCompensation() {
    const auto linear = xyt::test::runCli(kCubicMove);
    const QJsonObject lin = succeeded(linear);
    QVERIFY(!lin.contains("friction") && !lin.contains("stick_slip"));

    // The core's contract (TableFriction: every field at zero is the linear table of the
    // papers; simulateLoopInto runs the linear loop unless the table is active): the run with
    // every friction option at 0 prints the linear run's output byte for byte.
    const auto zero = xyt::test::runCli(
        kCubicMove + QStringList{"--coulomb", "0", "--static", "0", "--stribeck-velocity", "0",
                                 "--viscous", "0", "--backlash", "0", "--amp-deadband", "0",
                                 "--friction-compensation", "0"});
    QVERIFY(!succeeded(zero).isEmpty());
    QCOMPARE(zero.out, linear.out);

    const QJsonObject dry =
        succeeded(xyt::test::runCli(kCubicMove + QStringList{"--coulomb", "0.05"}));
    const QJsonObject friction = dry["friction"].toObject();
    // The options echoed; "static" is the breakaway level max(Fs, Fc) (Fs = 0 means Fc).
    QCOMPARE(friction["coulomb"].toDouble(), 0.05);
    QCOMPARE(friction["static"].toDouble(), 0.05);
    QCOMPARE(friction["electrical_pole"].toString(), QStringLiteral("faster"));
    QVERIFY(friction["compensation_percent"].isDouble());
    const QJsonObject stickSlip = dry["stick_slip"].toObject();
    for (const char* key :
         {"stops_during_move", "first_stop", "breakaways_at_rest", "hunting", "rest_peak_to_peak"})
        QVERIFY2(stickSlip.contains(key), key);
    QVERIFY(dry["warnings"].isArray());

    // Full compensation cancels the Coulomb level wherever the reference moves faster than the
    // 0.05 mm/s band (FrictionCompensation), so the table tracks closer to the linear loop.
    // Measured RMSE: 6.5913 mm with Coulomb 0.05 V, 5.6135 mm compensated, 5.5271 mm linear.
    const QJsonObject compensated = succeeded(xyt::test::runCli(
        kCubicMove + QStringList{"--coulomb", "0.05", "--friction-compensation", "100"}));
    QCOMPARE(compensated["friction"].toObject()["compensation_percent"].toDouble(), 100.0);
    const double rmseDry = dry["tracking"].toObject()["rmse"].toDouble();
    const double rmseCompensated = compensated["tracking"].toObject()["rmse"].toDouble();
    QVERIFY2(rmseCompensated < rmseDry,
             qPrintable(QString("%1 !< %2").arg(rmseCompensated).arg(rmseDry)));
}

void TstCliFriction::badInputExitsWithTwoNamingTheOption_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message"); // what stderr starts with, after "xytune-cli "
    const QStringList simulate = kCubicMove;
    // validateTableFriction / validateFrictionCompensation, named by the option.
    QTest::newRow("negative Coulomb")
        << simulate + QStringList{"--coulomb", "-1"} << "simulate: --coulomb: ";
    QTest::newRow("static below Coulomb")
        << simulate + QStringList{"--static", "0.01", "--coulomb", "0.02"}
        << "simulate: --static: ";
    QTest::newRow("Stribeck dip without its velocity")
        << simulate + QStringList{"--static", "0.1", "--coulomb", "0.02"}
        << "simulate: --stribeck-velocity: ";
    QTest::newRow("unknown electrical pole")
        << simulate + QStringList{"--electrical-pole", "middle"} << "simulate: --electrical-pole: ";
    QTest::newRow("compensation above 200 %")
        << simulate + QStringList{"--friction-compensation", "500"}
        << "simulate: --friction-compensation: ";
    // One axis' option on contour --gcode, named with its prefix.
    QTest::newRow("negative backlash on x")
        << QStringList{"contour", "--gcode", gcode_, "--x.backlash", "-1"}
        << "contour: --x.backlash: ";

    // The jog experiment's options.
    const QString session = dir_.filePath("bad.json"), pp = dir_.filePath("pp.json");
    QVERIFY(writeSession(session, [](QJsonObject&) {}));
    QVERIFY(writeSession(pp, [](QJsonObject& x) { x["method"] = "pole-placement-zpetc"; }));
    const QString refused = dir_.filePath("refused.csv");
    const QStringList jog = {"excite", "--signal", "jog", "--respond", session,
                             "--axis", "x",        "-o",  refused};
    QTest::newRow("jog without speeds") << jog << "excite: --speeds: ";
    QTest::newRow("jog speed not a number")
        << jog + QStringList{"--speeds", "1,abc"} << "excite: --speeds: ";
    // A pole-placement axis is an ARX model, not the continuous plant the table belongs to.
    QTest::newRow("jogs of a pole-placement axis")
        << QStringList{"excite", "--signal", "jog", "--speeds", "1,2",  "--respond",
                       pp,       "--axis",   "x",   "-o",       refused}
        << "excite: --axis: ";

    // A log without the reference column: the option that names it, the file and the column.
    const QString noReference = dir_.filePath("no_reference.csv");
    QVERIFY(writeAll(noReference, "t,q,y,u\n0,0,0,0\n0.01,0,0,0\n"));
    QTest::newRow("log without r")
        << QStringList{"identify", "--structure", "friction", "--data", noReference}
        << "identify: --reference-col: " + noReference + ": has no column 'r'";
}

void TstCliFriction::badInputExitsWithTwoNamingTheOption() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const auto run = xyt::test::runCli(args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    const QString err = QString::fromUtf8(run.err);
    // One line: "xytune-cli simulate: --coulomb: <reason>".
    QVERIFY2(err.startsWith("xytune-cli " + message), qPrintable(err));
    QCOMPARE(err.count('\n'), qsizetype(1));
    QVERIFY(!QFile::exists(dir_.filePath("refused.csv"))); // a refused jog writes no log
}

void TstCliFriction::contourShowsReversalSpikesAndCompensation() {
    const QStringList contour = {"contour", "--gcode", gcode_, "--method",
                                 "pid-ff",  "--dt",    "0.01"};
    const QJsonObject linear = succeeded(xyt::test::runCli(contour));
    const QJsonObject dry =
        succeeded(xyt::test::runCli(contour + QStringList{"--coulomb", "0.02"}));
    const QJsonObject compensated = succeeded(xyt::test::runCli(
        contour + QStringList{"--coulomb", "0.02", "--friction-compensation", "100"}));

    // Each axis reports its table and its findings; the linear table reports neither.
    for (const char* axis : {"x_axis", "y_axis"}) {
        QVERIFY(!linear[axis].toObject().contains("friction"));
        const QJsonObject a = dry[axis].toObject();
        QCOMPARE(a["friction"].toObject()["coulomb"].toDouble(), 0.02);
        QVERIFY2(a["stick_slip"].isObject(), axis);
    }
    // addReversalSpikeWarning: a circle on a table with friction says how high its spikes are.
    QVERIFY(warns(dry, "reversal spikes up to"));
    QVERIFY(!warns(linear, "reversal spikes up to"));

    // G as the core computes it: runProgramContour on the default session with both axes on
    // pid-ff and the friction (the CLI's sessionFor, the CLI's defaults --max-accel 100);
    // the JSON prints 17 digits: 1e-15.
    xyt::Session session = xyt::Session::paperDefault();
    for (xyt::AxisSettings& axis : session.axes) {
        axis.method = xyt::DesignMethod::PidFeedforward;
        axis.friction.coulombVolts = 0.02;
    }
    xyt::ContourRunOptions options;
    options.profile.dtSeconds = 0.01;
    options.profile.maxAccelMmPerS2 = 100.0;
    const auto core =
        xyt::runProgramContour(session, xyt::readGcode(kCircle.toStdString()), options);
    QVERIFY(core.circular.has_value());
    XYT_COMPARE_NEAR(isoG(dry), core.circular->iso.circularDeviationG, 1e-15, 0.0);

    // Compensation takes the Coulomb level out of the quadrant changes: G falls back toward the
    // linear table's. Measured: 1.43 mm with Coulomb 0.02 V, 0.99 mm compensated and linear.
    QVERIFY2(isoG(compensated) < isoG(dry),
             qPrintable(QString("%1 !< %2").arg(isoG(compensated)).arg(isoG(dry))));
}

QTEST_APPLESS_MAIN(TstCliFriction)
#include "tst_cli_friction.moc"
