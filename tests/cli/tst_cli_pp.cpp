// SPDX-License-Identifier: GPL-3.0-or-later
// CLI contract of xytune-cli pp | zpetc | contour (Patrick, Ishak and Adnan).
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QJsonArray>
#include <QTest>

#include <numbers>

class TstCliPp : public QObject {
    Q_OBJECT
private slots:
    void ppPresetKeys();
    void ppExplicitCoefficients();
    void zpetcKeys();
    void contourKeys();
    void zpetcFrequencyResponse();
    void badInput_data();
    void badInput();
};

void TstCliPp::ppPresetKeys() {
    const auto run = xyt::test::runCli({"pp", "--preset", "x-axis"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"F", "G", "Kf", "residual", "closed_loop", "warnings", "plant_zeros"})
        QVERIFY2(o.contains(key), key);
    // Kf = T(1)/B(1) = 0.8/0.0595 (paper Eq. 9 prints 13.4251, wrong: see tests/data/README.md).
    XYT_COMPARE_NEAR(o["Kf"].toDouble(), 0.8 / 0.0595, 1e-14, 0.0);
    // F from the independent numpy solve (tst_diophantine), 1e-12: JSON prints 17 digits.
    XYT_COMPARE_NEAR(o["F"].toArray()[2].toDouble(), 0.071970436540917365, 1e-12, 0.0);
    const QJsonObject cl = o["closed_loop"].toObject();
    QCOMPARE(cl["den"].toArray().size(), 2);
    QCOMPARE(cl["num"].toArray().size(), 4); // Kf B, ascending z^-1, leading 0 = delay
    QVERIFY(o["residual"].toDouble() < 1e-13);
}

void TstCliPp::ppExplicitCoefficients() {
    // The y-axis model typed by hand, comma-separated: same design as the preset.
    const auto run = xyt::test::runCli(
        {"pp", "--a", "1, -1.4590, 0.4587", "--b", "0 0.0352 0.0599 -0.0067", "--t", "1 -0.2"});
    QCOMPARE(run.exitCode, 0);
    // Kf = 0.8/0.0884 (paper Eq. 10 prints 9.0509).
    XYT_COMPARE_NEAR(run.json()["Kf"].toDouble(), 0.8 / 0.0884, 1e-14, 0.0);
}

void TstCliPp::zpetcKeys() {
    const auto run = xyt::test::runCli({"zpetc", "--preset", "y-axis", "--phase-deg", "90"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"zeros", "nmp_zeros", "preview_steps", "feedforward", "gain_factor",
                            "metrics", "F", "G", "Kf"})
        QVERIFY2(o.contains(key), key);
    QCOMPARE(o["preview_steps"].toInt(), 2);
    QCOMPARE(o["zeros"].toArray().size(), 2);
    const QJsonArray nmp = o["nmp_zeros"].toArray();
    QCOMPARE(nmp.size(), 1);
    // numpy.roots of the y-axis B / z^-1: -1.807037662228741.
    XYT_COMPARE_NEAR(nmp[0].toArray()[0].toDouble(), -1.807037662228741, 1e-12, 0.0);
    const QJsonObject ff = o["feedforward"].toObject();
    QVERIFY(ff.contains("num") && ff.contains("den"));
    const QJsonObject m = o["metrics"].toObject();
    for (const char* key : {"rmse_without_ff", "rmse_with_ff", "improvement_pct"})
        QVERIFY2(m.contains(key), key);
    // The y axis from rest at 30 mm: > 98 % (tst_zpetc checks the value against scipy).
    QVERIFY(m["improvement_pct"].toDouble() > 98.0);
}

void TstCliPp::contourKeys() {
    const auto run = xyt::test::runCli({"contour", "--preset", "paper-zpetc"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"x_axis", "y_axis", "contour_error"})
        QVERIFY2(o.contains(key), key);
    const QJsonObject ce = o["contour_error"].toObject();
    QVERIFY(ce["with_ff"].toObject()["max"].toDouble() <
            ce["without_ff"].toObject()["max"].toDouble());
    QCOMPARE(o["x_axis"].toObject()["metrics"].toObject()["samples"].toInt(), 898);
}

void TstCliPp::zpetcFrequencyResponse() {
    const auto run = xyt::test::runCli({"zpetc", "--preset", "x-axis", "--frequency-points", "7"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject f = run.json()["frequency_response"].toObject();
    QCOMPARE(f["omega"].toArray().size(), 7);
    // Zero phase error with ZPETC at every frequency (round-off, 1e-12 rad); the grid ends at
    // Nyquist pi/0.07 where the gain is (1 + zn)^2/(1 - zn)^2 = 0.1147 (zn = -2.0244).
    for (const auto& p : f["phase_with_ff_rad"].toArray())
        XYT_COMPARE_NEAR(p.toDouble(), 0.0, 0.0, 1e-12);
    const double zn = -2.0243841653913899;
    XYT_COMPARE_NEAR(f["gain_with_ff"].toArray().last().toDouble(),
                     (1 + zn) * (1 + zn) / ((1 - zn) * (1 - zn)), 1e-12, 0.0);
    XYT_COMPARE_NEAR(f["omega"].toArray().last().toDouble(), std::numbers::pi / 0.07, 1e-15, 0.0);
}

void TstCliPp::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("argument");
    QTest::newRow("common root") << QStringList{"pp",          "--a", "1 -1.4 0.45", "--b",
                                                "0 0.1 -0.05", "--t", "1 -0.2"}
                                 << "--b";
    QTest::newRow("not a number") << QStringList{"pp", "--preset", "x-axis", "--a", "1 abc"}
                                  << "--a";
    QTest::newRow("empty list") << QStringList{"pp", "--preset", "x-axis", "--b", ""} << "--b";
    QTest::newRow("T(0) != 1") << QStringList{"pp", "--preset", "x-axis", "--t", "2 -0.2"} << "--t";
    QTest::newRow("ts <= 0") << QStringList{"pp", "--preset", "x-axis", "--ts", "0"} << "--ts";
    QTest::newRow("ts NaN") << QStringList{"pp", "--preset", "x-axis", "--ts", "nan"} << "--ts";
    QTest::newRow("NaN coefficient")
        << QStringList{"pp", "--preset", "y-axis", "--a", "1 nan"} << "--a";
    QTest::newRow("no delay") << QStringList{"pp", "--preset", "x-axis", "--b", "0.1 0.2"} << "--b";
    QTest::newRow("missing b") << QStringList{"pp", "--a", "1 -0.5", "--t", "1"} << "--b";
    QTest::newRow("unknown preset") << QStringList{"pp", "--preset", "z-axis"} << "--preset";
    QTest::newRow("bad start") << QStringList{"zpetc", "--preset", "x-axis", "--start", "moon"}
                               << "--start";
    QTest::newRow("bad margin") << QStringList{"zpetc", "--preset", "x-axis", "--margin", "1"}
                                << "--margin";
    QTest::newRow("bad duration") << QStringList{"zpetc", "--preset", "x-axis", "--duration", "-1"}
                                  << "--duration";
    QTest::newRow("unknown pair") << QStringList{"contour", "--preset", "x-axis"} << "--preset";
}

void TstCliPp::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, argument);
    const auto run = xyt::test::runCli(args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(argument.toUtf8()), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.out.isEmpty());
}

QTEST_APPLESS_MAIN(TstCliPp)
#include "tst_cli_pp.moc"
