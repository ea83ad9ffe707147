// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/report/report_writer.h"
#include "ui/session/diagnostic_text.h"

#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

namespace xyt::ui {

bool ReportWriter::write(const Session& session, const QString& sessionName, const QString& pdfPath,
                         QString* error, const DesignReport::Progress& progress) {
    const auto fail = [error](const QString& message) {
        if (error)
            *error = message;
        return false;
    };
    // Opened first: an unwritable place is said at once, before the plots are drawn.
    QSaveFile file(pdfPath);
    if (!file.open(QIODevice::WriteOnly))
        return fail(tr("Cannot write the report to %1: %2").arg(pdfPath, file.errorString()));
    const SessionEvaluation evaluation = evaluateSession(session);
    for (const AxisEvaluation& axis : evaluation.axes)
        if (axis.runRefused) // no figure of such a session means anything (AxisEvaluation)
            return fail(
                tr("No report: the session's run is refused: %1: %2")
                    .arg(QString::fromStdString(axis.errorField), diagnosticText(axis.error)));
    const DesignReport report(session, evaluation, {sessionName, QDateTime::currentDateTime()},
                              progress);
    {
        QPdfWriter writer(&file);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setResolution(300);
        writer.setTitle(tr("XY Tune design report"));
        writer.setCreator(tr("XY Tune %1").arg(DesignReport::version()));
        QTextDocument document;
        report.loadInto(document);
        document.print(&writer); // 2 cm margins and the page numbers (non-paginated document)
    }
    if (!file.commit())
        return fail(tr("Cannot write the report to %1: %2").arg(pdfPath, file.errorString()));
    return true;
}

} // namespace xyt::ui
