// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/method_parameter_editor.h"

#include "ui/panels/number_field.h"
#include "ui/session/diagnostic_text.h"

#include <QFormLayout>
#include <QLabel>

namespace xyt::ui {

MethodParameterEditor::MethodParameterEditor(const DesignMethodModule& module, QWidget* parent)
    : MethodParameterEditor(module.parameters(), parent) {}

MethodParameterEditor::MethodParameterEditor(std::vector<MethodParameter> parameters,
                                             QWidget* parent)
    : MethodEditor(parent), parameters_(std::move(parameters)) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    // A long label goes above its field rather than widening the window's side panel.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    if (parameters_.empty())
        form->addRow(new QLabel(tr("This method has no settings."), this));
    for (const MethodParameter& p : parameters_) {
        const QString name = QString::fromStdString(p.name);
        // The core's check, so the field says what the evaluation and the session file say.
        auto* field = new NumberField(
            "parameters." + name,
            [p](double v) {
                AxisSettings probe;
                probe.parameters[p.name] = v;
                methodParameterValue(probe, 0, p);
            },
            this);
        const QString shown = coreText("xyt::ParameterLabel", p.label);
        field->setAccessibleName(shown);
        field->setToolTip(tr("%1 (%2 .. %3 %4)")
                              .arg(shown)
                              .arg(p.minimum)
                              .arg(p.maximum)
                              .arg(QString::fromStdString(p.unit)));
        const QString label =
            p.unit.empty() ? shown : tr("%1 (%2)").arg(shown, QString::fromStdString(p.unit));
        form->addRow(label, field);
        fields_[p.name] = field;
        connect(field, &NumberField::valueAccepted, this, [this, p](double v) {
            // A field left with its value (focus leaving it, the window closing) changes nothing.
            const auto it = current_.parameters.find(p.name);
            if (v == (it == current_.parameters.end() ? p.defaultValue : it->second))
                return;
            const std::string& key = p.name;
            AxisSettings next = current_;
            next.parameters[key] = v;
            emit settingsEdited(next, tr("Set %1 of %2 to %3")
                                          .arg(QString::fromStdString(key),
                                               QString::fromStdString(current_.id).toUpper())
                                          .arg(v));
        });
    }
}

void MethodParameterEditor::setSettings(const AxisSettings& settings) {
    current_ = settings;
    for (const MethodParameter& p : parameters_) {
        const auto it = settings.parameters.find(p.name);
        fields_.at(p.name)->setValue(it == settings.parameters.end() ? p.defaultValue : it->second);
    }
}

NumberField* MethodParameterEditor::field(const std::string& name) const {
    const auto it = fields_.find(name);
    return it == fields_.end() ? nullptr : it->second;
}

} // namespace xyt::ui
