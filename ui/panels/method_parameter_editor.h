// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/panels/method_editor.h"

#include <map>
#include <string>

namespace xyt::ui {

class NumberField;

/**
 * The editor of a registered design method whose settings are numbers
 * (DesignMethodModule::parameters): one field per parameter, labelled with its name and unit,
 * refusing at the field a value outside its range; an accepted value is one undo step. The
 * workbench gives this editor to a method registered without one of its own, so a method whose
 * settings are numbers needs no editor code.
 */
class MethodParameterEditor : public MethodEditor {
    Q_OBJECT
public:
    MethodParameterEditor(const DesignMethodModule& module, QWidget* parent = nullptr);
    /// The fields of @p parameters only (a method's editor that lays out the rest itself).
    MethodParameterEditor(std::vector<MethodParameter> parameters, QWidget* parent = nullptr);
    /// Shows @p settings' values (a parameter the settings lack shows its default).
    void setSettings(const AxisSettings& settings) override;
    /// The field of parameter @p name, or null.
    NumberField* field(const std::string& name) const;

private:
    AxisSettings current_;
    std::vector<MethodParameter> parameters_;
    std::map<std::string, NumberField*> fields_;
};

} // namespace xyt::ui
