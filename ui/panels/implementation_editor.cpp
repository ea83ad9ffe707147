// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/implementation_editor.h"

#include "core/model/errors.h"
#include "core/simulation/sampled_data.h"
#include "ui/panels/number_field.h"
#include "ui/session/diagnostic_text.h"

#include <QComboBox>
#include <QFormLayout>

#include <cmath>

namespace xyt::ui {

namespace {

/// The core's check of one implementation field, named by its session path.
NumberField::Validator implementationRule(const char* field) {
    return [field](double v) {
        SampledDataOptions o;
        o.umaxVolts = 1.0; // the session's limit is checked where it is edited
        const std::string name(field);
        const bool integer = name == "delay_samples" || name == "dac_bits";
        if (integer && (!std::isfinite(v) || v != std::floor(v) || std::abs(v) > 1e9))
            throw InvalidInput(
                "implementation." + name,
                (name == "dac_bits"
                     ? ImplementationEditor::tr("must be an integer in 0..32 (0: ideal DAC)")
                     : ImplementationEditor::tr("must be an integer in 0..%1")
                           .arg(kMaxDelaySamples))
                    .toStdString());
        if (name == "delay_samples")
            o.delaySamples = static_cast<int>(v);
        else if (name == "dac_bits")
            o.dacBits = static_cast<int>(v);
        else if (name == "encoder_resolution")
            o.encoderResolution = v;
        else if (!std::isfinite(v) || v < 0.0)
            throw InvalidInput(
                "implementation.tracking_time",
                ImplementationEditor::tr("must be >= 0 (s; 0: Tt = Ti = kp/ki)").toStdString());
        try {
            validateSampledDataOptions(o);
        } catch (const InvalidInput& e) {
            throw InvalidInput("implementation." + e.field(), e.reasonDiagnostic());
        }
    };
}

} // namespace

ImplementationEditor::ImplementationEditor(QWidget* parent) : QWidget(parent) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    delay_ =
        new NumberField("implementation.delay_samples", implementationRule("delay_samples"), this);
    delay_->setToolTip(
        tr("Computation delay: the command computed at sample k is applied at k + delay"));
    encoder_ = new NumberField("implementation.encoder_resolution",
                               implementationRule("encoder_resolution"), this);
    encoder_->setToolTip(tr("Encoder resolution in mm per count; 0 = ideal (no quantization)"));
    dacBits_ = new NumberField("implementation.dac_bits", implementationRule("dac_bits"), this);
    dacBits_->setToolTip(tr("DAC resolution over ±umax; 0 = ideal"));
    antiWindup_ = new QComboBox(this);
    antiWindup_->addItem(tr("clamping"));
    antiWindup_->addItem(tr("back-calculation"));
    antiWindup_->addItem(tr("none"));
    antiWindup_->setAccessibleName(tr("Anti-windup"));
    antiWindup_->setToolTip(tr("How the digital PI's integrator is kept from winding up while u is "
                               "clipped: clamping (conditional integration) is what ships"));
    trackingTime_ =
        new NumberField("implementation.tracking_time", implementationRule("tracking_time"), this);
    trackingTime_->setToolTip(tr("Back-calculation tracking time Tt (s); 0 = Ti = kp/ki"));
    form->addRow(tr("Delay (samples)"), delay_);
    form->addRow(tr("Encoder (mm/count)"), encoder_);
    form->addRow(tr("DAC bits"), dacBits_);
    form->addRow(tr("Anti-windup"), antiWindup_);
    form->addRow(tr("Tracking time (s)"), trackingTime_);
    const auto edited = [this](auto change) {
        return [this, change](double v) {
            ImplementationSettings next = current_;
            change(next, v);
            emitIfChanged(next);
        };
    };
    connect(
        delay_, &NumberField::valueAccepted, this,
        edited([](ImplementationSettings& s, double v) { s.delaySamples = static_cast<int>(v); }));
    connect(encoder_, &NumberField::valueAccepted, this,
            edited([](ImplementationSettings& s, double v) { s.encoderResolutionMm = v; }));
    connect(dacBits_, &NumberField::valueAccepted, this,
            edited([](ImplementationSettings& s, double v) { s.dacBits = static_cast<int>(v); }));
    connect(trackingTime_, &NumberField::valueAccepted, this,
            edited([](ImplementationSettings& s, double v) { s.trackingTimeSeconds = v; }));
    connect(antiWindup_, &QComboBox::activated, this, [this](int index) {
        ImplementationSettings next = current_;
        next.antiWindup = index == 0   ? AntiWindup::Clamp
                          : index == 1 ? AntiWindup::BackCalculation
                                       : AntiWindup::None;
        emitIfChanged(next);
    });
}

void ImplementationEditor::setSettings(const ImplementationSettings& settings) {
    current_ = settings;
    delay_->setValue(settings.delaySamples);
    encoder_->setValue(settings.encoderResolutionMm);
    dacBits_->setValue(settings.dacBits);
    trackingTime_->setValue(settings.trackingTimeSeconds);
    trackingTime_->setEnabled(settings.antiWindup == AntiWindup::BackCalculation);
    const int index = settings.antiWindup == AntiWindup::Clamp             ? 0
                      : settings.antiWindup == AntiWindup::BackCalculation ? 1
                                                                           : 2;
    if (antiWindup_->currentIndex() != index)
        antiWindup_->setCurrentIndex(index); // setCurrentIndex does not emit activated
}

void ImplementationEditor::emitIfChanged(const ImplementationSettings& next) {
    if (next == current_)
        return;
    current_ = next;
    trackingTime_->setEnabled(next.antiWindup == AntiWindup::BackCalculation);
    emit implementationEdited(next);
}

} // namespace xyt::ui
