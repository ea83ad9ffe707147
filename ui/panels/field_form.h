// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/panels/number_field.h"

#include <QMap>
#include <QString>

#include <functional>

class QFormLayout;
class QObject;

namespace xyt {
class InvalidInput;
}

namespace xyt::ui {

/**
 * The number fields of a fold's form, named as the core names them ("coulomb", "damping"),
 * each with its tooltip: a field the core refuses shows the reason at it (markError) until the
 * next accepted edit (clearErrors). What the Friction and Mode folds share.
 */
class FieldForm {
public:
    explicit FieldForm(QFormLayout* form) : form_(form) {}
    /// A field in a new row of the form; @p accepted runs on each accepted entry (its
    /// connection lives as long as @p context).
    NumberField* add(const QString& key, const QString& label, const QString& tip,
                     NumberField::Validator validator, QObject* context,
                     const std::function<void()>& accepted);
    NumberField* field(const QString& key) const { return fields_.value(key); }
    double value(const QString& key) const { return fields_.value(key)->value(); }
    const QMap<QString, NumberField*>& fields() const { return fields_; }
    QString tip(const QString& key) const { return tips_.value(key); }
    /// Whether a field holds text its own validator refused.
    bool anyError() const;
    /// Marks the field @p e names with its reason; false when the field is not in this form.
    bool markError(const InvalidInput& e) const;
    /// Every field back to its own tooltip.
    void clearErrors() const;

private:
    QFormLayout* form_;
    QMap<QString, NumberField*> fields_;
    QMap<QString, QString> tips_;
};

} // namespace xyt::ui
