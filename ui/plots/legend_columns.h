// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QCustomPlot;
class QCPLegend;

namespace xyt::ui {

/// Remembers @p columns as the most columns the legend @p legend (a row under its plot) is
/// laid out in; fitLegendColumns uses fewer when the row is too narrow for them.
void setMaxLegendColumns(QCPLegend* legend, int columns);

/**
 * Lays each legend of @p plot's layout rows out in as many columns as its row has room for, up
 * to the most set by setMaxLegendColumns, so that no entry is cut ("closed-loop unit ste"): a
 * narrow window gets more rows of whole entries. True when a legend changed (the layout must
 * run again).
 */
bool fitLegendColumns(QCustomPlot* plot);

} // namespace xyt::ui
