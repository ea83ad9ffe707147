// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/session_file_controller.h"

#include "core/model/errors.h"
#include "core/session/export_text.h"
#include "ui/files/coefficient_json.h"
#include "ui/files/session_file.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

namespace xyt::ui {

namespace {
constexpr int kMaxRecent = 8;

/// Why a session file was refused: the core's coded reason in the user's language (the file
/// format's own messages in English), with its JSON path.
QString loadErrorText(const files::SessionLoadResult& r) {
    if (!r.errorDiagnostic.coded())
        return r.message();
    const QString reason = diagnosticText(r.errorDiagnostic);
    return r.errorPath.isEmpty() ? reason : r.errorPath + QStringLiteral(": ") + reason;
}
} // namespace

SessionFileController::SessionFileController(TuningSession* session, QWidget* window)
    : QObject(window), session_(session), window_(window) {}

void SessionFileController::populateMenu(QMenu* file) {
    file->addAction(tr("&New"), QKeySequence::New, this, &SessionFileController::newSession);
    file->addAction(tr("&Open..."), QKeySequence::Open, this, &SessionFileController::open);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    // Filled when shown: never rebuilt (its actions deleted) while one of them runs.
    connect(recentMenu_, &QMenu::aboutToShow, this, &SessionFileController::rebuildRecentMenu);
    rebuildRecentMenu();
    file->addAction(tr("&Save"), QKeySequence::Save, this, &SessionFileController::save);
    file->addAction(tr("Save &As..."), QKeySequence::SaveAs, this, &SessionFileController::saveAs);
    file->addSeparator();
    QMenu* exports = file->addMenu(tr("&Export"));
    exports->addAction(tr("Coefficients as &JSON..."), this, [this] { exportDialog("json"); });
    exports->addAction(tr("Firmware &C header..."), this, [this] { exportDialog("c"); });
    octaveExport_ =
        exports->addAction(tr("&Octave/MATLAB script..."), this, [this] { exportDialog("m"); });
    exports->addAction(tr("Simulated signals as CS&V..."), this, [this] { exportDialog("csv"); });
    // A disabled action says why in its tooltip, which a menu shows only when asked to.
    exports->setToolTipsVisible(true);
    connect(session_, &TuningSession::designChanged, this,
            &SessionFileController::updateExportActions);
    updateExportActions();
}

void SessionFileController::updateExportActions() {
    if (!octaveExport_)
        return;
    // The script computes r(t) in closed form; a G-code program's feed profile has none, so the
    // export would be refused only after a file name was asked for.
    const bool program = session_->session().trajectory.kind == TrajectoryKind::Gcode;
    octaveExport_->setEnabled(!program);
    octaveExport_->setToolTip(
        program ? tr("Not for a G-code trajectory: the script computes the reference in "
                     "closed form, and a program's feed profile has none. Export the "
                     "simulated signals as CSV instead.")
                : tr("A GNU Octave / MATLAB script with each axis' plant, controller and "
                     "closed loop, plotting the response to the trajectory"));
}

bool SessionFileController::maybeSave() {
    if (!session_->isModified())
        return true;
    const auto answer = QMessageBox::warning(
        window_, tr("XY Tune"), tr("The design has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void SessionFileController::newSession() {
    if (!maybeSave())
        return;
    session_->reset(Session::paperDefault());
    setCurrentFile(QString());
    emit message(tr("New session with the paper's default design"));
}

void SessionFileController::open() {
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(
        window_, tr("Open session"), QString(), tr("XY Tune sessions (*.json);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

bool SessionFileController::openFile(const QString& path) {
    const files::SessionLoadResult r = files::loadSessionFile(path);
    if (!r.ok) {
        QMessageBox::warning(window_, tr("Open session"),
                             tr("%1 could not be opened; the current design is unchanged.\n\n%2")
                                 .arg(QFileInfo(path).fileName(), loadErrorText(r)));
        return false;
    }
    session_->reset(r.session);
    setCurrentFile(path);
    rememberRecent(path);
    if (!r.warnings.isEmpty())
        QMessageBox::information(window_, tr("Open session"),
                                 tr("Opened with notes:\n%1").arg(r.warnings.join("\n")));
    emit message(tr("Opened %1").arg(path));
    return true;
}

bool SessionFileController::save() {
    return currentFile_.isEmpty() ? saveAs() : saveTo(currentFile_);
}

bool SessionFileController::saveAs() {
    const QString path = QFileDialog::getSaveFileName(
        window_, tr("Save session"), currentFile_.isEmpty() ? "design.json" : currentFile_,
        tr("XY Tune sessions (*.json)"));
    return !path.isEmpty() && saveTo(path);
}

bool SessionFileController::saveTo(const QString& path) {
    QString error;
    if (!files::saveSessionFile(session_->session(), path, &error)) {
        QMessageBox::warning(
            window_, tr("Save session"),
            tr("The session was not saved; any existing file is unchanged.\n\n%1").arg(error));
        return false;
    }
    session_->markSaved();
    setCurrentFile(path);
    rememberRecent(path);
    emit message(tr("Saved %1").arg(path));
    return true;
}

bool SessionFileController::exportTo(const QString& format, const QString& path) {
    QByteArray bytes;
    try {
        const Session& s = session_->session();
        const SessionEvaluation& e = session_->evaluation();
        ExportOptions options;
        options.piMethod = s.piDiscretization;
        if (format == "json")
            bytes = QJsonDocument(files::coefficientsJson(s, e, options)).toJson();
        else if (format == "c")
            bytes = QByteArray::fromStdString(exportCHeader(s, e, options));
        else if (format == "m")
            bytes = QByteArray::fromStdString(exportOctaveScript(s, e, options));
        else
            bytes = QByteArray::fromStdString(exportCsv(s, e));
    } catch (const InvalidInput& e) {
        QMessageBox::warning(window_, tr("Export"), exceptionText(e));
        return false;
    }
    QString error;
    if (!files::writeFileAtomically(path, bytes, &error)) {
        QMessageBox::warning(window_, tr("Export"), error);
        return false;
    }
    emit message(tr("Exported %1").arg(path));
    return true;
}

void SessionFileController::exportDialog(const QString& format) {
    const QMap<QString, QString> filters = {{"json", tr("JSON (*.json)")},
                                            {"c", tr("C header (*.h)")},
                                            {"m", tr("Octave/MATLAB script (*.m)")},
                                            {"csv", tr("CSV (*.csv)")}};
    const QMap<QString, QString> names = {{"json", "xytune_coefficients.json"},
                                          {"c", "xytune_coefficients.h"},
                                          {"m", "xytune_design.m"},
                                          {"csv", "xytune_signals.csv"}};
    const QString path = QFileDialog::getSaveFileName(window_, tr("Export"), names.value(format),
                                                      filters.value(format));
    if (!path.isEmpty())
        exportTo(format, path);
}

QStringList SessionFileController::recentFiles() {
    return QSettings().value("session/recentFiles").toStringList();
}

void SessionFileController::rememberRecent(const QString& path) {
    QStringList list = recentFiles();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxRecent)
        list.removeLast();
    QSettings().setValue("session/recentFiles", list);
    if (recentMenu_)
        recentMenu_->setEnabled(!recentFiles().isEmpty());
}

void SessionFileController::rebuildRecentMenu() {
    if (!recentMenu_)
        return;
    recentMenu_->clear();
    const QStringList list = recentFiles();
    for (const QString& path : list)
        recentMenu_
            ->addAction(QFileInfo(path).fileName(), this,
                        [this, path] {
                            if (maybeSave())
                                openFile(path);
                        })
            ->setToolTip(path);
    recentMenu_->setEnabled(!list.isEmpty());
}

void SessionFileController::setCurrentFile(const QString& path) {
    currentFile_ = path;
    emit currentFileChanged(path);
}

} // namespace xyt::ui
