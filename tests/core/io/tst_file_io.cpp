// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/file_io.h: atomic writes that never lose the old file (issue 20: a full disk left a
// 0-byte file and reported success), no replacing of special files, bounded reads that never
// block on a FIFO nor read a device to exhaustion.
#include "core/io/file_io.h"
#include "tests/support/small_filesystem.h"

#include <QDir>
#include <QFile>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>

#include <sys/stat.h>

using namespace xyt;

class TstFileIo : public QObject {
    Q_OBJECT
private slots:
    void writesAndKeepsTheMode();
    void injectedFailureKeepsOldFile_data();
    void injectedFailureKeepsOldFile();
    void producerErrorKeepsOldFile();
    void refusesToReplaceSpecialFiles();
    void streamsLargeContent();
    void readRefusesSpecialFiles();
    void readStopsAtTheLimit();
    void fullDiskKeepsOldFile(); // last: it moves the process into its own mount namespace
};

namespace {

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

/// Only the files a test created: no temporary file may be left behind after a failure.
QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::System);
}

} // namespace

void TstFileIo::writesAndKeepsTheMode() {
    QTemporaryDir dir;
    const QString path = dir.filePath("out.txt");
    writeFileAtomically(path.toStdString(), "first");
    QCOMPARE(contents(path), QByteArray("first"));
    QVERIFY(::chmod(QFile::encodeName(path).constData(), 0640) == 0);
    writeFileAtomically(path.toStdString(), "second");
    QCOMPARE(contents(path), QByteArray("second"));
    struct stat st {};
    QVERIFY(::stat(QFile::encodeName(path).constData(), &st) == 0);
    QCOMPARE(st.st_mode & 07777, 0640u);
    QCOMPARE(entries(dir.path()), QStringList{"out.txt"});
}

void TstFileIo::injectedFailureKeepsOldFile_data() {
    QTest::addColumn<int>("step");
    QTest::addColumn<int>("error");
    QTest::newRow("write fails (full disk)") << int(WriteStep::Write) << ENOSPC;
    QTest::newRow("fsync fails (I/O error)") << int(WriteStep::Sync) << EIO;
    QTest::newRow("rename fails (commit)") << int(WriteStep::Rename) << EIO;
}

void TstFileIo::injectedFailureKeepsOldFile() {
    QFETCH(int, step);
    QFETCH(int, error);
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.txt");
    writeFileAtomically(path.toStdString(), "old content");
    injectWriteFailureForTesting(static_cast<WriteStep>(step));
    QString message;
    try {
        writeFileAtomically(path.toStdString(), "new content");
    } catch (const FileError& e) {
        message = QString::fromStdString(e.what());
    }
    injectWriteFailureForTesting(WriteStep::None);
    // The message is "<path>: <strerror>", the system's words, not "Unknown error".
    QCOMPARE(message, path + ": " + QString::fromUtf8(std::strerror(error)));
    QCOMPARE(contents(path), QByteArray("old content"));
    QCOMPARE(entries(dir.path()), QStringList{"keep.txt"});
}

void TstFileIo::producerErrorKeepsOldFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("keep.txt");
    writeFileAtomically(path.toStdString(), "old content");
    QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                             writeFileAtomically(path.toStdString(), [](const ByteSink& sink) {
                                 sink(std::string(100000, 'x')); // past the buffer: on disk
                                 throw std::runtime_error("refused half way");
                             }));
    QCOMPARE(contents(path), QByteArray("old content"));
    QCOMPARE(entries(dir.path()), QStringList{"keep.txt"});
}

void TstFileIo::refusesToReplaceSpecialFiles() {
    QTemporaryDir dir;
    const QString fifo = dir.filePath("pipe");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QVERIFY_THROWS_EXCEPTION(FileError, writeFileAtomically(fifo.toStdString(), "x"));
    struct stat st {};
    QVERIFY(::stat(QFile::encodeName(fifo).constData(), &st) == 0);
    QVERIFY(S_ISFIFO(st.st_mode)); // still the FIFO, not a regular file
    // /dev/null: refused before anything is created next to it.
    try {
        writeFileAtomically("/dev/null", "x");
        QFAIL("/dev/null was replaced");
    } catch (const FileError& e) {
        QCOMPARE(QString::fromStdString(e.path()), QStringLiteral("/dev/null"));
        QVERIFY(QString::fromStdString(e.reason()).contains("not a regular file"));
    }
    QVERIFY(::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
    QVERIFY_THROWS_EXCEPTION(FileError, writeFileAtomically(dir.path().toStdString(), "x"));
}

void TstFileIo::streamsLargeContent() {
    // 10 MB in 1000 pieces arrive intact (the sink's buffer is flushed in order).
    QTemporaryDir dir;
    const QString path = dir.filePath("big.bin");
    writeFileAtomically(path.toStdString(), [](const ByteSink& sink) {
        for (int i = 0; i < 1000; ++i)
            sink(std::string(10000, static_cast<char>('a' + i % 26)));
    });
    const QByteArray got = contents(path);
    QCOMPARE(got.size(), 10000000);
    for (int i = 0; i < 1000; ++i)
        QCOMPARE(got.at(i * 10000 + 9999), static_cast<char>('a' + i % 26));
}

void TstFileIo::readRefusesSpecialFiles() {
    QTemporaryDir dir;
    const QString fifo = dir.filePath("pipe");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    // A FIFO without a writer used to block forever (the test's ctest timeout would fail it);
    // /dev/zero was read until bad_alloc.
    for (const QString& path : {fifo, QStringLiteral("/dev/zero"), QStringLiteral("/dev/urandom")}) {
        try {
            readRegularFile(path.toStdString(), 8 * 1024 * 1024);
            QFAIL(qPrintable(path + " was read"));
        } catch (const FileError& e) {
            QVERIFY2(QString::fromStdString(e.reason()).contains("not a regular file"), e.what());
        }
    }
    QVERIFY_THROWS_EXCEPTION(FileError, readRegularFile(dir.filePath("missing").toStdString(), 10));
}

void TstFileIo::readStopsAtTheLimit() {
    QTemporaryDir dir;
    const QString path = dir.filePath("s.json");
    writeFileAtomically(path.toStdString(), std::string(100, 'x'));
    QCOMPARE(readRegularFile(path.toStdString(), 100).size(), std::size_t(100));
    try {
        readRegularFile(path.toStdString(), 99);
        QFAIL("a file one byte over the limit was read");
    } catch (const FileError& e) {
        QVERIFY2(QString::fromStdString(e.reason()).contains("limit of 99 bytes"), e.what());
    }
}

void TstFileIo::fullDiskKeepsOldFile() {
    QTemporaryDir dir;
    if (const QString why = xyt::test::mountSmallFilesystem(dir.path(), 64); !why.isEmpty())
        QSKIP(qPrintable(why));
    const auto unmount = qScopeGuard([&] { xyt::test::unmountSmallFilesystem(dir.path()); });
    const QString path = dir.filePath("keep.txt");
    writeFileAtomically(path.toStdString(), std::string(2000, 'o'));
    xyt::test::fillFilesystem(dir.path());
    QString message;
    try {
        writeFileAtomically(path.toStdString(), std::string(20000, 'n'));
    } catch (const FileError& e) {
        message = QString::fromStdString(e.what());
    }
    QCOMPARE(message, path + ": " + QString::fromUtf8(std::strerror(ENOSPC)));
    QCOMPARE(contents(path), QByteArray(2000, 'o'));
    QCOMPARE(entries(dir.path()), (QStringList{"filler", "keep.txt"}));
}

QTEST_APPLESS_MAIN(TstFileIo)
#include "tst_file_io.moc"
