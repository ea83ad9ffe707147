// SPDX-License-Identifier: GPL-3.0-or-later
// The MAT-file reader (core/identification/mat_reader.h). Files are written here with libmatio
// itself (v4, v5 plain and compressed, v7.3 through HDF5) and one comes from an independent
// writer, GNU Octave 7.3 (tests/data/experiment_octave.mat, tests/data/gen_experiment_mat.m).
// Expected values are the numbers written (exact in binary, so compared exactly).
#include "core/identification/mat_reader.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <matio.h>

#include <cmath>

namespace {

/// Writes double vectors (name, values, as a column when @p column) with libmatio.
bool writeMat(const QString& path, mat_ft version, matio_compression compression,
              const std::vector<std::pair<std::string, std::vector<double>>>& vars, bool column = true) {
    mat_t* m = Mat_CreateVer(path.toLocal8Bit().constData(), nullptr, version);
    if (!m)
        return false;
    bool ok = true;
    for (const auto& [name, values] : vars) {
        std::vector<double> data = values;
        size_t dims[2] = {column ? data.size() : 1, column ? 1 : data.size()};
        matvar_t* v = Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data.data(), 0);
        ok = ok && v && Mat_VarWrite(m, v, compression) == 0;
        Mat_VarFree(v);
    }
    Mat_Close(m);
    return ok;
}


const std::vector<double> kU = {0.0, 2.5, 2.5, -1.25, 0.5};
const std::vector<double> kY = {0.0, 0.125, 0.5, 1.125, 2.0};

} // namespace

class TstMatReader : public QObject {
    Q_OBJECT
private slots:
    void readsWhatLibmatioWrote_data();
    void readsWhatLibmatioWrote();
    void readsTheOctaveFile();
    void refusesWhatIsNotAVector();
    void refusesFilesThatAreNotMat_data();
    void refusesFilesThatAreNotMat();
};

void TstMatReader::readsWhatLibmatioWrote_data() {
    QTest::addColumn<int>("version");
    QTest::addColumn<int>("compression");
    QTest::addColumn<bool>("column");
    QTest::addColumn<QString>("expectedVersion");
    QTest::newRow("v4") << int(MAT_FT_MAT4) << int(MAT_COMPRESSION_NONE) << true << "v4";
    QTest::newRow("v5") << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_NONE) << true << "v5";
    QTest::newRow("v5 row vectors") << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_NONE) << false << "v5";
    QTest::newRow("v5 compressed (-v7)") << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_ZLIB) << true << "v5";
    QTest::newRow("v7.3 (HDF5)") << int(MAT_FT_MAT73) << int(MAT_COMPRESSION_NONE) << true << "v7.3";
}

void TstMatReader::readsWhatLibmatioWrote() {
    QFETCH(int, version);
    QFETCH(int, compression);
    QFETCH(bool, column);
    QFETCH(QString, expectedVersion);
    QTemporaryDir dir;
    const QString path = dir.filePath("run.mat");
    QVERIFY(writeMat(path, mat_ft(version), matio_compression(compression),
                     {{"u", kU}, {"y", kY}, {"t", {0.0, 0.07, 0.14, 0.21, 0.28}}}, column));
    const xyt::MatFileInfo info = xyt::listMatVariables(path.toStdString());
    QCOMPARE(QString::fromStdString(info.version), expectedVersion);
    QCOMPARE(info.variables.size(), std::size_t(3));
    for (const auto& v : info.variables) {
        QVERIFY(v.usable);
        QCOMPARE(v.className, std::string("double"));
        QCOMPARE(v.rows * v.columns, std::size_t(5));
    }
    const xyt::ExperimentTable t = xyt::readMat(path.toStdString(), {"y", "u"});
    QCOMPARE(t.names, (std::vector<std::string>{"y", "u"}));
    QCOMPARE(t.columns[0], kY);
    QCOMPARE(t.columns[1], kU);
    QCOMPARE(t.rowNumbers, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
    // Without names: every usable vector, in the order libmatio lists them (file order for v4
    // and v5; HDF5 lists v7.3 variables by name).
    QCOMPARE(xyt::readMat(path.toStdString()).names.size(), std::size_t(3));
    // An unknown name lists the usable ones.
    const QString message = xyt::test::invalidInputMessage([&] { xyt::readMat(path.toStdString(), {"pos"}); });
    QVERIFY2(message.contains("has no variable 'pos'; the real numeric vectors are: ") &&
                             message.contains("u") && message.contains("y") && message.contains("t"), qPrintable(message));
}

void TstMatReader::readsTheOctaveFile() {
    const std::string path = XYT_TEST_DATA_DIR "/experiment_octave.mat";
    const xyt::MatFileInfo info = xyt::listMatVariables(path);
    QCOMPARE(info.version, std::string("v5"));
    std::vector<std::string> usable, unusable;
    for (const auto& v : info.variables)
        (v.usable ? usable : unusable).push_back(v.name);
    QCOMPARE(usable, (std::vector<std::string>{"t", "u", "y", "counts", "ysingle", "withnan"}));
    QCOMPARE(unusable, (std::vector<std::string>{"cplx", "M", "name", "flag"}));
    const xyt::ExperimentTable table = xyt::readMat(path, {"t", "u", "y", "counts", "ysingle", "withnan"});
    for (std::size_t k = 0; k < 10; ++k) {
        QCOMPARE(table.columns[0][k], 0.25 * double(k));
        QCOMPARE(table.columns[1][k], k == 0 ? 0.0 : 2.5);
        QCOMPARE(table.columns[2][k], 0.125 * double(k * k));
        QCOMPARE(table.columns[4][k], 0.5 * double(k)); // single -> double exactly
    }
    // int32 converted exactly, the extremes included.
    QCOMPARE(table.columns[3][4], -2147483648.0);
    QCOMPARE(table.columns[3][5], 2147483647.0);
    // The NaN is the column's problem, named by element.
    QVERIFY(table.firstProblem[5]);
    QCOMPARE(table.firstProblem[5]->row, std::size_t(1));
    QCOMPARE(QString::fromStdString(table.cellField(5, 1)), QString::fromStdString(path + ": element 2 of withnan"));
}

void TstMatReader::refusesWhatIsNotAVector() {
    const std::string path = XYT_TEST_DATA_DIR "/experiment_octave.mat";
    const std::pair<const char*, const char*> cases[] = {
        {"M", "variable 'M' is a 3 x 3 matrix, not a vector"},
        {"cplx", "variable 'cplx' is complex"},
        {"name", "variable 'name' is of class char, not numeric"},
        {"flag", "variable 'flag' is logical"},
    };
    for (const auto& [variable, expected] : cases) {
        const std::string name = variable;  // a lambda may not capture a structured binding (clang 14)
        const QString message = xyt::test::invalidInputMessage([&] { xyt::readMat(path, {name}); });
        QVERIFY2(message.startsWith(QString::fromStdString(path) + ": " + expected), qPrintable(message));
    }
}

void TstMatReader::refusesFilesThatAreNotMat_data() {
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    QTest::newRow("empty") << QByteArray() << "is not a MAT file";
    QTest::newRow("text") << QByteArray("t,u\n0,1\n") << "is not a MAT file";
    QByteArray header(128, ' ');
    header.replace(0, 19, "MATLAB 5.0 MAT-file");
    header[124] = 0x00;
    header[125] = 0x01;
    header[126] = 'I';
    header[127] = 'M';
    QTest::newRow("v5 header, no variable") << header << "is not a MAT file: it holds a MATLAB header and no variable";
    QByteArray badVersion = header;
    badVersion[125] = 0x07;
    QTest::newRow("unknown version") << badVersion << "is not a MAT file: its MATLAB header states version";
    QByteArray junk = header + QByteArray(64, '\xff');
    QTest::newRow("v5 header, junk element") << junk << "";
}

void TstMatReader::refusesFilesThatAreNotMat() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = dir.filePath("junk.mat");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
    f.close();
    // Junk that passes our header check may be listed as nothing or refused by libmatio; it
    // must never crash, and a refusal names the file.
    QString message;
    try {
        const xyt::MatFileInfo info = xyt::listMatVariables(path.toStdString());
        QVERIFY(expected.isEmpty());
        for (const auto& v : info.variables)
            QVERIFY(!v.usable || v.rows * v.columns >= 1);
        return;
    } catch (const xyt::InvalidInput& e) {
        message = e.what();
    }
    QVERIFY2(message.startsWith(path + ": "), qPrintable(message));
    QVERIFY2(message.contains(expected), qPrintable(message));
}

QTEST_APPLESS_MAIN(TstMatReader)
#include "tst_mat_reader.moc"
