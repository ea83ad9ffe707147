// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/step_view.h"
#include "core/study/specification.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <memory>

namespace xyt::ui {

/// The step limits of @p spec (overshoot with its round-off slack, settling time, 2 % band), so
/// that the envelope drawn and the metrics panel's verdict agree.
StepEnvelope specificationEnvelope(const Specification& spec);

/**
 * The unit step of one axis: the closed loop's step, or for a pole-placement axis
 * the step with and without the ZPETC; markers for the rise time (10-90 %), the peak and the
 * settling time (2 % band) of the step the axis runs, all from the core's figures; and the
 * specification's envelope as Control System Designer draws it: the overshoot bound and,
 * from the settling-time limit on, the band, the forbidden side shaded, the samples where the
 * response leaves it drawn red. Time runs from the step instant. Draws a core StepView.
 */
class StepPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit StepPlot(QWidget* parent = nullptr);
    ~StepPlot() override;

    void showView(const StepView& view, const QString& title);
    /// Clears the plot and says why (no design, unstable loop): never an earlier response.
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    QString readoutText() const { return readout_->text(); }
    static QString readoutHint();
    /// The graph of a curve (null when not drawn), its data at t - stepAtSeconds.
    QCPGraph* curveGraph(StepCurveKind kind) const;
    /// Marker points: rise (t10, t90 at 10 / 90 % of the final value), peak (one point),
    /// settling (one point, on the band edge the response last left).
    QCPGraph* riseMarker() const { return rise_; }
    QCPGraph* peakMarker() const { return peak_; }
    QCPGraph* settlingMarker() const { return settling_; }
    /// The samples outside the envelope (NaN elsewhere).
    QCPGraph* violationGraph() const { return violation_; }
    /// Envelope lines: the overshoot bound (y), the band edges (y) and where the band starts (t);
    /// NaN when not drawn.
    double overshootBoundDrawn() const;
    double bandStartDrawn() const;
    QStringList markerTexts() const;

protected:
    void leaveEvent(QEvent* event) override;

private:
    void clearView();
    QCPItemText* addLabel(double t, double y, const QString& text, const QColor& color,
                          Qt::Alignment align);
    QCPItemRect* addShade(double t0, double y0, bool toTop);
    void onMouseMove(QMouseEvent* event);

    QCPTextElement* title_;
    QCPTextElement* readout_;
    QCPGraph* main_;
    QCPGraph* other_;
    QCPGraph* violation_;
    QCPGraph* rise_;
    QCPGraph* peak_;
    QCPGraph* settling_;
    QCPGraph* overshootLine_;
    QCPGraph* bandUpper_;
    QCPGraph* bandLower_;
    QList<QCPAbstractItem*> items_;
    std::unique_ptr<PlotNotice> notice_;
    StepCurveKind mainKind_ = StepCurveKind::ClosedLoop;
    StepCurveKind otherKind_ = StepCurveKind::ClosedLoop;
    bool hasResult_ = false;
};

} // namespace xyt::ui
