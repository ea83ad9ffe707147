// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/study/design_sweep.h"
#include "core/study/sweep_diagnosis.h"
#include "core/session/session.h"

#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>
#include <thread>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSpinBox;

namespace xyt::ui {

class DesignSpacePlot;
class TuningSession;

/**
 * The design-space study of paper 000 (issue 7) for the presenter's current axis: a grid of
 * (wn, kp) designs evaluated by the core (sweepDesignSpace) on a worker thread, shown as a heat
 * map (DesignSpacePlot). Clicking a cell loads that design into the session as one undo step.
 *
 * The study runs off the GUI thread; progress arrives through the core's callback, queued to
 * this widget. Run while a study runs cancels it first; Cancel stops it after the points being
 * computed; destroying the widget cancels and joins.
 */
class DesignSpaceView : public QWidget {
    Q_OBJECT
public:
    explicit DesignSpaceView(TuningSession* session, QWidget* parent = nullptr);
    ~DesignSpaceView() override;

    /// Starts a study of the current axis with the settings of the controls (cancels a running one).
    void run();
    /// Asks the running study to stop; its partial result is shown when it has stopped.
    void cancel();
    bool isRunning() const { return job_ != nullptr; }

    /// The last finished study (partial when cancelled).
    const std::optional<DesignSweepResult>& result() const { return result_; }
    /// The problem of the last finished study, and the axis it was for.
    const std::optional<DesignProblem>& studiedProblem() const { return problem_; }
    int studiedAxis() const { return studiedAxis_; }

    DesignSpacePlot* plot() const { return plot_; }
    QPushButton* runButton() const { return run_; }
    QPushButton* cancelButton() const { return cancel_; }
    /// Shown when no design is feasible and the diagnosis offers a relaxed specification.
    QPushButton* relaxButton() const { return relax_; }
    QProgressBar* progressBar() const { return progress_; }
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

protected:
    /// Wheel events over an unfocused field of the control panel scroll the panel.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Job {
        int id = 0;
        std::atomic<bool> cancel{false};
        std::thread thread;
    };

    void stopJob();
    void onProgress(int jobId, double fraction);
    void onFinished(int jobId, std::shared_ptr<DesignSweepResult> result, QString error);
    void showOutcome();
    void updateCurrentDesign();
    void applySpecification();
    void relaxSpecification();
    void showHover(std::optional<std::pair<std::size_t, std::size_t>> cell);
    void loadCell(std::size_t iWn, std::size_t iKp);
    void setStatus(const QString& text, bool isError = false);

    TuningSession* session_;
    std::unique_ptr<Job> job_;
    int lastJobId_ = 0;
    std::optional<DesignSweepResult> result_;
    std::optional<DesignProblem> problem_;
    std::optional<DesignProblem> pendingProblem_;
    Session studiedSession_;
    Session pendingSession_;
    int studiedAxis_ = 0;
    int pendingAxis_ = 0;
    bool studiedLogGrid_ = true;
    bool pendingLogGrid_ = true;
    double lastUmaxVolts_ = 0.0;

    DesignSpacePlot* plot_;
    QLabel* readout_;
    QScrollArea* controlPanel_ = nullptr;
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
};

/// The specification the view starts with for @p session: the session's (the paper's by
/// default: overshoot 0 %), with the session's actuator limit.
Specification initialSpecification(const Session& session);

} // namespace xyt::ui
