// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/friction_editor.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "ui/panels/field_form.h"
#include "ui/panels/fold_button.h"
#include "ui/panels/number_field.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace xyt::ui {

namespace {

void requireNonNegative(double v) {
    if (!(v >= 0.0))
        throw InvalidInput("value", makeDiagnostic("not_negative"));
}

} // namespace

FrictionEditor::FrictionEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    body_ = new QWidget(this);
    fold_ = makeFoldButton(this, tr("Friction and backlash"), body_);
    layout->addWidget(fold_);
    auto* form = new QFormLayout(body_);
    form->setContentsMargins(12, 0, 0, 0);
    form_ = std::make_unique<FieldForm>(form);
    const auto add = [&](const QString& key, const QString& label, const QString& tip) {
        form_->add(key, label, tip, requireNonNegative, this, [this] { emitIfValid(); });
    };
    add("coulomb", tr("Coulomb (V)"),
        tr("Coulomb friction Fc in volts of equivalent command: what the axis needs beyond its "
           "linear model to keep sliding"));
    add("static", tr("Static (V)"),
        tr("Static (breakaway) level Fs in volts; 0 takes the Coulomb level (no Stribeck dip)"));
    add("stribeck_velocity", tr("Stribeck velocity (mm/s)"),
        tr("vs of f(v) = sign(v) (Fc + (Fs - Fc) exp(-(v/vs)²)): how fast the friction falls "
           "from Fs to Fc"));
    add("viscous", tr("Viscous (V per mm/s)"),
        tr("Viscous friction beyond the model's own damping (a2/k0 already holds it): 0 by "
           "default"));
    add("backlash", tr("Backlash (mm)"),
        tr("Play between motor and table: the table stays while the motor crosses the gap"));
    add("amplifier_deadband", tr("Amplifier deadband (V)"),
        tr("|u| below it gives no output; beyond it the amplifier gives u - d sign(u)"));
    pole_ = new QComboBox(body_);
    pole_->addItem(tr("the faster pole"));
    pole_->addItem(tr("the slower pole"));
    pole_->setToolTip(tr("Which root of s² + a1 s + a2 is the drive's electrical lag; the other "
                         "is the moving mass, where the friction acts"));
    form->addRow(tr("Electrical lag"), pole_);
    connect(pole_, &QComboBox::activated, this, [this] { emitIfValid(); });
    add("percent", tr("Compensation (%)"),
        tr("Friction feedforward from the reference velocity, in percent of the Coulomb and "
           "viscous levels above (0: none)"));
    add("band", tr("Compensation band (mm/s)"),
        tr("The Coulomb term ramps linearly across |v| < band instead of jumping at v = 0"));
    note_ = new QLabel(this);
    note_->setWordWrap(true);
    note_->hide();
    layout->addWidget(body_);
    layout->addWidget(note_);
    setSettings({}, {}, true);
}

FrictionEditor::~FrictionEditor() = default;

NumberField* FrictionEditor::field(const QString& name) const {
    return form_->field(name);
}

bool FrictionEditor::isOpen() const {
    return fold_->isChecked();
}

void FrictionEditor::setSettings(const TableFriction& friction,
                                 const FrictionCompensation& compensation, bool massModel) {
    friction_ = friction;
    compensation_ = compensation;
    form_->field("coulomb")->setValue(friction.coulombVolts);
    form_->field("static")->setValue(friction.staticVolts);
    form_->field("stribeck_velocity")->setValue(friction.stribeckVelocityMmPerS);
    form_->field("viscous")->setValue(friction.viscousVoltsPerMmPerS);
    form_->field("backlash")->setValue(friction.backlashMm);
    form_->field("amplifier_deadband")->setValue(friction.amplifierDeadbandVolts);
    form_->field("percent")->setValue(compensation.percent);
    form_->field("band")->setValue(compensation.bandMmPerS);
    pole_->setCurrentIndex(friction.electricalPole == ElectricalPole::Faster ? 0 : 1);
    // An ARX model has no moving mass: only the input dead zone's two levels apply.
    const QString arx = tr("A pole-placement axis' ARX model has no moving mass: it takes the "
                           "Coulomb level and the amplifier deadband, as a dead zone of its input");
    for (auto it = form_->fields().begin(); it != form_->fields().end(); ++it) {
        const bool used = massModel || it.key() == "coulomb" || it.key() == "amplifier_deadband";
        it.value()->setEnabled(used);
        it.value()->setToolTip(used ? form_->tip(it.key()) : arx);
    }
    pole_->setEnabled(massModel);
    note_->setVisible(false);
    updateHeader();
}

void FrictionEditor::emitIfValid() {
    if (form_->anyError())
        return;
    TableFriction next;
    next.coulombVolts = form_->value("coulomb");
    next.staticVolts = form_->value("static");
    next.stribeckVelocityMmPerS = form_->value("stribeck_velocity");
    next.viscousVoltsPerMmPerS = form_->value("viscous");
    next.backlashMm = form_->value("backlash");
    next.amplifierDeadbandVolts = form_->value("amplifier_deadband");
    next.electricalPole =
        pole_->currentIndex() == 0 ? ElectricalPole::Faster : ElectricalPole::Slower;
    FrictionCompensation c;
    c.percent = form_->value("percent");
    c.bandMmPerS = form_->value("band");
    try {
        validateTableFriction(next);
        validateFrictionCompensation(c);
    } catch (const InvalidInput& e) {
        form_->markError(e);
        return;
    }
    form_->clearErrors();
    if (next == friction_ && c == compensation_)
        return;
    friction_ = next;
    compensation_ = c;
    updateHeader();
    emit frictionEdited(next, c);
}

void FrictionEditor::updateHeader() {
    QStringList set;
    if (friction_.coulombVolts > 0.0 || friction_.staticVolts > 0.0)
        set << tr("Coulomb %1 V").arg(formatNumber(friction_.coulombVolts));
    if (friction_.backlashMm > 0.0)
        set << tr("backlash %1 mm").arg(formatNumber(friction_.backlashMm));
    if (friction_.amplifierDeadbandVolts > 0.0)
        set << tr("deadband %1 V").arg(formatNumber(friction_.amplifierDeadbandVolts));
    if (friction_.viscousVoltsPerMmPerS > 0.0)
        set << tr("viscous");
    if (compensation_.percent > 0.0)
        set << tr("compensated %1 %").arg(formatNumber(compensation_.percent));
    fold_->setText(set.isEmpty() ? tr("Friction") : tr("Friction ●"));
    fold_->setToolTip(set.isEmpty() ? tr("Friction and backlash: none (the linear table)")
                                    : tr("Friction and backlash: %1").arg(set.join(", ")));
}

} // namespace xyt::ui
