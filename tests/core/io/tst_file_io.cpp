// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/file_io.h: atomic writes that never lose the old file (a full disk left a 0-byte file
// and reported success), no replacing of special files, symbolic links followed only where
// another user cannot aim them (root replaced another user's link target in /tmp), the owner of
// a replaced file kept, temporaries of a killed save removed, bounded reads that never block on
// a FIFO nor read a device to exhaustion.
#include "core/io/file_io.h"
#include "tests/support/small_filesystem.h"

#include <QDir>
#include <QFile>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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
    void danglingLinkCreatesItsTarget();
    void ownLinkIsFollowed();
    void foreignLinkInStickyFolderIsRefused();
    void linkToAnotherUsersFileIsRefused();
    void foreignFileInStickyFolderIsRefused();
    void replacedFileKeepsItsOwner();
    void temporaryNameCarriesThePid();
    void staleTemporariesAreRemoved();
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
    for (const QString& path :
         {fifo, QStringLiteral("/dev/zero"), QStringLiteral("/dev/urandom")}) {
        try {
            readRegularFile(path.toStdString(), 8 * 1024 * 1024);
            QFAIL(qPrintable(path + " was read"));
        } catch (const FileError& e) {
            QVERIFY2(QString::fromStdString(e.reason()).contains("not a regular file"), e.what());
            QCOMPARE(e.reasonDiagnostic().code, std::string("io_not_regular_to_read"));
        }
    }
    // The reasons carry their code (the workbench translates it); what() stays the English.
    const std::string missing = dir.filePath("missing").toStdString();
    try {
        readRegularFile(missing, 10);
        QFAIL("a missing file was read");
    } catch (const FileError& e) {
        QCOMPARE(e.reasonDiagnostic().code, std::string("io_no_such_file"));
        QCOMPARE(std::string(e.what()), missing + ": no such file");
        QCOMPARE(e.path(), missing);
    }
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
        QCOMPARE(e.reasonDiagnostic().code, std::string("io_size_over_limit"));
        QCOMPARE(e.reasonDiagnostic().args.at(1).text, std::string("99"));
    }
}

namespace {

/// The uid/gid that stands for "another user" (nobody), present on every Linux system.
constexpr uid_t kOtherUser = 65534;

QByteArray bytes(const QString& path) {
    return QFile::encodeName(path);
}

struct stat lstatOf(const QString& path) {
    struct stat st {};
    if (::lstat(bytes(path).constData(), &st) != 0)
        st.st_mode = 0;
    return st;
}

/// The reason writeFileAtomically gave, or "" when it wrote.
QString refusal(const QString& path, const char* content) {
    try {
        writeFileAtomically(path.toStdString(), content);
    } catch (const FileError& e) {
        return QString::fromStdString(e.reason());
    }
    return {};
}

/// Why the ownership cases cannot run here, or "" when they can: they create files and links
/// of another user, which takes root (CI runs the tests as root).
QString ownershipUnavailable(const QString& probeFolder) {
    if (::geteuid() != 0)
        return QStringLiteral("needs root to create another user's files and links (lchown)");
    const QByteArray probe = bytes(probeFolder + "/owner-probe");
    if (::symlink("x", probe.constData()) != 0)
        return QStringLiteral("cannot create a symbolic link here");
    const bool ok = ::lchown(probe.constData(), kOtherUser, kOtherUser) == 0;
    ::unlink(probe.constData());
    return ok ? QString() : QStringLiteral("uid 65534 cannot own files here (user namespace)");
}

/// A folder like /tmp: writable by everyone, sticky, owned by us.
QString stickyFolder(const QTemporaryDir& dir) {
    const QString folder = dir.filePath("shared");
    if (!QDir().mkdir(folder) || ::chmod(bytes(folder).constData(), 01777) != 0)
        return {};
    return folder;
}

} // namespace

void TstFileIo::danglingLinkCreatesItsTarget() {
    // The header says a link is followed; a dangling one was replaced by a regular file.
    QTemporaryDir dir;
    const QString link = dir.filePath("out.json"), target = dir.filePath("target.json");
    QVERIFY(::symlink("target.json", bytes(link).constData()) == 0);
    writeFileAtomically(link.toStdString(), "content");
    QVERIFY(S_ISLNK(lstatOf(link).st_mode));
    QVERIFY(S_ISREG(lstatOf(target).st_mode));
    QCOMPARE(contents(target), QByteArray("content"));
}

void TstFileIo::ownLinkIsFollowed() {
    // Our own link in a shared sticky folder, to our own file: the file is replaced, the link kept.
    QTemporaryDir dir;
    const QString shared = stickyFolder(dir);
    QVERIFY(!shared.isEmpty());
    const QString target = dir.filePath("mine.json"), link = shared + "/x.json";
    writeFileAtomically(target.toStdString(), "old");
    QVERIFY(::symlink(bytes(target).constData(), bytes(link).constData()) == 0);
    writeFileAtomically(link.toStdString(), "new");
    QCOMPARE(contents(target), QByteArray("new"));
    QVERIFY(S_ISLNK(lstatOf(link).st_mode));
}

void TstFileIo::foreignLinkInStickyFolderIsRefused() {
    // The issue: another user's "ln -s victim x.json" in a world-writable folder, then root's
    // save to x.json replaced the victim.
    QTemporaryDir dir;
    if (const QString why = ownershipUnavailable(dir.path()); !why.isEmpty())
        QSKIP(qPrintable(why));
    const QString shared = stickyFolder(dir);
    QVERIFY(!shared.isEmpty());
    const QString victim = dir.filePath("victim"), link = shared + "/x.json";
    writeFileAtomically(victim.toStdString(), "precious");
    QVERIFY(::symlink(bytes(victim).constData(), bytes(link).constData()) == 0);
    QVERIFY(::lchown(bytes(link).constData(), kOtherUser, kOtherUser) == 0);
    QVERIFY2(refusal(link, "attack").contains("symbolic link of another user (uid 65534)"),
             qPrintable(refusal(link, "attack")));
    QCOMPARE(contents(victim), QByteArray("precious"));
    // Dangling, it would have created a file where the link's owner chose.
    const QString planted = shared + "/y.json", created = dir.filePath("created");
    QVERIFY(::symlink(bytes(created).constData(), bytes(planted).constData()) == 0);
    QVERIFY(::lchown(bytes(planted).constData(), kOtherUser, kOtherUser) == 0);
    QVERIFY(refusal(planted, "attack").contains("refusing to follow it"));
    QVERIFY(!QFile::exists(created));
    // The same links in a folder that is not sticky pass this rule but not the next one.
    QVERIFY(::chmod(bytes(shared).constData(), 0777) == 0);
    QVERIFY(refusal(link, "attack").contains("a file of another user"));
    QVERIFY(refusal(planted, "attack").contains("refusing to create it"));
    QCOMPARE(contents(victim), QByteArray("precious"));
    QVERIFY(!QFile::exists(created));
    QCOMPARE(entries(shared), (QStringList{"x.json", "y.json"})); // no temporary left behind
}

void TstFileIo::linkToAnotherUsersFileIsRefused() {
    // A link may only lead to a file of its own owner: root's link onto a user's file, or a
    // user's link onto root's file, is not followed, in any folder.
    QTemporaryDir dir;
    if (const QString why = ownershipUnavailable(dir.path()); !why.isEmpty())
        QSKIP(qPrintable(why));
    const QString theirs = dir.filePath("theirs.json"), mine = dir.filePath("mine.json");
    writeFileAtomically(theirs.toStdString(), "theirs");
    QVERIFY(::chown(bytes(theirs).constData(), kOtherUser, kOtherUser) == 0);
    writeFileAtomically(mine.toStdString(), "mine");
    const QString toTheirs = dir.filePath("to-theirs"), toMine = dir.filePath("to-mine");
    QVERIFY(::symlink("theirs.json", bytes(toTheirs).constData()) == 0);
    QVERIFY(::symlink("mine.json", bytes(toMine).constData()) == 0);
    QVERIFY(::lchown(bytes(toMine).constData(), kOtherUser, kOtherUser) == 0);
    QCOMPARE(refusal(toTheirs, "x"),
             QStringLiteral(
                 "is a symbolic link to a file of another user (the file: uid 65534, the link: "
                 "uid 0); refusing to replace it"));
    QCOMPARE(
        refusal(toMine, "x"),
        QStringLiteral("is a symbolic link to a file of another user (the file: uid 0, the link: "
                       "uid 65534); refusing to replace it"));
    QCOMPARE(contents(theirs), QByteArray("theirs"));
    QCOMPARE(contents(mine), QByteArray("mine"));
    // The user's link to the user's own file: followed, and the file stays the user's.
    QVERIFY(::lchown(bytes(toTheirs).constData(), kOtherUser, kOtherUser) == 0);
    QCOMPARE(refusal(toTheirs, "updated"), QString());
    QCOMPARE(contents(theirs), QByteArray("updated"));
    QCOMPARE(lstatOf(theirs).st_uid, kOtherUser);
}

void TstFileIo::foreignFileInStickyFolderIsRefused() {
    // A file planted under our name in /tmp: replacing it and keeping its owner would hand our
    // content to that user (the kernel's protected_regular refuses such an open).
    QTemporaryDir dir;
    if (const QString why = ownershipUnavailable(dir.path()); !why.isEmpty())
        QSKIP(qPrintable(why));
    const QString shared = stickyFolder(dir);
    QVERIFY(!shared.isEmpty());
    const QString planted = shared + "/out.json";
    writeFileAtomically(planted.toStdString(), "planted");
    QVERIFY(::chown(bytes(planted).constData(), kOtherUser, kOtherUser) == 0);
    QVERIFY(refusal(planted, "ours")
                .contains("a file of another user (uid 65534) in a folder everyone may write to"));
    QCOMPARE(contents(planted), QByteArray("planted"));
    // Our own file there is replaced as anywhere.
    const QString own = shared + "/own.json";
    writeFileAtomically(own.toStdString(), "a");
    QCOMPARE(refusal(own, "b"), QString());
    QCOMPARE(contents(own), QByteArray("b"));
}

void TstFileIo::replacedFileKeepsItsOwner() {
    // Replaced as root, a user's file stayed root's (the mode was kept, the owner was not).
    QTemporaryDir dir;
    if (const QString why = ownershipUnavailable(dir.path()); !why.isEmpty())
        QSKIP(qPrintable(why));
    const QString path = dir.filePath("users.json");
    writeFileAtomically(path.toStdString(), "old");
    QVERIFY(::chown(bytes(path).constData(), kOtherUser, kOtherUser) == 0);
    QVERIFY(::chmod(bytes(path).constData(), 0604) == 0);
    writeFileAtomically(path.toStdString(), "new");
    const struct stat st = lstatOf(path);
    QCOMPARE(contents(path), QByteArray("new"));
    QCOMPARE(st.st_uid, kOtherUser);
    QCOMPARE(st.st_gid, static_cast<gid_t>(kOtherUser));
    QCOMPARE(st.st_mode & 07777, 0604u);
}

void TstFileIo::temporaryNameCarriesThePid() {
    // While the content is produced, the one file beside the target is .xytune-save-<pid>-XXXXXX.
    QTemporaryDir dir;
    const QString path = dir.filePath("out.txt");
    QStringList during;
    writeFileAtomically(path.toStdString(), [&](const ByteSink& sink) {
        during = entries(dir.path());
        sink("x");
    });
    QCOMPARE(during.size(), 1);
    const QString prefix = QStringLiteral(".xytune-save-%1-").arg(::getpid());
    QVERIFY2(during.first().startsWith(prefix) && during.first().size() == prefix.size() + 6,
             qPrintable(during.first()));
}

void TstFileIo::staleTemporariesAreRemoved() {
    // A save killed half way left its temporary (35-101 MB) forever; the next save to the
    // folder removes the ones whose process is gone, and only those.
    const pid_t dead = ::fork();
    if (dead == 0)
        ::_exit(0);
    QVERIFY(dead > 0);
    QVERIFY(::waitpid(dead, nullptr, 0) == dead); // reaped: the pid names no process now
    const pid_t living = ::fork();
    if (living == 0) {
        ::pause();
        ::_exit(0);
    }
    QVERIFY(living > 0);
    const auto stop = qScopeGuard([living] {
        ::kill(living, SIGKILL);
        ::waitpid(living, nullptr, 0);
    });
    QTemporaryDir dir;
    const QString stale = QStringLiteral(".xytune-save-%1-aB3dE9").arg(dead);
    const QString writing = QStringLiteral(".xytune-save-%1-Zz09aQ").arg(living);
    const QString own =
        QStringLiteral(".xytune-save-%1-q1w2e3").arg(::getpid()); // another thread's
    const QStringList notOurs = {
        QStringLiteral(".xytune-save-%1-aB3dE").arg(dead),      // five letters: not mkstemp's
        QStringLiteral(".xytune-save-%1-aB3dE9.bak").arg(dead), // more after the pattern
        QStringLiteral(".xytune-save-aB3dE9"),                  // the old name, without a pid
        QStringLiteral("xytune-save-%1-aB3dE9").arg(dead)};     // not hidden
    for (const QString& name :
         QStringList{stale, writing, own} + notOurs) { // not saved: a save cleans up
        QFile f(dir.filePath(name));
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write("leftover") == 8);
    }
    writeFileAtomically(dir.filePath("session.json").toStdString(), "saved");
    QStringList expected = QStringList{writing, own, "session.json"} + notOurs;
    expected.sort();
    QStringList got = entries(dir.path());
    got.sort();
    QCOMPARE(got, expected);
    // Another user's temporary with a dead pid is not ours to remove.
    if (ownershipUnavailable(dir.path()).isEmpty()) {
        const QString theirs = dir.filePath(stale);
        writeFileAtomically(theirs.toStdString(), "leftover");
        QVERIFY(::chown(bytes(theirs).constData(), kOtherUser, kOtherUser) == 0);
        writeFileAtomically(dir.filePath("session.json").toStdString(), "saved again");
        QVERIFY(QFile::exists(theirs));
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
