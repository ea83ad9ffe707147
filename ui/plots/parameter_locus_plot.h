// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/parameter_locus.h"
#include "ui/plots/plane_grid.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

namespace xyt::ui {

/**
 * The closed-loop poles of the Guillemin-Truxal design as omega_n or kp sweeps (the other held
 * at its current value), with the current design's poles marked: what the sliders move.
 */
class ParameterLocusPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit ParameterLocusPlot(QWidget* parent = nullptr);
    void showLocus(const ParameterLocus& locus, const std::vector<std::complex<double>>& current,
                   const QString& title);
    /// Clears the plot and says why there is no parameter locus (an invalid design, or a
    /// pole-placement axis, whose closed-loop poles are the roots of T, placed directly).
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_.text(); }
    const std::vector<QCPCurve*>& branchCurves() const { return branches_; }
    int branchCount() const { return static_cast<int>(branches_.size()); }
    QCPGraph* currentGraph() const { return current_; }
    /// The marks where the loop crosses the stability boundary (crossing poles, both halves).
    QCPGraph* boundaryGraph() const { return boundary_; }
    /// The texts of the parameter labels along the branches and at the boundary, as drawn.
    QStringList labelTexts() const;
    /// The branches the view was fitted on (those that move with the parameter).
    int framedBranchCount() const { return framedBranches_; }

private:
    std::vector<QCPCurve*> branches_;
    QCPGraph* current_;
    QCPGraph* ends_;
    QCPGraph* boundary_;
    std::vector<QCPItemText*> labels_;
    int framedBranches_ = 0;
    QCPTextElement* title_;
    PlaneGrid grid_;
    PlotNotice notice_;
    bool ranged_ = false;
    bool hasResult_ = false;
};

} // namespace xyt::ui
