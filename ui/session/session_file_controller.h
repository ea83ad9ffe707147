// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

class QAction;
class QMenu;
class QWidget;

namespace xyt::ui {

class TuningSession;

/**
 * File handling of the workbench: New, Open, Save, Save As, recent files, Export, and the
 * unsaved-changes prompt. A failed load leaves the session as it was and says why (with the
 * JSON path); a failed save leaves the old file intact (atomic write) and says why.
 */
class SessionFileController : public QObject {
    Q_OBJECT
public:
    SessionFileController(TuningSession* session, QWidget* window);

    /// Adds the File menu entries (New ... Export, Quit is the window's).
    void populateMenu(QMenu* file);
    QString currentFile() const { return currentFile_; }
    /// Asks to save unsaved changes: true when it is fine to go on (saved or discarded).
    bool maybeSave();

    bool openFile(const QString& path);
    /// Makes @p path the current file without reading it (recovered work that belongs to it).
    void adoptFile(const QString& path) { setCurrentFile(path); }
    bool saveTo(const QString& path);
    /// Writes an export (json, c, m, csv) to @p path; false with a message box on failure.
    bool exportTo(const QString& format, const QString& path);

    static QStringList recentFiles();
    /// File > Export > Octave/MATLAB script (disabled, with a tooltip saying why, on a G-code
    /// trajectory); null before populateMenu.
    QAction* octaveExportAction() const { return octaveExport_; }

public slots:
    void newSession();
    void open();
    bool save();
    bool saveAs();
    void exportDialog(const QString& format);

signals:
    void currentFileChanged(const QString& path);
    /// A message for the status bar.
    void message(const QString& text);

private:
    void setCurrentFile(const QString& path);
    void rememberRecent(const QString& path);
    void rebuildRecentMenu();
    void updateExportActions();

    TuningSession* session_;
    QWidget* window_;
    QString currentFile_;
    QMenu* recentMenu_ = nullptr;
    QAction* octaveExport_ = nullptr;
};

} // namespace xyt::ui
