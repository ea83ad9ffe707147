// SPDX-License-Identifier: GPL-3.0-or-later
// CLI contract of xytune-cli psd and identify --structure frf. Sources: the core's
// accelerometerSpectra and estimateFrequencyResponse on the same data (themselves checked
// against scipy.signal in tst_spectral_estimate and tst_accelerometer_log), which the commands
// must print unchanged; the exact ZOH response of the simulated mode for the --mode-frequency
// entry; bad arguments and files exit 2 naming the option, file or line.
#include "core/identification/accelerometer_log.h"
#include "core/identification/spectral_estimate.h"
#include "core/model/state_space.h"
#include "core/model/transfer_function.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace xyt;

namespace {

constexpr double kPi = 3.14159265358979323846;
const QString kAccelLog = QStringLiteral(XYT_SOURCE_DIR "/tests/data/klipper_accel_raw.csv");

/// JSON numbers are printed shortest-round-trip (Qt 6), so they read back as the same doubles;
/// 1e-15 relative allows for one rounding anyway.
void compareArray(const QJsonValue& printed, const std::vector<double>& core, const char* what) {
    const QJsonArray a = printed.toArray();
    QCOMPARE(static_cast<std::size_t>(a.size()), core.size());
    for (std::size_t k = 0; k < core.size(); ++k) {
        if (!std::isfinite(core[k])) {
            QVERIFY2(a[int(k)].isNull(), what); // JSON has no infinity: null
            continue;
        }
        QVERIFY2(test::near(a[int(k)].toDouble(), core[k], 1e-15, 0.0),
                 qPrintable(QString("%1[%2]: ").arg(what).arg(k) +
                            test::describe(a[int(k)].toDouble(), core[k], 1e-15, 0.0)));
    }
}

} // namespace

class TstCliSpectra : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void psdPrintsKlippersSpectra();
    void frfPrintsTheEstimate();
    void badInput_data();
    void badInput();
    void badLogs();

private:
    QTemporaryDir dir_;
    QString frf_;
    QString shortLog_;
    QString noAccelY_;
    TransferFunction mode_;
};

void TstCliSpectra::initTestCase() {
    QVERIFY(dir_.isValid());
    // A 50 Hz mode, zeta 0.05, ZOH at 1 kHz, driven by seeded white noise, output noise 0.2.
    const double ts = 1e-3, wn = 2.0 * kPi * 50.0, zeta = 0.05;
    mode_ =
        c2dZoh(TransferFunction::fromDescending({wn * wn}, {1.0, 2.0 * zeta * wn, wn * wn}), ts);
    const std::vector<double> b = mode_.numZInverse().ascending(),
                              a = mode_.denZInverse().ascending();
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    const std::size_t n = 20000;
    std::vector<double> u(n), y(n, 0.0);
    for (double& v : u)
        v = normal(rng);
    for (std::size_t k = 0; k < n; ++k) {
        double v = 0.0;
        for (std::size_t i = 0; i < b.size() && i <= k; ++i)
            v += b[i] * u[k - i];
        for (std::size_t i = 1; i < a.size() && i <= k; ++i)
            v -= a[i] * y[k - i];
        y[k] = v;
    }
    frf_ = dir_.filePath("chirp.csv");
    QFile f(frf_);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("t,Command,X\n");
    for (std::size_t k = 0; k < n; ++k)
        f.write(QString("%1,%2,%3\n")
                    .arg(k * ts, 0, 'g', 17)
                    .arg(u[k], 0, 'g', 17)
                    .arg(y[k] + 0.2 * normal(rng), 0, 'g', 17)
                    .toUtf8());
    f.close();
    // 1 kHz, 600 samples: Klipper's segment of 512 needs 768.
    shortLog_ = dir_.filePath("short.csv");
    QFile s(shortLog_);
    QVERIFY(s.open(QIODevice::WriteOnly));
    s.write("#time,accel_x,accel_y,accel_z\n");
    for (int k = 0; k < 600; ++k)
        s.write(QString::asprintf("%.6f,%.6f,%.6f,%.6f\n", 2.0 + k * 1e-3, std::sin(0.3 * k), 0.0,
                                  9810.0)
                    .toUtf8());
    s.close();
    noAccelY_ = dir_.filePath("no_y.csv");
    QFile m(noAccelY_);
    QVERIFY(m.open(QIODevice::WriteOnly));
    m.write("#time,accel_x,accel_z\n0.000000,1,2\n");
}

void TstCliSpectra::psdPrintsKlippersSpectra() {
    const auto run = test::runCli({"psd", "--data", kAccelLog});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject j = run.json();
    const AccelerometerSpectra s =
        accelerometerSpectra(readAccelerometerLogFile(kAccelLog.toStdString()), 200.0);
    compareArray(j["frequency"], s.frequencyHz, "frequency");
    compareArray(j["psd_x"], s.psdX, "psd_x");
    compareArray(j["psd_y"], s.psdY, "psd_y");
    compareArray(j["psd_z"], s.psdZ, "psd_z");
    compareArray(j["psd_sum"], s.psdSum, "psd_sum");
    QCOMPARE(j["samples"].toInt(), 1100);
    QCOMPARE(j["segment"].toInt(), 256); // 1 << int(400.36 * 0.5 - 1).bit_length()
    QCOMPARE(j["averages"].toInt(), int(s.segments.count));
    QCOMPARE(j["window"].toString(), QString("kaiser"));
    XYT_COMPARE_NEAR(j["kaiser_beta"].toDouble(), 6.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(j["overlap"].toDouble(), 0.5, 0.0, 0.0);
    XYT_COMPARE_NEAR(j["sample_time"].toDouble(), 1.0 / s.samplingHz, 1e-15, 0.0);
    QVERIFY(j["frequency"].toArray().last().toDouble() <= 200.0);
    // The peak: the core's pick of psd_sum from Klipper's MIN_FREQ (5 Hz) to 200 Hz.
    const ResonancePick p =
        pickResonance(s.frequencyHz, s.psdSum, ResonanceQuantity::Power, {5.0, 200.0});
    const QJsonObject peak = j["peak"].toObject();
    XYT_COMPARE_NEAR(peak["frequency"].toDouble(), p.frequencyHz, 1e-15, 0.0);
    QVERIFY(p.dampingRatio.has_value());
    XYT_COMPARE_NEAR(peak["damping"].toDouble(), *p.dampingRatio, 1e-15, 0.0);
    // --max-frequency 100 cuts the axis there.
    const auto cut = test::runCli({"psd", "--data", kAccelLog, "--max-frequency", "100"});
    QCOMPARE(cut.exitCode, 0);
    QVERIFY(cut.json()["frequency"].toArray().last().toDouble() <= 100.0);
}

void TstCliSpectra::frfPrintsTheEstimate() {
    const auto run =
        test::runCli({"identify", "--structure", "frf", "--data", frf_, "--input-col", "Command",
                      "--output-col", "X", "--time-col", "t", "--mode-frequency", "50"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject j = run.json();
    QCOMPARE(j["structure"].toString(), QString("frf"));
    // The core's estimate on the same columns and the sample time the command derived.
    const double ts = j["data"].toObject()["ts"].toDouble();
    XYT_COMPARE_NEAR(ts, 1e-3, 1e-12, 0.0);
    std::vector<double> u, y;
    QFile f(frf_);
    QVERIFY(f.open(QIODevice::ReadOnly));
    f.readLine();
    while (!f.atEnd()) {
        const QList<QByteArray> cells = f.readLine().trimmed().split(',');
        u.push_back(cells[1].toDouble());
        y.push_back(cells[2].toDouble());
    }
    const FrequencyResponseEstimate e = estimateFrequencyResponse(u, y, ts);
    compareArray(j["frequency"], e.frequencyHz, "frequency");
    compareArray(j["magnitude"], e.magnitude, "magnitude");
    compareArray(j["coherence"], e.coherence, "coherence");
    compareArray(j["magnitude_low"], e.magnitudeLow, "magnitude_low");
    compareArray(j["magnitude_high"], e.magnitudeHigh, "magnitude_high");
    std::vector<double> phaseDeg;
    for (double p : e.phaseRad)
        phaseDeg.push_back(p * 180.0 / kPi);
    compareArray(j["phase_deg"], phaseDeg, "phase_deg");
    QCOMPARE(j["segment"].toInt(), 4096); // 20000 >= 4.5 * 4096
    QCOMPARE(j["averages"].toInt(), 8);   // (20000 - 4096) / 2048 + 1
    QCOMPARE(j["window"].toString(), QString("hann"));
    XYT_COMPARE_NEAR(j["overlap"].toDouble(), 0.5, 0.0, 0.0);
    const ResonancePick p = pickResonance(e.frequencyHz, e.magnitude, ResonanceQuantity::Magnitude);
    XYT_COMPARE_NEAR(j["resonance"].toObject()["frequency"].toDouble(), p.frequencyHz, 1e-15, 0.0);
    // At 50 Hz the exact gain is 1 / (2 zeta) = 10 (ZOH: within 0.2 %); the printed estimate
    // lies within its 2-sigma band of it, widened by the interpolation between the bins
    // (0.24 Hz apart on a peak of half-power width 5 Hz: 1 %).
    const QJsonObject mode = j["mode"].toObject();
    const double exact = std::abs(mode_.frequencyResponse(2.0 * kPi * 50.0));
    QVERIFY2(mode["magnitude_low"].toDouble() * 0.99 <= exact &&
                 exact <= mode["magnitude_high"].toDouble() * 1.01,
             qPrintable(QString("exact %1 outside [%2, %3]")
                            .arg(exact)
                            .arg(mode["magnitude_low"].toDouble())
                            .arg(mode["magnitude_high"].toDouble())));
}

void TstCliSpectra::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("named");
    const QStringList frf{"identify",    "--structure", "frf",
                          "--input-col", "Command",     "--output-col",
                          "X",           "--time-col",  "t"};
    QTest::newRow("above Nyquist") << (frf + QStringList{"--mode-frequency", "600"})
                                   << "--mode-frequency: 600 Hz: frequency above the log's "
                                      "Nyquist frequency of 500 Hz";
    QTest::newRow("segment 3") << (frf + QStringList{"--segment-length", "3"})
                               << "--segment-length";
    QTest::newRow("segment too long")
        << (frf + QStringList{"--segment-length", "15000"}) << "--segment-length";
    QTest::newRow("band reversed") << (frf + QStringList{"--band", "80:20"}) << "--band";
    QTest::newRow("band beyond") << (frf + QStringList{"--band", "600:700"}) << "--band";
    QTest::newRow("no column") << QStringList{"identify",    "--structure", "frf",
                                              "--input-col", "U",           "--output-col",
                                              "X",           "--time-col",  "t"}
                               << "U";
    QTest::newRow("unknown option") << (frf + QStringList{"--na", "2"}) << "--na";
    QTest::newRow("psd no file") << QStringList{"psd", "--data", "/nonexistent/raw.csv"}
                                 << "--data";
    QTest::newRow("psd no data") << QStringList{"psd"} << "--data";
    QTest::newRow("psd max frequency")
        << QStringList{"psd", "--max-frequency", "0"} << "--max-frequency";
    QTest::newRow("psd band") << QStringList{"psd", "--band", "x"} << "--band";
    // 400 Hz and 256-sample segments: bins 1.56 Hz apart, so up to 2 Hz there are two bins,
    // too few for a peak; the message names the option that cut the spectrum.
    QTest::newRow("psd max frequency too low")
        << QStringList{"psd", "--max-frequency", "2"} << "--max-frequency: needs at least 3 bins";
    QTest::newRow("psd unknown") << QStringList{"psd", "--segment", "3"} << "--segment";
}

void TstCliSpectra::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, named);
    if (args.first() == "identify")
        args << "--data" << frf_;
    else if (!args.contains("--data") && named != "--data")
        args << "--data" << kAccelLog;
    const auto run = test::runCli(args);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(named.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TstCliSpectra::badLogs() {
    // The line and column named, and the file too short for Klipper's segment.
    const auto noY = test::runCli({"psd", "--data", noAccelY_});
    QCOMPARE(noY.exitCode, 2);
    QVERIFY2(noY.err.contains("no_y.csv: line 1: no accel_y column"), noY.err.constData());
    const auto tooShort = test::runCli({"psd", "--data", shortLog_});
    QCOMPARE(tooShort.exitCode, 2);
    QVERIFY2(tooShort.err.contains("short.csv: has 600 samples") &&
                 tooShort.err.contains("segment of 512"),
             tooShort.err.constData());
}

QTEST_APPLESS_MAIN(TstCliSpectra)
#include "tst_cli_spectra.moc"
