// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/nyquist.h"
#include "core/analysis/stability_margins.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <memory>

namespace xyt::ui {

/**
 * The Nyquist diagram of one axis loop: L along the whole contour (the upper half
 * from the core and its mirror image), the critical point -1, the circle of radius 1/Ms around
 * it (the closest the curve comes), the unit circle, and the criterion stated with its counts:
 * Z = N + P. Complex plane at equal aspect, framed on the region around -1.
 */
class NyquistPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit NyquistPlot(QWidget* parent = nullptr);
    ~NyquistPlot() override;
    void showCurve(const NyquistCurve& curve, const StabilityMargins& margins,
                   const QString& title);
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    /// The criterion line drawn under the plane, e.g. "N = 0, P = 0: Z = N + P = 0 …".
    QString criterionText() const { return criterion_->text(); }
    QString noticeText() const { return notice_->text(); }
    QCPCurve* curve() const { return curve_; }

private:
    QCPCurve* curve_;
    QCPCurve* mirror_;
    QCPCurve* unitCircle_;
    QCPCurve* msCircle_;
    QCPGraph* critical_;
    QCPTextElement* title_;
    QCPTextElement* criterion_;
    std::unique_ptr<PlotNotice> notice_;
    bool hasResult_ = false;
    bool ranged_ = false;
    double lastTs_ = -1.0;
};

} // namespace xyt::ui
