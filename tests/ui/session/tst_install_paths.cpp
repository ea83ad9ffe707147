// SPDX-License-Identifier: GPL-3.0-or-later
// Where the program finds its shared data: fake installed layouts and build trees made in a
// temporary folder, checked against the layout GNUInstallDirs gives (bin/ beside
// share/xytune/) and the rule of install_paths.h (the source tree serves only runs from the
// build tree).
#include "ui/session/install_paths.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace xyt::ui;

class TstInstallPaths : public QObject {
    Q_OBJECT
private slots:
    void init();
    void installedProgramFindsItsSharedFolder();
    void installedProgramNeverFallsBackToTheSource();
    void buildTreeRunUsesTheSourceResources();
    void folderBesideTheBuildTreeIsNotInIt();
    void installBelowTheBuildTreeFindsItsOwnCopy();
    void symbolicLinksAreResolved();
    void dataWithoutExamplesHasNoExamplesFolder();
    void thisBuildRunsFromItsBuildTree();

private:
    /// Makes the folder @p relative under the temporary root; returns its absolute path.
    QString makeFolder(const QString& relative);
    /// The canonical path of @p relative under the temporary root.
    QString canonical(const QString& relative) const;
    /// The GNUInstallDirs defaults: bin/ and share/xytune/ under one prefix; a build tree and
    /// a source tree of its own under the root.
    DataLocations fakeLocations() const;

    std::unique_ptr<QTemporaryDir> root_;
};

void TstInstallPaths::init() {
    root_ = std::make_unique<QTemporaryDir>();
    QVERIFY(root_->isValid());
    makeFolder("src/resources/examples");
    makeFolder("build/app");
}

QString TstInstallPaths::makeFolder(const QString& relative) {
    const QString path = QDir(root_->path()).filePath(relative);
    if (!QDir().mkpath(path))
        qFatal("cannot make %s", qPrintable(path));
    return path;
}

QString TstInstallPaths::canonical(const QString& relative) const {
    return QFileInfo(QDir(root_->path()).filePath(relative)).canonicalFilePath();
}

DataLocations TstInstallPaths::fakeLocations() const {
    return DataLocations{"../share/xytune", QDir(root_->path()).filePath("build"),
                         QDir(root_->path()).filePath("src/resources")};
}

void TstInstallPaths::installedProgramFindsItsSharedFolder() {
    const QString bin = makeFolder("prefix/bin");
    makeFolder("prefix/share/xytune/examples");
    QCOMPARE(dataFolder(bin, fakeLocations()), canonical("prefix/share/xytune"));
    QCOMPARE(examplesFolder(bin, fakeLocations()), canonical("prefix/share/xytune/examples"));
}

void TstInstallPaths::installedProgramNeverFallsBackToTheSource() {
    // An installed program whose share/xytune was removed: the source tree it was built from
    // still exists, yet it is not the program's data.
    const QString bin = makeFolder("prefix/bin");
    QVERIFY(QFileInfo(fakeLocations().sourceDataDir).isDir());
    QCOMPARE(dataFolder(bin, fakeLocations()), QString());
    QCOMPARE(examplesFolder(bin, fakeLocations()), QString());
}

void TstInstallPaths::buildTreeRunUsesTheSourceResources() {
    const QString app = QDir(root_->path()).filePath("build/app");
    QCOMPARE(dataFolder(app, fakeLocations()), canonical("src/resources"));
    QCOMPARE(examplesFolder(app, fakeLocations()), canonical("src/resources/examples"));
    // Deeper in the build tree (a test executable's folder) too.
    const QString tests = makeFolder("build/tests/ui");
    QCOMPARE(examplesFolder(tests, fakeLocations()), canonical("src/resources/examples"));
}

void TstInstallPaths::folderBesideTheBuildTreeIsNotInIt() {
    // "build2" starts with the characters of "build" but is another folder.
    const QString app = makeFolder("build2/app");
    QCOMPARE(dataFolder(app, fakeLocations()), QString());
}

void TstInstallPaths::installBelowTheBuildTreeFindsItsOwnCopy() {
    const QString bin = makeFolder("build/stage/usr/bin");
    makeFolder("build/stage/usr/share/xytune/examples");
    QCOMPARE(examplesFolder(bin, fakeLocations()),
             canonical("build/stage/usr/share/xytune/examples"));
}

void TstInstallPaths::symbolicLinksAreResolved() {
    makeFolder("prefix/bin");
    makeFolder("prefix/share/xytune/examples");
    const QString link = QDir(root_->path()).filePath("link");
    QVERIFY(QFile::link(QDir(root_->path()).filePath("prefix"), link));
    const QString found = examplesFolder(QDir(link).filePath("bin"), fakeLocations());
    QCOMPARE(found, canonical("prefix/share/xytune/examples"));
    QVERIFY(!found.contains("/link/"));
}

void TstInstallPaths::dataWithoutExamplesHasNoExamplesFolder() {
    const QString bin = makeFolder("prefix/bin");
    makeFolder("prefix/share/xytune");
    QCOMPARE(dataFolder(bin, fakeLocations()), canonical("prefix/share/xytune"));
    QCOMPARE(examplesFolder(bin, fakeLocations()), QString());
}

void TstInstallPaths::thisBuildRunsFromItsBuildTree() {
    // This test executable is never installed: it finds the source tree's resources/.
    const DataLocations compiled = compiledDataLocations();
    QVERIFY(QDir::isRelativePath(compiled.binToData));
    QVERIFY(compiled.binToData.endsWith("xytune"));
    const QString sourceResources =
        QFileInfo(QStringLiteral(XYT_SOURCE_DIR "/resources")).canonicalFilePath();
    QCOMPARE(dataFolder(), sourceResources);
    QCOMPARE(examplesFolder(), sourceResources + "/examples");
}

QTEST_GUILESS_MAIN(TstInstallPaths)
#include "tst_install_paths.moc"
