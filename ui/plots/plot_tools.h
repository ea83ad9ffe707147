// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QString>
#include <QVector>

#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPCurve;
class QCPRange;
class QCPGraphData;
class QCPItemText;
class QCPLegend;
class QCPTextElement;

namespace xyt::ui {

/// The workbench's palette, so every plot uses the same colours for the same things.
namespace colors {
inline const QColor reference{0x55, 0x55, 0x55};
inline const QColor output{0x1f, 0x77, 0xb4};
inline const QColor error{0xd6, 0x27, 0x28};
inline const QColor control{0x2c, 0xa0, 0x2c};
inline const QColor limit{0xd6, 0x27, 0x28};
inline const QColor snapshot{0xa0, 0xa0, 0xa0};
/// The digital implementation: the loop as the firmware runs it.
inline const QColor digital{0x94, 0x67, 0xbd};
/// A controller's command feedforward (its share of u).
inline const QColor feedforward{0xff, 0x7f, 0x0e};
/// A run without the input shaper, under the shaped one.
inline const QColor unshaped{0x8c, 0x56, 0x4b};
inline const QColor axisX{0x1f, 0x77, 0xb4};
inline const QColor axisY{0xff, 0x7f, 0x0e};
} // namespace colors

/**
 * Common behaviour of every plot: drag to pan, wheel to zoom, double-click to reset the view,
 * and a context menu with "Reset view", "Save as PNG..." and "Save as PDF...".
 */
void setupInteractivePlot(QCustomPlot* plot);
/// The smallest box holding every point of @p curves (empty curves left out) in @p xRange and
/// @p yRange; false when no curve has a point.
bool curvesBoundingBox(const std::vector<QCPCurve*>& curves, QCPRange& xRange, QCPRange& yRange);
/// Rescales every axis rect to its visible data (with a small margin).
void resetView(QCustomPlot* plot);
/// Asks for a file name and saves the plot; the format follows the extension (.png or .pdf).
void savePlotDialog(QCustomPlot* plot, const QString& suggestedName);
/// Saves to @p path (png or pdf by extension). Returns false and sets @p error on failure.
bool savePlot(QCustomPlot* plot, const QString& path, QString* error = nullptr);
/**
 * Samples (t_k, y_k) for a line plot of at most about 2 @p buckets points: all of them when
 * there are few enough, else, per bucket of consecutive samples, its smallest and largest value
 * in time order. The drawn line then has the same extremes as the full one at any zoom that
 * shows a bucket as a pixel or less, at a cost bounded by the bucket count (a 13-million-sample
 * run is not copied into the plot).
 */
QVector<QCPGraphData> minMaxDecimated(const std::vector<double>& t, const std::vector<double>& y,
                                      int buckets = 8192);
/// A flag signal as a band height: @p valueWhenSet where set, NaN (a gap) elsewhere; decimated
/// per bucket (first and last time of the bucket, set when any sample in it is set).
QVector<QCPGraphData> flagDecimated(const std::vector<double>& t, const std::vector<bool>& flags,
                                    double valueWhenSet, int buckets = 8192);

/// Readable fonts and light grid for an axis rect.
/**
 * Moves the plot's legend out of the axis rect into a row of its own under it (row @p row of
 * the plot layout), borderless and filled across in up to @p columns columns: there it can
 * hide no data, whatever the data does.
 */
void placeLegendBelow(QCustomPlot* plot, int row, int columns = 3);
/// Small icons and gaps, for a legend row under a narrow plot (QCustomPlot's 32 px icons clip
/// the names of a three-entry row at 1366 x 768).
void compactLegend(QCPLegend* legend);

void styleAxisRect(QCPAxisRect* rect);

/// A perceptually ordered blue-green-yellow map (the stops of matplotlib's viridis), 256
/// levels, NaN transparent (the plot's background shows where a cell has no figure).
QCPColorGradient viridisGradient();

/// A row of small left-aligned text (a hover readout, a criterion) under the plot at layout row
/// @p row, as short as its text.
QCPTextElement* addTextRow(QCustomPlot* plot, int row, const QString& text);

/**
 * A small annotation at (@p x, @p y) of @p rect on a translucent white box, placed on the side
 * where it has room: @p align as given in the left part of the view, mirrored to the left of the
 * point when @p rightHalf.
 */
QCPItemText* addAnnotation(QCustomPlot* plot, QCPAxisRect* rect, double x, double y,
                           const QString& text, const QColor& color, Qt::Alignment align,
                           bool rightHalf);

/// Shows @p text in the hover readout @p readout of @p plot, replotting only when it changed
/// (a mouse move that leaves the text as it was costs no repaint).
void setReadoutText(QCustomPlot* plot, QCPTextElement* readout, const QString& text);

} // namespace xyt::ui
