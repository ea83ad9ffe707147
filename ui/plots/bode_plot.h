// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/axis_frequency.h"
#include "core/session/axis_vibration.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

#include <memory>

namespace xyt::ui {

/// The specification's margin minima and the evaluation's verdicts on them
/// (SpecificationCheck::phaseMargin / gainMargin): a margin drawn red fails, green passes.
struct BodeMarginRequirements {
    double minPhaseMarginDeg = 0.0; ///< 0: none stated (quoted only when > 0)
    double minGainMarginDb = 0.0;
    bool phaseMarginMet = true;
    bool gainMarginMet = true;
};

/**
 * The Bode diagram of one axis: magnitude (dB) over phase (degrees) on a shared
 * logarithmic frequency axis. The open loop L with its stability margins drawn where they are
 * read (gain margin at the phase crossover, phase margin at the gain crossover), |S| and |T|,
 * and for a pole-placement axis the tracking response without and with ZPETC; the reference
 * frequency of a circle and the Nyquist frequency of a discrete loop are marked. A click on a
 * legend entry hides or shows its curve. Draws what the core computed, nothing else.
 */
class BodePlot : public PlotWidget {
    Q_OBJECT
public:
    explicit BodePlot(QWidget* parent = nullptr);
    ~BodePlot() override;
    void showAnalysis(const AxisFrequencyAnalysis& analysis, bool zpetcEnabled,
                      const QString& title, const BodeMarginRequirements& requirements = {});
    void showNoResult(const QString& title, const QString& reason);
    /// The loop with a measured plant (measuredOpenLoop), dots over L on both panels; null
    /// removes it. Call after showAnalysis.
    void showMeasuredLoop(const MeasuredOpenLoop* loop, const QString& source);
    QCPGraph* measuredMagnitudeGraph() const { return measuredMagnitude_; }
    QCPGraph* measuredPhaseGraph() const { return measuredPhase_; }
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    /// "ω = …  |L| = … dB  ∠L = …°" at the hovered frequency, or the hint.
    QString readoutText() const { return readout_->text(); }
    static QString readoutHint();
    QCPGraph* magnitudeGraph(const QString& name) const;
    QCPGraph* phaseGraph(const QString& name) const;
    /// The texts of the margin and frequency labels drawn (e.g. "GM 45.9 dB").
    QStringList markerTexts() const;
    QCPAxisRect* magnitudeRect() const { return magRect_; }
    QCPAxisRect* phaseRect() const { return phaseRect_; }

protected:
    void leaveEvent(QEvent* event) override;

private:
    struct Curve {
        QCPGraph* magnitude = nullptr;
        QCPGraph* phase = nullptr; ///< null for magnitude-only curves (|S|, |T|)
    };
    Curve& curve(const QString& name, const QColor& color, Qt::PenStyle style, bool withPhase);
    void clearMarkers();
    void addVerticalMarker(QCPAxisRect* rect, double omega, double from, double to,
                           const QPen& pen);
    void addLabel(QCPAxisRect* rect, double omega, double value, const QString& text,
                  const QColor& color, Qt::Alignment align);
    void onMouseMove(QMouseEvent* event);

    QCPGraph* measuredMagnitude_ = nullptr;
    QCPGraph* measuredPhase_ = nullptr;
    QCPAxisRect* magRect_;
    QCPAxisRect* phaseRect_;
    QCPTextElement* title_;
    QCPTextElement* readout_;
    QCPLegend* legend_;
    QMap<QString, Curve> curves_;
    QList<QCPAbstractItem*> markers_;
    std::unique_ptr<PlotNotice> notice_;
    FrequencyResponse openLoop_;
    bool hasResult_ = false;
    double lastTs_ = -1.0;
    QString lastTitle_;
};

} // namespace xyt::ui
