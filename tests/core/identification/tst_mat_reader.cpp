// SPDX-License-Identifier: GPL-3.0-or-later
// The MAT-file reader (core/identification/mat_reader.h). Files are written here with libmatio
// itself (v4, v5 plain and compressed, v7.3 through HDF5) and one comes from an independent
// writer, GNU Octave 7.3 (tests/data/experiment_octave.mat, tests/data/gen_experiment_mat.m).
// Expected values are the numbers written (exact in binary, so compared exactly).
#include "core/identification/experiment_file.h"
#include "core/identification/mat_reader.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <matio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

/// Writes double vectors (name, values, as a column when @p column) with libmatio.
bool writeMat(const QString& path, mat_ft version, matio_compression compression,
              const std::vector<std::pair<std::string, std::vector<double>>>& vars,
              bool column = true) {
    mat_t* m = Mat_CreateVer(path.toLocal8Bit().constData(), nullptr, version);
    if (!m)
        return false;
    bool ok = true;
    for (const auto& [name, values] : vars) {
        std::vector<double> data = values;
        size_t dims[2] = {column ? data.size() : 1, column ? 1 : data.size()};
        matvar_t* v =
            Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data.data(), 0);
        ok = ok && v && Mat_VarWrite(m, v, compression) == 0;
        Mat_VarFree(v);
    }
    Mat_Close(m);
    return ok;
}

const std::vector<double> kU = {0.0, 2.5, 2.5, -1.25, 0.5};
const std::vector<double> kY = {0.0, 0.125, 0.5, 1.125, 2.0};

/// A v5 file holding @p u (freed here) and the double vector y (kY).
bool writeWithU(const QString& path, matvar_t* u) {
    mat_t* m = Mat_CreateVer(path.toLocal8Bit().constData(), nullptr, MAT_FT_MAT5);
    if (!m || !u) {
        Mat_VarFree(u);
        if (m)
            Mat_Close(m);
        return false;
    }
    std::vector<double> y = kY;
    size_t dims[2] = {y.size(), 1};
    matvar_t* yv = Mat_VarCreate("y", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, y.data(), 0);
    const bool ok = Mat_VarWrite(m, u, MAT_COMPRESSION_NONE) == 0 && yv &&
                    Mat_VarWrite(m, yv, MAT_COMPRESSION_NONE) == 0;
    Mat_VarFree(u);
    Mat_VarFree(yv);
    Mat_Close(m);
    return ok;
}

/// @p count zeros as the double column @p name, written compressed: a calloc'ed buffer (zero
/// pages the kernel maps on read, never resident), so that the test itself stays small.
bool writeCompressedZeros(mat_t* m, const char* name, std::size_t count) {
    void* zeros = std::calloc(count, sizeof(double));
    size_t dims[2] = {count, 1};
    matvar_t* v = zeros ? Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, zeros,
                                        MAT_F_DONT_COPY_DATA)
                        : nullptr;
    const bool ok = v && Mat_VarWrite(m, v, MAT_COMPRESSION_ZLIB) == 0;
    if (v)
        v->data = nullptr; // ours, freed below
    Mat_VarFree(v);
    std::free(zeros);
    return ok;
}

/// A variable "u" of each kind that is not a real numeric vector, made with libmatio.
matvar_t* unusableU(const QString& kind) {
    static double values[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    static double imaginary[8] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    static char text[] = "hello";
    static unsigned char flags[4] = {1, 0, 1, 1};
    size_t column[2] = {4, 1};
    if (kind == "cell") {
        size_t one[2] = {1, 1};
        matvar_t* cells[2] = {
            Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, values, 0),
            Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, values + 1, 0)};
        size_t dims[2] = {2, 1};
        return Mat_VarCreate("u", MAT_C_CELL, MAT_T_CELL, 2, dims, cells, 0);
    }
    if (kind == "struct") {
        size_t one[2] = {1, 1};
        const char* fields[] = {"a"};
        matvar_t* s = Mat_VarCreateStruct("u", 2, one, fields, 1);
        Mat_VarSetStructFieldByName(
            s, "a", 0, Mat_VarCreate("a", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, column, values, 0));
        return s;
    }
    if (kind == "char") {
        size_t dims[2] = {1, 5};
        return Mat_VarCreate("u", MAT_C_CHAR, MAT_T_UINT8, 2, dims, text, 0);
    }
    if (kind == "complex") {
        mat_complex_split_t split{values, imaginary};
        return Mat_VarCreate("u", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, column, &split, MAT_F_COMPLEX);
    }
    if (kind == "3-D") {
        size_t dims[3] = {2, 2, 2};
        return Mat_VarCreate("u", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, dims, values, 0);
    }
    if (kind == "sparse") {
        // The 4 x 1 column (1, 0, 2, 0) in compressed-column form.
        static mat_uint32_t ir[2] = {0, 2}, jc[2] = {0, 2};
        mat_sparse_t sparse{};
        sparse.nzmax = 2;
        sparse.ir = ir;
        sparse.nir = 2;
        sparse.jc = jc;
        sparse.njc = 2;
        sparse.ndata = 2;
        sparse.data = values;
        return Mat_VarCreate("u", MAT_C_SPARSE, MAT_T_DOUBLE, 2, column, &sparse, 0);
    }
    if (kind == "logical")
        return Mat_VarCreate("u", MAT_C_UINT8, MAT_T_UINT8, 2, column, flags, MAT_F_LOGICAL);
    if (kind == "matrix") {
        size_t dims[2] = {4, 2};
        return Mat_VarCreate("u", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, values, 0);
    }
    if (kind == "empty") {
        size_t dims[2] = {0, 0};
        return Mat_VarCreate("u", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, nullptr, 0);
    }
    return nullptr;
}

/// What a read did in a child process, and the memory it took.
struct ChildRead {
    QString outcome; ///< "ok: ...", "refused: <message>", "out of memory", "crashed"
    double peakGrowthBytes =
        0.0; ///< the child's peak resident memory above the parent's at the fork
};

/// Field @p index of /proc/self/statm (0: address space, 1: resident), in bytes.
double statmBytes(int index) {
    long fields[2] = {0, 0};
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &fields[0], &fields[1]) != 2)
            fields[0] = fields[1] = 0;
        std::fclose(f);
    }
    return double(fields[index]) * double(::sysconf(_SC_PAGESIZE));
}

#if defined(__SANITIZE_ADDRESS__)
#define XYT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define XYT_TEST_UNDER_ASAN 1
#endif
#endif

/**
 * Runs @p read in a forked child whose address space may grow by at most @p limitBytes beyond
 * the parent's (RLIMIT_AS: a read that asks for gigabytes fails there instead of taking the
 * machine's memory; not set under AddressSanitizer, whose shadow memory reserves terabytes of
 * address space), and measures the child's peak resident memory (getrusage through wait4).
 */
ChildRead readInChild(const std::function<QString()>& read, [[maybe_unused]] double limitBytes) {
    int fds[2];
    if (::pipe(fds) != 0)
        return {"no pipe", 0.0};
    const double baseResident = statmBytes(1);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
#ifndef XYT_TEST_UNDER_ASAN
        const rlim_t limit = rlim_t(statmBytes(0) + limitBytes);
        const rlimit rl{limit, limit};
        ::setrlimit(RLIMIT_AS, &rl);
#endif
        QByteArray outcome;
        try {
            outcome = ("ok: " + read()).toUtf8();
        } catch (const xyt::InvalidInput& e) {
            outcome = QByteArray("refused: ") + e.what();
        } catch (const std::bad_alloc&) {
            outcome = "out of memory";
        } catch (const std::exception& e) {
            outcome = QByteArray("other exception: ") + e.what();
        }
        const ssize_t n = ::write(fds[1], outcome.constData(), std::size_t(outcome.size()));
        ::_exit(n == outcome.size() ? 0 : 1);
    }
    ::close(fds[1]);
    QByteArray outcome;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
        outcome.append(buffer, n);
    ::close(fds[0]);
    int status = 0;
    rusage usage{};
    if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status))
        return {"crashed", 0.0};
    return {QString::fromUtf8(outcome), double(usage.ru_maxrss) * 1024.0 - baseResident};
}

/// The names and lengths of a table, "u:300 y:300".
QString columnsText(const xyt::ExperimentTable& t) {
    QString text;
    for (std::size_t c = 0; c < t.names.size(); ++c)
        text += (c ? " " : "") + QString::fromStdString(t.names[c]) + ":" +
                QString::number(t.columns[c].size());
    return text;
}

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
    void namesWhyAVariableCannotBeUsed_data();
    void namesWhyAVariableCannotBeUsed();
    void readsTwoOfMoreThanAThousandVariables();
    void readsOnlyWhatIsAskedForInBoundedMemory_data();
    void readsOnlyWhatIsAskedForInBoundedMemory();
    void boundsWhatTheVariablesAskedForHoldTogether();

private:
    /// The v7 file of the reproduction (5e7 compressed zeros as z, then u and y), written once.
    QString zerosFile();
    QTemporaryDir dir_;
};

QString TstMatReader::zerosFile() {
    const QString file = dir_.filePath("zeros.mat");
    if (QFileInfo::exists(file))
        return file;
    mat_t* m = Mat_CreateVer(file.toLocal8Bit().constData(), nullptr, MAT_FT_MAT5);
    if (!m)
        return {};
    bool ok = writeCompressedZeros(m, "z", 50'000'000);
    for (const auto& [name, values] : {std::pair{"u", kU}, std::pair{"y", kY}}) {
        std::vector<double> data = values;
        size_t dims[2] = {data.size(), 1};
        matvar_t* v = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data.data(), 0);
        ok = ok && v && Mat_VarWrite(m, v, MAT_COMPRESSION_ZLIB) == 0;
        Mat_VarFree(v);
    }
    Mat_Close(m);
    if (!ok)
        QFile::remove(file);
    return ok ? file : QString();
}

void TstMatReader::readsWhatLibmatioWrote_data() {
    QTest::addColumn<int>("version");
    QTest::addColumn<int>("compression");
    QTest::addColumn<bool>("column");
    QTest::addColumn<QString>("expectedVersion");
    QTest::newRow("v4") << int(MAT_FT_MAT4) << int(MAT_COMPRESSION_NONE) << true << "v4";
    QTest::newRow("v5") << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_NONE) << true << "v5";
    QTest::newRow("v5 row vectors")
        << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_NONE) << false << "v5";
    QTest::newRow("v5 compressed (-v7)")
        << int(MAT_FT_MAT5) << int(MAT_COMPRESSION_ZLIB) << true << "v5";
    QTest::newRow("v7.3 (HDF5)") << int(MAT_FT_MAT73) << int(MAT_COMPRESSION_NONE) << true
                                 << "v7.3";
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
    const QString message =
        xyt::test::invalidInputMessage([&] { xyt::readMat(path.toStdString(), {"pos"}); });
    QVERIFY2(message.contains("has no variable 'pos'; the real numeric vectors are: ") &&
                 message.contains("u") && message.contains("y") && message.contains("t"),
             qPrintable(message));
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
    const xyt::ExperimentTable table =
        xyt::readMat(path, {"t", "u", "y", "counts", "ysingle", "withnan"});
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
    QCOMPARE(QString::fromStdString(table.cellField(5, 1)),
             QString::fromStdString(path + ": element 2 of withnan"));
}

void TstMatReader::refusesWhatIsNotAVector() {
    const std::string path = XYT_TEST_DATA_DIR "/experiment_octave.mat";
    const std::pair<const char*, const char*> cases[] = {
        {"M", "variable 'M' is a 3 x 3 matrix, not a vector"},
        {"cplx", "variable 'cplx' is complex"},
        {"name", "variable 'name' is text (a char array)"},
        {"flag", "variable 'flag' is logical (true/false)"},
    };
    for (const auto& [variable, expected] : cases) {
        const std::string name =
            variable; // a lambda may not capture a structured binding (clang 14)
        const QString message = xyt::test::invalidInputMessage([&] { xyt::readMat(path, {name}); });
        QVERIFY2(message.startsWith(QString::fromStdString(path) + ": " + expected),
                 qPrintable(message));
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
    QTest::newRow("v5 header, no variable")
        << header << "is not a MAT file: it holds a MATLAB header and no variable";
    QByteArray badVersion = header;
    badVersion[125] = 0x07;
    QTest::newRow("unknown version")
        << badVersion << "is not a MAT file: its MATLAB header states version";
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

// Each kind of variable that exists but cannot be a signal is named as what it is, not as a
// missing column; the sentence says what is needed. Reproduction: a cell `u` was reported as
// "has no column 'u'" by the table lookup after the whole file had been read.
void TstMatReader::namesWhyAVariableCannotBeUsed_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("why");
    QTest::newRow("cell") << "cell"
                          << "is a cell array";
    QTest::newRow("struct") << "struct"
                            << "is a struct";
    QTest::newRow("char") << "char"
                          << "is text (a char array)";
    QTest::newRow("complex") << "complex"
                             << "is complex";
    QTest::newRow("3-D") << "3-D"
                         << "is a 2 x 2 x 2 array (3 dimensions)";
    QTest::newRow("sparse") << "sparse"
                            << "is a sparse matrix";
    QTest::newRow("logical") << "logical"
                             << "is logical (true/false)";
    QTest::newRow("matrix") << "matrix"
                            << "is a 4 x 2 matrix, not a vector";
    QTest::newRow("empty") << "empty"
                           << "is empty";
}

void TstMatReader::namesWhyAVariableCannotBeUsed() {
    QFETCH(QString, kind);
    QFETCH(QString, why);
    QTemporaryDir dir;
    const QString path = dir.filePath("run.mat");
    QVERIFY(writeWithU(path, unusableU(kind)));
    const xyt::MatFileInfo info = xyt::listMatVariables(path.toStdString());
    QCOMPARE(info.variables.size(), std::size_t(2));
    QCOMPARE(info.variables[0].name, std::string("u"));
    QVERIFY(!info.variables[0].usable);
    QCOMPARE(QString::fromStdString(info.variables[0].whyNot), why);
    // As the CLI asks (identify --input-col u --output-col y).
    const QString message = xyt::test::invalidInputMessage([&] {
        xyt::readExperimentTable(path.toStdString(), 1, {"u", "y"});
    });
    QCOMPARE(message, path + ": variable 'u' " + why +
                          "; a vector of real numbers is needed (the real numeric vectors are: y)");
}

// More than kMaxExperimentColumns usable variables: two asked for are read (the reproduction
// said "more than 1000 variables asked for"); all of them, as the identification window asks,
// are the first 1000 with a warning for the rest; 1001 names are refused as such.
void TstMatReader::readsTwoOfMoreThanAThousandVariables() {
    QTemporaryDir dir;
    const QString path = dir.filePath("many.mat");
    std::vector<std::pair<std::string, std::vector<double>>> vars;
    for (std::size_t k = 0; k < xyt::kMaxExperimentColumns + 1; ++k)
        vars.push_back({"v" + std::to_string(k), {double(k)}});
    vars.push_back({"u", kU});
    vars.push_back({"y", kY});
    QVERIFY(writeMat(path, MAT_FT_MAT5, MAT_COMPRESSION_NONE, vars));
    const xyt::ExperimentTable two = xyt::readMat(path.toStdString(), {"u", "y"});
    QCOMPARE(two.names, (std::vector<std::string>{"u", "y"}));
    QCOMPARE(two.columns[0], kU);
    QCOMPARE(two.columns[1], kY);

    const xyt::ExperimentTable all = xyt::readMat(path.toStdString());
    QCOMPARE(all.names.size(), xyt::kMaxExperimentColumns);
    QCOMPARE(all.names.back(), "v" + std::to_string(xyt::kMaxExperimentColumns - 1));
    // v1000, u and y are left out: three warnings, each naming its variable.
    QCOMPARE(all.warnings.size(), std::size_t(3));
    QCOMPARE(QString::fromStdString(all.warnings[0]),
             "variable 'v1000' (1 x 1 elements) is not read: a table holds at most 1000 variables");
    QVERIFY(QString::fromStdString(all.warnings[2]).startsWith("variable 'y' "));

    std::vector<std::string> names;
    for (std::size_t k = 0; k < xyt::kMaxExperimentColumns + 1; ++k)
        names.push_back("v" + std::to_string(k));
    QCOMPARE(xyt::test::invalidInputMessage([&] { xyt::readMat(path.toStdString(), names); }),
             path + ": 1001 variables asked for, more than the 1000 a table may hold");
}

// The reproductions: a v7.3 file with an unwritten chunked dataset claiming 4e8 doubles
// (tests/data/mat73_unwritten_dataset.mat, 8 KB) took 6.27 GB when u and y were read; a v7
// file with 5e7 compressed zeros (about 390 KB, written here) took 800 MB. Each read runs in a
// child process whose address space may grow by 1 GiB at most, and its peak resident memory
// is measured: the variables asked for are read (or the big one refused, named) in less than
// 64 MB, where reading the big variable would take 3.2 GB or 400 MB.
void TstMatReader::readsOnlyWhatIsAskedForInBoundedMemory_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("names");
    QTest::addColumn<QString>("expected");
    const QString v73 = XYT_TEST_DATA_DIR "/mat73_unwritten_dataset.mat";
    QTest::newRow("v7.3, u and y") << v73 << QStringList{"u", "y"} << "ok: u:300 y:300";
    QTest::newRow("v7.3, every usable one") << v73 << QStringList{}
                                            << "ok: u:300 y:300; variable 'big' (400000000 x 1 "
                                               "elements) is not read: more than the 16777216 "
                                               "elements one variable may hold";
    QTest::newRow("v7.3, the big one")
        << v73 << QStringList{"big"}
        << "refused: " + v73 +
               ": variable 'big' claims 400000000 x 1 elements, more than the 16777216 one "
               "variable may hold";
    QTest::newRow("v7, u and y") << "zeros" << QStringList{"u", "y"} << "ok: u:5 y:5";
    QTest::newRow("v7, every usable one")
        << "zeros" << QStringList{}
        << "ok: u:5 y:5; variable 'z' (50000000 x 1 elements) is not read: more than the 16777216 "
           "elements one variable may hold";
    QTest::newRow("v7, the big one") << "zeros" << QStringList{"y", "z"}
                                     << "refused: zeros: variable 'z' claims 50000000 x 1 "
                                        "elements, more than the 16777216 one variable "
                                        "may hold";
}

void TstMatReader::readsOnlyWhatIsAskedForInBoundedMemory() {
    QFETCH(QString, file);
    QFETCH(QStringList, names);
    QFETCH(QString, expected);
    if (file == "zeros") {
        file = zerosFile();
        QVERIFY(!file.isEmpty());
        QVERIFY(QFileInfo(file).size() < 500'000);
        expected.replace("refused: zeros: ", "refused: " + file + ": ");
    }
    std::vector<std::string> wanted;
    for (const QString& n : names)
        wanted.push_back(n.toStdString());
    const std::string path = file.toStdString();
    const ChildRead r = readInChild(
        [&] {
            // As the CLI (the names given) and the identification window (none) read a file.
            const xyt::ExperimentTable t = xyt::readExperimentTable(path, 1, wanted);
            QString text = columnsText(t);
            for (const std::string& w : t.warnings)
                text += "; " + QString::fromStdString(w);
            return text;
        },
        1024.0 * 1024.0 * 1024.0);
    QCOMPARE(r.outcome, expected);
    QVERIFY2(r.peakGrowthBytes < 64e6,
             qPrintable(QString::number(r.peakGrowthBytes / 1e6) + " MB"));
}

// The variables asked for together: four of exactly kMaxMatVariableElements fill
// kMaxMatTableElements, one more element is refused before any data is read, naming the
// variable that crosses the bound; one of kMaxMatVariableElements + 1 is refused alone.
void TstMatReader::boundsWhatTheVariablesAskedForHoldTogether() {
    QTemporaryDir dir;
    const QString path = dir.filePath("full.mat");
    mat_t* m = Mat_CreateVer(path.toLocal8Bit().constData(), nullptr, MAT_FT_MAT5);
    QVERIFY(m);
    const std::size_t n = xyt::kMaxMatVariableElements;
    QCOMPARE(4 * n, std::size_t(xyt::kMaxMatTableElements));
    bool ok = writeCompressedZeros(m, "a", n) && writeCompressedZeros(m, "b", n) &&
              writeCompressedZeros(m, "c", n) && writeCompressedZeros(m, "d", n) &&
              writeCompressedZeros(m, "e", n + 1) && writeCompressedZeros(m, "one", 1);
    Mat_Close(m);
    QVERIFY(ok);
    const std::string p = path.toStdString();
    QCOMPARE(xyt::test::invalidInputMessage([&] {
                 xyt::readMat(p, {"a", "b", "c", "d", "one"});
             }),
             path + ": the variables asked for, up to 'one', hold 67108865 elements, more than the "
                    "67108864 one "
                    "read may hold");
    QCOMPARE(xyt::test::invalidInputMessage([&] {
                 xyt::readMat(p, {"one", "e"});
             }),
             path + ": variable 'e' claims 16777217 x 1 elements, more than the 16777216 one "
                    "variable may hold");
}

QTEST_APPLESS_MAIN(TstMatReader)
#include "tst_mat_reader.moc"
