// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <memory>

namespace xyt::ui {

/**
 * Time plots of one axis, three stacked panels sharing the time axis: reference and output,
 * tracking error, and control effort with the +-umax band and the clipped intervals shaded.
 * Only converts an AxisEvaluation into QCustomPlot data; computes nothing.
 */
class TimeResponsePlot : public PlotWidget {
    Q_OBJECT
public:
    explicit TimeResponsePlot(QWidget* parent = nullptr);

    /// Shows @p run (which may be invalid: the plots are cleared and the reason shown), with the
    /// axis' warnings and @p extraNotices (what the live view limited) in a notice box.
    void showAxis(const AxisEvaluation& axis, const QString& axisTitle, double umaxVolts,
                  const QStringList& extraNotices = {});
    /// Whether showAxis overlays the digital implementation (AxisEvaluation::digital): y and e
    /// at the controller's samples, and the command the plant receives (held, a staircase).
    void setDigitalVisible(bool visible);
    bool digitalVisible() const { return digitalVisible_; }
    /// A muted overlay of a stored design's output, error and control in all three panels, with
    /// a legend entry (an empty run hides it).
    void showSnapshot(const SimulationResult& run, const QString& name);

    QCPGraph* referenceGraph() const { return reference_; }
    QCPGraph* outputGraph() const { return output_; }
    QCPGraph* errorGraph() const { return error_; }
    QCPGraph* controlGraph() const { return control_; }
    QCPGraph* digitalOutputGraph() const { return digitalOutput_; }
    QCPGraph* digitalErrorGraph() const { return digitalError_; }
    QCPGraph* digitalControlGraph() const { return digitalControl_; }
    QCPGraph* snapshotOutputGraph() const { return snapshotOutput_; }
    /// The tool point and its error without the input shaper (AxisEvaluation::shaping).
    QCPGraph* unshapedOutputGraph() const { return unshapedOutput_; }
    QCPGraph* unshapedErrorGraph() const { return unshapedError_; }
    QCPGraph* snapshotErrorGraph() const { return snapshotError_; }
    QCPGraph* snapshotControlGraph() const { return snapshotControl_; }
    /// The band over the error plot where the table sticks (empty for a table without friction).
    QCPGraph* stuckGraph() const { return stuckUpper_; }
    QCPLegend* positionLegend() const { return legend_; }
    /// A run with a command feedforward: u's feedforward part and the rest (u - u_ff), and the
    /// legend naming the three lines of the control panel (hidden without a feedforward).
    QCPGraph* feedforwardGraph() const { return feedforward_; }
    QCPGraph* feedbackPartGraph() const { return feedbackPart_; }
    QCPLegend* controlLegend() const { return controlLegend_; }
    /// The warnings shown over the position panel, and the note in the control panel.
    QString noticeText() const { return notice_->text(); }
    QString controlNoticeText() const { return controlNotice_->text(); }

private:
    QCPAxisRect* positionRect_;
    QCPAxisRect* errorRect_;
    QCPAxisRect* controlRect_;
    QCPGraph* reference_;
    QCPGraph* output_;
    QCPGraph* snapshotOutput_;
    QCPGraph* error_;
    QCPGraph* control_;
    QCPGraph* snapshotControl_;
    QCPGraph* snapshotError_;
    QCPGraph* digitalOutput_;
    QCPGraph* digitalError_;
    QCPGraph* digitalControl_;
    QCPGraph* feedforward_;
    QCPGraph* feedbackPart_;
    QCPLegend* controlLegend_;
    bool digitalVisible_ = true;
    QCPLegend* legend_;
    std::unique_ptr<PlotNotice> notice_;
    std::unique_ptr<PlotNotice> controlNotice_;
    QCPGraph* unshapedOutput_;
    QCPGraph* unshapedError_;
    QCPGraph* clipUpper_;
    QCPGraph* clipLower_;
    QCPGraph* stuckUpper_; ///< the error plot's band where the table sticks (friction)
    QCPGraph* stuckLower_;
    QCPItemStraightLine* upperLimit_;
    QCPItemStraightLine* lowerLimit_;
    QCPTextElement* title_;
    bool autoRange_ = true;
};

} // namespace xyt::ui
