// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli shaper: the JSON against the core functions it reports (JSON prints shortest
// round-trip doubles, so they must be equal) and against closed forms for an undamped ZV
// (Singer and Seering: amplitudes 1/2, 1/2 at 0 and half a period; V(f) = |cos(pi f / 2 f_d)|);
// bad input exits with 2 and names the option.
#include "core/design/input_shaper.h"
#include "core/design/shaper_recommendation.h"
#include "core/design/shaper_sensitivity.h"
#include "core/identification/accelerometer_log.h"
#include "core/session/shaper_advice.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QJsonArray>
#include <QTest>

#include <cmath>
#include <numbers>

namespace {

std::vector<double> toVector(const QJsonValue& v) {
    std::vector<double> out;
    for (const QJsonValue& x : v.toArray())
        out.push_back(x.toDouble());
    return out;
}

} // namespace

class TstCliShaper : public QObject {
    Q_OBJECT
private slots:
    void jsonIsTheCoreFunctions_data();
    void jsonIsTheCoreFunctions();
    void undampedZvClosedForm();
    void badInputExitsWithTwo_data();
    void badInputExitsWithTwo();
    void recommendationIsTheCores_data();
    void recommendationIsTheCores();
};

void TstCliShaper::jsonIsTheCoreFunctions_data() {
    QTest::addColumn<QString>("type");
    QTest::addColumn<double>("frequency");
    QTest::addColumn<double>("damping");
    QTest::newRow("mzv") << "mzv" << 42.5 << 0.1;
    QTest::newRow("2hump_ei") << "2hump_ei" << 61.0 << 0.05;
    QTest::newRow("zvdd") << "zvdd" << 30.0 << 0.2;
}

void TstCliShaper::jsonIsTheCoreFunctions() {
    QFETCH(QString, type);
    QFETCH(double, frequency);
    QFETCH(double, damping);
    const auto run =
        xyt::test::runCli({"shaper", "--type", type, "--frequency", QString::number(frequency),
                           "--damping", QString::number(damping), "--points", "11"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    xyt::ShaperType t;
    QVERIFY(xyt::shaperFromName(type.toStdString(), t));
    const xyt::InputShaper s = xyt::designInputShaper(t, frequency, damping);
    QCOMPARE(o["type"].toString(), type);
    QCOMPARE(o["frequency"].toDouble(), frequency);
    QCOMPARE(o["damping"].toDouble(), damping);
    QCOMPARE(toVector(o["amplitudes"]), s.amplitudes);
    QCOMPARE(toVector(o["times"]), s.times);
    QCOMPARE(o["duration"].toDouble(), s.duration());
    QCOMPARE(o["delay"].toDouble(), xyt::shaperDelaySeconds(s));
    QCOMPARE(o["smoothing"].toDouble(), xyt::klipperShaperSmoothing(s, 5000.0, 5.0));
    QCOMPARE(o["max_accel"].toDouble(), xyt::klipperMaxAccel(s, 5.0));
    const xyt::ShaperSensitivity sens = xyt::shaperSensitivity(s, 11);
    const QJsonObject js = o["sensitivity"].toObject();
    QCOMPARE(toVector(js["frequency"]), sens.frequencyHz);
    QCOMPARE(toVector(js["vibration"]), sens.vibration);
}

/// Round-off of a handful of operations: 1e-15 relative, 1e-15 absolute near the zero.
void TstCliShaper::undampedZvClosedForm() {
    const auto run = xyt::test::runCli(
        {"shaper", "--type", "zv", "--frequency", "40", "--damping", "0", "--points", "5"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    const std::vector<double> a = toVector(o["amplitudes"]), t = toVector(o["times"]);
    QCOMPARE(a.size(), std::size_t(2));
    XYT_COMPARE_NEAR(a[0], 0.5, 1e-15, 0.0);
    XYT_COMPARE_NEAR(a[1], 0.5, 1e-15, 0.0);
    XYT_COMPARE_NEAR(t[1], 1.0 / 80.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(o["duration"].toDouble(), 1.0 / 80.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(o["delay"].toDouble(), 1.0 / 160.0, 1e-15, 0.0);
    const QJsonObject js = o["sensitivity"].toObject();
    const std::vector<double> f = toVector(js["frequency"]), v = toVector(js["vibration"]);
    QCOMPARE(f.size(), std::size_t(5)); // 0, 25, 50, 75, 100 Hz
    for (std::size_t k = 0; k < f.size(); ++k) {
        XYT_COMPARE_NEAR(f[k], 25.0 * static_cast<double>(k), 1e-15, 0.0);
        XYT_COMPARE_NEAR(v[k], std::abs(std::cos(std::numbers::pi * f[k] / 80.0)), 0.0, 1e-15);
    }
}

void TstCliShaper::badInputExitsWithTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("damping 1") << QStringList{"--type", "zv", "--frequency", "40", "--damping", "1"}
                               << "--damping: give a damping ratio in [0, 1)";
    QTest::newRow("damping negative")
        << QStringList{"--type", "zv", "--frequency", "40", "--damping", "-0.1"}
        << "--damping: give a damping ratio in [0, 1)";
    QTest::newRow("unknown type")
        << QStringList{"--type", "zvx", "--frequency", "40"}
        << "--type: unknown shaper 'zvx' (zv, mzv, zvd, zvdd, ei, 2hump_ei, 3hump_ei)";
    QTest::newRow("frequency 0") << QStringList{"--type", "ei", "--frequency", "0"}
                                 << "--frequency: give the mode's frequency in Hz, > 0";
    QTest::newRow("frequency negative") << QStringList{"--type", "ei", "--frequency", "-5"}
                                        << "--frequency: give the mode's frequency in Hz, > 0";
    QTest::newRow("frequency missing") << QStringList{"--type", "ei"} << "--frequency";
    QTest::newRow("type missing") << QStringList{"--frequency", "40"} << "--type: is required";
    QTest::newRow("points 1") << QStringList{"--type", "ei", "--frequency", "40", "--points", "1"}
                              << "--points";
    QTest::newRow("unknown option")
        << QStringList{"--type", "ei", "--frequency", "40", "--zeta", "0.1"} << "--zeta";
    QTest::newRow("recommend from nothing")
        << QStringList{"--recommend"} << "--recommend: give either --data";
    QTest::newRow("recommend from both")
        << QStringList{"--recommend", "--mode-frequency", "40", "--data", "x.csv"}
        << "--recommend: give either --data";
    QTest::newRow("recommend damping 1")
        << QStringList{"--recommend", "--mode-frequency", "40", "--mode-damping", "1"}
        << "--mode-damping: must be a damping ratio in [0, 1)";
    QTest::newRow("recommend axis w")
        << QStringList{"--recommend", "--data",
                       QStringLiteral(XYT_TEST_DATA_DIR) + "/klipper_accel_raw.csv", "--axis", "w"}
        << "--axis: must be x, y, z or sum";
    QTest::newRow("recommend smoothing 0")
        << QStringList{"--recommend", "--mode-frequency", "40", "--max-smoothing", "0"}
        << "--max-smoothing: give a smoothing limit > 0 mm";
}

void TstCliShaper::badInputExitsWithTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const auto run = xyt::test::runCli(QStringList{"shaper"} + args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1); // one line
}

void TstCliShaper::recommendationIsTheCores_data() {
    QTest::addColumn<QStringList>("args");
    QTest::newRow("modelled mode")
        << QStringList{"--mode-frequency", "47", "--mode-damping", "0.04"};
    QTest::newRow("klipper log, x") << QStringList{
        "--data", QStringLiteral(XYT_TEST_DATA_DIR) + "/klipper_accel_raw.csv", "--axis", "x"};
    QTest::newRow("klipper log, sum, limited")
        << QStringList{"--data", QStringLiteral(XYT_TEST_DATA_DIR) + "/klipper_accel_raw.csv",
                       "--max-smoothing", "0.1", "--klipper-shapers"};
}

// Source: the core's recommendShaper on the same spectrum (accelerometerShaperSpectrum of the
// log, flexibleModeSpectrum of the mode); the JSON prints shortest round-trip doubles, so equal.
void TstCliShaper::recommendationIsTheCores() {
    QFETCH(QStringList, args);
    const auto run = xyt::test::runCli(QStringList{"shaper", "--recommend"} + args);
    QVERIFY(run.finished);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QJsonObject o = run.json();
    xyt::ShaperRecommendationOptions options;
    xyt::PowerSpectrum spectrum;
    if (args.first() == "--data") {
        const xyt::AccelerometerLog log = xyt::readAccelerometerLogFile(args[1].toStdString());
        spectrum = xyt::accelerometerShaperSpectrum(
            xyt::accelerometerSpectra(log, options.maxSpectrumFrequencyHz),
            args.contains("--axis") ? "x" : "sum");
        if (args.contains("--max-smoothing")) {
            options.maxSmoothing = 0.1;
            options.shapers = xyt::klipperAutotuneShapers();
            options.useKlipperMinimumFrequencies = true;
        }
    } else {
        spectrum = xyt::flexibleModeSpectrum({47.0, 0.04, 0.0, 0.02}, 200.0, 0.2);
    }
    const xyt::ShaperRecommendation r = xyt::recommendShaper(spectrum, options);
    const QJsonObject best = o["recommended"].toObject();
    QCOMPARE(best["type"].toString(), QString(xyt::shaperName(r.best().shaper.type)));
    QCOMPARE(best["frequency"].toDouble(), r.best().shaper.frequencyHz);
    QCOMPARE(best["remaining_vibration"].toDouble(), r.best().remainingVibrations);
    QCOMPARE(best["max_accel"].toDouble(), r.best().maxAccelMmPerS2);
    QCOMPARE(o["shapers"].toArray().size(), static_cast<qsizetype>(r.fits.size()));
}

QTEST_APPLESS_MAIN(TstCliShaper)
#include "tst_cli_shaper.moc"
