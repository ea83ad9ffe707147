// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/robustness.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <memory>
#include <vector>

namespace xyt::ui {

/**
 * Where the ZPETC stops paying off (Patrick, Ishak and Adnan): the median RMSE with and without the
 * feedforward over the plants, against the mismatch (the share of the ranges set, 0 = the nominal
 * model), with the 5-95 % band of each. Draws the core's zpetcSensitivity curve; computes nothing.
 */
class SensitivityPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit SensitivityPlot(QWidget* parent = nullptr);
    ~SensitivityPlot() override;

    void showCurve(const std::vector<ZpetcSensitivityPoint>& curve);
    void showNoResult(const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    QCPGraph* withFfGraph() const { return with_; }
    QCPGraph* withoutFfGraph() const { return without_; }

private:
    QCPGraph *with_, *without_, *withLow_, *withHigh_, *withoutLow_, *withoutHigh_;
    std::unique_ptr<PlotNotice> notice_;
    bool hasResult_ = false;
};

} // namespace xyt::ui
