// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/plant_editor.h"

#include "core/model/errors.h"
#include "ui/panels/number_field.h"
#include "ui/session/diagnostic_text.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

namespace xyt::ui {

PlantEditor::PlantEditor(QWidget* parent) : QWidget(parent) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    preset_ = new QComboBox(this);
    for (const GtPreset& p : gtPresets())
        preset_->addItem(coreText("xyt::PresetName", p.name), QString::fromStdString(p.name));
    preset_->addItem(tr("custom"), QString());
    preset_->setAccessibleName(tr("Plant preset"));
    preset_->setToolTip(tr("A plant of Braga et al.: the lower base (Eq. 2) or the upper base "
                           "(Eq. 1) with the paper's ωn and kp; \"custom\" once a coefficient "
                           "is edited"));
    k0_ = new NumberField(
        "k0", [](double v) { requireNonZero(v, "k0"); }, this);
    a1_ = new NumberField("a1", {}, this);
    a2_ = new NumberField("a2", {}, this);
    unit_ = new NumberField(
        "model unit", [](double v) { requirePositive(v, "model unit"); }, this);
    k0_->setToolTip(tr("Gain k0 of G(s) = k0 / (s³ + a1 s² + a2 s), in model units per volt·s³"));
    a1_->setToolTip(tr("Coefficient a1 (1/s) of G(s) = k0 / (s³ + a1 s² + a2 s): the sum of the "
                       "two non-zero poles' magnitudes"));
    a2_->setToolTip(tr("Coefficient a2 (1/s²) of G(s) = k0 / (s³ + a1 s² + a2 s): the product of "
                       "the two non-zero poles; k0/a2 is the velocity gain"));
    unit_->setToolTip(
        tr("Model output units per mm of trajectory (0.001: the model is in metres)"));
    auto* formula = new QLabel(tr("G(s) = k0 / (s³ + a1 s² + a2 s)"), this);
    form->addRow(formula);
    form->addRow(tr("Preset"), preset_);
    form->addRow(tr("k&0"), k0_);
    form->addRow(tr("a&1"), a1_);
    form->addRow(tr("a&2"), a2_);
    form->addRow(tr("Model unit per mm"), unit_);

    for (NumberField* f : {k0_, a1_, a2_})
        connect(f, &NumberField::valueAccepted, this, [this] { emitPlant(); });
    connect(unit_, &NumberField::valueAccepted, this, &PlantEditor::modelUnitEdited);
    connect(preset_, &QComboBox::activated, this, [this](int index) {
        const auto preset = findGtPreset(preset_->itemData(index).toString().toStdString());
        if (preset)
            emit presetChosen(*preset);
    });
}

void PlantEditor::setPlant(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit) {
    plant_ = plant;
    k0_->setValue(plant.k0);
    a1_->setValue(plant.a1);
    a2_->setValue(plant.a2);
    unit_->setValue(modelUnitsPerPositionUnit);
    syncPresetBox();
}

void PlantEditor::emitPlant() {
    if (k0_->hasError() || a1_->hasError() || a2_->hasError())
        return;
    const ThirdOrderPlant next{k0_->value(), a1_->value(), a2_->value()};
    if (next == plant_)
        return;
    plant_ = next;
    syncPresetBox();
    emit plantEdited(next);
}

void PlantEditor::syncPresetBox() {
    int index = preset_->count() - 1; // custom
    for (int i = 0; i < preset_->count() - 1; ++i) {
        const auto p = findGtPreset(preset_->itemData(i).toString().toStdString());
        if (p && p->plant == plant_)
            index = i;
    }
    preset_->setCurrentIndex(index);
}

} // namespace xyt::ui
