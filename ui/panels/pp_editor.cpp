// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/pp_editor.h"

#include "core/design/pole_placement.h"
#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"
#include "ui/panels/number_field.h"
#include "ui/panels/parameter_slider.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

namespace xyt::ui {

namespace {
QString listText(const std::vector<double>& v) {
    QStringList parts;
    for (double x : v)
        parts << QString::number(x, 'g', 10);
    return parts.join(' ');
}
} // namespace

PpEditor::PpEditor(QWidget* parent) : QWidget(parent) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(new QLabel(tr("B(z⁻¹)/A(z⁻¹), ascending powers of z⁻¹"), this));
    preset_ = new QComboBox(this);
    for (const auto& p : polePlacementPresets())
        preset_->addItem(coreText("xyt::PresetName", p.name), QString::fromStdString(p.name));
    preset_->addItem(tr("custom"), QString());
    preset_->setAccessibleName(tr("ARX preset"));
    preset_->setToolTip(tr("An axis model of Patrick, Ishak and Adnan: the x axis (Eq. 1) or the "
                           "y axis (Eq. 3), with T = 1 − 0.2 z⁻¹ and Ts = 70 ms"));
    a_ = new QLineEdit(this);
    b_ = new QLineEdit(this);
    a_->setAccessibleName("A");
    b_->setAccessibleName("B");
    a_->setToolTip(tr("A(z⁻¹) = 1 + a1 z⁻¹ + ...: coefficients separated by spaces or commas"));
    b_->setToolTip(tr("B(z⁻¹) = 0 + b1 z⁻¹ + ...: leading zeros are the delay"));
    a_->setProperty("normalToolTip", a_->toolTip());
    b_->setProperty("normalToolTip", b_->toolTip());
    t1_ = new ParameterSlider(tr("Desired pole t&1 (T = 1 + t1 z⁻¹)"), QString(), -0.95, 0.95,
                              false, this);
    t1_->setDescription(tr("The desired closed-loop pole: T = 1 + t1 z⁻¹ puts the RST loop's "
                           "pole at z = −t1; the Diophantine equation A F + B G = T gives F, G"));
    ts_ = new NumberField(
        "ts", [](double v) { requirePositive(v, "ts"); }, this);
    zpetc_ = new QCheckBox(tr("ZPETC feedforward"), this);
    ts_->setToolTip(tr("Sample time Ts (s) of the ARX model and of its RST controller"));
    zpetc_->setToolTip(tr("Tomizuka's zero-phase-error tracking controller ahead of the loop: "
                          "u_ff(k) = A_c B⁻*(z⁻¹) / (B⁺ [B⁻(1)]²) r(k + p), the reference "
                          "previewed p samples"));
    form->addRow(tr("Preset"), preset_);
    form->addRow(tr("&A"), a_);
    form->addRow(tr("&B"), b_);
    form->addRow(t1_);
    form->addRow(tr("Ts (s)"), ts_);
    form->addRow(zpetc_);

    connect(a_, &QLineEdit::editingFinished, this, [this] { emitIfValid(-1); });
    connect(b_, &QLineEdit::editingFinished, this, [this] { emitIfValid(-1); });
    connect(ts_, &NumberField::valueAccepted, this, [this] { emitIfValid(-1); });
    connect(zpetc_, &QCheckBox::toggled, this, [this] { emitIfValid(-1); });
    connect(t1_, &ParameterSlider::valueChanged, this, [this] { emitIfValid(kMergeT1); });
    connect(preset_, &QComboBox::activated, this, [this](int index) {
        const auto p = findPolePlacementPreset(preset_->itemData(index).toString().toStdString());
        if (!p)
            return;
        a_->setText(listText(p->a.ascending()));
        b_->setText(listText(p->b.ascending()));
        t1_->setValue(p->t.coefficient(1));
        ts_->setValue(p->tsSeconds);
        emitIfValid(-1);
    });
}

void PpEditor::setSettings(const PpAxisSettings& s) {
    current_ = s;
    // Always the presenter's value, focused or not: after an undo, redo or load a field must not
    // keep showing (and later re-apply) text the session no longer has.
    a_->setText(listText(s.a));
    b_->setText(listText(s.b));
    clearFieldError(a_, a_->property("normalToolTip").toString());
    clearFieldError(b_, b_->property("normalToolTip").toString());
    {
        const QSignalBlocker block(t1_);
        t1_->setValue(s.t1);
    }
    ts_->setValue(s.tsSeconds);
    {
        const QSignalBlocker block(zpetc_);
        zpetc_->setChecked(s.zpetcEnabled);
    }
    int index = preset_->count() - 1;
    for (int i = 0; i + 1 < preset_->count(); ++i) {
        const auto p = findPolePlacementPreset(preset_->itemData(i).toString().toStdString());
        if (p && p->a.ascending() == s.a && p->b.ascending() == s.b)
            index = i;
    }
    preset_->setCurrentIndex(index);
}

bool PpEditor::parseList(QLineEdit* field, const char* name, std::vector<double>& out) {
    try {
        out = parseCoefficientList(field->text().toStdString(), name);
        if (std::string(name) == "A" && out[0] == 0.0)
            throw InvalidInput(
                "A", tr("the z^0 coefficient must be nonzero (A is monic)").toStdString());
        clearFieldError(field, field->property("normalToolTip").toString());
        return true;
    } catch (const InvalidInput& e) {
        markFieldError(field, exceptionText(e));
        return false;
    }
}

void PpEditor::emitIfValid(int mergeKey) {
    PpAxisSettings next = current_;
    const bool okA = parseList(a_, "A", next.a);
    const bool okB = parseList(b_, "B", next.b);
    if (!okA || !okB || ts_->hasError())
        return;
    next.t1 = t1_->value();
    next.tsSeconds = ts_->value();
    next.zpetcEnabled = zpetc_->isChecked();
    if (next == current_)
        return;
    current_ = next;
    emit settingsEdited(next, mergeKey);
}

} // namespace xyt::ui
