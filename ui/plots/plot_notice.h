// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <initializer_list>

#include <QString>
#include <QStringList>
#include <Qt>

class QCustomPlot;
class QCPAxisRect;
class QCPItemText;
class QCPGraph;

namespace xyt::ui {

/**
 * A notice box inside a plot's axis rect: the core's warnings about what the plot shows (locus
 * truncated, run diverged, loop simulated without saturation, view limited, no design), on a
 * pale amber background so it reads as a remark about the data, not as data. Hidden when empty.
 */
class PlotNotice {
public:
    /// A box in @p rect, anchored at @p corner (e.g. Qt::AlignTop | Qt::AlignRight).
    PlotNotice(QCustomPlot* plot, QCPAxisRect* rect, Qt::Alignment corner);
    /// Shows the lines (one per warning, wrapped to the axis rect's width when drawn); an
    /// empty list hides the box.
    void setLines(const QStringList& lines);
    /// A strong notice (no result at all): red text instead of the amber box's dark text.
    void setSevere(bool severe);
    /// The lines as given, one per line (the box wraps them to its width).
    QString text() const;
    bool isShown() const;

private:
    QCPItemText* item_;
    QStringList lines_; ///< as given, before wrapping
};

/// Clears @p graphs and shows @p reason as a strong notice (no result to draw), then replots:
/// what a plot shows when it has nothing for the current design.
void clearWithNotice(QCustomPlot* plot, PlotNotice& notice, std::initializer_list<QCPGraph*> graphs,
                     const QString& reason);

} // namespace xyt::ui
