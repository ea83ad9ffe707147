// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/pid_feedforward_editor.h"

#include "core/model/errors.h"
#include "ui/panels/method_parameter_editor.h"
#include "ui/panels/parameter_slider.h"
#include "ui/plots/number_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace xyt::ui {

namespace {

std::vector<MethodParameter> only(const DesignMethodModule& module,
                                  std::initializer_list<const char*> names) {
    std::vector<MethodParameter> out;
    for (const char* name : names)
        for (const MethodParameter& p : module.parameters())
            if (p.name == name)
                out.push_back(p);
    return out;
}

double parameterOr(const AxisSettings& settings, const std::string& name, double fallback) {
    const auto it = settings.parameters.find(name);
    return it == settings.parameters.end() ? fallback : it->second;
}

const char* const kFeedforwardNames[3] = {"ff1", "ff2", "ff3"};

} // namespace

PidFeedforwardEditor::PidFeedforwardEditor(const DesignMethodModule& module, QWidget* parent)
    : MethodEditor(parent), parameters_(module.parameters()),
      gains_(new MethodParameterEditor(only(module, {"p", "i", "d"}), this)),
      limits_(new MethodParameterEditor(only(module, {"ff0", "bias", "deadband", "max_error_i",
                                                      "max_output", "derivative_filter"}),
                                        this)),
      modelLabel_(new QLabel(this)), fromModel_(new QPushButton(tr("From model"), this)),
      derivativeSource_(new QComboBox(this)),
      onMeasurement_(new QCheckBox(tr("D on the measurement (no kick)"), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(gains_);
    // Headings rather than group boxes: a box's frame would widen the window's side panel.
    layout->addWidget(new QLabel(tr("<b>Feedforward</b>, % of the model's inverse"), this));
    QWidget* ff = this;
    QVBoxLayout* ffLayout = layout;
    const QString labels[3] = {tr("FF1 (velocity)"), tr("FF2 (acceleration)"), tr("FF3 (jerk)")};
    for (int k = 0; k < 3; ++k) {
        auto* slider = new ParameterSlider(labels[k], QStringLiteral("%"), 0.0, 200.0, false, ff);
        slider->setFieldRange(0.0, 1e6);
        slider->setDescription(tr("The gain %1 as a percentage (%) of the plant's exact inverse "
                                  "(FF1 = a2 u/k0, FF2 = a1 u/k0, FF3 = u/k0): 100 % cancels "
                                  "the plant's dynamics along the trajectory")
                                   .arg(QString(kFeedforwardNames[k]).toUpper()));
        sliders_[static_cast<std::size_t>(k)] = slider;
        ffLayout->addWidget(slider);
        connect(slider, &ParameterSlider::valueChanged, this, [this, k](double percent) {
            if (!model_)
                return;
            const double modelGain = k == 0 ? model_->ff1 : (k == 1 ? model_->ff2 : model_->ff3);
            AxisSettings next = current_;
            next.parameters[kFeedforwardNames[k]] = percent / 100.0 * modelGain;
            edit(next,
                 tr("Set %1 of %2 to %3 % of the model")
                     .arg(QString(kFeedforwardNames[k]).toUpper(),
                          QString::fromStdString(current_.id).toUpper())
                     .arg(percent),
                 k);
        });
    }
    modelLabel_->setWordWrap(true);
    modelLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    ffLayout->addWidget(modelLabel_);
    fromModel_->setToolTip(tr("Set FF1, FF2 and FF3 to the plant's exact inverse "
                              "(a2 u/k0, a1 u/k0, u/k0) and FF0 to 0"));
    ffLayout->addWidget(fromModel_);
    connect(fromModel_, &QPushButton::clicked, this, [this] {
        if (!model_)
            return;
        AxisSettings next = current_;
        next.parameters["ff0"] = 0.0;
        next.parameters["ff1"] = model_->ff1;
        next.parameters["ff2"] = model_->ff2;
        next.parameters["ff3"] = model_->ff3;
        edit(next, tr("Feedforward of %1 from the model")
                       .arg(QString::fromStdString(current_.id).toUpper()));
    });
    derivativeSource_->addItem(tr("r′, r″, r‴ by backward differences"));
    derivativeSource_->addItem(tr("r′, r″, r‴ from the trajectory"));
    derivativeSource_->setToolTip(
        tr("Where the feedforward reads the command's derivatives: backward differences of the "
           "commanded position each period (LinuxCNC's pid), or the trajectory generator's own "
           "velocity, acceleration and jerk"));
    derivativeSource_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    derivativeSource_->setMinimumContentsLength(16);
    derivativeSource_->setAccessibleName(tr("Command derivatives"));
    ffLayout->addWidget(derivativeSource_);
    connect(derivativeSource_, &QComboBox::activated, this, [this](int index) {
        AxisSettings next = current_;
        next.parameters["command_derivatives"] = index;
        edit(next, tr("Take the command's derivatives of %1 from the %2")
                       .arg(QString::fromStdString(current_.id).toUpper(),
                            index == 0 ? tr("backward differences") : tr("trajectory generator")));
    });
    layout->addWidget(new QLabel(tr("<b>Limits and filter</b>"), this));
    layout->addWidget(limits_);
    onMeasurement_->setToolTip(tr("The D term differentiates the measured position (D = −fb′) "
                                  "instead of the error, so a step of the command gives no kick"));
    layout->addWidget(onMeasurement_);
    connect(onMeasurement_, &QCheckBox::clicked, this, [this](bool on) {
        AxisSettings next = current_;
        next.parameters["derivative_on_measurement"] = on ? 1.0 : 0.0;
        edit(next, on ? tr("Differentiate the measurement of %1")
                            .arg(QString::fromStdString(current_.id).toUpper())
                      : tr("Differentiate the error of %1")
                            .arg(QString::fromStdString(current_.id).toUpper()));
    });
    for (MethodParameterEditor* fields : {gains_, limits_})
        connect(fields, &MethodEditor::settingsEdited, this,
                [this](const AxisSettings& next, const QString& description) {
                    edit(next, description);
                });
}

void PidFeedforwardEditor::edit(const AxisSettings& next, const QString& description,
                                int mergeKey) {
    emit settingsEdited(next, description, mergeKey);
}

void PidFeedforwardEditor::setSettings(const AxisSettings& settings) {
    current_ = settings;
    gains_->setSettings(settings);
    limits_->setSettings(settings);
    try {
        model_ = modelFeedforwardGains(settings.gt.plant, settings.gt.modelUnitsPerPositionUnit);
    } catch (const InvalidInput&) {
        model_.reset();
    }
    for (int k = 0; k < 3; ++k) {
        ParameterSlider* slider = sliders_[static_cast<std::size_t>(k)];
        const QSignalBlocker quiet(slider);
        slider->setEnabled(model_.has_value());
        if (!model_)
            continue;
        const double modelGain = k == 0 ? model_->ff1 : (k == 1 ? model_->ff2 : model_->ff3);
        double fallback = 0.0;
        for (const MethodParameter& p : parameters_)
            if (p.name == kFeedforwardNames[k])
                fallback = p.defaultValue;
        slider->setValue(100.0 * parameterOr(settings, kFeedforwardNames[k], fallback) / modelGain);
    }
    fromModel_->setEnabled(model_.has_value());
    modelLabel_->setText(modelText());
    {
        const QSignalBlocker quiet(derivativeSource_);
        derivativeSource_->setCurrentIndex(
            parameterOr(settings, "command_derivatives", 0.0) == 1.0 ? 1 : 0);
    }
    const QSignalBlocker quiet(onMeasurement_);
    onMeasurement_->setChecked(parameterOr(settings, "derivative_on_measurement", 0.0) == 1.0);
}

QString PidFeedforwardEditor::modelText() const {
    if (!model_)
        return tr("The plant has no usable inverse (k0 must be finite and nonzero): no "
                  "feedforward from the model.");
    return tr("100 % = FF1 %1 V/(mm/s), FF2 %2 V/(mm/s²), FF3 %3 V/(mm/s³)")
        .arg(significant(model_->ff1, 4), significant(model_->ff2, 4), significant(model_->ff3, 4));
}

ParameterSlider* PidFeedforwardEditor::feedforwardSlider(int order) const {
    return sliders_.at(static_cast<std::size_t>(std::clamp(order, 1, 3) - 1));
}

} // namespace xyt::ui
