// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"

#include <QWidget>

class QComboBox;

namespace xyt::ui {

class NumberField;

/// Editor of G(s) = k0 / (s^3 + a1 s^2 + a2 s) with the presets of Braga et al. and the model
/// unit scale. Invalid values stay at the field (red, with the reason) and are not applied.
class PlantEditor : public QWidget {
    Q_OBJECT
public:
    explicit PlantEditor(QWidget* parent = nullptr);

    void setPlant(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit);
    NumberField* k0Field() const { return k0_; }
    NumberField* a1Field() const { return a1_; }
    NumberField* a2Field() const { return a2_; }
    NumberField* unitField() const { return unit_; }
    QComboBox* presetBox() const { return preset_; }

signals:
    void plantEdited(const ThirdOrderPlant& plant);
    /// A preset was chosen: its plant and design parameters.
    void presetChosen(const GtPreset& preset);
    void modelUnitEdited(double modelUnitsPerPositionUnit);

private:
    void emitPlant();
    void syncPresetBox();

    QComboBox* preset_;
    NumberField* k0_;
    NumberField* a1_;
    NumberField* a2_;
    NumberField* unit_;
    ThirdOrderPlant plant_;
};

} // namespace xyt::ui
