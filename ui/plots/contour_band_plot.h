// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/contour_robustness.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <memory>
#include <vector>

namespace xyt::ui {

/**
 * The XY contour under plant-model mismatch: the programmed contour, the nominal
 * traced contour and the band the mismatched plant pairs trace (min-max light, 5-95 % darker),
 * their contour error magnified about the contour as a ballbar plot does (along the outward
 * radius of a circle, the left normal of a path). The magnification is chosen so that the
 * band's outer edge spans a tenth of the contour's size for 90 % of the time (a 1-2-5 step, at
 * least 1), and said in the title.
 * Equal scales on both axes. Draws a core ContourRobustnessResult; computes nothing.
 */
class ContourBandPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit ContourBandPlot(QWidget* parent = nullptr);
    ~ContourBandPlot() override;

    void showResult(const ContourRobustnessResult& result);
    /// Clears the plot and says why: never an earlier result.
    void showNoResult(const QString& reason);
    bool hasResult() const { return hasResult_; }
    double magnification() const { return magnification_; }
    QString noticeText() const { return notice_->text(); }
    QString titleText() const { return title_->text(); }
    /// One per connected piece of the judged contour (a program's rapids split it).
    const std::vector<QCPCurve*>& programmedCurves() const { return programmed_; }
    const std::vector<QCPCurve*>& nominalCurves() const { return nominal_; }
    const std::vector<QCPCurve*>& outerBands() const { return outer_; } ///< min-max polygons
    const std::vector<QCPCurve*>& innerBands() const { return inner_; } ///< 5-95 % polygons

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void clearCurves();
    void fitEqualScale();
    QCPCurve* addCurve(const QPen& pen, const QBrush& brush);

    QCPTextElement* title_;
    std::vector<QCPCurve*> programmed_, nominal_, outer_, inner_;
    std::unique_ptr<PlotNotice> notice_;
    double magnification_ = 1.0;
    bool hasResult_ = false;
    bool fitPending_ = false; ///< fit the view at the next layout (a new result, a new size)
};

} // namespace xyt::ui
