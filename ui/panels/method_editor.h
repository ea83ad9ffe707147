// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

#include <QWidget>

#include <functional>

namespace xyt::ui {

/**
 * The editor panel of a design method, shown in the window's design box for an axis of that
 * method. The window gives it the current axis' settings on every change (setSettings) and
 * applies what it edits as one undo step (settingsEdited).
 */
class MethodEditor : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;
    /// Shows the settings of the current axis.
    virtual void setSettings(const AxisSettings& settings) = 0;

signals:
    /// The axis' settings as edited, applied as one undo step named @p description; successive
    /// edits with the same @p mergeKey (>= 0, a slider being dragged; per method editor, the
    /// window adds the axis) merge into one step.
    void settingsEdited(const AxisSettings& settings, const QString& description,
                        int mergeKey = -1);
};

/// Makes the editor of a method (its module, the editor's parent).
using MethodEditorFactory =
    std::function<MethodEditor*(const DesignMethodModule& module, QWidget* parent)>;

/**
 * Registers the editor of @p method, at start-up with its module (before a window is built): the
 * window shows it for an axis of that method. A method registered without an editor gets a
 * MethodParameterEditor of its parameters.
 */
void registerMethodEditor(DesignMethod method, MethodEditorFactory factory);

/// The editor of a registered (not built-in) method @p module: its registered one, else a
/// MethodParameterEditor.
MethodEditor* createMethodEditor(const DesignMethodModule& module, QWidget* parent);

} // namespace xyt::ui
