// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QWidget>

class QComboBox;

namespace xyt::ui {

class NumberField;

/**
 * Editor of the digital implementation: computation delay (samples), encoder
 * resolution (mm per count, 0 = ideal), DAC bits (0 = ideal), anti-windup and its tracking time.
 * Each field is checked by the core's rule and names it ("implementation.dac_bits: must be an
 * integer in 0..32"); an invalid entry stays at its field and is not applied.
 */
class ImplementationEditor : public QWidget {
    Q_OBJECT
public:
    explicit ImplementationEditor(QWidget* parent = nullptr);
    /// Shows @p settings without emitting implementationEdited.
    void setSettings(const ImplementationSettings& settings);
    NumberField* delayField() const { return delay_; }
    NumberField* encoderField() const { return encoder_; }
    NumberField* dacBitsField() const { return dacBits_; }
    NumberField* trackingTimeField() const { return trackingTime_; }
    QComboBox* antiWindupBox() const { return antiWindup_; }

signals:
    void implementationEdited(const ImplementationSettings& settings);

private:
    void emitIfChanged(const ImplementationSettings& next);

    NumberField* delay_;
    NumberField* encoder_;
    NumberField* dacBits_;
    QComboBox* antiWindup_;
    NumberField* trackingTime_;
    ImplementationSettings current_;
};

} // namespace xyt::ui
