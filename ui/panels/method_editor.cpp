// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/method_editor.h"

#include "ui/panels/method_parameter_editor.h"
#include "ui/panels/pid_feedforward_editor.h"

#include <map>

namespace xyt::ui {

namespace {

std::map<DesignMethod, MethodEditorFactory>& editorFactories() {
    // The built-in methods that are edited in a method editor (the first two have their own
    // pages in the window).
    static std::map<DesignMethod, MethodEditorFactory> factories = {
        {DesignMethod::PidFeedforward,
         [](const DesignMethodModule& module, QWidget* parent) -> MethodEditor* {
             return new PidFeedforwardEditor(module, parent);
         }},
    };
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
