// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/axis_vibration.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <memory>
#include <optional>

namespace xyt {
struct AccelerometerSpectra;
struct FrequencyResponseEstimate;
} // namespace xyt

namespace xyt::ui {

/// What was measured, drawn over the model: a frequency-response estimate of the axis (mm/V)
/// and an accelerometer log's spectra; null when there is none.
struct VibrationMeasurements {
    const FrequencyResponseEstimate* response = nullptr;
    QString responseSource;
    const AccelerometerSpectra* acceleration = nullptr;
    QString accelerationSource;
    /// The mode picked from the measured response (measuredModePick), marked where it lies.
    std::optional<double> measuredModeHz, measuredModeDamping;
};

/**
 * The Vibration view of one axis: above, the magnitude of the rigid plant, of the plant with its
 * flexible mode and of the notch over frequency in Hz; below, the input shaper's sensitivity
 * curve (residual vibration against the mode's frequency) with the 5 % tolerance, the mode
 * marked and the residual read there; a summary row states the shaper's delay and the tool
 * point's residual vibration with and without it. Draws AxisVibration, computes nothing.
 */
class VibrationPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit VibrationPlot(QWidget* parent = nullptr);
    ~VibrationPlot() override;
    /// @p summary: the shaper's effect on the run, or "" when the reference is not shaped.
    void showVibration(const AxisVibration& vibration, const QString& title, const QString& summary,
                       const VibrationMeasurements& measured = {});
    void showNoResult(const QString& title, const QString& reason);
    bool hasResult() const { return hasResult_; }
    QString noticeText() const { return notice_->text(); }
    QString summaryText() const;
    QCPGraph* rigidGraph() const { return rigid_; }
    QCPGraph* plantGraph() const { return plant_; }
    QCPGraph* notchGraph() const { return notch_; }
    QCPGraph* sensitivityGraph() const { return sensitivity_; }
    /// The measured |H| (where its coherence is at least kMinCoherence) and the accelerometer
    /// PSD (dB re its largest bin, on the right axis).
    QCPGraph* measuredGraph() const { return measured_; }
    QCPGraph* accelerationGraph() const { return acceleration_; }
    static constexpr double kMinCoherence = 0.5;
    QCPAxisRect* responseRect() const { return responseRect_; }
    QCPAxisRect* shaperRect() const { return shaperRect_; }
    /// The texts of the labels drawn (the mode, the notch, the residual at the mode).
    QStringList markerTexts() const;

private:
    QString description_; ///< what the plot draws: the start of its tooltip
    void clearMarkers();
    void placeLegend(bool shown);

    QCPTextElement* title_;
    QCPAxisRect* responseRect_;
    QCPAxisRect* shaperRect_;
    QCPGraph *rigid_, *plant_, *notch_, *sensitivity_, *tolerance_, *measured_, *acceleration_;
    QCPTextElement* summary_;
    QList<QCPAbstractItem*> markers_;
    QCPLegend* legend_;
    std::unique_ptr<PlotNotice> notice_;
    std::unique_ptr<PlotNotice> shaperNotice_; ///< says where to set a shaper when there is none
    bool hasResult_ = false;
};

} // namespace xyt::ui
