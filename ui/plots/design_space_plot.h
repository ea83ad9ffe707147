// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/design_sweep.h"

#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace xyt::ui {

/// A corner of the grid's cells: corner (a, b) is the lower-left corner of cell (a, b), so
/// a runs over [0, wnCount] and b over [0, kpCount].
struct GridCorner {
    int iWn = 0;
    int iKp = 0;
    friend bool operator==(const GridCorner&, const GridCorner&) = default;
};

/**
 * The outline of the feasible cells: closed loops of cell edges, each edge separating a feasible
 * cell from an infeasible one or from the outside of the grid. @p mask is indexed as
 * DesignSweepResult::feasibleMask (row iWn, column iKp). The feasible cells lie on the left of
 * every loop (counter-clockwise around a region in (wn, kp)); each loop ends on its first corner.
 */
std::vector<std::vector<GridCorner>> feasibleOutline(const std::vector<std::uint8_t>& mask,
                                                     int wnCount, int kpCount);

/// The cell edges of one grid axis: count + 1 values. Inner edges lie halfway between two grid
/// values, in log space (geometric mean) on a log grid, so that they match the cells of a colour
/// map drawn on a logarithmic axis; the outer edges mirror the first and last inner edge.
std::vector<double> cellEdges(const std::vector<double>& values, bool logarithmic);

/**
 * The heat map of a design-space study (core DesignSweepResult): one metric over wn (x) x kp (y)
 * with its colour scale, infeasible cells veiled, unstable or diverged cells grey, cells a
 * cancelled study did not reach light grey, the feasible region outlined, the best grid design
 * (star), the refined best (diamond) and the session's current design (cross). Computes nothing;
 * reports the cell under the mouse and the cell clicked.
 */
class DesignSpacePlot : public PlotWidget {
    Q_OBJECT
public:
    explicit DesignSpacePlot(QWidget* parent = nullptr);

    /// Draws @p result (grids of at least 2 x 2 values), the metric @p metric (log colour scale
    /// when @p logColor). @p logGrid says how the grid was spaced (log axes then).
    void showResult(const DesignSweepResult& result, bool logGrid, SweepCriterion metric,
                    bool logColor, const QString& title);
    /// Redraws the held result with another metric or colour scale.
    void setMetric(SweepCriterion metric, bool logColor);
    /// Moves the cross of the current design.
    void setCurrentDesign(double wn, double kp);
    bool hasResult() const { return hasResult_; }

    /// The grid cell under a widget pixel, when inside the grid.
    std::optional<std::pair<std::size_t, std::size_t>> cellAtPixel(const QPointF& pixel) const;
    /// The pixel of grid point (iWn, iKp) (the cell's centre).
    QPointF pixelOfCell(std::size_t iWn, std::size_t iKp) const;
    /// Sets the view to the whole grid.
    void showWholeGrid();

    QCPColorMap* colorMap() const { return map_; }
    QCPColorMap* statusMap() const { return status_; }
    QCPColorScale* colorScale() const { return scale_; }
    /// The notice over the map ("not computed yet" before the first study).
    QString noticeText() const;
    QCPGraph* bestMarker() const { return best_; }
    QCPGraph* refinedMarker() const { return refined_; }
    QCPGraph* leastViolatingMarker() const { return leastViolating_; }
    /// Marks the least-violating design (▲) of a study without a feasible one, or clears it.
    void setLeastViolating(std::optional<std::pair<double, double>> wnKp);
    QCPGraph* currentMarker() const { return current_; }
    /// One curve per loop of feasibleOutline (the dark halo curves are not counted).
    int outlineCount() const { return static_cast<int>(outline_.size()); }
    QCPCurve* outlineCurve(int i) const { return outline_.at(static_cast<std::size_t>(i)); }

    /// Values of the status layer (statusMap cells).
    enum CellStatus { Feasible = 0, Infeasible = 1, Failed = 2, NotComputed = 3 };

signals:
    /// The mouse moved over a cell (nullopt: off the grid).
    void cellHovered(std::optional<std::pair<std::size_t, std::size_t>> cell);
    /// The user clicked (not dragged) on a cell.
    void cellClicked(std::size_t iWn, std::size_t iKp);

private:
    void drawMetric();
    void drawOutline();
    void showContextMenu(const QPoint& pos);

    DesignSweepResult result_;
    bool hasResult_ = false;
    bool logGrid_ = true;
    SweepCriterion metric_ = SweepCriterion::Itae;
    bool logColor_ = true;
    std::vector<double> wnEdges_;
    std::vector<double> kpEdges_;

    QCPTextElement* title_;
    QCPColorMap* map_;
    QCPColorMap* status_;
    QCPColorScale* scale_;
    std::unique_ptr<PlotNotice> notice_;
    std::vector<QCPCurve*> outline_;
    std::vector<QCPCurve*> outlineHalo_;
    QCPGraph* best_;
    QCPGraph* refined_;
    QCPGraph* leastViolating_;
    QCPGraph* current_;
    QPoint pressPos_;
};

/// "ITAE", "max |e|", "RMSE", "max |u|".
QString metricLabel(SweepCriterion metric);
/// The metric's label with its unit (trajectory unit "mm" for the errors, V for the command).
QString metricAxisLabel(SweepCriterion metric);

} // namespace xyt::ui
