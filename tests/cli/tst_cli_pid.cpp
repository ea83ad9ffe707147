// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI contract for the PID with command feedforward (LinuxCNC's pid): simulate --method
// pid-ff and --ff-from-model, tune (target margin and relay experiment), export --format
// linuxcnc, each figure against the source named beside it.
#include "core/design/pid_tuning.h"
#include "core/design/relay_experiment.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <complex>
#include <map>
#include <numbers>

namespace {

// Braga et al.'s lower base (Eq. 19, metres per volt) and the paper's model unit (m per mm).
constexpr double kK0 = 77.8, kA1 = 125.3, kA2 = 3665.0, kUnit = 0.001;

const QStringList kPaperMove = {"--preset", "lower-base", "--trajectory", "cubic",      "--xf",
                                "600",      "--tf",       "130",          "--duration", "130"};

/// The run's JSON, after checking that it succeeded with nothing on stderr.
QJsonObject succeeded(const xyt::test::CliRun& run) {
    if (!run.finished || run.exitCode != 0 || !run.err.isEmpty())
        qWarning("exit %d: %s", run.exitCode, run.err.constData());
    return run.finished && run.exitCode == 0 && run.err.isEmpty() ? run.json() : QJsonObject();
}

/// The `setp pid.N.PIN value` lines of a LinuxCNC export, by "N.PIN".
std::map<QString, double> setpValues(const QByteArray& hal) {
    std::map<QString, double> pins;
    for (const QByteArray& line : hal.split('\n')) {
        const QList<QByteArray> words = line.split(' ');
        if (words.size() == 3 && words[0] == "setp" && words[1].startsWith("pid."))
            pins[QString::fromUtf8(words[1].mid(4))] = words[2].toDouble();
    }
    return pins;
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TstCliPid : public QObject {
    Q_OBJECT
private slots:
    void feedforwardFromModelCutsTheErrorThousandfold();
    void pidWithoutFeedforwardTracksAsThePaperPi();
    void quinticWithTrajectoryDerivativesIsTheSessionsRun();
    void badGainsExitWithTwoNamingTheOption_data();
    void badGainsExitWithTwoNamingTheOption();
    void tuneMeetsTheTargetMargin();
    void tuneSaysWhenThePhaseIsOutOfReach();
    void tuneFromTheRelayExperiment();
    void exportWritesLinuxCncPins();
    void exportRefusesPolePlacementNamingTheAxis();
    void helpListsTheNewOptions();
};

void TstCliPid::feedforwardFromModelCutsTheErrorThousandfold() {
    // Source: the independent SciPy loop of tests/data/gen_pid_feedforward.py (figures in
    // tests/data/README.md, "PID with feedforward"): the lower base under the paper's PI at
    // 10 ms on the 130 s cubic, RMSE 5.87346 mm without feedforward and 0.00183526 mm with the
    // model's FF1..FF3 from backward differences.
    const auto gt =
        xyt::test::runCli(QStringList{"simulate"} + kPaperMove + QStringList{"--digital"});
    const QJsonObject g = succeeded(gt);
    QCOMPARE(g["method"].toString(), QStringLiteral("guillemin-truxal"));
    const double gtRmse = g["digital"].toObject()["tracking"].toObject()["rmse"].toDouble();
    // The session's Tustin PI is the CLI's: evaluateAxis of the paper's session (duration 130 s)
    // runs the same loop (same operations: 1e-12 for the JSON round trip).
    xyt::Session paper = xyt::Session::paperDefault();
    paper.trajectory.durationSeconds = 130.0;
    const xyt::AxisEvaluation session = xyt::evaluateAxis(paper, 0);
    QVERIFY(session.digital);
    XYT_COMPARE_NEAR(gtRmse, session.digital->metrics.rmse, 1e-12, 0.0);
    // Against SciPy's rectangle-rule PI: the Tustin PI differs by 0.003 % of the RMSE (the
    // tolerance of tests/core/session/tst_pid_feedforward.cpp): 1e-4.
    XYT_COMPARE_NEAR(gtRmse, 5.87346, 1e-4, 0.0);

    const auto ff = xyt::test::runCli(QStringList{"simulate"} + kPaperMove +
                                      QStringList{"--digital", "--ff-from-model"});
    const QJsonObject o = succeeded(ff);
    QCOMPARE(o["method"].toString(), QStringLiteral("pid-ff"));
    QCOMPARE(o["converted_from"].toString(), QStringLiteral("guillemin-truxal"));
    const double ffRmse = o["digital"].toObject()["tracking"].toObject()["rmse"].toDouble();
    // SciPy (as above): 0.00183526 mm, printed to six digits: 1e-5 relative.
    XYT_COMPARE_NEAR(ffRmse, 0.00183526, 1e-5, 0.0);
    QVERIFY2(gtRmse / ffRmse >= 1000.0, qPrintable(QString::number(ffRmse)));
    // The PI in mm units (withModelFeedforward: P = kp u, I = ki u with kp = 30, ki = wn^4/k0
    // = 16/77.8, Braga et al. Eq. 20) and the plant's exact inverse (modelFeedforwardGains:
    // FF1 = a2 u/k0, FF2 = a1 u/k0, FF3 = u/k0); one rounding apart from these expressions.
    const QJsonObject gains = o["gains"].toObject();
    XYT_COMPARE_NEAR(gains["p"].toDouble(), 30.0 * kUnit, 1e-15, 0.0);
    XYT_COMPARE_NEAR(gains["i"].toDouble(), 16.0 / kK0 * kUnit, 1e-15, 0.0);
    const QJsonObject model = o["model_feedforward"].toObject();
    XYT_COMPARE_NEAR(model["ff1"].toDouble(), kA2 * kUnit / kK0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(model["ff2"].toDouble(), kA1 * kUnit / kK0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(model["ff3"].toDouble(), kUnit / kK0, 1e-15, 0.0);
    QCOMPARE(gains["ff1"].toDouble(), model["ff1"].toDouble()); // the same double, printed twice
    // Invariant: the feedback alone is Braga et al.'s PI, so the converted axis without its
    // feedforward tracks as the Guillemin-Truxal simulate's continuous run (C = kp + ki/s both;
    // P/u and I/u round once each: 1e-12).
    XYT_COMPARE_NEAR(o["tracking_without_feedforward_rmse"].toDouble(),
                     g["tracking"].toObject()["rmse"].toDouble(), 1e-12, 0.0);
}

void TstCliPid::pidWithoutFeedforwardTracksAsThePaperPi() {
    // Source: the SciPy loop (tests/data/README.md, "PID with feedforward"): the paper's PI in
    // LinuxCNC's units without feedforward, RMSE 5.87346 mm (both loops run LinuxCNC's
    // rectangle rule, printed to six digits: 1e-5 relative).
    const auto run =
        xyt::test::runCli(QStringList{"simulate", "--method", "pid-ff"} + kPaperMove +
                          QStringList{"--ff1", "0", "--ff2", "0", "--ff3", "0", "--digital"});
    const QJsonObject o = succeeded(run);
    QCOMPARE(o["method"].toString(), QStringLiteral("pid-ff"));
    QVERIFY(o["converted_from"].isNull());
    XYT_COMPARE_NEAR(o["digital"].toObject()["tracking"].toObject()["rmse"].toDouble(), 5.87346,
                     1e-5, 0.0);
    // Invariant: with FF0..FF3 and the bias 0 the run with the feedforward is the run without.
    // The run with one takes it as a second input of the discretized loop (simulateLoop), so
    // the two agree to the round-off of different arithmetic over 13001 steps: 1e-9.
    XYT_COMPARE_NEAR(o["tracking"].toObject()["rmse"].toDouble(),
                     o["tracking_without_feedforward_rmse"].toDouble(), 1e-9, 0.0);
    // The loop's margins are reported (PI + lower base: a stable loop, a finite phase margin).
    const QJsonObject margins = o["margins"].toObject();
    QVERIFY(margins["closed_loop_stable"].toBool());
    QVERIFY(margins["phase_margin"].toObject()["deg"].isDouble());
}

void TstCliPid::quinticWithTrajectoryDerivativesIsTheSessionsRun() {
    // Invariant: simulate --method pid-ff is the session's evaluation (evaluateAxis) of the axis
    // it describes: same settings, same figures (1e-12: the JSON round trip).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath("run.csv");
    const auto run = xyt::test::runCli({"simulate",   "--method",
                                        "pid-ff",     "--preset",
                                        "lower-base", "--trajectory",
                                        "quintic",    "--xf",
                                        "300",        "--tf",
                                        "60",         "--duration",
                                        "80",         "--d",
                                        "0.0005",     "--derivative-filter",
                                        "0.005",      "--trajectory-derivatives",
                                        "--digital",  "--csv",
                                        csv});
    const QJsonObject o = succeeded(run);
    QCOMPARE(o["trajectory"].toString(), QStringLiteral("quintic"));
    QCOMPARE(o["gains"].toObject()["command_derivatives"].toString(), QStringLiteral("trajectory"));
    xyt::Session s = xyt::Session::paperDefault();
    xyt::AxisSettings& axis = s.axes[0];
    axis.method = xyt::DesignMethod::PidFeedforward;
    axis.parameters = {
        {"p", 30.0 * kUnit},  {"i", 16.0 / kK0 * kUnit},    {"d", 0.0005},
        {"ff0", 0.0},         {"ff1", kA2 * kUnit / kK0},   {"ff2", kA1 * kUnit / kK0},
        {"ff3", kUnit / kK0}, {"derivative_filter", 0.005}, {"command_derivatives", 1.0}};
    s.axes[1] = axis;
    s.trajectory.profile = xyt::MoveProfile::Quintic;
    s.trajectory.xf = 300.0;
    s.trajectory.tfSeconds = 60.0;
    s.trajectory.durationSeconds = 80.0;
    const xyt::AxisEvaluation a = xyt::evaluateAxis(s, 0);
    QVERIFY2(a.ok, a.error.text.c_str());
    QVERIFY(a.digital);
    // The gains typed above equal the CLI's defaults up to one rounding: 1e-9 on the figures.
    XYT_COMPARE_NEAR(o["tracking"].toObject()["rmse"].toDouble(), a.metrics.rmse, 1e-9, 0.0);
    XYT_COMPARE_NEAR(o["digital"].toObject()["tracking"].toObject()["rmse"].toDouble(),
                     a.digital->metrics.rmse, 1e-9, 0.0);
    // The reference is the quintic (QuinticTrajectory's closed form), not the cubic: the CSV's
    // r column, 10 significant digits.
    const xyt::QuinticTrajectory quintic(0.0, 300.0, 0.0, 60.0);
    const QList<QByteArray> lines = readAll(csv).split('\n');
    QVERIFY(lines.size() > 2001);
    const QList<QByteArray> row = lines[2001].split(','); // t = 20 s
    XYT_COMPARE_NEAR(row[0].toDouble(), 20.0, 1e-9, 0.0);
    XYT_COMPARE_NEAR(row[1].toDouble(), quintic.position(20.0), 1e-9, 0.0);
    const xyt::CubicTrajectory cubic(0.0, 300.0, 0.0, 60.0);
    QVERIFY(std::abs(quintic.position(20.0) - cubic.position(20.0)) > 1.0);
}

void TstCliPid::badGainsExitWithTwoNamingTheOption_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("option");
    const QStringList pid = QStringList{"simulate", "--method", "pid-ff"} + kPaperMove;
    // The method's parameter ranges (pidFeedforwardParameters: gains >= 0).
    QTest::newRow("negative FF1") << pid + QStringList{"--ff1", "-1"} << "--ff1";
    QTest::newRow("negative max_error_i")
        << pid + QStringList{"--max-error-i", "-1"} << "--max-error-i";
    QTest::newRow("FF1 not a number") << pid + QStringList{"--ff1", "nan"} << "--ff1";
    // designPidFeedforward: 0 < Tf < Ts/pi = 0.00318 s puts the corner beyond Nyquist.
    QTest::newRow("derivative filter below Ts/pi")
        << pid + QStringList{"--derivative-filter", "0.001"} << "--derivative-filter";
    // The session has no sine trajectory.
    QTest::newRow("sine with pid-ff")
        << QStringList{"simulate",   "--method",     "pid-ff", "--preset",
                       "lower-base", "--trajectory", "sine",   "--amplitude",
                       "25",         "--omega",      "0.06"}
        << "--trajectory";
    QTest::newRow("Guillemin-Truxal option with pid-ff")
        << pid + QStringList{"--wn", "2"} << "--wn";
    QTest::newRow("PID gain without pid-ff")
        << QStringList{"simulate"} + kPaperMove + QStringList{"--p", "0.03"} << "--p";
    QTest::newRow("FF1 with --ff-from-model")
        << pid + QStringList{"--ff-from-model", "--ff1", "0.04"} << "--ff1";
    QTest::newRow("the Guillemin-Truxal PI's option")
        << pid + QStringList{"--digital", "--anti-windup", "none"} << "--anti-windup";
    // A negative plant gain makes the preset's PI's default I negative: the plant is named.
    QTest::newRow("default I from a negative k0") << pid + QStringList{"--k0", "-77.8"} << "--k0";
    QTest::newRow("unknown method")
        << QStringList{"simulate", "--method", "zpetc"} + kPaperMove << "--method";
}

void TstCliPid::badGainsExitWithTwoNamingTheOption() {
    QFETCH(QStringList, args);
    QFETCH(QString, option);
    const auto run = xyt::test::runCli(args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    const QString err = QString::fromUtf8(run.err);
    // One line: "xytune-cli simulate: --ff1: <reason>".
    QVERIFY2(err.startsWith("xytune-cli simulate: " + option + ": "), qPrintable(err));
    QCOMPARE(err.count('\n'), qsizetype(1));
}

void TstCliPid::tuneMeetsTheTargetMargin() {
    // Source: the closed form of tunePidForMargin checks itself back (achieved crossover and
    // margin from the gains); the test recomputes |L(j wc)| = 1 and arg L = -180 + PM from the
    // printed gains with L = (P + I/(jw) + D jw)/u * k0/((jw)^3 + a1 (jw)^2 + a2 jw).
    const auto run = xyt::test::runCli(
        {"tune", "--preset", "lower-base", "--crossover", "20", "--phase-margin", "60"});
    const QJsonObject o = succeeded(run);
    QCOMPARE(o["status"].toString(), QStringLiteral("ok"));
    QCOMPARE(o["structure"].toString(), QStringLiteral("pid")); // the default
    const QJsonObject achieved = o["achieved"].toObject();
    XYT_COMPARE_NEAR(achieved["crossover"].toDouble(), 20.0, 1e-6, 0.0);
    XYT_COMPARE_NEAR(achieved["phase_margin"].toDouble(), 60.0, 1e-6, 0.0);
    const QJsonObject gains = o["gains"].toObject();
    const double p = gains["p"].toDouble(), i = gains["i"].toDouble(), d = gains["d"].toDouble();
    const std::complex<double> jw(0.0, 20.0);
    const std::complex<double> loop =
        (p + i / jw + d * jw) / kUnit * (kK0 / (jw * jw * jw + kA1 * jw * jw + kA2 * jw));
    // A handful of roundings of order-one terms: 1e-12.
    XYT_COMPARE_NEAR(std::abs(loop), 1.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(180.0 + std::arg(loop) * 180.0 / std::numbers::pi, 60.0, 1e-12, 0.0);
    // The PID rule's third condition Ti = 4 Td (pid_tuning.h): I = P/(4 Td), D = P Td.
    XYT_COMPARE_NEAR(i * d, p * p / 4.0, 1e-12, 0.0);
    QVERIFY(o["closed_loop_stable"].toBool());
}

void TstCliPid::tuneSaysWhenThePhaseIsOutOfReach() {
    // Closed form: arg G(j20) = -90 - atan2(a1 w, a2 - w^2) = -127.5 deg, so a 60 deg margin
    // needs a controller phase of 60 - 90 + 37.5 = +7.5 deg, which a PI (-90..0 deg) lacks.
    const double w = 20.0;
    const double needed = 60.0 - 90.0 + std::atan2(kA1 * w, kA2 - w * w) * 180.0 / std::numbers::pi;
    QVERIFY(needed > 0.0);
    const auto run = xyt::test::runCli({"tune", "--preset", "lower-base", "--crossover", "20",
                                        "--phase-margin", "60", "--structure", "pi"});
    const QJsonObject o = succeeded(run); // exit 0: a target out of reach is a status
    QCOMPARE(o["status"].toString(), QStringLiteral("unreachable"));
    QVERIFY(!o["reason"].toString().isEmpty());
    QVERIFY(o["gains"].isNull());
    XYT_COMPARE_NEAR(o["required_controller_phase"].toDouble(), needed, 1e-12, 0.0);
}

void TstCliPid::tuneFromTheRelayExperiment() {
    // Source: the core's exact limit cycle (relayLimitCycle, Tsypkin's method) called here, and
    // the rules' definitions (relay_experiment.h): Ziegler-Nichols PI P = 0.45 Ku, Ti = Tu/1.2;
    // Tyreus-Luyben PI P = Ku/3.2, Ti = 2.2 Tu.
    const auto run =
        xyt::test::runCli({"tune", "--preset", "lower-base", "--relay", "1", "--structure", "pi"});
    const QJsonObject o = succeeded(run);
    const xyt::RelayLimitCycle cycle = xyt::relayLimitCycle({kK0, kA1, kA2}, kUnit, 1.0);
    QVERIFY(cycle.found);
    const QJsonObject relay = o["relay"].toObject();
    XYT_COMPARE_NEAR(relay["period"].toDouble(), cycle.periodSeconds, 1e-12, 0.0);
    XYT_COMPARE_NEAR(relay["limit_cycle_amplitude"].toDouble(), cycle.amplitudeMm, 1e-12, 0.0);
    const double ku = relay["ultimate_gain"].toDouble(), tu = relay["period"].toDouble();
    // Ku = 4 d/(pi a) (the relay's describing-function gain at the exact amplitude).
    XYT_COMPARE_NEAR(ku, 4.0 / (std::numbers::pi * cycle.amplitudeMm), 1e-12, 0.0);
    const QJsonObject zn = o["ziegler_nichols"].toObject();
    XYT_COMPARE_NEAR(zn["p"].toDouble(), 0.45 * ku, 1e-12, 0.0);
    XYT_COMPARE_NEAR(zn["i"].toDouble(), 0.45 * ku / (tu / 1.2), 1e-12, 0.0);
    const QJsonObject tl = o["tyreus_luyben"].toObject();
    XYT_COMPARE_NEAR(tl["p"].toDouble(), ku / 3.2, 1e-12, 0.0);
    XYT_COMPARE_NEAR(tl["i"].toDouble(), ku / 3.2 / (2.2 * tu), 1e-12, 0.0);
    // The describing function's closed form: w180 = sqrt(a2), Ku = u a1 a2/k0.
    const QJsonObject df = o["describing_function"].toObject();
    XYT_COMPARE_NEAR(df["period"].toDouble(), 2.0 * std::numbers::pi / std::sqrt(kA2), 1e-12, 0.0);
    XYT_COMPARE_NEAR(df["ultimate_gain"].toDouble(), kUnit * kA1 * kA2 / kK0, 1e-12, 0.0);

    // --crossover and --relay are exclusive: refused naming both.
    const auto both = xyt::test::runCli({"tune", "--preset", "lower-base", "--relay", "1",
                                         "--crossover", "20", "--phase-margin", "60"});
    QCOMPARE(both.exitCode, 2);
    QVERIFY2(both.err.contains("--relay") && both.err.contains("--crossover"),
             both.err.constData());
}

void TstCliPid::exportWritesLinuxCncPins() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString session = dir.filePath("paper.json"), hal = dir.filePath("paper.hal"),
                  halFf = dir.filePath("paper_ff.hal");
    QCOMPARE(xyt::test::runCli({"new", "-o", session}).exitCode, 0);
    QCOMPARE(xyt::test::runCli({"export", session, "--format", "linuxcnc", "-o", hal}).exitCode, 0);
    const QByteArray text = readAll(hal);
    // Braga et al.'s PI in LinuxCNC's units (linuxcnc_export.h: P = kp u, 17 digits, so the
    // value reads back to the same double).
    QVERIFY2(text.contains("setp pid.0.Pgain 0.029999999999999999\n"), text.constData());
    const std::map<QString, double> pins = setpValues(text);
    QCOMPARE(pins.at("0.Pgain"), 30.0 * kUnit);
    QVERIFY2(text.contains("FERROR = "), text.constData());
    QVERIFY2(text.contains("setp pid.0.FF1 0\n"), text.constData()); // the PI has no feedforward

    QCOMPARE(xyt::test::runCli(
                 {"export", session, "--format", "linuxcnc", "-o", halFf, "--ff-from-model"})
                 .exitCode,
             0);
    // modelFeedforwardGains: FF1 = a2 u/k0 (one rounding apart from this expression).
    const std::map<QString, double> ff = setpValues(readAll(halFf));
    XYT_COMPARE_NEAR(ff.at("0.FF1"), kA2 * kUnit / kK0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ff.at("0.FF3"), kUnit / kK0, 1e-15, 0.0);

    // --ff-from-model belongs to the LinuxCNC format.
    const auto c = xyt::test::runCli(
        {"export", session, "--format", "c", "-o", dir.filePath("x.h"), "--ff-from-model"});
    QCOMPARE(c.exitCode, 2);
    QVERIFY2(c.err.contains("--ff-from-model"), c.err.constData());
}

void TstCliPid::exportRefusesPolePlacementNamingTheAxis() {
    // linuxcnc_export.h: a pole-placement axis has no pid equivalent, refused by its field.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("pp.json"), hal = dir.filePath("pp.hal");
    QCOMPARE(xyt::test::runCli({"new", "-o", path}).exitCode, 0);
    QJsonObject doc = QJsonDocument::fromJson(readAll(path)).object();
    QJsonArray axes = doc["axes"].toArray();
    QJsonObject y = axes[1].toObject();
    y["method"] = "pole-placement-zpetc";
    axes[1] = y;
    doc["axes"] = axes;
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(QJsonDocument(doc).toJson());
    f.close();
    const auto run = xyt::test::runCli({"export", path, "--format", "linuxcnc", "-o", hal});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("axes[1].method"), run.err.constData());
    QVERIFY(!QFile::exists(hal));
}

void TstCliPid::helpListsTheNewOptions() {
    const auto general = xyt::test::runCli({"--help"});
    QCOMPARE(general.exitCode, 0);
    QVERIFY(general.out.contains("\n  tune "));
    const auto tune = xyt::test::runCli({"tune", "--help"});
    QCOMPARE(tune.exitCode, 0);
    QVERIFY(tune.out.startsWith("usage: xytune-cli tune [OPTIONS]\n"));
    for (const char* word :
         {"--crossover", "--phase-margin", "--relay", "--structure", "\"unreachable\""})
        QVERIFY2(tune.out.contains(word), word);
    QVERIFY(!tune.out.contains("\n  simulate "));
    const auto simulate = xyt::test::runCli({"simulate", "--help"});
    for (const char* word : {"--method pid-ff", "--ff-from-model", "--max-error-i",
                             "--trajectory-derivatives", "cubic|quintic"})
        QVERIFY2(simulate.out.contains(word), word);
    const auto exportHelp = xyt::test::runCli({"export", "--help"});
    QVERIFY(exportHelp.out.contains("linuxcnc"));
    QVERIFY(exportHelp.out.contains("--ff-from-model"));
}

QTEST_APPLESS_MAIN(TstCliPid)
#include "tst_cli_pid.moc"
