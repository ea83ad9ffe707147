// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "core/study/contour_robustness.h"
#include "core/study/robustness.h"

#include "ui/jobs/job_runner.h"
#include "ui/session/tuning_session.h"

#include <QMap>
#include <QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QStackedWidget;
class QVBoxLayout;

namespace xyt::ui {

class ContourBandPlot;
class EnvelopePlot;
class HistogramPlot;
class SensitivityPlot;
class StaleVeil;

/**
 * Robustness of the current axis to plant-model mismatch: a relative range per
 * plant parameter, Monte Carlo plants from a seed and the box's corners, run by the core
 * (analyzeRobustness) on a worker thread with progress and cancel; the chosen signal's envelope
 * over time around the nominal run, the chosen figure's histogram with the specification's
 * limit, the fraction of plants meeting the specification, the unstable plants and the worst
 * one, which "Load worst case" makes the session's plant (one undo step). For a pole-placement
 * axis with ZPETC the run also computes the ZPETC sensitivity curve (zpetcSensitivity at 0, 25,
 * 50, 75 and 100 % of the ranges), shown as the fourth "histogram" choice. With "XY contour"
 * (a circle or G-code trajectory) both axes are analyzed together (analyzeContourRobustness):
 * each range applies to the parameter of that name on every axis that has one, the envelope is
 * the contour error's, the figures are the max |contour error| histogram and the XY band
 * (ContourBandPlot), and "Load worst case" loads the worst pair into both axes in one undo step.
 * The run takes its inputs from the presenter when Run is pressed, and its result keeps the
 * stamp of the design it was computed for: once the design (or, in axis mode, the selected axis)
 * no longer matches, the plots are veiled with what the result was computed for ("axis X,
 * ωn = 2 rad/s, kp = 30") and "Load worst case" is off, including for a run that finishes after
 * the design changed; an undo back to the analyzed design lifts the veil. The range rows follow
 * the selected axis (both axes' parameters in contour mode).
 */
class RobustnessView : public QWidget {
    Q_OBJECT
public:
    explicit RobustnessView(TuningSession* session, QWidget* parent = nullptr);
    ~RobustnessView() override;

    void run();
    void cancel();
    /// Makes the worst plant of the shown result the session's plant (an undoable step).
    void loadWorstCase();
    bool isRunning() const { return runner_.isRunning(); }
    /// True when a result is shown and describes the current design (and axis).
    bool resultIsCurrent() const;
    /// The cover over a stale result, with what it was computed for.
    StaleVeil* veil() const { return veil_; }
    const std::optional<RobustnessResult>& result() const { return result_; }
    /// The problem of the shown result (its ranges included).
    const std::optional<RobustnessProblem>& analyzedProblem() const { return problem_; }
    int analyzedAxis() const { return stamp_ ? stamp_->axis : -1; }
    /// The joint XY result shown (contour mode), and its problem.
    const std::optional<ContourRobustnessResult>& contourResult() const { return contourResult_; }
    const std::optional<ContourRobustnessProblem>& analyzedContourProblem() const {
        return contourProblem_;
    }
    bool contourMode() const;

    /// The range box (in %) of parameter @p name of the current axis, or null.
    QDoubleSpinBox* rangeBox(const QString& name) const { return ranges_.value(name, nullptr); }
    QStringList parameterNames() const { return ranges_.keys(); }
    QSpinBox* samplesBox() const { return samples_; }
    QSpinBox* seedBox() const { return seed_; }
    QCheckBox* cornersBox() const { return corners_; }
    QCheckBox* contourBox() const { return contour_; }
    QComboBox* signalBox() const { return signal_; }
    QComboBox* figureBox() const { return figure_; }
    QPushButton* runButton() const { return run_; }
    QPushButton* cancelButton() const { return cancel_; }
    QPushButton* worstButton() const { return worst_; }
    EnvelopePlot* envelopePlot() const { return envelope_; }
    HistogramPlot* histogramPlot() const { return histogram_; }
    SensitivityPlot* sensitivityPlot() const { return sensitivity_; }
    ContourBandPlot* bandPlot() const { return band_; }
    /// The ZPETC sensitivity curve of the shown result (empty unless pole placement + ZPETC).
    const std::vector<ZpetcSensitivityPoint>& sensitivityCurve() const { return curve_; }
    /// The mismatch scales of the curve.
    static std::vector<double> sensitivityScales() { return {0.0, 0.25, 0.5, 0.75, 1.0}; }
    QString statusText() const;

signals:
    void analysisFinished();

private:
    // The constructor's steps, in the order the widgets are made (their tab order).
    /// The ranges of the parameters (± %), filled by rebuildRanges.
    QGroupBox* buildRangeBox();
    /// Plants, seed, corners and the XY-contour switch.
    QHBoxLayout* buildOptions();
    /// Run, Cancel, Load worst case and the progress.
    QHBoxLayout* buildActions();
    /// The envelope, the figure (histogram, sensitivity or XY band), the veil and the status.
    QVBoxLayout* buildPlots();
    /// The signal and figure choices under the ranges.
    QGroupBox* buildShowBox();
    void connectControls();
    /// What a run computes: the axis or the joint result, with the problem it solved.
    struct Outcome {
        std::optional<RobustnessResult> axis;
        std::optional<RobustnessProblem> problem;
        std::vector<ZpetcSensitivityPoint> curve;
        std::optional<ContourRobustnessResult> contour;
        std::optional<ContourRobustnessProblem> contourProblem;
    };

    void rebuildRanges();
    void onDesignChanged();
    void onFinished(Outcome&& outcome, const ResultStamp& stamp);
    /// Veils the shown result when it no longer describes the design, lifts the veil when it does.
    void showFreshness();
    void onModeChanged();
    /// The signal and figure choices of the mode (axis or XY contour).
    void fillChoices();
    /// Forgets the shown result and says why on every plot.
    void clearResult(const QString& why);
    QString axisSummary(const RobustnessResult& r) const;
    QString contourSummary(const ContourRobustnessResult& r) const;
    void redraw();
    void setStatus(const QString& text, bool isError = false);

    TuningSession* session_;
    std::optional<RobustnessResult> result_;
    std::vector<ZpetcSensitivityPoint> curve_;
    std::optional<RobustnessProblem> problem_;
    std::optional<ContourRobustnessResult> contourResult_;
    std::optional<ContourRobustnessProblem> contourProblem_;
    std::optional<ResultStamp> stamp_; ///< what the shown result was computed for
    QString summary_;                  ///< the status line of the shown result
    bool summaryIsError_ = false;
    QMap<QString, double> rangePct_; ///< kept per parameter name across redesigns

    QWidget* controlContent_;
    QFormLayout* rangeForm_;
    QMap<QString, QDoubleSpinBox*> ranges_;
    QStringList rangeOrder_;
    QSpinBox* samples_;
    QSpinBox* seed_;
    QCheckBox* corners_;
    QCheckBox* contour_;
    QComboBox* signal_;
    QComboBox* figure_;
    QPushButton* run_;
    QPushButton* cancel_;
    QPushButton* worst_;
    QProgressBar* progress_;
    QLabel* status_;
    EnvelopePlot* envelope_;
    HistogramPlot* histogram_;
    SensitivityPlot* sensitivity_;
    ContourBandPlot* band_;
    QStackedWidget* figureStack_;
    StaleVeil* veil_;
    JobRunner<Outcome, ResultStamp> runner_; ///< last: destroyed first, before the widgets
};

} // namespace xyt::ui
