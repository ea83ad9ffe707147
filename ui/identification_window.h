// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_data.h"
#include "core/identification/experiment_table.h"
#include "core/identification/identification.h"
#include "core/identification/io_data.h"
#include "ui/jobs/job_runner.h"

#include <QDialog>
#include <QStringList>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QCPGraph;
class QCPCurve;
class QCustomPlot;
class QDoubleSpinBox;
class QGroupBox;
class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QTableWidget;
class QTabWidget;
class QUndoCommand;

namespace xyt::ui {

class PlotNotice;
class PoleZeroPlot;
class TuningSession;

/**
 * "Identify a model from data": loads an experiment file (CSV/TSV, .lvm, .mat),
 * picks the input, output and time columns, preprocesses (range, detrend, decimate), and runs
 * the core's identifyModel for the chosen structure on a worker thread with progress and cancel.
 * Every fit becomes a row of the candidates table (fits, AIC, residual tests, NMP) so that
 * several models can be compared; the selected one is drawn: measured and simulated output,
 * the residual correlations with their bounds, the z-plane pole-zero map. "Use for axis X/Y"
 * makes it the axis' plant in one undo step (axisWithIdentifiedModel). The window computes
 * nothing itself: it shows the core's IdentifiedModel.
 */
class IdentificationWindow : public QDialog {
    Q_OBJECT
public:
    /// One fitted model with the data it was fitted to (after the preprocessing).
    struct Candidate {
        IdentifiedModel model;
        IoData estimation;
        std::optional<IoData> validation;
        QStringList
            notes;       ///< what the window did to the data (e.g. the initial position taken off)
        QString message; ///< the fit's report, shown again whenever its row is selected
        bool messageIsError = false;
    };

    explicit IdentificationWindow(TuningSession* session, QWidget* parent = nullptr);
    ~IdentificationWindow() override;

    /// Reads @p path as the estimation data and fills the column choices; false (and the
    /// core's message in the status line) when it cannot be read. The candidates of the file
    /// loaded before are cleared (each candidate belongs to the data it was fitted to); the
    /// record is drawn at once, with its sample time and time range in their fields.
    bool loadFile(const QString& path);
    /// Reads @p path as the validation data (same column names); "" removes it.
    bool loadValidationFile(const QString& path);
    /// Starts a fit of the chosen structure (on a worker thread).
    void fit();
    void cancel();
    /// Makes the selected candidate the plant of axis @p axis (0 = X, 1 = Y): one undo step.
    void useForAxis(int axis);
    /// Welch's estimate of the record's y/u (its columns, range and preprocessing as a fit
    /// takes them), handed to the workbench as axis @p axis' measured response; false, with the
    /// reason in the status line, when the record cannot give one.
    bool showFrequencyResponse(int axis);
    bool isRunning() const { return runner_.isRunning(); }

    const std::vector<Candidate>& candidates() const { return candidates_; }
    /// The candidate shown in the plots, or null.
    const Candidate* selectedCandidate() const;
    QString statusText() const;

    QPushButton* loadButton() const { return load_; }
    QPushButton* validationButton() const { return loadValidation_; }
    QPushButton* fitButton() const { return fit_; }
    QPushButton* cancelButton() const { return cancel_; }
    QPushButton* useXButton() const { return useX_; }
    QPushButton* useYButton() const { return useY_; }
    QPushButton* frequencyResponseButton(int axis) const {
        return axis == 0 ? frequencyX_ : frequencyY_;
    }
    QComboBox* inputBox() const { return input_; }
    QComboBox* outputBox() const { return output_; }
    QComboBox* timeBox() const { return time_; }
    QComboBox* unitBox() const { return unit_; }
    QComboBox* structureBox() const { return structure_; }
    QDoubleSpinBox* sampleTimeBox() const { return ts_; }
    QDoubleSpinBox* rangeStartBox() const { return t0_; }
    QDoubleSpinBox* rangeEndBox() const { return t1_; }
    QCheckBox* detrendBox() const { return detrend_; }
    QSpinBox* decimateBox() const { return decimate_; }
    QSpinBox* maxIterationsBox() const { return maxIterations_; }
    /// The order box "na", "nb", "nc", "nd", "nf" or "nk", or null.
    QSpinBox* orderBox(const QString& name) const;
    QTableWidget* candidateTable() const { return table_; }
    QProgressBar* progressBar() const { return progress_; }
    QLabel* fileLabel() const { return fileName_; }
    /// The selected candidate's parameters with their standard deviations ("a1 = -1.658 ± 0.0012
    /// ..."), empty without a selection.
    QString parametersText() const;

    QCustomPlot* timePlot() const { return timePlot_; }
    QCPGraph* measuredGraph() const { return measured_; }
    QCPGraph* simulatedGraph() const { return simulated_; }
    QCustomPlot* residualPlot() const { return residualPlot_; }
    QCPGraph* autocorrelationGraph() const { return autoStems_; }
    QCPGraph* crossCorrelationGraph() const { return crossStems_; }
    PoleZeroPlot* poleZeroPlot() const { return pzPlot_; }
    /// The notes under the pole-zero map (integrator, instability, NMP zeros).
    QString poleZeroNoticeText() const;
    /// The model's poles and zeros on the map (nullptr while no model is shown).
    QCPGraph* polesGraph() const;
    QCPGraph* zerosGraph() const;
    QTabWidget* plotTabs() const { return tabs_; }

signals:
    /// A fit ended (with a candidate, an error or a cancel).
    void fitFinished();

private:
    // The constructor's steps, in the order the widgets are made (their tab order).
    /// File, columns, sample time, unit, range, preprocessing and validation data.
    QGroupBox* buildDataBox();
    /// Structure, orders, iterations, Fit, Cancel and the progress.
    QGroupBox* buildModelBox();
    /// The message area (at most five lines, scrolling beyond).
    QScrollArea* buildStatus();
    /// The candidates' table, the selected estimate and the "Use for axis" row (returned).
    QHBoxLayout* buildCandidates();
    void connectControls();
    void buildPlots();
    void updateOrderBoxes();
    void setStatus(const QString& text, bool isError = false);
    /// A fit ended: @p candidate is what it was fitted to, @p model what it found.
    void onFinished(IdentifiedModel&& model, const Candidate& candidate);
    void onFailed(const QString& error);
    void addRow(const Candidate& c);
    void showCandidate(int index);
    void clearPlots(const QString& reason);
    /// Draws the loaded record as the chosen columns make it (before any fit) and shows its
    /// sample time and time range; "" or the core's message when the columns cannot be used.
    QString previewRecord();
    /// The status of the selected candidate (its fit's report), or the opening prompt.
    void showSelectionStatus();
    ExperimentColumns columns(const ExperimentTable& table) const;
    /// The range boxes mean the whole record (0 to 0, or the range previewRecord showed).
    bool rangeIsWhole() const;
    /// The record of @p table with the chosen columns and preprocessing.
    /// @throws InvalidInput as the core does.
    IoData record(const ExperimentTable& table) const;

    TuningSession* session_;
    std::optional<ExperimentTable> experiment_;
    std::optional<ExperimentTable> validationExperiment_;
    std::vector<Candidate> candidates_;
    int shown_ = -1;
    /// The range boxes' values that mean the whole record (set by previewRecord).
    std::optional<std::array<double, 2>> wholeRange_;
    /// The undo step "Use for axis" made and the stack index after it: the status that names it
    /// is replaced once the step is undone or the stack cleared (File › New, Open).
    const QUndoCommand* usedStep_ = nullptr;
    int usedIndex_ = 0;

    QPushButton* load_;
    QPushButton* loadValidation_;
    QLabel* fileName_;
    QLabel* validationName_;
    QComboBox* input_;
    QComboBox* output_;
    QComboBox* time_;
    QDoubleSpinBox* ts_;
    QComboBox* unit_;
    QDoubleSpinBox* t0_;
    QDoubleSpinBox* t1_;
    QCheckBox* detrend_;
    QSpinBox* decimate_;
    QComboBox* structure_;
    std::vector<std::pair<QString, QSpinBox*>> orders_;
    QSpinBox* maxIterations_;
    QPushButton* fit_;
    QPushButton* cancel_;
    QProgressBar* progress_;
    QLabel* status_;
    QTableWidget* table_;
    QLabel* parameters_;
    QPushButton* useX_;
    QPushButton* useY_;
    QPushButton* frequencyX_;
    QPushButton* frequencyY_;
    QTabWidget* tabs_;
    QCustomPlot* timePlot_;
    QCPGraph* measured_;
    QCPGraph* simulated_;
    QCustomPlot* residualPlot_;
    QCPGraph* autoStems_;
    QCPGraph* autoBound_[2];
    QCPGraph* crossStems_;
    QCPGraph* crossBound_[2];
    PoleZeroPlot* pzPlot_;
    std::unique_ptr<PlotNotice> timeNotice_;
    std::unique_ptr<PlotNotice> residualNotice_;
    /// Last: destroyed first, before the widgets. A fit's stamp is the candidate it fits.
    JobRunner<IdentifiedModel, Candidate> runner_;
};

} // namespace xyt::ui
