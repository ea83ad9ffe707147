// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/coupling_sweep.h"
#include "ui/jobs/job_runner.h"
#include "ui/session/tuning_session.h"

#include <QDialog>
#include <QElapsedTimer>

#include <cstddef>
#include <memory>
#include <optional>

class QCPColorMap;
class QCPColorScale;
class QCPGraph;
class QCPItemRect;
class QCPItemText;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace xyt::ui {

class PlotWidget;
class StaleVeil;

/**
 * The cross-coupling's gains tuned by the contour error ("Tune…" in the Cross-coupling fold):
 * the session's contour run once for each (kp, ki) of a small grid (sweepSessionCoupling, on
 * the session as it is when the sweep starts, in the background with a progress bar and Cancel)
 * and drawn as a heat map of the max contour error over the grid (log colour scale; refused,
 * failed and saturating cells marked, the best cell starred, the independent axes' figure
 * beside it). A cell's figures show on hover; a click selects it and Apply sets its gains as
 * the session's cross-coupling (one undo step). A result whose session has changed since (in
 * anything but the swept gains, sameCouplingSweepInputs) is veiled as stale, with Apply off.
 */
class CouplingSweepDialog : public QDialog {
    Q_OBJECT
public:
    explicit CouplingSweepDialog(TuningSession* session, QWidget* parent = nullptr);
    ~CouplingSweepDialog() override;

    /// Starts a sweep of the session as it is over the grid of the fields (a running one is
    /// dropped); false (nothing started) when a field's list is refused, said at the field.
    bool run();
    /// What "Tune…" does: a sweep of the session as it is, unless the last result or the
    /// running sweep is for it already.
    void runUnlessCurrent();
    /// Asks the running sweep to stop; what ran is delivered and drawn, marked cancelled.
    void cancel();
    bool isRunning() const { return runner_->isRunning(); }
    /// The last sweep's result (cancelled ones included).
    const std::optional<CouplingSweepResult>& result() const { return result_; }
    /// The last sweep describes the session as it is now.
    bool isCurrent() const;
    /// Why the last run failed ("" when it did not).
    QString failureText() const { return failure_; }

    std::optional<std::size_t> selectedCell() const { return selected_; }
    /// Selects a cell of the result (what a click on the map does).
    void selectCell(std::size_t index);
    /// Sets the selected cell's gains as the session's cross-coupling (one undo step); false
    /// (nothing changed) without a current result or a selected cell that ran.
    bool apply();

    /// What the map shows for cell @p index on hover.
    QString cellToolTip(std::size_t index) const;
    /// The cell of the result under a pixel of the map, when inside the grid.
    std::optional<std::size_t> cellAtPixel(const QPointF& pixel) const;
    /// The centre of cell @p index in the map's pixels.
    QPointF pixelOfCell(std::size_t index) const;
    /// The tooltip the last hover showed ("" off the grid).
    QString hoverText() const { return hover_; }

    QLineEdit* kpListField() const { return kpList_; }
    QLineEdit* kiListField() const { return kiList_; }
    QPushButton* runButton() const { return run_; }
    QPushButton* cancelButton() const { return cancel_; }
    QPushButton* applyButton() const { return apply_; }
    QProgressBar* progressBar() const { return progress_; }
    PlotWidget* plot() const { return plot_; }
    QCPColorMap* colorMap() const { return map_; }
    QCPColorScale* colorScale() const { return scale_; }
    QCPGraph* bestMarker() const { return best_; }
    QCPGraph* unstableMarkers() const { return unstable_; }
    QCPGraph* failedMarkers() const { return failed_; }
    QCPGraph* saturatedMarkers() const { return saturated_; }
    /// The independent axes, the best and the selected cell, in words.
    QString summaryText() const;
    QString statusText() const;
    QString fieldErrorText() const;
    StaleVeil* staleVeil() const { return veil_; }

protected:
    void reject() override;

private:
    void finished(CouplingSweepResult&& result, const ResultStamp& stamp);
    void failed(const QString& message, const ResultStamp& stamp);
    void draw();
    void showSelection();
    void updateState();
    void hover(const QPoint& pixel, const QPoint& global);

    TuningSession* session_;
    QLabel* subject_;
    QLineEdit* kpList_;
    QLineEdit* kiList_;
    QPushButton* run_;
    QLabel* fieldError_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    PlotWidget* plot_;
    QCPColorMap* map_;
    QCPColorScale* scale_;
    QCPGraph* unstable_;
    QCPGraph* failed_;
    QCPGraph* notRun_;
    QCPGraph* saturated_;
    QCPGraph* best_;
    QCPItemRect* selection_;
    std::vector<QCPItemText*> values_;
    StaleVeil* veil_;
    QLabel* status_;
    QLabel* summary_;
    QPushButton* apply_;

    std::optional<CouplingSweepResult> result_;
    ResultStamp stamp_; ///< what result_ was computed for
    std::optional<std::size_t> selected_;
    QString failure_;
    QString plotDescription_; ///< the map's tooltip away from a cell
    QString hover_;
    QElapsedTimer clock_;
    qint64 elapsedMs_ = 0;
    std::unique_ptr<JobRunner<CouplingSweepResult, ResultStamp>> runner_;
};

} // namespace xyt::ui
