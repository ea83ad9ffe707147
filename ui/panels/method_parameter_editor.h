// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

#include <QWidget>

#include <map>
#include <string>

namespace xyt::ui {

class NumberField;

/**
 * The editor of a registered design method whose settings are numbers
 * (DesignMethodModule::parameters): one field per parameter, labelled with its name and unit,
 * refusing at the field a value outside its range. The workbench gives every such method this
 * editor, so a method needs no editor code of its own.
 */
class MethodParameterEditor : public QWidget {
    Q_OBJECT
public:
    MethodParameterEditor(const DesignMethodModule& module, QWidget* parent = nullptr);
    /// Shows @p settings' values (a parameter the settings lack shows its default).
    void setSettings(const AxisSettings& settings);
    /// The field of parameter @p name, or null.
    NumberField* field(const std::string& name) const;
    DesignMethod method() const { return method_; }

signals:
    void parameterEdited(const std::string& name, double value);

private:
    DesignMethod method_;
    std::vector<MethodParameter> parameters_;
    std::map<std::string, NumberField*> fields_;
};

} // namespace xyt::ui
