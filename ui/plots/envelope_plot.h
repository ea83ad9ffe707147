// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/robustness.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <memory>

namespace xyt::ui {

/**
 * A signal of the robustness analysis over time: the band between the smallest and
 * the largest value of the stable runs shaded light, the 5-95 % band darker, the median dashed
 * and the nominal run solid on top. Draws a core SignalEnvelope; computes nothing.
 */
class EnvelopePlot : public PlotWidget {
    Q_OBJECT
public:
    explicit EnvelopePlot(QWidget* parent = nullptr);
    ~EnvelopePlot() override;

    void showEnvelope(const SignalEnvelope& envelope, const QString& title,
                      const QString& unitLabel);
    /// Clears the plot and says why: never an earlier result.
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    QCPGraph* minGraph() const { return min_; }
    QCPGraph* maxGraph() const { return max_; }
    QCPGraph* p05Graph() const { return p05_; }
    QCPGraph* p95Graph() const { return p95_; }
    QCPGraph* medianGraph() const { return p50_; }
    QCPGraph* nominalGraph() const { return nominal_; }

private:
    QCPTextElement* title_;
    QCPGraph *min_, *max_, *p05_, *p95_, *p50_, *nominal_;
    std::unique_ptr<PlotNotice> notice_;
    bool hasResult_ = false;
};

} // namespace xyt::ui
