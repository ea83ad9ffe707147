// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/field_form.h"

#include "core/model/errors.h"
#include "ui/session/diagnostic_text.h"

#include <QFormLayout>

namespace xyt::ui {

NumberField* FieldForm::add(const QString& key, const QString& label, const QString& tip,
                            NumberField::Validator validator, QObject* context,
                            const std::function<void()>& accepted) {
    auto* f = new NumberField(key, std::move(validator), form_->parentWidget());
    f->setToolTip(tip);
    fields_.insert(key, f);
    tips_.insert(key, tip);
    form_->addRow(label, f);
    QObject::connect(f, &NumberField::valueAccepted, context, [accepted] { accepted(); });
    return f;
}

bool FieldForm::anyError() const {
    for (NumberField* f : fields_)
        if (f->hasError())
            return true;
    return false;
}

bool FieldForm::markError(const InvalidInput& e) const {
    NumberField* f = fields_.value(QString::fromStdString(e.field()));
    if (f)
        markFieldError(f, diagnosticText(e.reasonDiagnostic()));
    return f != nullptr;
}

void FieldForm::clearErrors() const {
    for (auto it = fields_.begin(); it != fields_.end(); ++it)
        clearFieldError(it.value(), tips_.value(it.key()));
}

} // namespace xyt::ui
