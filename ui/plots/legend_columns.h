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
 * narrow window gets more rows of whole entries, and closes the gaps of entries taken out.
 * True when a legend changed (the layout must run again). Run before a layout, with the row's
 * width from the last one (entries come and go with the design, the width seldom changes), and
 * after it, for a row whose width changed.
 */
bool fitLegendColumns(QCustomPlot* plot);

} // namespace xyt::ui
