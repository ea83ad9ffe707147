// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli bode and margins: closed forms through the real binary, the paper
// designs against the core, CSV against JSON, bad input named.
#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using xyt::test::runCli;

class TstCliFrequency : public QObject {
    Q_OBJECT
private slots:
    void marginsOfAThirdOrderLoopMatchTheClosedForm();
    void marginsOfTheLowerBaseEqualTheCore();
    void discreteIntegratorClosedForm();
    void bodeCsvHoldsTheJsonResponse();
    void polePlacementBodeHasTheZeroPhaseTracking();
    void reportQuotesTheMargins();
    void badInputIsNamed_data();
    void badInputIsNamed();
};

void TstCliFrequency::marginsOfAThirdOrderLoopMatchTheClosedForm() {
    // L = K / (s (s+1)(s+2)), K = 2: phase crossover at sqrt(2), gain margin 6/K = 3.
    const auto r = runCli({"margins", "--num", "2", "--den", "1 3 2 0"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject gm = r.json()["gain_margin"].toObject();
    XYT_COMPARE_NEAR(gm["factor"].toDouble(), 3.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(gm["db"].toDouble(), 20.0 * std::log10(3.0), 1e-12, 0.0);
    XYT_COMPARE_NEAR(gm["omega"].toDouble(), std::sqrt(2.0), 1e-12, 0.0);
    QVERIFY(r.json()["closed_loop_stable"].toBool());
    QCOMPARE(r.json()["nyquist"].toObject()["closed_loop_unstable_poles"].toInt(), 0);
    // L = 1/(s (s+1)): no phase crossover, the gain margin is infinite ("inf", never null).
    const auto second = runCli({"margins", "--num", "1", "--den", "1 1 0"});
    QCOMPARE(second.json()["gain_margin"].toObject()["factor"].toString(), QString("inf"));
    // Phase margin: wc^4 + wc^2 - 1 = 0, PM = 180 - 90 - atan(wc).
    const double wc = std::sqrt((std::sqrt(5.0) - 1.0) / 2.0);
    XYT_COMPARE_NEAR(second.json()["phase_margin"].toObject()["deg"].toDouble(),
                     90.0 - std::atan(wc) * 180.0 / M_PI, 1e-10, 0.0);
}

void TstCliFrequency::marginsOfTheLowerBaseEqualTheCore() {
    const auto r = runCli({"margins", "--gt-preset", "lower-base", "--wn", "2", "--kp", "30"});
    QCOMPARE(r.exitCode, 0);
    const auto preset = xyt::findGtPreset("lower-base");
    const xyt::StabilityMargins m = xyt::stabilityMargins(
        xyt::gtLoopTransferFunctions(xyt::designGuilleminTruxal(preset->plant, 2.0, 30.0))
            .openLoop);
    // The JSON writes 17 significant digits: the same doubles.
    QCOMPARE(r.json()["gain_margin"].toObject()["db"].toDouble(), m.gainMarginDb);
    QCOMPARE(r.json()["phase_margin"].toObject()["deg"].toDouble(), m.phaseMarginDeg);
    QCOMPARE(r.json()["peak_sensitivity"].toObject()["ms"].toDouble(), m.peakSensitivity);
}

void TstCliFrequency::discreteIntegratorClosedForm() {
    // L = K z^-1 / (1 - z^-1) = K/(z - 1), K = 0.5, Ts = 0.1: the phase crossover is at z = -1
    // (omega = pi/Ts) with |L| = K/2, so GM = 2/K = 4 (derived in tst_stability_margins).
    const auto r = runCli({"margins", "--num", "0 0.5", "--den", "1 -1", "--ts", "0.1"});
    QCOMPARE(r.exitCode, 0);
    XYT_COMPARE_NEAR(r.json()["gain_margin"].toObject()["factor"].toDouble(), 4.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(r.json()["gain_margin"].toObject()["omega"].toDouble(), M_PI / 0.1, 1e-12,
                     0.0);
    QVERIFY(!r.json()["delay_margin"].toObject()["samples"].isNull());
}

void TstCliFrequency::bodeCsvHoldsTheJsonResponse() {
    QTemporaryDir dir;
    const QString path = dir.filePath("bode.csv");
    const auto r = runCli({"bode", "--gt-preset", "upper-base", "--csv", path});
    QCOMPARE(r.exitCode, 0);
    const QJsonArray w = r.json()["frequency"].toArray(), db = r.json()["magnitude_db"].toArray();
    QVERIFY(w.size() > 50);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.first(), QByteArray("frequency,magnitude_db,phase_deg"));
    QCOMPARE(lines.size() - 1, w.size());
    for (int i = 0; i < w.size(); i += 13) {
        const QList<QByteArray> cells = lines[i + 1].split(',');
        QCOMPARE(cells[0].toDouble(), w[i].toDouble());
        QCOMPARE(cells[1].toDouble(), db[i].toDouble());
    }
    // The grid holds the crossovers exactly (where the margins are read).
    const double wpc = r.json()["margins"].toObject()["gain_margin"].toObject()["omega"].toDouble();
    bool found = false;
    for (const QJsonValue& v : w)
        found = found || v.toDouble() == wpc;
    QVERIFY(found);
}

void TstCliFrequency::polePlacementBodeHasTheZeroPhaseTracking() {
    const auto r = runCli({"bode", "--pp-preset", "x-axis"});
    QCOMPARE(r.exitCode, 0);
    const QJsonArray phase =
        r.json()["tracking"].toObject()["with_zpetc"].toObject()["phase_deg"].toArray();
    QVERIFY(!phase.isEmpty());
    for (const QJsonValue& v : phase)
        QVERIFY(std::abs(v.toDouble()) <
                1e-6); // ZPETC: zero phase error (Patrick, Ishak and Adnan Eq. 6)
    XYT_COMPARE_NEAR(r.json()["frequency"].toArray().last().toDouble(), M_PI / 0.07, 1e-12, 0.0);
}

void TstCliFrequency::reportQuotesTheMargins() {
    // The default report (both bases of Braga et al.): the core's margins, 3 significant digits.
    const auto r = runCli({"report"});
    QCOMPARE(r.exitCode, 0);
    for (const char* name : {"lower-base", "upper-base"}) {
        const auto preset = xyt::findGtPreset(name);
        const xyt::StabilityMargins m = xyt::stabilityMargins(
            xyt::gtLoopTransferFunctions(
                xyt::designGuilleminTruxal(preset->plant, preset->omegaNRadPerSec, preset->kp))
                .openLoop);
        const QString expected = QString("GM %1 dB at %2 rad/s, PM %3 deg at %4 rad/s")
                                     .arg(QString::number(m.gainMarginDb, 'g', 3),
                                          QString::number(m.gainMarginOmegaRadPerSec, 'g', 3),
                                          QString::number(m.phaseMarginDeg, 'g', 3),
                                          QString::number(m.phaseMarginOmegaRadPerSec, 'g', 3));
        QVERIFY2(QString::fromUtf8(r.out).contains(expected), qPrintable(expected));
    }
}

void TstCliFrequency::badInputIsNamed_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("field");
    QTest::newRow("no loop") << QStringList{"margins"} << "--gt-preset";
    QTest::newRow("two loops") << QStringList{"margins", "--gt-preset", "lower-base", "--num",
                                              "1",       "--den",       "1 1"}
                               << "--gt-preset";
    QTest::newRow("unknown preset")
        << QStringList{"bode", "--pp-preset", "z-axis"} << "--pp-preset";
    QTest::newRow("den missing") << QStringList{"margins", "--num", "1"} << "--den";
    QTest::newRow("negative wn") << QStringList{"margins", "--gt-preset", "lower-base", "--wn",
                                                "-1"}
                                 << "--wn";
    QTest::newRow("improper") << QStringList{"margins", "--num", "1 0 0", "--den", "1 1"} << "num";
    QTest::newRow("bad ts") << QStringList{"bode", "--num", "1", "--den", "1 -1", "--ts", "0"}
                            << "--ts";
    QTest::newRow("unknown option")
        << QStringList{"bode", "--gt-preset", "lower-base", "--points", "3"} << "--points";
}

void TstCliFrequency::badInputIsNamed() {
    QFETCH(QStringList, args);
    QFETCH(QString, field);
    const auto r = runCli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(QString::fromUtf8(r.err).contains(field), r.err.constData());
    QVERIFY(r.out.isEmpty());
}

QTEST_APPLESS_MAIN(TstCliFrequency)
#include "tst_cli_frequency.moc"
