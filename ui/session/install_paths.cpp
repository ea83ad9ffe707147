// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/install_paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace xyt::ui {

namespace {

/// @p path with symbolic links resolved when it exists, else made absolute and clean.
QString installPathsCanonical(const QString& path) {
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? QDir::cleanPath(info.absoluteFilePath()) : canonical;
}

/// Whether @p path is @p folder or lies under it (both canonical, so "/a/build2" is not under
/// "/a/build").
bool installPathsUnder(const QString& path, const QString& folder) {
    if (folder.isEmpty())
        return false;
    const QString p = installPathsCanonical(path);
    const QString f = installPathsCanonical(folder);
    return p == f || p.startsWith(f.endsWith('/') ? f : f + '/');
}

} // namespace

DataLocations compiledDataLocations() {
    return DataLocations{QStringLiteral(XYT_BIN_TO_DATA), QStringLiteral(XYT_BUILD_DIR),
                         QStringLiteral(XYT_SOURCE_DATA_DIR)};
}

QString dataFolder(const QString& applicationDir, const DataLocations& where) {
    if (applicationDir.isEmpty())
        return QString();
    // The installed layout first: an install into a folder below the build tree (a test's
    // temporary prefix) still finds its own copy.
    if (!where.binToData.isEmpty()) {
        const QString installed = QDir(applicationDir).filePath(where.binToData);
        if (QFileInfo(installed).isDir())
            return installPathsCanonical(installed);
    }
    if (installPathsUnder(applicationDir, where.buildDir) && !where.sourceDataDir.isEmpty() &&
        QFileInfo(where.sourceDataDir).isDir())
        return installPathsCanonical(where.sourceDataDir);
    return QString();
}

QString examplesFolder(const QString& applicationDir, const DataLocations& where) {
    const QString data = dataFolder(applicationDir, where);
    if (data.isEmpty())
        return QString();
    const QString examples = QDir(data).filePath(QStringLiteral("examples"));
    return QFileInfo(examples).isDir() ? examples : QString();
}

QString dataFolder() {
    return dataFolder(QCoreApplication::applicationDirPath(), compiledDataLocations());
}

QString examplesFolder() {
    return examplesFolder(QCoreApplication::applicationDirPath(), compiledDataLocations());
}

} // namespace xyt::ui
