// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/number_field.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"
#include "ui/session/diagnostic_text.h"

namespace xyt::ui {

QString formatNumber(double v) {
    return QString::number(v, 'g', 10);
}

QString withDecimalPoint(QString text) {
    return text.replace(QLatin1Char(','), QLatin1Char('.'));
}

NumberField::NumberField(const QString& fieldName, Validator validator, QWidget* parent)
    : QLineEdit(parent), fieldName_(fieldName), validator_(std::move(validator)) {
    setAccessibleName(fieldName);
    connect(this, &QLineEdit::editingFinished, this, &NumberField::commit);
    connect(this, &QLineEdit::textEdited, this, [this] {
        if (hasError_)
            clearError();
    });
}

void NumberField::setValue(double v) {
    value_ = v;
    clearError();
    setText(formatNumber(v));
}

bool NumberField::commit() {
    try {
        const double v =
            parseNumber(withDecimalPoint(text()).toStdString(), fieldName_.toStdString());
        if (validator_)
            validator_(v);
        clearError();
        value_ = v;
        emit valueAccepted(v);
        return true;
    } catch (const InvalidInput& e) {
        showError(diagnosticText(e.reasonDiagnostic()));
        return false;
    }
}

void markFieldError(QLineEdit* field, const QString& message) {
    field->setStyleSheet(
        QStringLiteral("QLineEdit { border: 2px solid #d32f2f; background: #fff3f3; }"));
    field->setToolTip(message);
}

void clearFieldError(QLineEdit* field, const QString& normalToolTip) {
    field->setStyleSheet(QString());
    field->setToolTip(normalToolTip);
}

void NumberField::showError(const QString& message) {
    if (!hasError_)
        normalToolTip_ = toolTip();
    hasError_ = true;
    errorText_ = tr("%1: %2").arg(fieldName_, message);
    markFieldError(this, errorText_);
}

void NumberField::clearError() {
    if (!hasError_)
        return;
    hasError_ = false;
    errorText_.clear();
    clearFieldError(this, normalToolTip_);
}

} // namespace xyt::ui
