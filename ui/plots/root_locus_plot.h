// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/root_locus.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "ui/plots/plane_grid.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"
#include "ui/plots/requirement_overlay.h"

#include <qcustomplot.h>

#include <optional>

namespace xyt::ui {

/**
 * The root locus of 1 + K L(s) = 0 (or in z) with the open-loop poles (x) and zeros (o), the
 * current closed-loop poles (filled diamonds, K = 1 is the design), the zeta/omega_n grid, a
 * hover readout of K, zeta and omega_n, and a click on a branch that picks that gain.
 * Draws a core RootLocus; computes nothing but the pick (core pickLocusPoint).
 */
class RootLocusPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit RootLocusPlot(QWidget* parent = nullptr);

    void showLocus(const RootLocus& locus, const std::vector<std::complex<double>>& currentPoles,
                   const QString& title);
    /// The specification (and the design's omega_n) drawn over the next locus shown.
    void setRequirements(const LocusRequirements& requirements) { requirements_ = requirements; }
    const RequirementOverlay& requirementOverlay() const { return overlay_; }
    /// Clears the plot and says why there is no locus (invalid or failed design): never the
    /// locus of an earlier design.
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasLocus_; }
    /// The warnings shown with the locus (the core's, e.g. a truncated locus).
    QString noticeText() const { return notice_.text(); }
    /// The hint shown in the readout while no branch is hovered.
    static QString readoutHint();
    /// The locus point nearest to a pixel, when within @p maxPixels of it.
    std::optional<LocusPick> pickAtPixel(const QPointF& pixel, double maxPixels = 12.0) const;
    const RootLocus& locus() const { return locus_; }
    QString readoutText() const { return readout_->text(); }
    int branchCurveCount() const { return static_cast<int>(branches_.size()); }
    QCPCurve* branchCurve(int i) const { return branches_.at(static_cast<std::size_t>(i)); }
    QCPGraph* currentPolesGraph() const { return current_; }
    QCPGraph* zerosGraph() const { return zeros_; }
    /// Whether the open-loop zeros (o) can be dragged (a controller whose zeros are its own:
    /// the PID's). A press within a few pixels of a zero then drags it instead of panning.
    void setZerosDraggable(bool draggable);
    bool zerosDraggable() const { return zerosDraggable_; }

signals:
    /// The user clicked on a branch: the loop gain K at that point (K = 1 is the current design).
    void gainPicked(double gain);
    /// The user drags a closed-loop pole of the design along the locus: the loop gain of the
    /// point reached, relative to the design when the drag began (the locus then); @p finished
    /// on release.
    void gainDragged(double gain, bool finished);
    /// The user drags the zero that was at @p from to @p to (s-plane); @p finished on release.
    void zeroDragged(std::complex<double> from, std::complex<double> to, bool finished);

protected:
    void leaveEvent(QEvent* event) override;

private:
    void clearHover();
    void onMouseMove(QMouseEvent* event);
    void onMousePress(QMouseEvent* event);
    void onMouseRelease(QMouseEvent* event);
    /// The zero within @p maxPixels of @p pixel, if any.
    std::optional<std::complex<double>> zeroAtPixel(const QPointF& pixel,
                                                    double maxPixels = 8.0) const;
    bool zerosDraggable_ = false;
    std::optional<std::complex<double>> draggedZero_; ///< where the dragged zero is now
    /// The locus when a closed-loop pole's drag began (its gains are relative to that design).
    std::optional<RootLocus> gainDragLocus_;
    std::vector<std::complex<double>> currentPoles_;
    /// The gain of @p pixel on the drag's locus, if any.
    std::optional<double> dragGainAt(const QPointF& pixel) const;

    RootLocus locus_;
    PlaneGrid grid_;
    RequirementOverlay overlay_;
    LocusRequirements requirements_;
    std::vector<QCPCurve*> branches_;
    QCPGraph* poles_;
    QCPGraph* zeros_;
    QCPGraph* current_;
    QCPGraph* hover_;
    QCPTextElement* readout_;
    QCPTextElement* title_;
    PlotNotice notice_;
    QPoint pressPos_;
    bool hasLocus_ = false;
    double lastTs_ = -1.0;
};

/// The specification's step limits, and a Guillemin–Truxal axis' ωn, as the locus of @p axis
/// draws them (the root-locus view and the design report alike).
LocusRequirements axisLocusRequirements(const Session& session, int axis);

/// The closed-loop poles of an evaluated axis' design; none when they cannot be computed.
std::vector<std::complex<double>> designClosedLoopPoles(const AxisEvaluation& evaluation);

} // namespace xyt::ui
