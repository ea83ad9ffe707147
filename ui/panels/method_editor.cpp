// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/method_editor.h"

#include "ui/panels/method_parameter_editor.h"

#include <map>

namespace xyt::ui {

namespace {

std::map<DesignMethod, MethodEditorFactory>& editorFactories() {
    static std::map<DesignMethod, MethodEditorFactory> factories;
    return factories;
}

} // namespace

void registerMethodEditor(DesignMethod method, MethodEditorFactory factory) {
    editorFactories()[method] = std::move(factory);
}

MethodEditor* createMethodEditor(const DesignMethodModule& module, QWidget* parent) {
    const auto it = editorFactories().find(module.method());
    if (it != editorFactories().end())
        return it->second(module, parent);
    return new MethodParameterEditor(module, parent);
}

} // namespace xyt::ui
