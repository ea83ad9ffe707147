// SPDX-License-Identifier: GPL-3.0-or-later
// CLI contract of xytune-cli identify. Sources: noise-free data generated here by the
// difference equation of Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model
// (filterDifferenceEquation) and by the exact ZOH discretization of Braga et al.'s lower base
// (simulateThirdOrderPlant), which the command must recover to round-off; the figures printed are
// identifyModel's on the same record; bad arguments and files exit 2 naming the option, file, line
// or column.
#include "core/design/digital_controller.h"
#include "core/identification/continuous_fit.h"
#include "core/identification/identification.h"
#include "core/identification/prediction_error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace xyt;

namespace {

/// A +-2 V random binary input (fixed seed), switching at most every sample.
std::vector<double> binaryInput(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> u(n);
    for (double& v : u)
        v = (rng() & 1u) ? 2.0 : -2.0;
    return u;
}

void writeCsv(const QString& path, const QString& header, const std::vector<double>& t,
              const std::vector<double>& u, const std::vector<double>& y, char separator = ',') {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(header.toUtf8() + '\n');
    for (std::size_t k = 0; k < u.size(); ++k)
        f.write((QStringList{QString::number(t[k], 'g', 17), QString::number(u[k], 'g', 17),
                             QString::number(y[k], 'g', 17)}
                     .join(QChar(separator)) +
                 '\n')
                    .toUtf8());
}

} // namespace

class TstCliIdentify : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void arxRecoversXAxisArxModel();
    void outputErrorAndValidationFile();
    void continuousFitRecoversTheLowerBase();
    void initialPositionIsWhereTheTableStood();
    void zeroOrdersAreTheEstimatorsModels_data();
    void zeroOrdersAreTheEstimatorsModels();
    void examplesRecoverTheirModels();
    void sessionTakesTheModel();
    void badInput_data();
    void badInput();
    void sampleTimesOutsideTheRangeAreRefused_data();
    void sampleTimesOutsideTheRangeAreRefused();
    void sessionThatCannotRunIsNotWritten();
    void oldMacLineEndsAreRead();
    void orderTableIsBoundedAndShowsProgress();
    void lackOfMemoryIsSaidWithExit2();

private:
    QTemporaryDir dir_;
    QString arx_;
    const std::vector<double> a_{1.0, -1.6580, 0.6583};
    const std::vector<double> b_{0.0, 0.0421, 0.0628, -0.0454};
};

void TstCliIdentify::initTestCase() {
    QVERIFY(dir_.isValid());
    const std::vector<double> u = binaryInput(500, 11);
    const std::vector<double> y = filterDifferenceEquation(b_, a_, u);
    std::vector<double> t(u.size());
    for (std::size_t k = 0; k < t.size(); ++k)
        t[k] = 0.07 * static_cast<double>(k);
    arx_ = dir_.filePath("arx.csv");
    writeCsv(arx_, "t,Command,X", t, u, y);
}

void TstCliIdentify::arxRecoversXAxisArxModel() {
    const auto run = test::runCli({"identify", "--data", arx_, "--time-col", "t", "--input-col",
                                   "Command", "--output-col", "X", "--structure", "arx", "--na",
                                   "2", "--nb", "3", "--nk", "1"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject model = run.json().value("model").toObject();
    QCOMPARE(model.value("structure").toString(), QString("ARX(2,3,1)"));
    QCOMPARE(model.value("status").toString(), QString("converged"));
    const QJsonArray a = model.value("polynomials").toObject().value("a").toArray();
    const QJsonArray b = model.value("polynomials").toObject().value("b").toArray();
    QCOMPARE(a.size(), 3);
    QCOMPARE(b.size(), 4);
    // Noise-free data of the model itself: recovered to round-off (1e-9 relative).
    for (int i = 1; i < 3; ++i)
        QVERIFY(test::near(a[i].toDouble(), a_[static_cast<std::size_t>(i)], 1e-9));
    for (int i = 1; i < 4; ++i)
        QVERIFY(test::near(b[i].toDouble(), b_[static_cast<std::size_t>(i)], 1e-9));
    QVERIFY(test::near(run.json()
                           .value("fit")
                           .toObject()
                           .value("estimation")
                           .toObject()
                           .value("simulation")
                           .toDouble(),
                       100.0, 1e-9));
    QCOMPARE(run.json().value("data").toObject().value("samples").toInt(), 500);
    QVERIFY(test::near(run.json().value("data").toObject().value("ts").toDouble(), 0.07, 1e-12));
    // Patrick, Ishak and Adnan's B has a zero outside the unit circle (the reason for ZPETC).
    QCOMPARE(run.json().value("non_minimum_phase").toBool(), true);
    QCOMPARE(run.json().value("stable").toBool(), true);
}

void TstCliIdentify::outputErrorAndValidationFile() {
    // A second record of the same system (another input, semicolon-separated with decimal
    // commas as European exports write it) validates the estimate: 100 % there too.
    const std::vector<double> u = binaryInput(300, 12);
    const std::vector<double> y = filterDifferenceEquation(b_, a_, u);
    const QString path = dir_.filePath("validation.csv");
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("t;Command;X\n");
        for (std::size_t k = 0; k < u.size(); ++k)
            f.write(
                QStringLiteral("%1;%2;%3\n")
                    .arg(QString::number(0.07 * static_cast<double>(k), 'g', 17).replace('.', ','))
                    .arg(QString::number(u[k], 'g', 17).replace('.', ','))
                    .arg(QString::number(y[k], 'g', 17).replace('.', ','))
                    .toUtf8());
    }
    const auto run = test::runCli({"identify", "--data", arx_, "--time-col", "t", "--input-col",
                                   "Command", "--output-col", "X", "--structure", "oe", "--nb", "3",
                                   "--nf", "2", "--nk", "1", "--validate", path});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject fit = run.json().value("fit").toObject();
    QVERIFY(
        test::near(fit.value("validation").toObject().value("simulation").toDouble(), 100.0, 1e-7));
    // The OE model of ARX-generated noise-free data is B/A: F = A.
    const QJsonArray f =
        run.json().value("model").toObject().value("polynomials").toObject().value("f").toArray();
    QVERIFY(test::near(f[1].toDouble(), a_[1], 1e-7));
    QVERIFY(test::near(f[2].toDouble(), a_[2], 1e-7));
}

void TstCliIdentify::continuousFitRecoversTheLowerBase() {
    // Braga et al.'s lower base (k0 = 77.8 in metres; here the log is in mm, so k0 = 77 800) under
    // a +-2.5 V square wave of 0.5 s period logged at 10 ms, in an LVM file.
    const ThirdOrderPlant lower{77800.0, 125.3, 3665.0};
    std::vector<double> u(400), t(400);
    for (std::size_t k = 0; k < u.size(); ++k) {
        t[k] = 0.01 * static_cast<double>(k);
        u[k] = (k / 25) % 2 == 0 ? 2.5 : -2.5;
    }
    const std::vector<double> y = simulateThirdOrderPlant(lower, u, 0.01);
    const QString path = dir_.filePath("lower.lvm");
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("LabVIEW Measurement\t\nWriter_Version\t2\nSeparator\tTab\nDecimal_Separator\t.\n"
                "X_Columns\tOne\n***End_of_Header***\t\n\nChannels\t2\t\nSamples\t400\t400\t\n"
                "X0\t0.0\t0.0\t\nDelta_X\t0.01\t0.01\t\n***End_of_Header***\t\t\nX_"
                "Value\tCommand\tPosition\tComment\n");
        for (std::size_t k = 0; k < u.size(); ++k)
            f.write(QStringLiteral("%1\t%2\t%3\n")
                        .arg(t[k], 0, 'g', 17)
                        .arg(u[k], 0, 'g', 17)
                        .arg(y[k], 0, 'g', 17)
                        .toUtf8());
    }
    // The file's own sample time (Delta_X) is used when no time option is given.
    const auto run = test::runCli({"identify", "--data", path, "--input-col", "Command",
                                   "--output-col", "Position", "--structure", "gt3"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject plant = run.json().value("model").toObject().value("plant").toObject();
    QVERIFY(test::near(plant.value("k0").toDouble(), lower.k0, 1e-7));
    QVERIFY(test::near(plant.value("a1").toDouble(), lower.a1, 1e-7));
    QVERIFY(test::near(plant.value("a2").toDouble(), lower.a2, 1e-7));
    QCOMPARE(run.json().value("continuous_poles").toArray().size(), 3);
}

void TstCliIdentify::initialPositionIsWhereTheTableStood() {
    // The lower base at rest at 3.70 mm when the log starts, under a +-2.5 V square wave, with a
    // +-0.05 mm measurement noise (fixed seed): the first logged sample is not where the table
    // stood. initial_position is the position itself (README: "where the table stood"), 3.70 mm
    // within the noise's effect on the fit, not its offset from that first sample.
    const ThirdOrderPlant lower{77800.0, 125.3, 3665.0};
    const double restMm = 3.70;
    std::vector<double> u(400), t(400);
    for (std::size_t k = 0; k < u.size(); ++k) {
        t[k] = 0.01 * static_cast<double>(k);
        u[k] = (k / 25) % 2 == 0 ? 2.5 : -2.5;
    }
    std::vector<double> y = simulateThirdOrderPlant(lower, u, 0.01);
    const std::vector<double> noise = binaryInput(y.size(), 21); // +-2, scaled to +-0.05 mm
    for (std::size_t k = 0; k < y.size(); ++k)
        y[k] += restMm + 0.025 * noise[k];
    const QString path = dir_.filePath("at_rest_3.70.csv");
    writeCsv(path, "t,Command,Position", t, u, y);
    const auto run = test::runCli({"identify", "--data", path, "--time-col", "t", "--input-col",
                                   "Command", "--output-col", "Position", "--structure", "gt3"});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject plant = run.json().value("model").toObject().value("plant").toObject();
    const double reported = plant.value("initial_position").toDouble();
    QVERIFY2(std::abs(reported - restMm) <= 0.01, qPrintable(QString::number(reported, 'g', 10)));
    // The first sample is 0.05 mm off the rest position: a figure relative to it is far off.
    QVERIFY(test::near(std::abs(y.front() - restMm), 0.05, 1e-9));
}

void TstCliIdentify::zeroOrdersAreTheEstimatorsModels_data() {
    // Orders each estimator takes (arx.h, prediction_error.h): na = 0 (FIR), nk = 0 (a direct
    // feedthrough), nc, nd, nf = 0. The CLI refused every 0 ("from 1 to 100").
    QTest::addColumn<QString>("structure");
    QTest::addColumn<QList<int>>("orders"); // na nb nc nd nf nk
    QTest::newRow("ARX na 0 (FIR)") << "arx" << QList<int>{0, 3, 0, 0, 0, 1};
    QTest::newRow("ARX nk 0") << "arx" << QList<int>{2, 3, 0, 0, 0, 0};
    QTest::newRow("OE nf 0") << "oe" << QList<int>{0, 3, 0, 0, 0, 1};
    QTest::newRow("OE nk 0") << "oe" << QList<int>{0, 3, 0, 0, 2, 0};
    QTest::newRow("BJ nc 0, nd 0") << "bj" << QList<int>{0, 3, 0, 0, 2, 1};
    QTest::newRow("BJ nf 0, nk 0") << "bj" << QList<int>{0, 3, 1, 1, 0, 0};
}

void TstCliIdentify::zeroOrdersAreTheEstimatorsModels() {
    QFETCH(QString, structure);
    QFETCH(QList<int>, orders);
    const int na = orders[0], nb = orders[1], nc = orders[2], nd = orders[3], nf = orders[4],
              nk = orders[5];
    QStringList args{"identify",
                     "--data",
                     arx_,
                     "--time-col",
                     "t",
                     "--input-col",
                     "Command",
                     "--output-col",
                     "X",
                     "--structure",
                     structure,
                     "--nb",
                     QString::number(nb),
                     "--nk",
                     QString::number(nk)};
    if (structure == "arx")
        args << "--na" << QString::number(na);
    if (structure != "arx")
        args << "--nf" << QString::number(nf);
    if (structure == "bj")
        args << "--nc" << QString::number(nc) << "--nd" << QString::number(nd);
    const auto run = test::runCli(args);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    // The core estimator on the same record (written with 17 digits: read back exactly).
    IoData data;
    data.u = binaryInput(500, 11);
    data.y = filterDifferenceEquation(b_, a_, data.u);
    data.tsSeconds = 0.07;
    PemOptions pem;
    pem.search.maxIterations = 100; // the CLI's --max-iterations default
    const PolynomialModel expected =
        structure == "arx"  ? estimateArx(data, ArxOrders{na, nb, nk}).model
        : structure == "oe" ? estimateOe(data, OeOrders{nb, nf, nk}, pem).model
                            : estimateBj(data, BjOrders{nb, nc, nd, nf, nk}, pem).model;
    const QJsonObject polynomials =
        run.json().value("model").toObject().value("polynomials").toObject();
    const std::pair<const char*, const std::vector<double>*> named[] = {{"a", &expected.a},
                                                                        {"b", &expected.b},
                                                                        {"c", &expected.c},
                                                                        {"d", &expected.d},
                                                                        {"f", &expected.f}};
    for (const auto& entry : named) {
        const char* name = entry.first;
        const std::vector<double>& want = *entry.second;
        const QJsonArray got = polynomials.value(name).toArray();
        QVERIFY2(got.size() == qsizetype(want.size()), name);
        for (std::size_t i = 0; i < want.size(); ++i)
            QVERIFY2(test::near(got[qsizetype(i)].toDouble(), want[i], 1e-12, 1e-15),
                     qPrintable(QStringLiteral("%1[%2]: %3, the estimator's %4")
                                    .arg(name)
                                    .arg(i)
                                    .arg(got[qsizetype(i)].toDouble(), 0, 'g', 17)
                                    .arg(want[i], 0, 'g', 17)));
    }
    // nk leading zeros in B, then nb coefficients.
    QCOMPARE(polynomials.value("b").toArray().size(), qsizetype(nk + nb));
}

void TstCliIdentify::examplesRecoverTheirModels() {
    // The committed synthetic logs (resources/examples/make_identification_logs.sh states how
    // they were made): the lower base under a square wave in LVM, Patrick, Ishak and Adnan's x axis
    // under a PRBS in CSV, each with white measurement noise (output-error noise).
    const QString examples = QStringLiteral(XYT_SOURCE_DIR "/resources/examples/");
    const auto within3Sigma = [](const QJsonObject& parameters, const QString& name, double truth) {
        const QJsonObject p = parameters.value(name).toObject();
        const double deviation =
            std::abs(p.value("value").toDouble() - truth) / p.value("std").toDouble();
        if (!(deviation <= 3.0))
            qWarning("%s is %g standard deviations off", qPrintable(name), deviation);
        return deviation <= 3.0;
    };
    const auto gt =
        test::runCli({"identify", "--data", examples + "synthetic_lower_base_square_10ms.lvm",
                      "--input-col", "u", "--output-col", "y", "--structure", "gt3"});
    QCOMPARE(gt.exitCode, 0);
    const QJsonObject gtp = gt.json().value("model").toObject().value("parameters").toObject();
    QVERIFY(within3Sigma(gtp, "k0", 77800.0)); // Braga et al. Eq. 2 in mm (77.8 in m)
    QVERIFY(within3Sigma(gtp, "a1", 125.3));
    QVERIFY(within3Sigma(gtp, "a2", 3665.0));
    QVERIFY(gt.json().value("residual_tests").toObject().value("passed").toBool());
    const QStringList prbs{"identify",
                           "--data",
                           examples + "synthetic_x_axis_prbs_70ms.csv",
                           "--time-col",
                           "t",
                           "--input-col",
                           "u",
                           "--output-col",
                           "y"};
    const auto oe = test::runCli(
        prbs + QStringList{"--structure", "oe", "--nb", "3", "--nf", "2", "--nk", "1"});
    QCOMPARE(oe.exitCode, 0);
    const QJsonObject oep = oe.json().value("model").toObject().value("parameters").toObject();
    QVERIFY(within3Sigma(oep, "f1", a_[1]));
    QVERIFY(within3Sigma(oep, "f2", a_[2]));
    for (int i = 1; i <= 3; ++i)
        QVERIFY(within3Sigma(oep, QStringLiteral("b%1").arg(i), b_[static_cast<std::size_t>(i)]));
    QVERIFY(oe.json().value("non_minimum_phase").toBool());
    // The ARX order table is arxOrderTable's (2 x 2 x 1 orders), with the smallest AIC named.
    const auto table =
        test::runCli(prbs + QStringList{"--structure", "arx", "--order-table", "1:2,2:3,1:1"});
    QCOMPARE(table.exitCode, 0);
    const QJsonObject t = table.json().value("order_table").toObject();
    QCOMPARE(t.value("rows").toArray().size(), 4);
    double bestAic = INFINITY;
    QString best;
    for (const QJsonValue& row : t.value("rows").toArray())
        if (row.toObject().value("aic").toDouble() < bestAic) {
            bestAic = row.toObject().value("aic").toDouble();
            best = QStringLiteral("ARX(%1,%2,%3)")
                       .arg(row.toObject().value("na").toInt())
                       .arg(row.toObject().value("nb").toInt())
                       .arg(row.toObject().value("nk").toInt());
        }
    QCOMPARE(t.value("best_aic").toString(), best);
    // The textbook case on the same log: ARX under output-error noise is biased far beyond its
    // standard deviations, and its residuals are not white.
    const auto arx = test::runCli(prbs + QStringList{"--structure", "arx"});
    QCOMPARE(arx.exitCode, 0);
    const QJsonObject a1 =
        arx.json().value("model").toObject().value("parameters").toObject().value("a1").toObject();
    QVERIFY(std::abs(a1.value("value").toDouble() - a_[1]) > 3.0 * a1.value("std").toDouble());
    QVERIFY(!arx.json().value("residual_tests").toObject().value("passed").toBool());
}

void TstCliIdentify::sessionTakesTheModel() {
    const QString in = dir_.filePath("paper.json");
    const QString out = dir_.filePath("identified.json");
    QCOMPARE(test::runCli({"new", "-o", in}).exitCode, 0);
    const auto run = test::runCli({"identify", "--data", arx_, "--time-col", "t", "--input-col",
                                   "Command", "--output-col", "X", "--structure", "arx",
                                   "--session", in, "--axis", "y", "-o", out});
    QCOMPARE(run.exitCode, 0);
    QFile f(out);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject y =
        QJsonDocument::fromJson(f.readAll()).object().value("axes").toArray()[1].toObject();
    QCOMPARE(y.value("method").toString(), QString("pole-placement-zpetc"));
    const QJsonArray a = y.value("pp").toObject().value("a").toArray();
    QVERIFY(test::near(a[1].toDouble(), a_[1], 1e-9));
    QVERIFY(test::near(y.value("pp").toObject().value("ts").toDouble(), 0.07, 1e-12));
    const QJsonObject origin = y.value("model_origin").toObject();
    QCOMPARE(origin.value("structure").toString(), QString("ARX(2,3,1)"));
    QVERIFY(origin.value("source").toString().contains("arx.csv"));
    QCOMPARE(origin.value("samples").toInt(), 500);
    // The written session loads again (the report reads it) and names the model's origin.
    const auto report = test::runCli({"report", out});
    QCOMPARE(report.exitCode, 0);
    QVERIFY2(report.out.contains("model: identified ARX(2,3,1) from "), report.out.constData());
    // Its covariance drives the robustness analysis of that axis.
    const auto robust =
        test::runCli({"robustness", out, "--axis", "y", "--from-identification", "--samples", "5"});
    QCOMPARE(robust.exitCode, 0);
    QVERIFY(robust.json()
                .value("axes")
                .toArray()[0]
                .toObject()
                .value("uncertainty")
                .toString()
                .startsWith("identified"));
    QCOMPARE(origin.value("covariance").toArray().size(), 25); // 5 x 5, row by row
}

void TstCliIdentify::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("named");
    const QStringList columns{"--time-col", "t", "--input-col", "Command", "--output-col", "X"};
    QTest::newRow("no data") << QStringList{"--structure", "arx"} << "--data";
    QTest::newRow("missing file") << QStringList{"--data", "/nonexistent/run.csv", "--structure",
                                                 "arx"} +
                                         columns
                                  << "--data";
    QTest::newRow("unknown column") << QStringList{"--structure", "arx", "--time-col",   "t",
                                                   "--input-col", "U",   "--output-col", "X"}
                                    << "Command";
    QTest::newRow("unknown structure")
        << QStringList{"--structure", "narmax"} + columns << "--structure";
    QTest::newRow("no time") << QStringList{"--structure", "arx",          "--input-col",
                                            "Command",     "--output-col", "X"}
                             << "--ts";
    QTest::newRow("bad range") << QStringList{"--structure", "arx", "--range", "5:1"} + columns
                               << "--range";
    QTest::newRow("negative order")
        << QStringList{"--structure", "arx", "--na", "-1"} + columns << "--na";
    // A model without input coefficients: no estimator takes nb = 0.
    QTest::newRow("nb 0") << QStringList{"--structure", "oe", "--nb", "0"} + columns
                          << "--nb: must be a whole number from 1 to 100";
    QTest::newRow("decimate 0") << QStringList{"--structure", "arx", "--decimate", "0"} + columns
                                << "--decimate";
    QTest::newRow("unknown option")
        << QStringList{"--structure", "arx", "--order", "3"} + columns << "--order";
    QTest::newRow("session without -o")
        << QStringList{"--structure", "arx", "--session", "s.json", "--axis", "x"} + columns
        << "-o";
    QTest::newRow("bad order table")
        << QStringList{"--structure", "arx", "--order-table", "1:2,3"} + columns << "--order-table";
    QTest::newRow("-o without session")
        << QStringList{"--structure", "arx", "-o", "out.json"} + columns << "--session";
}

void TstCliIdentify::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, named);
    QStringList full{"identify"};
    if (!args.contains("--data") && named != "--data")
        full << "--data" << arx_;
    full += args;
    const auto run = test::runCli(full);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(named.toUtf8()), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TstCliIdentify::sampleTimesOutsideTheRangeAreRefused_data() {
    QTest::addColumn<QString>("ts");
    QTest::addColumn<QString>("structure");
    // 5e-324 was taken and written as the session's pp.ts, which `report` then refused; gt3
    // on such a record said "k0: must be nonzero" instead of naming the sample time.
    QTest::newRow("subnormal, arx") << "5e-324"
                                    << "arx";
    QTest::newRow("subnormal, gt3") << "5e-324"
                                    << "gt3";
    QTest::newRow("1e300, arx") << "1e300"
                                << "arx";
    QTest::newRow("1e300, gt3") << "1e300"
                                << "gt3";
}

void TstCliIdentify::sampleTimesOutsideTheRangeAreRefused() {
    QFETCH(QString, ts);
    QFETCH(QString, structure);
    const QString in = dir_.filePath("range_in.json");
    const QString out = dir_.filePath("range_out_" + structure + ".json");
    QCOMPARE(test::runCli({"new", "-o", in}).exitCode, 0);
    const auto run = test::runCli({"identify", "--data", arx_, "--ts", ts, "--input-col", "Command",
                                   "--output-col", "X", "--structure", structure, "--session", in,
                                   "--axis", "x", "-o", out});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.startsWith("xytune-cli identify: --ts: ") &&
                 run.err.contains("is outside the accepted sample times, 1e-09 s to 10000 s"),
             run.err.constData());
    QVERIFY(!run.err.contains("k0"));
    QVERIFY(!QFile::exists(out));
}

void TstCliIdentify::sessionThatCannotRunIsNotWritten() {
    // 1 us is an accepted sample time, but the default session's run would need 5.2e8 samples
    // at pp.ts = 1e-6 (`report`: "needs 5.2e+08 samples at this dt"): it refused the file written.
    const QString in = dir_.filePath("run_in.json");
    const QString out = dir_.filePath("run_out.json");
    QCOMPARE(test::runCli({"new", "-o", in}).exitCode, 0);
    const auto run = test::runCli({"identify", "--data", arx_, "--ts", "1e-6", "--input-col",
                                   "Command", "--output-col", "X", "--structure", "arx",
                                   "--session", in, "--axis", "x", "-o", out});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.startsWith("xytune-cli identify: -o: the session with this model cannot be "
                                "run as report runs it (") &&
                 run.err.contains("samples") && run.err.contains("nothing was written"),
             run.err.constData());
    QVERIFY(!QFile::exists(out));
}

void TstCliIdentify::oldMacLineEndsAreRead() {
    // The estimation file with CR alone ending its lines (old Mac OS): the same 500 samples
    // and the same model as with LF (it was one line: "the column name ... is used twice").
    QFile lf(arx_);
    QVERIFY(lf.open(QIODevice::ReadOnly));
    const QString cr = dir_.filePath("arx_cr.csv");
    QFile f(cr);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(lf.readAll().replace('\n', '\r'));
    f.close();
    const QStringList rest{"--time-col",   "t", "--input-col", "Command",
                           "--output-col", "X", "--structure", "arx"};
    const auto fromCr = test::runCli(QStringList{"identify", "--data", cr} + rest);
    QCOMPARE(fromCr.exitCode, 0);
    QCOMPARE(fromCr.json().value("data").toObject().value("samples").toInt(), 500);
    const auto fromLf = test::runCli(QStringList{"identify", "--data", arx_} + rest);
    QCOMPARE(fromCr.json().value("model").toObject().value("parameters"),
             fromLf.json().value("model").toObject().value("parameters"));
}

void TstCliIdentify::orderTableIsBoundedAndShowsProgress() {
    const QStringList columns{"identify", "--data",      arx_,      "--time-col",
                              "t",        "--input-col", "Command", "--output-col",
                              "X",        "--structure", "arx",     "--order-table"};
    // A million fits were started with nothing shown: refused at once, with the count.
    const auto huge = test::runCli(columns + QStringList{"1:100,1:100,0:100"}, 20000);
    QVERIFY(huge.finished);
    QCOMPARE(huge.exitCode, 2);
    QCOMPARE(
        huge.err,
        QByteArray("xytune-cli identify: --order-table: '1:100,1:100,0:100' asks for 1010000 fits; "
                   "at most 1000 are run in one table (narrow the ranges)\n"));
    // 10 x 10 x 10 is the largest table; its progress goes to stderr, stdout stays JSON.
    const auto most = test::runCli(columns + QStringList{"1:10,1:10,0:9"});
    QCOMPARE(most.exitCode, 0);
    QCOMPARE(most.json().value("order_table").toObject().value("rows").toArray().size(), 1000);
    QByteArray expected;
    for (int percent = 0; percent <= 100; percent += 10)
        expected += "xytune-cli identify: order table " + QByteArray::number(percent) + " % done\n";
    QCOMPARE(most.err, expected);
    QCOMPARE(test::runCli(columns + QStringList{"1:10,1:10,0:10"}).exitCode, 2); // 1100 fits
}

void TstCliIdentify::lackOfMemoryIsSaidWithExit2() {
#if defined(__SANITIZE_ADDRESS__)
    QSKIP("AddressSanitizer reserves more address space than any limit tried here");
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    QSKIP("AddressSanitizer reserves more address space than any limit tried here");
#endif
#endif
    // 32 MiB of "u,y" rows of 4 bytes: 8.4 million rows, 200 MB of table (two columns and the
    // line numbers). Under an address-space limit that holds the program and the text but not
    // the table, the command said "internal error: std::bad_alloc" (exit 1). The program's own
    // size is not known here, so limits 128 MB apart are tried: one of them falls in that
    // 200 MB window, and none may end in an internal error.
    const QString path = dir_.filePath("many_rows.csv");
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QByteArray text = "u,y\n";
        text.reserve(32 << 20);
        while (text.size() < (32 << 20))
            text += "1,2\n";
        f.write(text);
    }
    int said = 0;
    for (int megabytes = 128; megabytes <= 1024 && said == 0; megabytes += 128) {
        QProcess p;
        p.start("/bin/sh",
                {"-c",
                 "ulimit -v $1 && exec \"$0\" identify --data \"$2\" --ts 0.01 --input-col u "
                 "--output-col y --structure arx",
                 QStringLiteral(XYT_CLI_PATH), QString::number(megabytes * 1024), path});
        QVERIFY(p.waitForFinished(60000));
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(!err.contains("internal error"), err.constData());
        // The reader names the file and the amount; a later step (the fit) may fail instead
        // under a limit just above, which the command's last catch says without a file.
        if (err.startsWith(("xytune-cli identify: " + path +
                            ": the file needs more memory than is available (")
                               .toUtf8())) {
            QCOMPARE(p.exitCode(), 2);
            QVERIFY2(err.contains(" MB for 8388607 rows of 2 columns, 8 bytes a number)"),
                     err.constData());
            ++said;
        } else if (err.startsWith(
                       "xytune-cli identify: the command needs more memory than is available")) {
            QCOMPARE(p.exitCode(), 2);
        }
    }
    QVERIFY(said > 0);
}

QTEST_MAIN(TstCliIdentify)
#include "tst_cli_identify.moc"
