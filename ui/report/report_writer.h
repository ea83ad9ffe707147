// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "ui/report/design_report.h"

#include <QCoreApplication>
#include <QString>

namespace xyt::ui {

/**
 * Writes the design report of a session as an A4 PDF (QPdfWriter at 300 dpi, the document laid
 * out by QTextDocument::print with 2 cm margins and page numbers). The session is evaluated here
 * (evaluateSession, at its own dt), so the report is of the session as given, never of an older
 * evaluation. The file is written through QSaveFile: a failed report leaves an existing file as
 * it was.
 */
class ReportWriter {
    Q_DECLARE_TR_FUNCTIONS(ReportWriter)
public:
    /**
     * Writes the report of @p session, whose file is called @p sessionName (empty: never saved),
     * to @p pdfPath. Returns false with @p error naming the path and the reason when the file
     * cannot be written, or the session's field when its run is refused (nothing is written).
     */
    static bool write(const Session& session, const QString& sessionName, const QString& pdfPath,
                      QString* error, const DesignReport::Progress& progress = {});
};

} // namespace xyt::ui
