// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QTextBrowser>

namespace xyt::ui {

/**
 * The design equations of the current axis with the current numbers, for teaching: f1, f2, f3,
 * psi1, psi2, G_R(s), G_c(s) (Braga et al. Eq. 7, 11-18). A read-only text browser (it scrolls
 * itself): the numbers change with every slider step, and a word-wrapped rich-text label in a
 * scroll area re-laid its whole text out at several widths for each change (about 1.5 ms of
 * the step); the browser lays it out once, at its width.
 */
class EquationsPanel : public QTextBrowser {
    Q_OBJECT
public:
    explicit EquationsPanel(QWidget* parent = nullptr);
    void showAxis(const AxisSettings& settings, const AxisEvaluation& axis);
    /// The HTML shown (as given to it, not as QTextDocument re-exports it).
    QString text() const { return html_; }

private:
    void showHtml(const QString& html);
    QString html_;
};

/// HTML of a polynomial in z^-1, ascending powers as Patrick, Ishak and Adnan type them.
QString zInverseHtml(const Polynomial& p);
/// HTML of a polynomial in @p variable with superscript powers.
QString polynomialHtml(const Polynomial& p, const QString& variable);

} // namespace xyt::ui
