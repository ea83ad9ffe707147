// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QCustomPlot;
class QCPAxis;

namespace xyt::ui {

/**
 * Gives each axis of @p plot no more ticks than its labels have room for along it ("-20-10" on
 * a narrow XY plot, the phase labels of a short Bode plane on each other), and back up to the
 * ticker's own count when the plot widens. True when a count changed (the plot must be drawn
 * again).
 */
bool fitTickCounts(QCustomPlot* plot);

/// fitTickCounts for the vertical axes alone, whose count follows the axis' range (the ticks a
/// count gives are measured): called before a drawing lays the plot out, with the new ranges
/// and the heights of the last layout, so that a design that moves a range costs no second
/// drawing. True when a count changed.
bool fitVerticalTickCounts(QCustomPlot* plot);

/// Asks for no more ticks on @p axis than one per @p pixels of its length (a short panel
/// gets fewer value lines than a tall one), within the ticker's own count; fitTickCounts
/// applies it with the label room. On a vertical axis it bounds the labels drawn (n labels
/// need (n - 1) * @p pixels), on a horizontal one the count asked of the ticker.
void setLeastTickSpacing(QCPAxis* axis, int pixels);

} // namespace xyt::ui
