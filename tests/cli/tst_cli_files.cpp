// SPDX-License-Identifier: GPL-3.0-or-later
// The files side of xytune-cli: every write (export json|c|m|csv, new -o, simulate --csv, sweep
// --csv) leaves the old file intact when the write or the commit fails and says why (exit 2,
// the argument, the path, the system's reason); special files are neither replaced nor read,
// and the refusal names the path once; file names that are not UTF-8 reach the system as the
// bytes the shell passed; the report shows hostile labels escaped; duplicate keys are refused.
#include "core/session/session_evaluation.h"
#include "tests/support/cli_runner.h"
#include "tests/support/small_filesystem.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using xyt::test::runCli;

class TstCliFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void failedWriteKeepsOldFile_data();
    void failedWriteKeepsOldFile();
    void specialFilesAreNotReplaced();
    void specialFilesAreNotRead();
    void sessionSpecificationKeysAndFieldNames();
    void reportLeadsWithTheRunAsItHappens();
    void reportEscapesLabels();
    void duplicateKeyIsRefused();
    void unreadableSessionNamesThePathOnce();
    void nonUtf8FileNamesKeepTheirBytes();
    void helpAgreesOnTheExitCode();
    void fullDiskKeepsOldFile(); // last: it moves the process into its own mount namespace

private:
    QTemporaryDir dir_;
    QString session_;
};

namespace {

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

void put(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
}

const QStringList kCubic = {"simulate", "--preset", "lower-base", "--trajectory", "cubic",
                            "--xf",     "600",      "--tf",       "130"};

/// Each writing command with {out} for the file it writes and the argument that names it.
void addWriterRows() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("argument");
    for (const QString format : {"json", "c", "m", "csv"})
        QTest::newRow(qPrintable("export " + format))
            << QStringList{"export", "{session}", "--format", format, "-o", "{out}"} << "-o";
    QTest::newRow("new") << QStringList{"new", "-o", "{out}"} << "-o";
    QTest::newRow("simulate --csv") << kCubic + QStringList{"--csv", "{out}"} << "--csv";
    QTest::newRow("sweep --csv") << QStringList{"sweep", "--preset", "lower-base", "--wn",
                                                "1:3:2", "--kp",     "20:40:2",    "--trajectory",
                                                "cubic", "--xf",     "600",        "--tf",
                                                "130",   "--csv",    "{out}"}
                                 << "--csv";
}

/// The JSON of the default session that `xytune-cli new` wrote to @p path; empty when it failed.
QJsonObject newSessionJson(const QString& path) {
    if (runCli({"new", "-o", path}).exitCode != 0)
        return {};
    return QJsonDocument::fromJson(contents(path)).object();
}

/// Applies @p edit to axes[0] of the session JSON @p root.
void editAxisX(QJsonObject& root, const std::function<void(QJsonObject&)>& edit) {
    QJsonArray axes = root["axes"].toArray();
    QJsonObject x = axes[0].toObject();
    edit(x);
    axes[0] = x;
    root["axes"] = axes;
}

QStringList substituted(QStringList args, const QString& session, const QString& out) {
    for (QString& a : args)
        a = a.replace("{session}", session).replace("{out}", out);
    return args;
}

/// xytune-cli run with arguments given as bytes: QProcess encodes a QString argument as UTF-8,
/// so it cannot pass a file name that is not UTF-8. Output goes through files in @p scratch.
xyt::test::CliRun runCliWithBytes(const QList<QByteArray>& args, const QString& scratch) {
    const QByteArray out = QFile::encodeName(scratch + "/stdout"),
                     err = QFile::encodeName(scratch + "/stderr");
    std::vector<char*> argv;
    QByteArray program = XYT_CLI_PATH;
    argv.push_back(program.data());
    QList<QByteArray> copies = args;
    for (QByteArray& a : copies)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    xyt::test::CliRun r;
    const pid_t child = ::fork();
    if (child == 0) {
        const int o = ::open(out.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        const int e = ::open(err.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0)
            ::_exit(127);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    if (child < 0 || ::waitpid(child, &status, 0) != child || !WIFEXITED(status))
        return r;
    r.finished = true;
    r.exitCode = WEXITSTATUS(status);
    r.out = contents(scratch + "/stdout");
    r.err = contents(scratch + "/stderr");
    return r;
}

/// The names in @p folder as bytes (QDir would decode them, losing what is not UTF-8).
QList<QByteArray> rawNames(const QString& folder) {
    QList<QByteArray> names;
    DIR* dir = ::opendir(QFile::encodeName(folder).constData());
    if (!dir)
        return names;
    while (const dirent* entry = ::readdir(dir))
        if (entry->d_name[0] != '.')
            names << QByteArray(entry->d_name);
    ::closedir(dir);
    return names;
}

} // namespace

void TstCliFiles::initTestCase() {
    session_ = dir_.filePath("session.json");
    const auto run = runCli({"new", "-o", session_});
    QCOMPARE(run.exitCode, 0);
}

void TstCliFiles::failedWriteKeepsOldFile_data() {
    addWriterRows();
}

void TstCliFiles::failedWriteKeepsOldFile() {
    QFETCH(QStringList, args);
    QFETCH(QString, argument);
    // The injected failure at each step of the write (core/io/file_io.h test hook).
    const std::pair<QString, int> steps[] = {{"write", ENOSPC}, {"sync", EIO}, {"rename", EIO}};
    for (const auto& [step, error] : steps) {
        const QString out = dir_.filePath("out-" + step);
        put(out, "old content\n");
        const auto run =
            runCli(substituted(args, session_, out), 60000, {"XYT_TEST_FAIL_WRITE=" + step});
        QVERIFY(run.finished);
        const QByteArray diagnostic = step.toUtf8() + ": " + run.err;
        QVERIFY2(run.exitCode == 2, diagnostic.constData());
        QVERIFY2(run.err.count('\n') == 1, diagnostic.constData());
        QVERIFY2(run.err.contains((argument + ": cannot write " + out + ": ").toUtf8()),
                 diagnostic.constData());
        QVERIFY2(run.err.contains(std::strerror(error)), diagnostic.constData());
        QVERIFY2(run.out.isEmpty(), run.out.constData()); // no path printed as if it succeeded
        QCOMPARE(contents(out), QByteArray("old content\n"));
    }
    // Without the injected failure the same command writes the file.
    const QString out = dir_.filePath("out-ok");
    QCOMPARE(runCli(substituted(args, session_, out)).exitCode, 0);
    QVERIFY(QFile(out).size() > 0);
}

void TstCliFiles::specialFilesAreNotReplaced() {
    // A FIFO stands for any special file (/dev/null as root was replaced by a regular file).
    const QString fifo = dir_.filePath("pipe-out");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    for (const QStringList& args : {QStringList{"new", "-o", fifo},
                                    QStringList{"export", session_, "--format", "c", "-o", fifo}}) {
        const auto run = runCli(args, 20000);
        QVERIFY2(run.finished && run.exitCode == 2, run.err.constData());
        QVERIFY2(run.err.contains("not a regular file"), run.err.constData());
        struct stat st {};
        QVERIFY(::stat(QFile::encodeName(fifo).constData(), &st) == 0 && S_ISFIFO(st.st_mode));
    }
}

void TstCliFiles::specialFilesAreNotRead() {
    // A FIFO without a writer blocked forever; /dev/zero was read until bad_alloc (2.1 GB).
    const QString fifo = dir_.filePath("pipe-in");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    for (const QString& path :
         {fifo, QStringLiteral("/dev/zero"), QStringLiteral("/dev/urandom")}) {
        const auto run = runCli({"report", path}, 10000);
        QVERIFY2(run.finished, qPrintable(path + " was still being read after 10 s"));
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("not a regular file"), run.err.constData());
    }
}

void TstCliFiles::reportEscapesLabels() {
    // NUL cut the report short; ESC, BEL and CR reached the terminal raw.
    QByteArray json = contents(session_);
    const qsizetype at = json.indexOf("\"label\": \"");
    QVERIFY(at > 0);
    const qsizetype end = json.indexOf('"', at + 10);
    json.replace(at, end - at + 1, R"("label": "a\u0000b\u001b[2J\u0007\rZ")");
    const QString path = dir_.filePath("hostile.json");
    put(path, json);
    const auto run = runCli({"report", path});
    QCOMPARE(run.exitCode, 0);
    for (const char c : run.out)
        QVERIFY2(static_cast<unsigned char>(c) >= 0x20 || c == '\n',
                 qPrintable(QStringLiteral("control byte %1 in the report").arg(int(c))));
    QVERIFY2(run.out.contains("a\\x00b\\x1b[2J\\x07\\x0dZ"), run.out.constData());
    QVERIFY(run.out.contains("== Axis y")); // the report goes on past the NUL
}

void TstCliFiles::duplicateKeyIsRefused() {
    // Qt keeps the last of two equal keys, other readers the first: refuse, naming the key.
    QByteArray json = contents(session_);
    const qsizetype at = json.indexOf("\"umax\":");
    QVERIFY(at > 0);
    json.insert(at, "\"umax\": 250,\n    ");
    const QString path = dir_.filePath("duplicate.json");
    put(path, json);
    const auto run = runCli({"report", path});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("umax: appears more than once"), run.err.constData());
}

void TstCliFiles::unreadableSessionNamesThePathOnce() {
    // "report: pipe: pipe: is not a regular file": the loader's message already held the path.
    const QString fifo = dir_.filePath("once-pipe");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    const QString big = dir_.filePath("once-big.json");
    put(big, QByteArray(8 * 1024 * 1024 + 1, ' ')); // one byte over the 8 MB limit
    const QString missing = dir_.filePath("once-missing.json");
    const std::pair<QString, QString> cases[] = {
        {fifo, "is not a regular file (a device, FIFO or socket); refusing to read it"},
        {big, "8388609 bytes is larger than the limit of 8388608 bytes"},
        {missing, "no such file"}};
    for (const auto& [path, reason] : cases) {
        for (const QStringList& args :
             {QStringList{"report", path},
              QStringList{"export", path, "--format", "c", "-o", dir_.filePath("once.h")}}) {
            const auto run = runCli(args, 20000);
            QVERIFY2(run.finished && run.exitCode == 2, run.err.constData());
            QCOMPARE(QString::fromUtf8(run.err),
                     "xytune-cli " + args.first() + ": " + path + ": " + reason + "\n");
        }
    }
}

void TstCliFiles::nonUtf8FileNamesKeepTheirBytes() {
    // `new -o $'name_\xff.json'` wrote "name_\xef\xbf\xbd.json" (U+FFFD) and exited 0; reading
    // such a name failed with "no such file". The bytes reach open/rename unchanged, and the
    // messages and the printed path show the byte escaped.
    QTemporaryDir dir;
    const QByteArray folder = QFile::encodeName(dir.path());
    const QByteArray session = folder + "/name_\xff.json";
    auto run = runCliWithBytes({"new", "-o", session}, dir.path());
    QVERIFY2(run.finished && run.exitCode == 0, run.err.constData());
    QCOMPARE(run.out, folder + "/name_\\xff.json\n");
    struct stat st {};
    QVERIFY2(::stat(session.constData(), &st) == 0 && S_ISREG(st.st_mode),
             "the file has another name");
    // Read back (report, export) and written (export -o) under names with invalid bytes,
    // including a lone continuation byte and a truncated sequence.
    run = runCliWithBytes({"report", session}, dir.path());
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.startsWith("XY Tune report: " + folder + "/name_\\xff.json\n"),
             run.out.constData());
    const QByteArray header = folder + "/c_\x80\xe2\x82.h";
    run = runCliWithBytes({"export", session, "--format", "c", "-o", header}, dir.path());
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(::stat(header.constData(), &st) == 0 && st.st_size > 0);
    // Valid UTF-8 beside the invalid bytes is kept as well (a character outside the BMP too).
    const QByteArray csv = folder + "/x_\xff\xfe_\xc3\xa4_\xf0\x9f\x98\x80.csv";
    run = runCliWithBytes({"simulate", "--preset", "lower-base", "--trajectory", "cubic", "--xf",
                           "600", "--tf", "130", "--csv", csv},
                          dir.path());
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(::stat(csv.constData(), &st) == 0 && st.st_size > 0);
    // A missing file is named with the byte escaped, never as U+FFFD.
    run = runCliWithBytes({"report", folder + "/absent_\xff.json"}, dir.path());
    QCOMPARE(run.exitCode, 2);
    QCOMPARE(run.err, "xytune-cli report: " + folder + "/absent_\\xff.json: no such file\n");
    QList<QByteArray> expected = {"c_\x80\xe2\x82.h", "name_\xff.json", "stderr", "stdout",
                                  "x_\xff\xfe_\xc3\xa4_\xf0\x9f\x98\x80.csv"};
    QList<QByteArray> got = rawNames(dir.path());
    std::sort(expected.begin(), expected.end());
    std::sort(got.begin(), got.end());
    QCOMPARE(got, expected);
}

void TstCliFiles::helpAgreesOnTheExitCode() {
    // --help said a file that cannot be written exits 1, the README and the writers 2.
    const auto run = runCli({"--help"});
    QCOMPARE(run.exitCode, 0);
    const QString help = QString::fromUtf8(run.out).simplified();
    QVERIFY2(help.contains("2 invalid input or a file that could not be read or written"),
             run.out.constData());
    QVERIFY2(help.contains("1 an internal error"), run.out.constData());
}

void TstCliFiles::fullDiskKeepsOldFile() {
    QTemporaryDir disk;
    if (const QString why = xyt::test::mountSmallFilesystem(disk.path(), 64); !why.isEmpty())
        QSKIP(qPrintable(why));
    const auto unmount = qScopeGuard([&] { xyt::test::unmountSmallFilesystem(disk.path()); });
    // The session itself on the full disk, so that export replaces it in place as in the issue.
    const QString session = disk.filePath("s.json");
    QCOMPARE(runCli({"new", "-o", session}).exitCode, 0);
    const QByteArray before = contents(session);
    xyt::test::fillFilesystem(disk.path());
    for (const QString format : {"c", "json", "m", "csv"}) {
        const auto run = runCli({"export", session, "--format", format, "-o", session});
        QVERIFY2(run.exitCode == 2, run.err.constData());
        QVERIFY2(run.err.contains(std::strerror(ENOSPC)), run.err.constData());
        QCOMPARE(contents(session), before);
    }
    const auto run = runCli({"new", "-o", session});
    QVERIFY2(run.exitCode == 2 && run.err.contains(std::strerror(ENOSPC)), run.err.constData());
    QCOMPARE(contents(session), before);
}

void TstCliFiles::sessionSpecificationKeysAndFieldNames() {
    // The move-and-settle keys of the specification are written, read back (the report
    // judges with them), optional in version-1 files; a wn of 1e308 names the session path and the
    // reason, not the reference model's "den[2]: must be a number, got NaN".
    QTemporaryDir dir;
    const QString path = dir.filePath("s.json");
    QJsonObject root = newSessionJson(path);
    QVERIFY(!root.isEmpty());
    QJsonObject spec = root["specification"].toObject();
    QCOMPARE(spec["in_position_window_mm"].toDouble(), 0.01);
    QCOMPARE(spec["max_settle_time"].toDouble(), 100.0);
    auto write = [&](const QJsonObject& o) { put(path, QJsonDocument(o).toJson()); };
    // A 5 mm window: the report's move-and-settle line uses it.
    spec["in_position_window_mm"] = 5.0;
    root["specification"] = spec;
    write(root);
    auto run = runCli({"report", path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("move and settle (window 5 mm)"), run.out.constData());
    QVERIFY2(run.out.contains("Run: duration "), run.out.constData());
    // Without both keys: refused in the current format version, the defaults in a version-1
    // file (written before the move-and-settle specification; read through its migration).
    spec.remove("in_position_window_mm");
    spec.remove("max_settle_time");
    root["specification"] = spec;
    write(root);
    run = runCli({"report", path});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("specification.in_position_window_mm: is missing"),
             run.err.constData());
    root["version"] = 1;
    write(root);
    run = runCli({"report", path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("move and settle (window 0.01 mm)"), run.out.constData());
    // A zero window is refused naming its path.
    spec["in_position_window_mm"] = 0.0;
    root["specification"] = spec;
    write(root);
    run = runCli({"report", path});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("specification.in_position_window_mm"), run.err.constData());
    // wn = 1e308: the axis is not designed, the message names axes[0].gt.wn and the overflow.
    spec.remove("in_position_window_mm");
    root["specification"] = spec;
    editAxisX(root, [](QJsonObject& x) {
        QJsonObject gt = x["gt"].toObject();
        gt["wn"] = 1e308;
        x["gt"] = gt;
    });
    write(root);
    run = runCli({"report", path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(
        run.out.contains("not designed: axes[0].gt.wn: 1e+308 rad/s is out of range: wn^4 = inf"),
        run.out.constData());
    QVERIFY2(run.out.contains("for the reference model"), run.out.constData());
    QVERIFY(!run.out.contains("NaN") && !run.out.contains("nan"));
}

void TstCliFiles::reportLeadsWithTheRunAsItHappens() {
    // Axis x by pole placement + ZPETC on the default 600 mm cubic: the linear design tracks to
    // 0.0002 mm with |u| up to 4.71 V, while its digital implementation, limited to 2.5 V,
    // saturates and loses the trajectory (the verdict is the implementation's). The report
    // printed the design's figures beside "saturated yes"; the run that happens comes first now,
    // labelled, with the core's figures (evaluateSession of the same session).
    QTemporaryDir dir;
    const QString path = dir.filePath("pp.json");
    QJsonObject root = newSessionJson(path);
    QVERIFY(!root.isEmpty());
    editAxisX(root, [](QJsonObject& x) { x["method"] = "pole-placement-zpetc"; });
    put(path, QJsonDocument(root).toJson());
    xyt::Session session = xyt::Session::paperDefault();
    session.axes[0].method = xyt::DesignMethod::PolePlacementZpetc;
    QVERIFY(session.axes[0].pp.zpetcEnabled);
    const xyt::SessionEvaluation evaluation = xyt::evaluateSession(session);
    const xyt::AxisEvaluation& a = evaluation.axes[0];
    QVERIFY(a.ok && a.digital);
    QVERIFY(a.digital->metrics.saturated);
    QVERIFY(a.digital->metrics.maxAbsError > 100.0); // 228 mm in the issue's reproduction
    QVERIFY(a.metrics.maxAbsError < 0.001);          // 0.0002 mm: the design's
    const auto fixed = [](double v) { return QString::number(v, 'f', 4); };
    const auto run = runCli({"report", path});
    QCOMPARE(run.exitCode, 0);
    const QString out = QString::fromUtf8(run.out);
    const QString axisX = out.section("== Axis y", 0, 0);
    const QString asItRuns =
        QStringLiteral("  tracking as it runs (the digital implementation at Ts = 0.07 s, |u| "
                       "limited to 2.5 V): RMSE %1 mm, max |e| %2 mm")
            .arg(fixed(a.digital->metrics.rmse), fixed(a.digital->metrics.maxAbsError));
    const QString asDesigned =
        QStringLiteral("  tracking as designed (the linear loop at Ts, |u| over the limit "
                       "flagged, not applied): RMSE %1 mm, max |e| %2 mm")
            .arg(fixed(a.metrics.rmse), fixed(a.metrics.maxAbsError));
    QVERIFY2(axisX.contains(asItRuns), qPrintable(axisX));
    QVERIFY2(axisX.contains(asDesigned), qPrintable(axisX));
    QVERIFY(axisX.indexOf(asItRuns) < axisX.indexOf(asDesigned));
    // The verdict says which run fails: the design flags |u| over the limit too, but only the
    // implementation loses the trajectory.
    QVERIFY2(axisX.contains("no saturation (as designed and as it runs)"), qPrintable(axisX));
    QVERIFY2(axisX.contains("tracking error (as it runs)"), qPrintable(axisX));
}

QTEST_APPLESS_MAIN(TstCliFiles)
#include "tst_cli_files.moc"
