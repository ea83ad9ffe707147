// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI contract for gt / simulate / report: keys, values equal to the core's,
// the CSV columns, and exit code 2 with one stderr line naming the argument for bad input.
#include "core/design/guillemin_truxal.h"
#include "core/simulation/metrics.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <cstdlib>
#include <numbers>

namespace {
std::vector<double> jsonNumbers(const QJsonValue& v) {
    std::vector<double> out;
    for (const QJsonValue& x : v.toArray())
        out.push_back(x.toDouble());
    return out;
}

/// Qt prints JSON doubles in the shortest form that reads back exactly, so values equal the
/// core's to the last bit; 1e-15 relative only allows for the text round trip.
void compareArray(const QJsonValue& v, const std::vector<double>& expected) {
    const std::vector<double> got = jsonNumbers(v);
    QCOMPARE(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        XYT_COMPARE_NEAR(got[i], expected[i], 1e-15, 0.0);
}

void requireNoNonFinite(const QByteArray& out) {
    const QByteArray lower = out.toLower();
    QVERIFY2(!lower.contains("nan") && !lower.contains("inf"), out.constData());
}
} // namespace

class TstCliGt : public QObject {
    Q_OBJECT
private slots:
    void gtMatchesCore_data();
    void gtMatchesCore();
    void simulateMatchesCoreAndWritesCsv_data();
    void simulateMatchesCoreAndWritesCsv();
    void unstableDesignIsNotAnError();
    void simulateDigitalMatchesCore();
    void automaticDurationIncludesTheSettle();
    void commandHelpIsThatCommandsOnly();
    void reportReadsTheDefaultDesign();
    void badInputExitsWithTwo_data();
    void badInputExitsWithTwo();
};

void TstCliGt::gtMatchesCore_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<double>("k0");
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::addColumn<double>("wn");
    QTest::addColumn<double>("kp");
    QTest::newRow("Braga et al.'s lower base")
        << QStringList{"--preset", "lower-base", "--wn", "2", "--kp", "30"} << 77.8 << 125.3
        << 3665.0 << 2.0 << 30.0;
    QTest::newRow("upper base, preset defaults")
        << QStringList{"--preset", "upper-base"} << 24.44 << 68.18 << 863.0 << 1.0 << 30.0;
    QTest::newRow("explicit plant, --name=value")
        << QStringList{"--k0=10", "--a1", "5", "--a2", "6", "--wn", "0.5", "--kp", "2"} << 10.0
        << 5.0 << 6.0 << 0.5 << 2.0;
    QTest::newRow("preset with a1 overridden")
        << QStringList{"--preset", "lower-base", "--a1", "100"} << 77.8 << 100.0 << 3665.0 << 2.0
        << 30.0;
}

void TstCliGt::gtMatchesCore() {
    QFETCH(QStringList, args);
    QFETCH(double, k0);
    QFETCH(double, a1);
    QFETCH(double, a2);
    QFETCH(double, wn);
    QFETCH(double, kp);
    const auto run = xyt::test::runCli(QStringList{"gt"} + args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    requireNoNonFinite(run.out);
    const QJsonObject o = run.json();
    const xyt::GtDesign d = xyt::designGuilleminTruxal({k0, a1, a2}, wn, kp);
    const std::pair<const char*, double> scalars[] = {
        {"f1", d.f1},     {"f2", d.f2}, {"f3", d.f3}, {"psi1", d.psi1},
        {"psi2", d.psi2}, {"kp", d.kp}, {"ki", d.ki}};
    for (const auto& [key, value] : scalars) {
        QVERIFY2(o.contains(key), key);
        XYT_COMPARE_NEAR(o[key].toDouble(), value, 1e-15, 0.0);
    }
    // Polynomials of s in descending powers (the CLI convention).
    compareArray(o["reference_model"].toObject()["num"], d.referenceModel.num().descending());
    compareArray(o["reference_model"].toObject()["den"], d.referenceModel.den().descending());
    compareArray(o["controller"].toObject()["num"], d.controller.num().descending());
    compareArray(o["controller"].toObject()["den"], d.controller.den().descending());
    const QJsonObject cl = o["closed_loop"].toObject();
    compareArray(cl["num"], d.closedLoop.num().descending());
    compareArray(cl["den"], d.closedLoop.den().descending());
    const QJsonArray poles = cl["poles"].toArray();
    QCOMPARE(poles.size(), qsizetype(4));
    for (qsizetype i = 0; i < poles.size(); ++i) {
        XYT_COMPARE_NEAR(poles[i].toArray()[0].toDouble(), d.closedLoopPoles[std::size_t(i)].real(),
                         1e-15, 0.0);
        XYT_COMPARE_NEAR(poles[i].toArray()[1].toDouble(), d.closedLoopPoles[std::size_t(i)].imag(),
                         1e-15, 0.0);
    }
    QCOMPARE(o["stable"].toBool(), d.stable);
}

void TstCliGt::simulateMatchesCoreAndWritesCsv_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("cubic");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("duration");
    QTest::newRow("paper cubic 0 -> 600 in 130 s, lower base")
        << QStringList{"--preset", "lower-base", "--trajectory", "cubic",      "--xf",
                       "600",      "--tf",       "130",          "--duration", "130"}
        << true << 0.01 << 130.0;
    QTest::newRow("circle axis: 25 mm sine at 0.06 rad/s, upper base, ramp-in 10 s")
        << QStringList{"--preset",   "upper-base", "--trajectory", "sine", "--amplitude", "25",
                       "--omega",    "0.06",       "--phase-deg",  "90",   "--ramp-in",   "10",
                       "--duration", "60",         "--dt",         "0.02"}
        << false << 0.02 << 60.0;
}

void TstCliGt::simulateMatchesCoreAndWritesCsv() {
    QFETCH(QStringList, args);
    QFETCH(bool, cubic);
    QFETCH(double, dt);
    QFETCH(double, duration);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csvPath = dir.filePath("run.csv");
    const auto run =
        xyt::test::runCli(QStringList{"simulate"} + args + QStringList{"--csv", csvPath});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    requireNoNonFinite(run.out);
    // Tracking figures and the closed loop's unit-step figures under their own keys.
    QVERIFY(!run.json().contains("metrics"));
    const QJsonObject m = run.json()["tracking"].toObject();
    const QJsonObject stepJson = run.json()["step_response"].toObject();
    for (const char* key : {"rmse", "max_abs_error", "max_abs_error_pct", "max_abs_u", "saturated",
                            "saturated_time", "itae"})
        QVERIFY2(m.contains(key), key);
    for (const char* key : {"stable", "final_value", "settling_time", "overshoot_pct", "peak_time"})
        QVERIFY2(stepJson.contains(key), key);
    QCOMPARE(run.json()["move_and_settle"].isNull(), !cubic);

    // The same run through the core: the preset's unit scale (0.001 m per mm), umax 2.5 V.
    const auto preset = xyt::findGtPreset(args[1].toStdString());
    const xyt::GtDesign d =
        xyt::designGuilleminTruxal(preset->plant, preset->omegaNRadPerSec, preset->kp);
    xyt::LoopSimulationOptions options;
    options.dtSeconds = dt;
    options.umaxVolts = 2.5;
    options.modelUnitsPerPositionUnit = preset->modelUnitsPerPositionUnit;
    const auto times = xyt::sampleTimes(duration, dt);
    const xyt::CubicTrajectory c(0.0, 600.0, 0.0, 130.0);
    const xyt::Sinusoid s{25.0, 0.06, std::numbers::pi / 2.0, 0.0, 10.0};
    const std::vector<double> r = cubic
                                      ? xyt::sampled([&](double t) { return c.position(t); }, times)
                                      : xyt::sampled([&](double t) { return s.value(t); }, times);
    const xyt::SimulationResult core =
        xyt::simulateLoop(d.plant.transferFunction(), d.controller, r, options);
    const xyt::TrackingMetrics tm = xyt::trackingMetrics(core);
    const xyt::StepCharacteristics step = xyt::stepCharacteristics(d.closedLoop);
    // Same computation, same binary code path: exact up to the JSON text round trip, except
    // the phase (90 degrees -> rad, 1 ulp): 1e-12 relative.
    XYT_COMPARE_NEAR(m["rmse"].toDouble(), tm.rmse, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m["max_abs_error"].toDouble(), tm.maxAbsError, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m["max_abs_error_pct"].toDouble(), tm.maxAbsErrorPct, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m["max_abs_u"].toDouble(), tm.maxAbsU, 1e-12, 0.0);
    QCOMPARE(m["saturated"].toBool(), tm.saturated);
    XYT_COMPARE_NEAR(m["saturated_time"].toDouble(), tm.saturatedTimeSeconds, 1e-12, 0.0);
    XYT_COMPARE_NEAR(stepJson["settling_time"].toDouble(), step.settlingTimeSeconds, 1e-15, 0.0);
    XYT_COMPARE_NEAR(stepJson["overshoot_pct"].toDouble(), step.overshootPct, 1e-15, 0.0);
    XYT_COMPARE_NEAR(stepJson["peak_time"].toDouble(), step.peakTimeSeconds, 1e-15, 0.0);
    XYT_COMPARE_NEAR(m["itae"].toDouble(), tm.itae, 1e-12, 0.0);
    if (cubic)
        QVERIFY(
            !tm.saturated); // Braga et al.: no saturation on the cubic (0.33 V, see tst_simulation)

    // The CSV: header t,r,y,e,u and one row per sample, written with 10 significant digits.
    QFile file(csvPath);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    QCOMPARE(file.readLine().trimmed(), QByteArray("t,r,y,e,u"));
    std::size_t k = 0;
    while (!file.atEnd()) {
        const QList<QByteArray> cells = file.readLine().trimmed().split(',');
        QCOMPARE(cells.size(), qsizetype(5));
        QVERIFY(k < core.t.size());
        const double expected[] = {core.t[k], core.r[k], core.y[k], core.e[k], core.u[k]};
        for (int j = 0; j < 5; ++j)
            XYT_COMPARE_NEAR(cells[j].toDouble(), expected[j], 1e-9, 1e-12);
        ++k;
    }
    QCOMPARE(k, core.t.size());
}

// simulate --digital runs the sampled-data loop of the core with the options given;
// its figures equal simulateSampledPi's (JSON round trip only), and the options are echoed.
void TstCliGt::simulateDigitalMatchesCore() {
    QTemporaryDir dir;
    const QString csvPath = dir.filePath("digital.csv");
    const auto run = xyt::test::runCli({"simulate",
                                        "--preset",
                                        "upper-base",
                                        "--trajectory",
                                        "cubic",
                                        "--xf",
                                        "600",
                                        "--tf",
                                        "130",
                                        "--duration",
                                        "160",
                                        "--digital",
                                        "--controller-ts",
                                        "0.02",
                                        "--discretization",
                                        "backward-euler",
                                        "--delay-samples",
                                        "1",
                                        "--encoder-resolution",
                                        "0.001",
                                        "--dac-bits",
                                        "16",
                                        "--anti-windup",
                                        "back-calculation",
                                        "--tracking-time",
                                        "3",
                                        "--csv",
                                        csvPath});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject d = run.json()["digital"].toObject();
    QCOMPARE(d["controller_ts"].toDouble(), 0.02);
    QCOMPARE(d["discretization"].toString(), QString("backward-euler"));
    QCOMPARE(d["anti_windup"].toString(), QString("back-calculation"));
    QCOMPARE(d["delay_samples"].toInt(), 1);
    QCOMPARE(d["dac_bits"].toInt(), 16);
    const auto preset = *xyt::findGtPreset("upper-base");
    const auto design = xyt::designGuilleminTruxal(preset.plant, preset.omegaNRadPerSec, preset.kp);
    const xyt::DigitalPi pi =
        xyt::digitalPi(design.kp, design.ki, 0.02, xyt::PiDiscretization::BackwardEuler,
                       xyt::AntiWindup::BackCalculation, 3.0);
    xyt::SampledDataOptions o;
    o.delaySamples = 1;
    o.encoderResolution = 0.001;
    o.dacBits = 16;
    o.umaxVolts = 2.5;
    const xyt::CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    const auto times = xyt::sampleTimes(160.0, 0.02);
    const auto core =
        xyt::simulateSampledPi(preset.plant.transferFunction(), pi,
                               xyt::sampled([&](double t) { return cubic.position(t); }, times), o,
                               preset.modelUnitsPerPositionUnit);
    const xyt::TrackingMetrics m = xyt::trackingMetrics(core.result);
    QCOMPARE(d["samples"].toDouble(), static_cast<double>(times.size()));
    XYT_COMPARE_NEAR(d["tracking"]["rmse"].toDouble(), m.rmse, 1e-15, 0.0);
    XYT_COMPARE_NEAR(d["tracking"]["max_abs_u"].toDouble(), m.maxAbsU, 1e-15, 0.0);
    QCOMPARE(d["poles"].toArray().size(), 3 + 2 + 1); // plant, PI (I, e[k-1]), one delay sample
    QVERIFY(d["warnings"].isArray());
    // --csv holds the digital run beside the continuous one (engineers compare it with their
    // firmware's logs): at each row of --dt (0.01 s) the controller's last sample at or before
    // t (every other row at --controller-ts 0.02), bit for bit simulateSampledPi's.
    QFile csv(csvPath);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
    QCOMPARE(lines[0], QByteArray("t,r,y,e,u,t_digital,y_digital,e_digital,u_digital"));
    QCOMPARE(lines.size(), qsizetype(1 + 16001));
    for (qsizetype k = 1; k < lines.size(); ++k) {
        const QList<QByteArray> cells = lines[k].split(',');
        QCOMPARE(cells.size(), qsizetype(9));
        const std::size_t j =
            static_cast<std::size_t>(k - 1) / 2; // t = (k - 1) 0.01 holds sample floor((k - 1) / 2)
        QVERIFY2(std::strtod(cells[5].constData(), nullptr) == core.result.t[j] &&
                     std::strtod(cells[6].constData(), nullptr) == core.result.y[j] &&
                     std::strtod(cells[7].constData(), nullptr) == core.result.e[j] &&
                     std::strtod(cells[8].constData(), nullptr) == core.result.u[j],
                 lines[k].constData());
    }
    // Digital options without --digital are refused naming the option.
    const auto refused =
        xyt::test::runCli({"simulate", "--preset", "upper-base", "--trajectory", "cubic", "--xf",
                           "600", "--tf", "130", "--dac-bits", "16"});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains("--dac-bits: needs --digital"), refused.err.constData());
}

void TstCliGt::unstableDesignIsNotAnError() {
    // kp = 10000 is past the Routh bound kp < a1 a2 / k0 = 5903 of the lower base: exit 0, the
    // result says stable: false, step figures are null, every number is finite.
    const auto run = xyt::test::runCli({"simulate", "--preset", "lower-base", "--kp", "10000",
                                        "--trajectory", "cubic", "--xf", "600", "--tf", "130"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    requireNoNonFinite(run.out);
    const QJsonObject o = run.json();
    QCOMPARE(o["stable"].toBool(true), false);
    QVERIFY(o["step_response"].toObject()["settling_time"].isNull());
    QVERIFY(o["step_response"].toObject()["overshoot_pct"].isNull());
    QCOMPARE(o["step_response"].toObject()["stable"].toBool(true), false);
    QVERIFY(o["tracking"].toObject()["rmse"].isDouble());
    // No settle to wait for: the automatic run is the move alone.
    QCOMPARE(o["duration"].toDouble(), 130.0);
    QCOMPARE(o["move_and_settle"].toObject()["settled"].toBool(true), false);
    const auto gt = xyt::test::runCli({"gt", "--preset", "lower-base", "--kp", "10000"});
    QCOMPARE(gt.exitCode, 0);
    QCOMPARE(gt.json()["stable"].toBool(true), false);
}

void TstCliGt::automaticDurationIncludesTheSettle() {
    // Without --duration a cubic runs past tf until the slowest closed-loop pole has
    // brought |e| into the window. The lower base's slow pole is p = -0.00693 rad/s (its PI zero
    // at -psi1), so the estimate is ln(|e(tf)| / w) / |p| with e(tf) the error at the last
    // sample of the move (checked against a core run of the move alone).
    // A 400 s move: the cap is tf + 3 moves = 1600 s, long enough for the slow pole to bring
    // |e| from ~1.2 mm into 0.01 mm, so the slow mode dominates the settle (at tf = 130 s the
    // lower base needs ~860 s, beyond its 520 s cap: the upper base's case below).
    const auto run = xyt::test::runCli({"simulate", "--preset", "lower-base", "--trajectory",
                                        "cubic", "--xf", "600", "--tf", "400"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    requireNoNonFinite(run.out);
    const QJsonObject o = run.json();
    const auto preset = xyt::findGtPreset("lower-base");
    const xyt::GtDesign d =
        xyt::designGuilleminTruxal(preset->plant, preset->omegaNRadPerSec, preset->kp);
    xyt::LoopSimulationOptions options;
    options.umaxVolts = 2.5;
    options.modelUnitsPerPositionUnit = preset->modelUnitsPerPositionUnit;
    const xyt::CubicTrajectory c(0.0, 600.0, 0.0, 400.0);
    const auto moveRun = xyt::simulateLoop(
        d.plant.transferFunction(), d.controller,
        xyt::sampled([&](double t) { return c.position(t); }, xyt::sampleTimes(400.0, 0.01)),
        options);
    double slowest = -INFINITY;
    for (const auto& p : d.closedLoopPoles)
        slowest = std::max(slowest, p.real());
    const double estimate = std::log(std::abs(moveRun.e.back()) / 0.01) / -slowest;
    const QJsonObject choice = o["duration_choice"].toObject();
    QVERIFY(choice["automatic"].toBool());
    QVERIFY(choice["includes_settle"].toBool());
    XYT_COMPARE_NEAR(choice["settle_estimate"].toDouble(), estimate, 1e-12, 0.0);
    // tf + 1.5 x estimate + a tenth of the move, under the cap tf + 3 x 400 s.
    XYT_COMPARE_NEAR(o["duration"].toDouble(), 400.0 + 1.5 * estimate + 40.0, 1e-12, 0.0);
    QCOMPARE(choice["cap"].toDouble(), 1600.0);
    // The run settles within it: the measured settle time is within 5 % of the estimate (the
    // slow mode dominates after tf) and the final error is inside the window.
    const QJsonObject ms = o["move_and_settle"].toObject();
    QVERIFY(ms["settled"].toBool());
    XYT_COMPARE_NEAR(ms["settle_time"].toDouble(), estimate, 0.05, 0.0);
    QVERIFY(std::abs(ms["final_error"].toDouble()) <= 0.01);
    QCOMPARE(ms["window_mm"].toDouble(), 0.01);
    // The final-position overshoot is max (y - 600) over the run (every y lies in the CSV's
    // core-equal run: checked in simulateMatchesCoreAndWritesCsv); the type-2 loop must overshoot
    // the target (its step error integrates to zero, see core/study/specification.h).
    QVERIFY(ms["final_overshoot_mm"].toDouble() > 0.0);
    // The upper base needs more than the cap: the run is cut to it and says so.
    const auto upper = xyt::test::runCli({"simulate", "--preset", "upper-base", "--trajectory",
                                          "cubic", "--xf", "600", "--tf", "130"});
    QCOMPARE(upper.exitCode, 0);
    QVERIFY(upper.json()["duration_choice"].toObject()["capped"].toBool());
    QCOMPARE(upper.json()["duration"].toDouble(), 520.0); // tf + 3 x 130 s
    QCOMPARE(upper.json()["move_and_settle"].toObject()["settled"].toBool(true), false);
    QVERIFY(upper.json()["move_and_settle"].toObject()["settle_time"].isNull());
}

void TstCliGt::commandHelpIsThatCommandsOnly() {
    // COMMAND --help printed the general help of every command.
    const QStringList commands = {"gt",     "simulate", "report", "new",   "export",
                                  "rlocus", "sweep",    "pp",     "zpetc", "contour"};
    auto entry = [](const QString& c) { return "\n  " + c + " "; };
    const auto general = xyt::test::runCli({"--help"});
    QCOMPARE(general.exitCode, 0);
    for (const QString& c : commands)
        QVERIFY2(QString::fromUtf8(general.out).contains(entry(c)), qPrintable(c));
    for (const QString& c : commands) {
        const auto run = xyt::test::runCli({c, "--help"});
        QCOMPARE(run.exitCode, 0);
        const QString text = QString::fromUtf8(run.out);
        QVERIFY2(text.startsWith("usage: xytune-cli " + c + " [OPTIONS]\n"), qPrintable(text));
        QVERIFY2(text.contains(entry(c)), qPrintable(text));
        for (const QString& other : commands)
            if (other != c)
                QVERIFY2(!text.contains(entry(other)), qPrintable(c + " shows " + other));
        QVERIFY(text.size() < general.out.size() / 2);
    }
}

void TstCliGt::reportReadsTheDefaultDesign() {
    const auto run = xyt::test::runCli({"report"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    requireNoNonFinite(run.out);
    const QString text = QString::fromUtf8(run.out);
    // Both bases with the values of Eq. 17-18 and 15 (upper f1 = 68.18, not the printed 64.18).
    QVERIFY2(text.contains("f1 = 62.6500  f2 = 916.2500  f3 = 291.7500"), qPrintable(text));
    QVERIFY2(text.contains("f1 = 68.1800  f2 = 863.0000  f3 = 733.2000"), qPrintable(text));
    QVERIFY(text.contains("cubic 0 -> 600 in 130 s"));
    QVERIFY(text.contains("saturated no"));
    QVERIFY(text.contains("Circle contour"));
}

void TstCliGt::badInputExitsWithTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("argument");
    const QStringList cubic{"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                            "--xf",     "600",      "--tf",       "130"};
    QTest::newRow("wn < 0") << QStringList{"gt", "--preset", "lower-base", "--wn", "-1"} << "--wn";
    QTest::newRow("wn = 0") << QStringList{"gt", "--preset", "lower-base", "--wn", "0"} << "--wn";
    QTest::newRow("wn NaN as text")
        << QStringList{"gt", "--preset", "lower-base", "--wn", "nan"} << "--wn";
    QTest::newRow("kp inf as text")
        << QStringList{"gt", "--preset", "lower-base", "--kp", "inf"} << "--kp";
    QTest::newRow("kp = 0") << QStringList{"gt", "--preset", "lower-base", "--kp", "0"} << "--kp";
    QTest::newRow("kp not a number")
        << QStringList{"gt", "--preset", "lower-base", "--kp", "thirty"} << "--kp";
    QTest::newRow("k0 = 0") << QStringList{"gt", "--k0", "0", "--a1", "1", "--a2",
                                           "1",  "--wn", "1", "--kp", "1"}
                            << "--k0";
    QTest::newRow("a1 -Infinity") << QStringList{"gt", "--preset", "upper-base", "--a1",
                                                 "-Infinity"}
                                  << "--a1";
    QTest::newRow("a2 missing without preset")
        << QStringList{"gt", "--k0", "1", "--a1", "1", "--wn", "1", "--kp", "1"} << "--a2";
    QTest::newRow("unknown preset") << QStringList{"gt", "--preset", "middle-base"} << "--preset";
    QTest::newRow("unknown option")
        << QStringList{"gt", "--preset", "lower-base", "--kd", "1"} << "--kd";
    QTest::newRow("option given twice")
        << QStringList{"gt", "--preset", "lower-base", "--wn", "1", "--wn", "2"} << "--wn";
    QTest::newRow("option without value")
        << QStringList{"gt", "--preset", "lower-base", "--wn"} << "--wn";
    QTest::newRow("dt = 0") << cubic + QStringList{"--dt", "0"} << "--dt";
    QTest::newRow("dt < 0") << cubic + QStringList{"--dt", "-0.01"} << "--dt";
    QTest::newRow("duration too long for memory")
        << cubic + QStringList{"--duration", "1e9"} << "--duration";
    QTest::newRow("duration NaN") << cubic + QStringList{"--duration", "NaN"} << "--duration";
    QTest::newRow("duration = 0") << cubic + QStringList{"--duration", "0"} << "--duration";
    QTest::newRow("umax = 0") << cubic + QStringList{"--umax", "0"} << "--umax";
    QTest::newRow("umax inf") << cubic + QStringList{"--umax", "inf"} << "--umax";
    QTest::newRow("xf NaN") << QStringList{"simulate",     "--preset", "lower-base",
                                           "--trajectory", "cubic",    "--xf",
                                           "nan",          "--tf",     "130"}
                            << "--xf";
    // Regression: the core's "tf" used to reach stderr without the "--" of the argument.
    QTest::newRow("tf before t0") << QStringList{"simulate",     "--preset", "lower-base",
                                                 "--trajectory", "cubic",    "--xf",
                                                 "600",          "--t0",     "100",
                                                 "--tf",         "50"}
                                  << "--tf";
    QTest::newRow("missing trajectory")
        << QStringList{"simulate", "--preset", "lower-base"} << "--trajectory";
    QTest::newRow("unknown trajectory")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "spiral"}
        << "--trajectory";
    QTest::newRow("sine omega = 0")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "sine", "--amplitude",
                       "25",       "--omega",  "0"}
        << "--omega";
    QTest::newRow("sine ramp-in < 0")
        << QStringList{"simulate", "--preset", "lower-base", "--trajectory", "sine", "--amplitude",
                       "25",       "--omega",  "0.06",       "--ramp-in",    "-1"}
        << "--ramp-in";
    QTest::newRow("unit scale = 0")
        << cubic + QStringList{"--model-unit-scale", "0"} << "--model-unit-scale";
    QTest::newRow("csv not writable")
        << cubic + QStringList{"--csv", "/nonexistent-dir/run.csv"} << "--csv";
    QTest::newRow("report takes no option") << QStringList{"report", "--wn", "2"} << "--wn";
}

void TstCliGt::badInputExitsWithTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, argument);
    const auto run = xyt::test::runCli(args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY2(run.err.contains((argument + ":").toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

QTEST_APPLESS_MAIN(TstCliGt)
#include "tst_cli_gt.moc"
