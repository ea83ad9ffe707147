// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QLabel>

namespace xyt::ui {

/// The design equations of the current axis with the current numbers, for teaching: f1, f2, f3,
/// psi1, psi2, G_R(s), G_c(s) (paper 000 Eq. 7, 11-18).
class EquationsPanel : public QLabel {
    Q_OBJECT
public:
    explicit EquationsPanel(QWidget* parent = nullptr);
    void showAxis(const AxisSettings& settings, const AxisEvaluation& axis);
};

/// HTML of a polynomial in z^-1, ascending powers as typed in paper 001.
QString zInverseHtml(const Polynomial& p);
/// HTML of a polynomial in @p variable with superscript powers.
QString polynomialHtml(const Polynomial& p, const QString& variable);

} // namespace xyt::ui
