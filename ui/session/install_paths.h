// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace xyt::ui {

/**
 * Where the program's shared data lies, as compiled in (ui/CMakeLists.txt): the folder an
 * installed program finds relative to its own, and the source folder a program run from the
 * build tree uses instead.
 */
struct DataLocations {
    /// From the installed executable's folder to the data folder: the relative path from
    /// CMAKE_INSTALL_BINDIR to CMAKE_INSTALL_DATADIR/xytune ("../share/xytune" with the
    /// GNUInstallDirs defaults), so an installed tree works at any prefix or DESTDIR.
    QString binToData;
    /// The build tree (PROJECT_BINARY_DIR): a program whose folder lies under it was not
    /// installed.
    QString buildDir;
    /// The data folder for runs from the build tree: the source tree's `resources/`
    /// (PROJECT_SOURCE_DIR/resources), which holds `examples/` as the installed folder does.
    QString sourceDataDir;
};

/// The locations compiled into this build.
DataLocations compiledDataLocations();

/**
 * The folder of XY Tune's shared data, absolute and canonical, or "" when there is none:
 *  1. `applicationDir/binToData` when that folder exists: the installed layout,
 *     `<prefix>/share/xytune` beside `<prefix>/bin`;
 *  2. else, only when @p applicationDir lies under `where.buildDir` (a program run from the
 *     build tree), `where.sourceDataDir`: the source tree's `resources/`.
 * An installed program whose data folder is missing gets "", never the source tree it was
 * built from.
 * @param applicationDir the executable's folder (QCoreApplication::applicationDirPath()).
 */
QString dataFolder(const QString& applicationDir, const DataLocations& where);

/// The `examples/` folder of dataFolder(applicationDir, where) (G-code programs, example logs
/// and sessions), or "" when there is none.
QString examplesFolder(const QString& applicationDir, const DataLocations& where);

/// dataFolder() of the running program: QCoreApplication::applicationDirPath() and the
/// compiled-in locations (needs a QCoreApplication).
QString dataFolder();

/// examplesFolder() of the running program: `<prefix>/share/xytune/examples` when installed,
/// the source tree's `resources/examples` when run from the build tree.
QString examplesFolder();

} // namespace xyt::ui
