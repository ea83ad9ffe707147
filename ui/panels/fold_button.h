// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QToolButton;
class QWidget;

namespace xyt::ui {

/**
 * The header of a fold in the control panel: a flat, checkable tool button named
 * @p accessibleName with a right arrow, which shows @p body (hidden at first) and turns its
 * arrow down while checked. The caller sets its text and places both.
 */
QToolButton* makeFoldButton(QWidget* parent, const QString& accessibleName, QWidget* body);

} // namespace xyt::ui
