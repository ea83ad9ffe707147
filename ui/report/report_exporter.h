// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QAction;
class QMenu;
class QWidget;

namespace xyt::ui {

class SessionFileController;
class TuningSession;

/**
 * File › Export report...: asks for a PDF's name and writes the design report of the session as
 * it is at that moment (ReportWriter evaluates the presenter's current session), with a progress
 * dialog once it takes longer than 0.3 s and a message box naming the path and the reason when
 * it fails.
 */
class ReportExporter : public QObject {
    Q_OBJECT
public:
    ReportExporter(TuningSession* session, SessionFileController* files, QWidget* window);
    /// Adds the action to @p file and returns it.
    QAction* addToMenu(QMenu* file);
    QAction* action() const { return action_; }
    /// Writes the report to @p path (what the action does once a name is chosen); false, after a
    /// message box, when it cannot.
    bool exportTo(const QString& path);

public slots:
    /// Asks for the file name, then exportTo.
    void exportDialog();

signals:
    /// A message for the status bar.
    void message(const QString& text);

private:
    TuningSession* session_;
    SessionFileController* files_;
    QWidget* window_;
    QAction* action_ = nullptr;
};

} // namespace xyt::ui
