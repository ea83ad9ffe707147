// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/friction_identification.h"

#include <QDialog>

#include <optional>

class QComboBox;
class QCPErrorBars;
class QCPGraph;
class QCustomPlot;
class QLabel;
class QPushButton;

namespace xyt::ui {

class TuningSession;

/**
 * Design › Friction curve from a jog log: the Stribeck curve of an axis measured with
 * constant-velocity jogs (xytune-cli excite --signal jog, or a machine's log with time,
 * reference, position and command columns). Draws each jog's steady command against its
 * velocity with its standard deviation and the fitted curve (identifyFriction), gives the levels
 * with their standard deviations and the slope against the model's own a2/k0, and sets them as
 * the current axis' table friction (one undo step): the Coulomb level, the viscous friction
 * beyond the model's damping, and the static level and Stribeck velocity when the data held them.
 */
class FrictionCurveDialog : public QDialog {
    Q_OBJECT

public:
    FrictionCurveDialog(TuningSession* session, QWidget* parent = nullptr);
    /// Reads @p path and estimates (what "Open log…" does after its file dialog).
    void loadFile(const QString& path);

    QComboBox* columnBox(int which) const { return columns_[which]; } ///< t, r, y, u
    QCustomPlot* plot() const { return plot_; }
    QCPGraph* pointsGraph() const { return points_; }
    QLabel* resultLabel() const { return result_; }
    QPushButton* applyButton() const { return apply_; }
    const std::optional<FrictionEstimate>& estimate() const { return estimate_; }

private:
    void runEstimate();
    void draw();
    void apply();

    TuningSession* session_;
    QString path_;
    QLabel* file_;
    QComboBox* columns_[4];
    QCustomPlot* plot_;
    QCPGraph* points_;
    QCPErrorBars* bars_;
    QCPGraph* forward_;
    QCPGraph* backward_;
    QLabel* result_;
    QPushButton* apply_;
    std::vector<std::string> names_;
    std::vector<std::vector<double>> data_;
    std::optional<FrictionEstimate> estimate_;
};

} // namespace xyt::ui
