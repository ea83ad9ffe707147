// SPDX-License-Identifier: GPL-3.0-or-later
// The memory the text experiment readers take (core/identification/delimited_reader.h,
// lvm_reader.h through readExperimentTable). Target: at most the file's size plus 8 bytes a
// numeric cell plus a fixed overhead. The readers also keep each row's line number (8 bytes a
// row), so the bound checked here is
//     file bytes + 8 x cells + 8 x rows + 32 MB
// where 32 MB stands for the fixed overhead at this scale (allocator slack, the header, the
// reader's buffers). The reader of before took 20 to 28 times the file's size (a string per
// cell, a vector per row, a table of every line), over 600 MB for these 32 MiB files. Each read
// runs in a forked child, whose ru_maxrss growth is its own peak. When the memory is not there,
// the reader says so, naming the file and the amount, instead of throwing std::bad_alloc.
#include "core/identification/experiment_file.h"
#include "core/model/errors.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define XYT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define XYT_ASAN 1
#endif
#endif

namespace {

constexpr std::size_t kFileBytes = 32u << 20;
constexpr double kFixedOverhead = 32.0 * (1 << 20);

/// What a child reports back: its peak RSS growth in bytes and the message of what it threw.
struct ChildResult {
    long long peakGrowth = -1;
    std::string message;
};

/// Runs @p body in a forked child and returns its peak RSS growth (ru_maxrss after minus before:
/// the child starts with the parent's pages, so the growth is what @p body allocated and
/// touched) and the what() of an exception it threw.
ChildResult inChild(const std::function<void()>& body) {
    int fds[2];
    if (::pipe(fds) != 0)
        return {};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        rusage before{}, after{};
        ::getrusage(RUSAGE_SELF, &before);
        std::string message;
        try {
            body();
        } catch (const std::exception& e) {
            message = e.what();
        }
        ::getrusage(RUSAGE_SELF, &after);
        const long long growth =
            (static_cast<long long>(after.ru_maxrss) - before.ru_maxrss) * 1024;
        [[maybe_unused]] auto w1 = ::write(fds[1], &growth, sizeof growth);
        [[maybe_unused]] auto w2 = ::write(fds[1], message.data(), message.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    ChildResult r;
    if (::read(fds[0], &r.peakGrowth, sizeof r.peakGrowth) != sizeof r.peakGrowth)
        r.peakGrowth = -1;
    char buffer[1024];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
        r.message.append(buffer, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return r;
}

/// A file of about kFileBytes: @p head, then @p row(k) until the size is reached.
/// Returns the number of rows written.
std::size_t writeFile(const QString& path, const std::string& head,
                      const std::function<std::string(std::size_t)>& row) {
    std::string text = head;
    text.reserve(kFileBytes + 256);
    std::size_t rows = 0;
    while (text.size() < kFileBytes)
        text += row(rows++);
    std::FILE* f = std::fopen(path.toLocal8Bit().constData(), "wb");
    if (!f || std::fwrite(text.data(), 1, text.size(), f) != text.size())
        rows = 0;
    if (f)
        std::fclose(f);
    return rows;
}

std::string numbers(std::size_t k, char sep, bool withTime) {
    char line[96];
    const double t = 0.001 * static_cast<double>(k);
    const double u = (k / 7) % 2 ? 2.5 : -2.5;
    const double y = 0.25 * static_cast<double>(k % 1000);
    if (withTime)
        std::snprintf(line, sizeof line, "%.3f%c%.4f%c%.4f\n", t, sep, u, sep, y);
    else
        std::snprintf(line, sizeof line, "%c%.4f%c%.4f\n", sep, u, sep, y);
    return line;
}

double fileBytes(const QString& path) {
    return static_cast<double>(QFileInfo(path).size());
}

double bound(double fileBytes, double cells, double rows) {
    return fileBytes + 8.0 * cells + 8.0 * rows + kFixedOverhead;
}

} // namespace

class TstExperimentMemory : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void csvTakesTheFileAndEightBytesACell();
    void blankLinesTakeNoMemory();
    void lvmTakesTheFileAndEightBytesACell();
    void chosenColumnsOnlyAreKept();
    void lackOfMemoryIsSaidNamingTheFile();

private:
    /// Reads @p path keeping @p columns in a child: @p keptColumns columns of @p rows rows, the
    /// last from line @p lastLine, within bound() of the file's size and those cells.
    void readWithinTheBound(const QString& path, const std::vector<std::string>& columns,
                            std::size_t keptColumns, std::size_t rows, std::size_t lastLine);
    QTemporaryDir dir_;
};

void TstExperimentMemory::readWithinTheBound(const QString& path,
                                             const std::vector<std::string>& columns,
                                             std::size_t keptColumns, std::size_t rows,
                                             std::size_t lastLine) {
    const ChildResult r = inChild([&] {
        const xyt::ExperimentTable t = xyt::readExperimentTable(path.toStdString(), 1, columns);
        if (t.columns.size() != keptColumns || t.columns.back().size() != rows ||
            t.rowNumbers.back() != lastLine)
            throw std::runtime_error("not the table written");
    });
    QCOMPARE(QString::fromStdString(r.message), QString());
    const double limit = bound(fileBytes(path), double(keptColumns * rows), double(rows));
    const QString figures =
        QString("peak growth %1 MB, bound %2 MB").arg(r.peakGrowth >> 20).arg(limit / (1 << 20));
    qInfo("%s", qPrintable(figures));
    QVERIFY2(r.peakGrowth > 0 && double(r.peakGrowth) <= limit, qPrintable(figures));
}

void TstExperimentMemory::initTestCase() {
    QVERIFY(dir_.isValid());
#ifdef XYT_ASAN
    QSKIP("AddressSanitizer keeps freed blocks in quarantine and reserves address space: RSS and "
          "RLIMIT_AS say nothing about the reader there");
#endif
}

void TstExperimentMemory::csvTakesTheFileAndEightBytesACell() {
    const QString path = dir_.filePath("run.csv");
    const std::size_t rows =
        writeFile(path, "t,u,y\n", [](std::size_t k) { return numbers(k, ',', true); });
    QVERIFY(rows > 0);
    readWithinTheBound(path, {}, 3, rows, rows + 1);
}

void TstExperimentMemory::blankLinesTakeNoMemory() {
    // 32 MiB of blank lines between two rows: no row, no cell, only the text.
    const QString path = dir_.filePath("blank.csv");
    std::string text = "t,u,y\n0,1,2\n";
    text.append(kFileBytes, '\n');
    text += "0.01,3,4\n";
    std::FILE* f = std::fopen(path.toLocal8Bit().constData(), "wb");
    QVERIFY(f);
    QCOMPARE(std::fwrite(text.data(), 1, text.size(), f), text.size());
    std::fclose(f);
    text = std::string();
    readWithinTheBound(path, {}, 3, 2, kFileBytes + 3);
}

void TstExperimentMemory::lvmTakesTheFileAndEightBytesACell() {
    const QString path = dir_.filePath("run.lvm");
    const std::string head =
        "LabVIEW Measurement\t\nSeparator\tTab\nX_Columns\tNo\n***End_of_Header***\t\n"
        "Channels\t2\nDelta_X\t0.001\t0.001\n***End_of_Header***\nX_Value\tu\ty\tComment\n";
    const std::size_t rows =
        writeFile(path, head, [](std::size_t k) { return numbers(k, '\t', false); });
    QVERIFY(rows > 0);
    readWithinTheBound(path, {}, 2, rows, rows + 8);
}

void TstExperimentMemory::chosenColumnsOnlyAreKept() {
    // Reading two of three columns: 8 bytes a kept cell (the identify command reads so).
    const QString path = dir_.filePath("chosen.csv");
    const std::size_t rows =
        writeFile(path, "t,u,y\n", [](std::size_t k) { return numbers(k, ',', true); });
    QVERIFY(rows > 0);
    readWithinTheBound(path, {"u", "y"}, 2, rows, rows + 1);
}

void TstExperimentMemory::lackOfMemoryIsSaidNamingTheFile() {
    // "1,2,3" rows: 6 bytes of text, 32 bytes of table (3 cells and the line number). The
    // child's address space is limited to what it uses now plus the text and 16 MB, so the
    // text is read but the columns cannot be: the reader must say so, not throw bad_alloc.
    const QString path = dir_.filePath("small_rows.csv");
    const std::size_t rows =
        writeFile(path, "t,u,y\n", [](std::size_t) { return std::string("1,2,3\n"); });
    QVERIFY(rows > 0);
    const ChildResult r = inChild([&] {
        long pages = 0;
        if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(statm, "%ld", &pages) != 1)
                pages = 0;
            std::fclose(statm);
        }
        const rlim_t limit =
            static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + kFileBytes +
            (16u << 20);
        const rlimit rl{limit, limit};
        if (pages == 0 || ::setrlimit(RLIMIT_AS, &rl) != 0)
            throw std::runtime_error("cannot limit the address space");
        xyt::readExperimentTable(path.toStdString());
    });
    // The amount: rows x (3 columns + the line numbers) x 8 bytes, in MB rounded up.
    const std::size_t megabytes = (rows * 32 + (1u << 20) - 1) >> 20;
    QCOMPARE(QString::fromStdString(r.message),
             QString("%1: the file needs more memory than is available (%2 MB for %3 rows of 3 "
                     "columns, 8 bytes a "
                     "number)")
                 .arg(path)
                 .arg(megabytes)
                 .arg(rows));
}

QTEST_APPLESS_MAIN(TstExperimentMemory)
#include "tst_experiment_memory.moc"
