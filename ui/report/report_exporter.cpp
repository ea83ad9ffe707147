// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/report/report_exporter.h"

#include "ui/report/report_writer.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>

namespace xyt::ui {

ReportExporter::ReportExporter(TuningSession* session, SessionFileController* files,
                               QWidget* window)
    : QObject(window), session_(session), files_(files), window_(window) {}

QAction* ReportExporter::addToMenu(QMenu* file) {
    action_ = file->addAction(tr("Export &report (PDF)..."), this, &ReportExporter::exportDialog);
    action_->setToolTip(tr("A PDF of the design for a lab report or a design review: plants, "
                           "controllers, figures against the specification, warnings and plots"));
    return action_;
}

void ReportExporter::exportDialog() {
    const QString current = files_ ? files_->currentFile() : QString();
    const QString suggested =
        current.isEmpty()
            ? QStringLiteral("xytune_report.pdf")
            : QFileInfo(current).dir().filePath(QFileInfo(current).completeBaseName() +
                                                QStringLiteral("_report.pdf"));
    const QString path =
        QFileDialog::getSaveFileName(window_, tr("Export report"), suggested, tr("PDF (*.pdf)"));
    if (!path.isEmpty())
        exportTo(path);
}

bool ReportExporter::exportTo(const QString& path) {
    // The session as it is now: the report evaluates this copy itself, at the session's dt.
    const Session session = session_->session();
    const QString current = files_ ? files_->currentFile() : QString();
    const QString name = current.isEmpty() ? QString() : QFileInfo(current).fileName();
    // A report takes about a second (eight plots drawn, the session evaluated at full length):
    // a progress dialog appears once it has taken 0.3 s.
    QProgressDialog progress(tr("Writing the report..."), QString(), 0, DesignReport::kParts,
                             window_);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    progress.setValue(0);
    QElapsedTimer timer;
    timer.start();
    QString error;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const bool ok = ReportWriter::write(session, name, path, &error,
                                        [&progress](int done, int) { progress.setValue(done); });
    QApplication::restoreOverrideCursor();
    progress.reset();
    if (!ok) {
        QMessageBox::warning(
            window_, tr("Export report"),
            tr("The report was not written; any existing file is unchanged.\n\n%1").arg(error));
        return false;
    }
    emit message(tr("Report written to %1 (%2 s)")
                     .arg(path, QString::number(timer.elapsed() / 1000.0, 'f', 1)));
    return true;
}

} // namespace xyt::ui
