// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QCustomPlot;

namespace xyt::ui {

/**
 * Gives each axis of @p plot no more ticks than its labels have room for along it ("-20-10" on
 * a narrow XY plot, the phase labels of a short Bode plane on each other), and back up to the ticker's own count when the plot
 * widens. True when a count changed (the plot must be drawn again).
 */
bool fitTickCounts(QCustomPlot* plot);

} // namespace xyt::ui
