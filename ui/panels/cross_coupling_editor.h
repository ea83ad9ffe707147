// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/cross_coupling.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace xyt::ui {

class NumberField;

/**
 * The "Cross-coupling" fold of the trajectory box: Koren's cross-coupled contouring controller
 * over both axes (Session::crossCoupling): its PI gains on the estimated contour error (0 and 0:
 * off) and the estimate (linear or circular). Folded, its header says whether it is on. A gain
 * the core refuses (validateCrossCoupling) stays at its field, red with the reason, and nothing
 * is applied. Below the fields, the coupled loop's stability on straight lines as the last
 * evaluation found it (setStability), and "Tune…", which asks for the sweep of the gains over
 * the contour error (tuneRequested: the window opens CouplingSweepDialog).
 */
class CrossCouplingEditor : public QWidget {
    Q_OBJECT
public:
    explicit CrossCouplingEditor(QWidget* parent = nullptr);
    void setCoupling(const CrossCoupling& coupling);
    /// The line under the fields: the coupled loop's stability and margins, or why there are
    /// none; empty hides it.
    void setStability(const QString& text, bool warning);

    NumberField* kpField() const { return kp_; }
    NumberField* kiField() const { return ki_; }
    QComboBox* estimateBox() const { return estimate_; }
    QToolButton* foldButton() const { return fold_; }
    QLabel* stabilityLabel() const { return stability_; }
    QPushButton* tuneButton() const { return tune_; }

signals:
    void couplingEdited(const CrossCoupling& coupling);
    /// "Tune…" was pressed.
    void tuneRequested();

private:
    void emitIfValid();
    void updateHeader();

    QToolButton* fold_;
    QWidget* body_;
    NumberField* kp_;
    NumberField* ki_;
    QComboBox* estimate_;
    QLabel* stability_;
    QPushButton* tune_;
    CrossCoupling coupling_;
};

} // namespace xyt::ui
