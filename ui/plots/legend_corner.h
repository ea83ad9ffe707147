// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QRect>

class QCustomPlot;
class QCPAxisRect;

namespace xyt::ui {

/// The points of @p rect's visible graphs and curves that lie in @p area (pixels); long
/// graphs are sampled (at most about 4000 points each), so the count is a measure, not exact.
int pointsIn(QCPAxisRect* rect, const QRect& area);

/**
 * Moves each legend set in a corner of an axis rect of @p plot to the corner where it covers
 * the fewest points of that rect's traces (the one it is in while none is clearer), so that a
 * legend does not sit on a trace where a free corner exists. A corner holding a notice or a
 * label is never chosen; when every corner holds one the legend is hidden until one is free.
 * True when one moved, hid or came back.
 */
bool placeInsetLegends(QCustomPlot* plot);

} // namespace xyt::ui
