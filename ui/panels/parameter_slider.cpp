// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/parameter_slider.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"
#include "ui/panels/number_field.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace xyt::ui {

namespace {

constexpr int kSteps = 1000;

/// The label as a user reads it: "ω&n" -> "ωn" ("&&" stands for one '&').
QString withoutMnemonic(const QString& label) {
    QString out;
    for (int i = 0; i < label.size(); ++i) {
        if (label[i] == '&' && i + 1 < label.size())
            ++i;
        out += label[i];
    }
    return out;
}

/**
 * A spin box whose text is read by the line edits' parser (parseNumber), so "1e9", "2.5E-3" and
 * "1000000000" mean what they say. Any text can be typed (a partial "1e" must be allowed); what
 * is not a number in range when the entry ends is handed to onRefused and the value stays.
 * QDoubleSpinBox rounds to decimals() places: 15 keeps every typed value of the parameters'
 * ranges exactly (the slider's values have 4 significant digits).
 */
class NotationSpinBox : public QDoubleSpinBox {
public:
    explicit NotationSpinBox(QWidget* parent) : QDoubleSpinBox(parent) { setDecimals(15); }
    std::function<void(const QString&)> onRefused;

    QValidator::State validate(QString& input, int&) const override {
        return parse(input) ? QValidator::Acceptable : QValidator::Intermediate;
    }
    double valueFromText(const QString& text) const override {
        return parse(text).value_or(value());
    }
    QString textFromValue(double v) const override { return formatNumber(v); }
    void fixup(QString& input) const override {
        // Called when the entry ends on text that validate() did not accept: say why, once the
        // spin box has put its value back.
        if (onRefused && !input.trimmed().isEmpty())
            onRefused(stripped(input));
    }

private:
    QString stripped(const QString& input) const {
        QString t = input;
        if (!suffix().isEmpty() && t.endsWith(suffix()))
            t.chop(suffix().size());
        return t.trimmed();
    }
    std::optional<double> parse(const QString& input) const {
        try {
            const double v = parseNumber(stripped(input).toStdString(), "value");
            if (v < minimum() || v > maximum())
                return std::nullopt;
            return v;
        } catch (const InvalidInput&) {
            return std::nullopt;
        }
    }
};

} // namespace

ParameterSlider::ParameterSlider(const QString& label, const QString& unit, double minimum,
                                 double maximum, bool logScale, QWidget* parent)
    : QWidget(parent), min_(minimum), max_(maximum), log_(logScale), name_(withoutMnemonic(label)) {
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* name = new QLabel(label, this);
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setRange(0, kSteps);
    slider_->setTracking(true);
    slider_->setAccessibleName(name_);
    auto* spin = new NotationSpinBox(this);
    spin_ = spin;
    spin_->setRange(minimum, maximum);
    spin_->setSingleStep(logScale ? minimum : (maximum - minimum) / 100.0);
    spin_->setKeyboardTracking(false);
    spin_->setSuffix(unit.isEmpty() ? QString() : " " + unit);
    spin_->setAccessibleName(name_ + tr(" value"));
    describe();
    spin_->setMinimumWidth(110);
    spin->onRefused = [this](const QString& text) { refuse(text); };
    exact_ = new QLabel(this);
    exact_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    exact_->setStyleSheet("color: palette(mid);");
    name->setBuddy(spin_);
    layout->addWidget(name, 0, 0);
    layout->addWidget(exact_, 0, 1, Qt::AlignRight);
    layout->addWidget(slider_, 1, 0);
    layout->addWidget(spin_, 1, 1);
    layout->setColumnStretch(0, 1);

    connect(slider_, &QSlider::valueChanged, this, [this](int position) {
        if (updating_)
            return;
        const double v = fromPosition(position);
        showValue(v);
        emit valueChanged(v);
    });
    connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (updating_)
            return;
        showValue(v);
        emit valueChanged(v);
    });
}

void ParameterSlider::setFieldRange(double minimum, double maximum) {
    const QSignalBlocker block(spin_);
    spin_->setRange(std::min(minimum, min_), std::max(maximum, max_));
}

int ParameterSlider::toPosition(double v) const {
    const double f = log_ ? std::log(v / min_) / std::log(max_ / min_) : (v - min_) / (max_ - min_);
    return static_cast<int>(std::lround(std::clamp(f, 0.0, 1.0) * kSteps));
}

double ParameterSlider::fromPosition(int position) const {
    const double f = static_cast<double>(position) / kSteps;
    const double v = log_ ? min_ * std::pow(max_ / min_, f) : min_ + f * (max_ - min_);
    // Round to 4 significant digits so dragged values read cleanly (30, not 29.9734).
    const double magnitude = std::pow(10.0, std::floor(std::log10(std::abs(v))) - 3);
    return std::clamp(std::round(v / magnitude) * magnitude, min_, max_);
}

QString ParameterSlider::exactText() const {
    return exact_->text();
}

void ParameterSlider::showValue(double v) {
    value_ = v;
    clearFieldError();
    updating_ = true;
    slider_->setValue(toPosition(v));
    spin_->setValue(v);
    const bool beyond = v < min_ || v > max_;
    exact_->setText(beyond ? tr("%1, beyond the slider (%2 to %3)")
                                 .arg(formatNumber(v), formatNumber(min_), formatNumber(max_))
                           : QString::number(v, 'g', 10));
    // Only when it changes: a new style sheet re-polishes the label and lays the window out again.
    const QString style =
        beyond ? QStringLiteral("color: #b26a00;") : QStringLiteral("color: palette(mid);");
    if (exact_->styleSheet() != style)
        exact_->setStyleSheet(style);
    updating_ = false;
}

void ParameterSlider::refuse(const QString& text) {
    fieldError_ =
        tr("%1: '%2' is not a number from %3 to %4")
            .arg(name_, text, formatNumber(spin_->minimum()), formatNumber(spin_->maximum()));
    if (QLineEdit* edit = spin_->findChild<QLineEdit*>())
        markFieldError(edit, fieldError_);
    spin_->setToolTip(fieldError_);
}

void ParameterSlider::clearFieldError() {
    if (fieldError_.isEmpty())
        return;
    fieldError_.clear();
    if (QLineEdit* edit = spin_->findChild<QLineEdit*>())
        xyt::ui::clearFieldError(edit, QString());
    describe();
}

void ParameterSlider::setDescription(const QString& description) {
    description_ = description;
    if (fieldError_.isEmpty())
        describe();
}

void ParameterSlider::describe() {
    const QString what = description_.isEmpty() ? name_ : description_;
    slider_->setToolTip(log_ ? tr("%1 (logarithmic scale)").arg(what) : what);
    spin_->setToolTip(
        tr("%1\nType a value (scientific notation such as 2.5e3 is accepted).").arg(what));
}

void ParameterSlider::setValue(double v) {
    if (!std::isfinite(v))
        return;
    if (v < spin_->minimum() ||
        v > spin_->maximum()) { // a loaded value the field must show as it is
        const QSignalBlocker block(spin_);
        spin_->setRange(std::min(spin_->minimum(), v), std::max(spin_->maximum(), v));
    }
    showValue(v);
}

} // namespace xyt::ui
