// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/parameter_slider.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {
constexpr int kSteps = 1000;
}

ParameterSlider::ParameterSlider(const QString& label, const QString& unit, double minimum,
                                 double maximum, bool logScale, QWidget* parent)
    : QWidget(parent), min_(minimum), max_(maximum), log_(logScale) {
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* name = new QLabel(label, this);
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setRange(0, kSteps);
    slider_->setTracking(true);
    slider_->setAccessibleName(label);
    slider_->setToolTip(logScale ? tr("%1 (logarithmic scale)").arg(label) : label);
    spin_ = new QDoubleSpinBox(this);
    spin_->setDecimals(6);
    spin_->setRange(minimum, maximum);
    spin_->setSingleStep(logScale ? minimum : (maximum - minimum) / 100.0);
    spin_->setKeyboardTracking(false);
    spin_->setSuffix(unit.isEmpty() ? QString() : " " + unit);
    spin_->setAccessibleName(label + tr(" value"));
    spin_->setMinimumWidth(110);
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

void ParameterSlider::showValue(double v) {
    value_ = v;
    updating_ = true;
    slider_->setValue(toPosition(v));
    spin_->setValue(v);
    exact_->setText(QString::number(v, 'g', 10));
    updating_ = false;
}

void ParameterSlider::setValue(double v) {
    if (!std::isfinite(v))
        return;
    if (v < min_ || v > max_) {
        min_ = std::min(min_, v);
        max_ = std::max(max_, v);
        spin_->setRange(min_, max_);
    }
    showValue(v);
}

} // namespace xyt::ui
