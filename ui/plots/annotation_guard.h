// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

class QCustomPlot;
class QCPItemText;

namespace xyt::ui {

/**
 * Keeps the text annotations of @p plot inside their axis rect and apart, on every drawing:
 * each QCPItemText clipped to an axis rect (a marker's label, a notice) is moved the least
 * distance into its rect, then below (or else above) any annotation placed before it that
 * it overlaps. A title or readout of the plot's layout wider than its row is broken at
 * spaces into lines, and a legend in a row of its own takes as many columns as the row has
 * room for (fitLegendColumns) and an axis no more ticks than its labels have room
 * for (fitTickCounts), and a legend set in a corner goes to the corner with the fewest trace
 * points (placeInsetLegends); the plot is then drawn again with the taller rows. The text keeps the
 * point the plot gave it: each drawing starts from there, so a zoom or a new result places it
 * afresh. A label too large for its rect stays at its top left corner.
 */
void guardAnnotations(QCustomPlot* plot);

/**
 * Marks @p text (a notice) as wrapped by the guard: its lines @p lines are broken at spaces
 * to the width of its axis rect at each drawing (continuation lines indented by @p indent),
 * so a notice takes fewer lines on a wide plot and stays whole on a narrow one.
 */
void setWrappedLines(QCPItemText* text, const QStringList& lines, const QString& indent);

} // namespace xyt::ui
