// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli excite: the JSON, the file equal to the core's signal (read back with
// the project's readers, so bit-exact), and exit code 2 with one stderr line naming the option
// for bad input, nothing written.
#include "core/identification/delimited_reader.h"
#include "core/identification/excitation.h"
#include "core/identification/lvm_reader.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>

class TstCliExcite : public QObject {
    Q_OBJECT
private slots:
    void squareToCsv();
    void prbsToLvm();
    void chirpToCsv();
    void badInputExitsWithTwo_data();
    void badInputExitsWithTwo();
    void failedWriteExitsWithTwoNamingTheOption();
};

void TstCliExcite::squareToCsv() {
    QTemporaryDir dir;
    const QString path = dir.filePath("square.csv");
    const auto run =
        xyt::test::runCli({"excite", "--signal", "square", "--ts", "0.01", "--duration", "2",
                           "--amplitude", "1.5", "--period", "0.5", "--offset", "0.5", "-o", path});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    const QJsonObject o = run.json();
    QCOMPARE(o["path"].toString(), path);
    QCOMPARE(o["samples"].toInt(), 200);
    QCOMPARE(o["ts"].toDouble(), 0.01);
    QCOMPARE(o["max_abs_u"].toDouble(), 2.0);
    QCOMPARE(o["umax"].toDouble(), 2.5); // the default: the paper's +-2.5 V amplifier range
    xyt::ExcitationTiming t;
    t.tsSeconds = 0.01;
    t.durationSeconds = 2.0;
    const xyt::ExcitationSignal expected = xyt::squareWave({1.5, 0.5, 0.5}, t);
    const xyt::ExperimentTable table = xyt::readDelimitedFile(path.toStdString()).table;
    QCOMPARE(table.columns[1], expected.u);
}

void TstCliExcite::prbsToLvm() {
    QTemporaryDir dir;
    const QString path = dir.filePath("prbs.lvm");
    const auto run =
        xyt::test::runCli({"excite", "--signal", "prbs", "--ts", "0.07", "--duration", "8.68",
                           "--amplitude", "2", "--clock", "2", "--register", "6", "-o", path});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    QCOMPARE(o["samples"].toInt(), 124); // 8.68 / 0.07 = 124 = (2^6 - 1) x 2 - 2
    const xyt::LvmTable lvm = xyt::readLvmFile(path.toStdString());
    QCOMPARE(*lvm.table.sampleTimeSeconds, 0.07);
    const std::vector<std::uint8_t> bits = xyt::prbsBits(6, 62);
    for (std::size_t k = 0; k < 124; ++k)
        QCOMPARE(lvm.table.columns[1][k], bits[k / 2] ? 2.0 : -2.0);
}

void TstCliExcite::chirpToCsv() {
    QTemporaryDir dir;
    const QString path = dir.filePath("chirp.CSV");
    const auto run = xyt::test::runCli({"excite", "--signal", "chirp", "--ts", "0.01", "--duration",
                                        "5", "--amplitude", "1", "--f0", "0.1", "--f1", "2",
                                        "--umax", "1", "-o", path});
    QCOMPARE(run.exitCode, 0);
    xyt::ExcitationTiming t;
    t.tsSeconds = 0.01;
    t.durationSeconds = 5.0;
    t.umaxVolts = 1.0;
    const xyt::ExcitationSignal expected = xyt::chirp({1.0, 0.1, 2.0, 0.0}, t);
    QCOMPARE(xyt::readDelimitedFile(path.toStdString()).table.columns[1], expected.u);
}

void TstCliExcite::badInputExitsWithTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("option");
    const QStringList square = {"--signal", "square",      "--ts", "0.01",     "--duration",
                                "1",        "--amplitude", "1",    "--period", "0.2"};
    QTest::newRow("no signal") << QStringList{"--ts", "0.01"} << "--signal";
    QTest::newRow("unknown signal") << QStringList{"--signal", "sine"} << "--signal";
    QTest::newRow("option of another signal") << square + QStringList{"--f0", "1"} << "--f0";
    QTest::newRow("negative ts") << QStringList{"--signal",   "square", "--ts",        "-0.01",
                                                "--duration", "1",      "--amplitude", "1",
                                                "--period",   "0.2"}
                                 << "--ts";
    QTest::newRow("ts not a number")
        << QStringList{"--signal", "square",      "--ts", "fast",     "--duration",
                       "1",        "--amplitude", "1",    "--period", "0.2"}
        << "--ts";
    QTest::newRow("missing period")
        << QStringList{"--signal", "square", "--ts", "0.01", "--duration", "1", "--amplitude", "1"}
        << "--period";
    QTest::newRow("above umax") << QStringList{"--signal",   "square", "--ts",        "0.01",
                                               "--duration", "1",      "--amplitude", "3",
                                               "--period",   "0.2"}
                                << "--amplitude";
    QTest::newRow("register 32") << QStringList{"--signal",   "prbs", "--ts",        "0.01",
                                                "--duration", "1",    "--amplitude", "1",
                                                "--clock",    "1",    "--register",  "32"}
                                 << "--register";
    QTest::newRow("clock 0") << QStringList{"--signal",   "prbs", "--ts",        "0.01",
                                            "--duration", "1",    "--amplitude", "1",
                                            "--clock",    "0",    "--register",  "8"}
                             << "--clock";
    QTest::newRow("f1 above Nyquist")
        << QStringList{"--signal",    "chirp", "--ts", "0.01", "--duration", "1",
                       "--amplitude", "1",     "--f0", "1",    "--f1",       "80"}
        << "--f1";
    QTest::newRow("period shorter than 2 ts")
        << QStringList{"--signal", "square",      "--ts", "0.01",     "--duration",
                       "1",        "--amplitude", "1",    "--period", "0.01"}
        << "--period";
}

void TstCliExcite::badInputExitsWithTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, option);
    QTemporaryDir dir;
    for (const QString& out : {dir.filePath("u.csv"), dir.filePath("u.txt")}) {
        QStringList full = QStringList{"excite"} + args + QStringList{"-o", out};
        if (out.endsWith(".txt") && option != "-o")
            continue;
        const auto run = xyt::test::runCli(full);
        QVERIFY(run.finished);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.out.isEmpty());
        const QString err = QString::fromUtf8(run.err).trimmed();
        QVERIFY2(!err.contains('\n'), qPrintable(err));
        QVERIFY2(err.startsWith("xytune-cli excite: " + option + ":"), qPrintable(err));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }
    // The output name itself: only .csv and .lvm.
    const auto run =
        xyt::test::runCli({"excite", "--signal", "square", "--ts", "0.01", "--duration", "1",
                           "--amplitude", "1", "--period", "0.2", "-o", dir.filePath("u.txt")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(QString::fromUtf8(run.err).startsWith("xytune-cli excite: -o:"));
}

void TstCliExcite::failedWriteExitsWithTwoNamingTheOption() {
    // A write failure exited 1 without naming -o, against the README and every other writer:
    // exit 2, one line "-o: cannot write <path>: <reason>", the old file unchanged.
    QTemporaryDir dir;
    const QStringList square = {"excite", "--signal",    "square", "--ts",     "0.01", "--duration",
                                "1",      "--amplitude", "1",      "--period", "0.2",  "-o"};
    const QString path = dir.filePath("u.csv");
    {
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly) && old.write("old\n") == 4);
    }
    const auto full =
        xyt::test::runCli(square + QStringList{path}, 60000, {"XYT_TEST_FAIL_WRITE=write"});
    QVERIFY(full.finished);
    QCOMPARE(full.exitCode, 2);
    QVERIFY(full.out.isEmpty());
    const QString err = QString::fromUtf8(full.err);
    QCOMPARE(err.count('\n'), 1);
    QVERIFY2(err.startsWith("xytune-cli excite: -o: cannot write " + path + ": " +
                            QString::fromUtf8(std::strerror(ENOSPC))),
             qPrintable(err));
    QFile kept(path);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("old\n"));
    // A folder that does not exist: the system's reason, the same exit code and option.
    const QString missing = dir.filePath("no-such-folder/u.lvm");
    const auto run = xyt::test::runCli(square + QStringList{missing});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(QString::fromUtf8(run.err).startsWith("xytune-cli excite: -o: cannot write " +
                                                   missing + ": " +
                                                   QString::fromUtf8(std::strerror(ENOENT))),
             run.err.constData());
}

QTEST_APPLESS_MAIN(TstCliExcite)
#include "tst_cli_excite.moc"
