// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_study.h"
#include "core/session/session.h"
#include "core/study/design_sweep.h"
#include "core/study/sweep_diagnosis.h"

#include "ui/jobs/job_runner.h"
#include "ui/session/tuning_session.h"

#include <QWidget>

#include <initializer_list>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QToolButton;
class QSpinBox;
class QTimer;

namespace xyt::ui {

class DesignSpacePlot;
class StaleVeil;

/**
 * The design-space study of Braga et al. for the presenter's current axis: a grid of
 * (wn, kp) designs evaluated by the core (sweepDesignSpace) on a worker thread, shown as a heat
 * map (DesignSpacePlot). Clicking a cell loads that design into the session as one undo step.
 *
 * The study runs off the GUI thread; progress arrives through the core's callback, queued to
 * this widget. Run while a study runs cancels it first; Cancel stops it after the points being
 * computed; destroying the widget cancels and joins.
 *
 * Live map (on by default): while the view is visible, a change of what the study
 * depends on (the axis, its plant, the trajectory, the actuator limit, the settle limit and
 * in-position window, the grid) starts a preview at once, at most 50 x 50 designs coarse in
 * time (kLivePreviewFidelity), cancelling the study under way; when the inputs have rested for
 * kLiveRestMs the full study (the grid at the session's dt) follows. A change of wn or kp only
 * moves the design marker; a change of the other limits judges the map again. The workers run
 * at a lower priority than the GUI thread, so the sliders stay as fast as without the map.
 *
 * A map keeps the stamp of the study settings it was computed for. When they no longer match
 * the session (another plant, method or axis, File › New, a study finishing after a change),
 * the map is veiled with what it was computed for, its cells neither load nor describe a
 * design, and, Live on, a new study starts.
 */
class DesignSpaceView : public QWidget {
    Q_OBJECT
public:
    explicit DesignSpaceView(TuningSession* session, QWidget* parent = nullptr);
    ~DesignSpaceView() override;

    /// Starts a study of the current axis with the settings of the controls (cancels a running
    /// one).
    void run();
    /// How the next study is computed: the live preview or the full study.
    enum class StudyKind { Preview, Full };
    static constexpr int kLivePreviewCount = 50; ///< designs per side of the preview, at most
    static constexpr int kLiveRestMs = 400;      ///< rest before the full study follows
    /// Asks the running study to stop; its partial result is shown when it has stopped.
    void cancel();
    bool isRunning() const { return runner_.isRunning(); }
    /// True when a map is shown and describes the session's current axis and study settings.
    bool resultIsCurrent() const;
    /// The cover over a stale map, with what it was computed for.
    StaleVeil* veil() const { return veil_; }

    /// The last finished study (partial when cancelled).
    const std::optional<DesignSweepResult>& result() const { return result_; }
    /// The shown result is a live preview (the full study has not replaced it yet).
    bool resultIsPreview() const { return resultIsPreview_; }
    /// Wall time of the last finished study or preview, in ms.
    double lastElapsedMs() const { return lastElapsedMs_; }
    /// Kind of the study under way (meaningful while isRunning()).
    StudyKind runningKind() const { return runningKind_; }
    QCheckBox* liveBox() const { return live_; }
    /// The problem of the last finished study, and the axis it was for.
    const std::optional<DesignProblem>& studiedProblem() const { return problem_; }
    int studiedAxis() const { return stamp_ ? stamp_->axis : session_->currentAxis(); }

    DesignSpacePlot* plot() const { return plot_; }
    QPushButton* runButton() const { return run_; }
    QPushButton* cancelButton() const { return cancel_; }
    /// Shown when no design is feasible and the diagnosis offers a relaxed specification.
    QPushButton* relaxButton() const { return relax_; }
    QProgressBar* progressBar() const { return progress_; }
    QToolButton* settingsButton() const { return settings_; }
    QScrollArea* controlPanel() const { return controlPanel_; }
    QLabel* statusLabel() const { return status_; }
    QString statusText() const;
    QString readoutText() const;
    QDoubleSpinBox* wnMinBox() const { return wnMin_; }
    QDoubleSpinBox* wnMaxBox() const { return wnMax_; }
    QSpinBox* wnCountBox() const { return wnCount_; }
    QDoubleSpinBox* kpMinBox() const { return kpMin_; }
    QDoubleSpinBox* kpMaxBox() const { return kpMax_; }
    QSpinBox* kpCountBox() const { return kpCount_; }
    QCheckBox* logGridBox() const { return logGrid_; }
    QComboBox* criterionBox() const { return criterion_; }
    QComboBox* metricBox() const { return metric_; }
    QCheckBox* logColorBox() const { return logColor_; }
    QDoubleSpinBox* settlingBox() const { return settling_; }
    QDoubleSpinBox* overshootBox() const { return overshoot_; }
    QDoubleSpinBox* errorBox() const { return error_; }
    QDoubleSpinBox* umaxBox() const { return umax_; }
    QDoubleSpinBox* phaseMarginBox() const { return phaseMargin_; }
    QDoubleSpinBox* gainMarginBox() const { return gainMargin_; }

signals:
    /// A study or a preview finished (completed or cancelled) and its result is shown.
    void studyFinished(xyt::ui::DesignSpaceView::StudyKind kind);

protected:
    void showEvent(QShowEvent* event) override;
    /// Hides the controls while the view is narrower than kWideEnoughForSettings, until the
    /// user shows or hides them.
    void resizeEvent(QResizeEvent* event) override;
    /// Wheel events over an unfocused field of the control panel scroll the panel.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// What a study computes, with the inputs it was computed from.
    struct Outcome {
        DesignSweepResult result;
        DesignProblem problem;
        StudyKind kind = StudyKind::Full;
        bool logGrid = true;
        double elapsedMs = 0.0;
    };

    // The constructor's steps, in the order the widgets are made (their tab order).
    QGroupBox* buildGrid();
    QGroupBox* buildChoice();
    QGroupBox* buildSpecification(const Specification& spec);
    /// Settings, Live, Run, Cancel, Relax and the progress: the row at the top of the tab.
    QHBoxLayout* buildActions();
    /// The scrolling column of @p groups beside the map.
    void buildControlPanel(std::initializer_list<QGroupBox*> groups);
    /// The map, its veil, and the status and hover strips under it (returned).
    QHBoxLayout* buildMapAndTexts();
    void connectControls();

    void startStudy(StudyKind kind);
    /// Starts a preview when live, visible, and the map shown (or under way) is not of the
    /// session's current study settings; @p force: also when it is (the grid changed).
    void scheduleLive(bool force = false);
    void onRest();
    void onFinished(Outcome&& outcome, const ResultStamp& stamp);
    /// Veils a map that no longer describes the session's study, lifts the veil when it does.
    void showFreshness();
    void showOutcome();
    void showOutcomeText();
    void updateCurrentDesign();
    void applySpecification();
    void relaxSpecification();
    void showHover(std::optional<std::pair<std::size_t, std::size_t>> cell);
    void loadCell(std::size_t iWn, std::size_t iKp);
    void setStatus(const QString& text, bool isError = false);

    TuningSession* session_;
    std::optional<DesignSweepResult> result_;
    std::optional<DesignProblem> problem_;
    std::optional<ResultStamp> stamp_; ///< what the shown map was computed for
    StudyKind runningKind_ = StudyKind::Full;
    bool staleStatus_ = false; ///< the status says the map is stale (not the outcome)
    bool studiedLogGrid_ = true;
    double lastUmaxVolts_ = 0.0;
    bool resultIsPreview_ = false;
    double lastElapsedMs_ = 0.0;
    QCheckBox* live_ = nullptr;
    QTimer* rest_ = nullptr;

    DesignSpacePlot* plot_;
    QLabel* readout_;
    QScrollArea* controlPanel_ = nullptr;
    QToolButton* settings_ = nullptr; ///< shows or hides controlPanel_
    bool settingsChosen_ = false;     ///< the user toggled settings_: no longer by width
    /// Width (px) from which the controls are shown beside the map by default: below it the
    /// map (about 250 px narrower with them) would be too small to point at a cell.
    static constexpr int kWideEnoughForSettings = 640;
    QPushButton* relax_ = nullptr;
    std::optional<SweepDiagnosis> diagnosis_;
    QLabel* status_;
    QPushButton* run_;
    QPushButton* cancel_;
    QProgressBar* progress_;
    QDoubleSpinBox* wnMin_;
    QDoubleSpinBox* wnMax_;
    QSpinBox* wnCount_;
    QDoubleSpinBox* kpMin_;
    QDoubleSpinBox* kpMax_;
    QSpinBox* kpCount_;
    QCheckBox* logGrid_;
    QComboBox* criterion_;
    QComboBox* metric_;
    QCheckBox* logColor_;
    QDoubleSpinBox* settling_;
    QDoubleSpinBox* overshoot_;
    QDoubleSpinBox* error_;
    QDoubleSpinBox* umax_;
    QDoubleSpinBox* phaseMargin_;
    QDoubleSpinBox* gainMargin_;
    StaleVeil* veil_ = nullptr;
    JobRunner<Outcome, ResultStamp> runner_; ///< last: destroyed first, before the widgets
};

/// The specification the view starts with for @p session: the session's (the paper's by
/// default: overshoot 0 %), with the session's actuator limit.
Specification initialSpecification(const Session& session);

} // namespace xyt::ui
