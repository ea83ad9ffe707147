// SPDX-License-Identifier: GPL-3.0-or-later
// Klipper's raw accelerometer log and its spectra. Sources: the format Klipper's
// ACCELEROMETER_MEASURE writes ("#time,accel_x,accel_y,accel_z", then "%.6f" rows) and the
// spectra of Klipper's shaper_calibrate.py calc_freq_response as scipy.signal.welch computes them
// with its parameters (tests/data/gen_spectral_estimate.py -> klipper_accel_raw.csv and
// spectral_estimate_scipy.json); the refusals name the line and column.
#include "core/identification/accelerometer_log.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace xyt;

namespace {

std::vector<double> doubles(const QJsonValue& v) {
    std::vector<double> out;
    for (const QJsonValue& e : v.toArray())
        out.push_back(e.toDouble());
    return out;
}

/// A log of @p n rows at 1 kHz: "#time,accel_x,accel_y,accel_z" and "%.6f" rows.
std::string logText(std::size_t n, const std::string& header = "#time,accel_x,accel_y,accel_z",
                    const std::string& lineEnd = "\n") {
    std::string s = header + lineEnd;
    char row[128];
    for (std::size_t i = 0; i < n; ++i) {
        std::snprintf(row, sizeof row, "%.6f,%.6f,%.6f,%.6f", 3.0 + i * 1e-3,
                      100.0 * std::sin(0.7 * i), -50.0 * std::cos(0.2 * i), 9810.0 + i % 3);
        s += row + lineEnd;
    }
    return s;
}

/// Replaces line @p line (1-based) of @p text with @p replacement.
std::string withLine(const std::string& text, std::size_t line, const std::string& replacement) {
    std::size_t start = 0;
    for (std::size_t i = 1; i < line; ++i)
        start = text.find('\n', start) + 1;
    const std::size_t end = text.find('\n', start);
    return text.substr(0, start) + replacement + text.substr(end);
}

void expectRefusal(const std::string& text, const std::string& field, const std::string& part) {
    try {
        readAccelerometerLog(text, "raw.csv");
        QFAIL(qPrintable(QString::fromStdString("no refusal naming " + field)));
    } catch (const InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), QString::fromStdString(field));
        QVERIFY2(std::string(e.what()).find(part) != std::string::npos, e.what());
    }
}

} // namespace

class TstAccelerometerLog : public QObject {
    Q_OBJECT
private slots:
    void klipperSpectraMatchScipy();
    void klipperSegmentLengthRule();
    void formatVariants();
    void refusals_data();
    void refusals();
    void tooShortForKlipperSegment();
};

void TstAccelerometerLog::klipperSpectraMatchScipy() {
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/tests/data/spectral_estimate_scipy.json"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject k = QJsonDocument::fromJson(f.readAll()).object()["klipper"].toObject();
    const AccelerometerLog log =
        readAccelerometerLogFile(XYT_SOURCE_DIR "/tests/data/klipper_accel_raw.csv");
    QCOMPARE(log.size(), static_cast<std::size_t>(k["samples"].toInt()));
    // N / T from the same parsed times (both parse "%.6f" to the nearest double).
    XYT_COMPARE_NEAR(log.klipperSamplingHz, k["sampling_hz"].toDouble(), 1e-14, 0.0);
    const AccelerometerSpectra s = accelerometerSpectra(log, 1e9);
    QCOMPARE(s.segments.segmentLength, static_cast<std::size_t>(k["segment"].toInt()));
    const std::vector<double> freq = doubles(k["frequency"]);
    QCOMPARE(s.frequencyHz.size(), freq.size());
    // FFTs of 256 points in double (pocketfft against Eigen's kissfft): round-off a few 1e-16
    // of the largest bin; 1e-10 relative with a floor of 1e-12 of the largest value.
    const auto compare = [&](const std::vector<double>& a, const char* name) {
        const std::vector<double> e = doubles(k[name]);
        double largest = 0.0;
        for (double v : e)
            largest = std::max(largest, v);
        for (std::size_t i = 0; i < e.size(); ++i)
            QVERIFY2(test::near(a[i], e[i], 1e-10, 1e-12 * largest),
                     qPrintable(QString("%1[%2]: ").arg(name).arg(i) +
                                test::describe(a[i], e[i], 1e-10, 1e-12 * largest)));
    };
    compare(s.frequencyHz, "frequency");
    compare(s.psdX, "psd_x");
    compare(s.psdY, "psd_y");
    compare(s.psdZ, "psd_z");
    compare(s.psdSum, "psd_sum");
    // Up to 200 Hz, as Klipper plots: the Nyquist bin (200.18 Hz) is dropped.
    const AccelerometerSpectra cut = accelerometerSpectra(log, 200.0);
    QCOMPARE(cut.frequencyHz.size(), freq.size() - 1);
    QVERIFY(cut.frequencyHz.back() <= 200.0);
    // The 47 Hz line of x (gen_spectral_estimate.py) is the peak of psd_x.
    const ResonancePick p = pickResonance(cut.frequencyHz, cut.psdX, ResonanceQuantity::Power);
    XYT_COMPARE_NEAR(p.frequencyHz, 47.0, 0.0, s.samplingHz / s.segments.segmentLength);
}

void TstAccelerometerLog::klipperSegmentLengthRule() {
    // 1 << int(fs * 0.5 - 1).bit_length() (shaper_calibrate.py calc_freq_response).
    QCOMPARE(klipperSegmentLength(3200.0), std::size_t{2048}); // 1599: 11 bits
    QCOMPARE(klipperSegmentLength(1600.0), std::size_t{1024}); // 799: 10 bits
    QCOMPARE(klipperSegmentLength(400.36), std::size_t{256});  // 199: 8 bits
    QCOMPARE(klipperSegmentLength(1026.0), std::size_t{1024}); // 512: 10 bits
    QCOMPARE(klipperSegmentLength(1025.9), std::size_t{512});  // 511: 9 bits
}

void TstAccelerometerLog::formatVariants() {
    const std::string plain = logText(40);
    const AccelerometerLog a = readAccelerometerLog(plain, "raw.csv");
    QCOMPARE(a.size(), std::size_t{40});
    XYT_COMPARE_NEAR(a.meanIntervalSeconds, 1e-3, 1e-9, 0.0);
    XYT_COMPARE_NEAR(a.klipperSamplingHz, 40.0 / 0.039, 1e-9, 0.0);
    XYT_COMPARE_NEAR(a.z[1], 9811.0, 0.0, 0.0);
    // CRLF (the Go port writes its header so), the "##" statistics line of older Klipper, a
    // later comment line, reordered and extra columns.
    const AccelerometerLog b = readAccelerometerLog(
        "##rate=1000\r\n" + logText(40, "#time,accel_x,accel_y,accel_z", "\r\n"), "raw.csv");
    QCOMPARE(b.x, a.x);
    std::string commented = plain;
    commented.insert(commented.find("3.010000"), "# a comment\n\n");
    QCOMPARE(readAccelerometerLog(commented, "raw.csv").x, a.x);
    const AccelerometerLog c = readAccelerometerLog(
        "# accel_z , time,accel_x,accel_y,extra\n1,0.000,2,3,x\n1,0.001,2,3,y\n" +
            std::string("1,0.002,2,3,\n1,0.003,2,3,\n1,0.004,2,3,\n1,0.005,2,3,\n") +
            "1,0.006,2,3,\n1,0.007,2,3,\n1,0.008,2,3,\n1,0.009,2,3,\n1,0.010,2,3,\n" +
            "1,0.011,2,3,\n1,0.012,2,3,\n1,0.013,2,3,\n1,0.014,2,3,\n1,0.015,2,3,\n",
        "raw.csv");
    QCOMPARE(c.size(), std::size_t{16});
    XYT_COMPARE_NEAR(c.y[3], 3.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(c.timeSeconds[15], 0.015, 0.0, 0.0);
}

void TstAccelerometerLog::refusals_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("part");
    const std::string good = logText(40);
    const auto row = [](const char* name, const std::string& text, const char* field,
                        const char* part) {
        QTest::newRow(name) << QString::fromStdString(text) << field << part;
    };
    row("no header", logText(40).substr(31), "raw.csv: line 1", "no header");
    row("empty", "", "raw.csv: line 1", "no header");
    row("no accel_y", logText(40, "#time,accel_x,accel_z"), "raw.csv: line 1", "no accel_y column");
    row("no time", logText(40, "#t,accel_x,accel_y,accel_z"), "raw.csv: line 1", "no time column");
    row("not a number", withLine(good, 5, "3.003000,abc,1,2"),
        "raw.csv: line 5, column 2 (accel_x)", "'abc' is not a number");
    row("nan", withLine(good, 5, "3.003000,1,nan,2"), "raw.csv: line 5, column 3 (accel_y)", "NaN");
    row("beyond 100 000 g", withLine(good, 6, "3.004000,1e10,0,0"),
        "raw.csv: line 6, column 2 (accel_x)", "not an acceleration");
    row("too few fields", withLine(good, 7, "3.005000,1,2"), "raw.csv: line 7", "has 3 fields");
    row("too many fields", withLine(good, 7, "3.005000,1,2,3,4"), "raw.csv: line 7",
        "more than the header's 4 fields");
    row("time repeated", withLine(good, 9, "3.006000,1,2,3"), "raw.csv: line 9, column 1 (time)",
        "is not after 3.006 s on line 8");
    row("time reversed", withLine(good, 9, "2.000000,1,2,3"), "raw.csv: line 9, column 1 (time)",
        "is not after");
    // A lost sample: the row of line 12 (time 3.010) is removed, so line 12 now holds 3.011,
    // an interval of 2 ms against a mean of 40/39 ms.
    row("gap", withLine(good, 12, "# lost"), "raw.csv: line 13", "differs from the log's mean");
    row("too few samples", logText(15), "raw.csv", "15 samples, fewer than 16");
}

void TstAccelerometerLog::refusals() {
    QFETCH(QString, text);
    QFETCH(QString, field);
    QFETCH(QString, part);
    expectRefusal(text.toStdString(), field.toStdString(), part.toStdString());
}

void TstAccelerometerLog::tooShortForKlipperSegment() {
    // 1 kHz: Klipper's segment is 512 (int(499).bit_length() = 9); 767 samples are fewer than
    // two half-overlapping segments, 768 are enough.
    const AccelerometerLog shortLog = readAccelerometerLog(logText(767), "raw.csv");
    try {
        accelerometerSpectra(shortLog, 200.0);
        QFAIL("no refusal");
    } catch (const InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), QString("raw.csv"));
        QVERIFY2(std::string(e.what()).find("segment of 512") != std::string::npos, e.what());
    }
    const AccelerometerSpectra s =
        accelerometerSpectra(readAccelerometerLog(logText(768), "raw.csv"), 200.0);
    QCOMPARE(s.segments.count, std::size_t{2});
    try {
        accelerometerSpectra(shortLog, 0.0);
        QFAIL("no refusal");
    } catch (const InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), QString("--max-frequency"));
    }
}

QTEST_APPLESS_MAIN(TstAccelerometerLog)
#include "tst_accelerometer_log.moc"
