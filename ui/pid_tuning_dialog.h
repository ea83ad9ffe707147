// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pid_tuning.h"
#include "core/design/relay_experiment.h"
#include "core/session/session.h"

#include <QDialog>

#include <array>
#include <optional>

class QComboBox;
class QCustomPlot;
class QLabel;
class QPushButton;
class QTableWidget;

namespace xyt::ui {

class NumberField;
class TuningSession;

/// The feedback gains a tuning rule proposes (LinuxCNC units, position in mm).
struct ProposedGains {
    QString rule;
    bool ok = false;
    QString reason; ///< when !ok
    double p = 0.0, i = 0.0, d = 0.0;
    double crossoverRadPerSec = 0.0, phaseMarginDeg = 0.0; ///< of the loop they give
};

/**
 * Tuning rules for the feedback of a PID + feedforward axis, side by side: PI or PID from a
 * target crossover and phase margin in closed form on the axis' model (tunePidForMargin), and a
 * simulated relay experiment (Åström and Hägglund) with the gains Ziegler–Nichols and
 * Tyreus–Luyben give from its limit cycle, as a relay autotune on the machine would. Each row
 * is applied to the axis as one undo step (its P, I, D; the feedforward is kept). The relay's
 * limit cycle is drawn; the exact period and amplitude are shown with the describing
 * function's estimate.
 */
class PidTuningDialog : public QDialog {
    Q_OBJECT
public:
    PidTuningDialog(TuningSession* session, int axis, QWidget* parent = nullptr);

    /// The rows: 0 the crossover rule, 1 Ziegler–Nichols, 2 Tyreus–Luyben.
    const ProposedGains& proposal(int row) const;
    NumberField* crossoverField() const { return crossover_; }
    NumberField* phaseMarginField() const { return phaseMargin_; }
    NumberField* relayField() const { return relay_; }
    QComboBox* structureBox() const { return structure_; }
    QPushButton* applyButton(int row) const;
    QCustomPlot* relayPlot() const { return plot_; }
    QString relayText() const;
    /// Recomputes every row from the fields (called on each accepted edit).
    void recompute();

private:
    void apply(int row);

    TuningSession* session_;
    int axis_;
    ThirdOrderPlant plant_;
    double unit_ = 0.001;
    QComboBox* structure_;
    NumberField* crossover_;
    NumberField* phaseMargin_;
    NumberField* relay_;
    QTableWidget* table_;
    std::array<QPushButton*, 3> apply_{};
    std::array<ProposedGains, 3> rows_;
    QLabel* relayLabel_;
    QCustomPlot* plot_;
};

} // namespace xyt::ui
