// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/robustness.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <memory>
#include <optional>

namespace xyt::ui {

/**
 * The distribution of one figure over the stable runs of a robustness analysis: the
 * core's histogram as bars, the nominal plant's value and the specification's limit (when the
 * figure has one) as vertical lines. Computes nothing.
 */
class HistogramPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit HistogramPlot(QWidget* parent = nullptr);
    ~HistogramPlot() override;

    void showHistogram(const Histogram& h, double nominal, std::optional<double> limit,
                       const QString& title, const QString& unitLabel);
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    QCPBars* bars() const { return bars_; }
    /// x of the limit line (NaN when not drawn) and of the nominal line.
    double limitDrawn() const;
    double nominalDrawn() const;

private:
    QCPTextElement* title_;
    QCPBars* bars_;
    QCPItemStraightLine* limit_;
    QCPItemStraightLine* nominal_;
    std::unique_ptr<PlotNotice> notice_;
    bool hasResult_ = false;
};

} // namespace xyt::ui
