// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLineEdit>

#include <functional>

namespace xyt::ui {

/**
 * A line edit for one number. The text is parsed by the core's parser and checked by an optional
 * validator (which throws xyt::InvalidInput); an invalid entry is shown at the field (red frame,
 * tooltip with the reason), never applied, and `valueAccepted` is emitted only for valid ones.
 *
 * The decimal separator is the point, in every language (engineering convention; session files
 * and exports are C-locale), and a comma is accepted as well: "1,5" is 1.5, as a Brazilian or
 * European user types it (withDecimalPoint). A single number has no other use for a comma.
 */
class NumberField : public QLineEdit {
    Q_OBJECT
public:
    using Validator = std::function<void(double)>;
    NumberField(const QString& fieldName, Validator validator = {}, QWidget* parent = nullptr);

    double value() const { return value_; }
    /// Shows @p v without emitting valueAccepted.
    void setValue(double v);
    bool hasError() const { return hasError_; }
    QString errorText() const { return errorText_; }
    /// Parses and validates the current text: emits valueAccepted or shows the error.
    bool commit();

signals:
    void valueAccepted(double value);

private:
    void showError(const QString& message);
    void clearError();

    QString fieldName_;
    Validator validator_;
    double value_ = 0.0;
    bool hasError_ = false;
    QString errorText_;
    QString normalToolTip_;
};

/// Shows an input error at a line edit: red frame and the reason as its tooltip.
void markFieldError(QLineEdit* field, const QString& message);
/// Removes the error marking (the tooltip becomes @p normalToolTip).
void clearFieldError(QLineEdit* field, const QString& normalToolTip);

/// @p text with each decimal comma made a point ("1,5e-3" -> "1.5e-3"): what NumberField parses.
QString withDecimalPoint(QString text);

/// Formats a number for display with up to 10 significant digits.
QString formatNumber(double v);

} // namespace xyt::ui
