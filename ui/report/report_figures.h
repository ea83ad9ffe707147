// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QImage>
#include <QString>

#include <vector>

namespace xyt::ui {

/// One picture of the design report: a workbench plot drawn offscreen at a fixed size.
struct ReportFigure {
    QString name;                            ///< the document's resource name ("xyt-figure:x-bode")
    QString caption;                         ///< what it shows, under it
    QImage image;                            ///< drawn at kReportFigureScale times its logical size
    int logicalWidth = 0, logicalHeight = 0; ///< px at 96 dpi, as the document lays it out
};

/**
 * Width (px at 96 dpi) of a figure: the text width of an A4 page printed by QTextDocument (21
 * cm less 2 mm of printer margin and 2 cm of frame margin each side: 16.6 cm, 627 px), less a
 * few pixels so that no rounding pushes a figure past the margin.
 */
inline constexpr int kReportFigureWidth = 620;
/// Device pixels per logical pixel of a figure: twice the screen's, sharp when printed.
inline constexpr double kReportFigureScale = 2.0;

/**
 * The plots of axis @p axis as the workbench draws them (its own plot classes, fed as its views
 * feed them): the root locus with the specification's region, the Bode diagram with the margins,
 * the closed loop's unit step, and the time response to the trajectory with the digital
 * implementation overlaid. An axis without a design gets the plots' "no design" notice.
 */
std::vector<ReportFigure> axisFigures(const Session& session, const SessionEvaluation& evaluation,
                                      int axis);

/// The XY contour (commanded and traced path, the error magnified), and for a program that is
/// one full circle the ballbar (polar) view of the ISO 230-4 test.
std::vector<ReportFigure> contourFigures(const Session& session,
                                         const SessionEvaluation& evaluation);

} // namespace xyt::ui
