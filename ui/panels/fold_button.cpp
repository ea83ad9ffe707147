// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/fold_button.h"

#include <QToolButton>
#include <QWidget>

namespace xyt::ui {

QToolButton* makeFoldButton(QWidget* parent, const QString& accessibleName, QWidget* body) {
    auto* fold = new QToolButton(parent);
    fold->setCheckable(true);
    fold->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    fold->setArrowType(Qt::RightArrow);
    fold->setAutoRaise(true);
    fold->setAccessibleName(accessibleName);
    body->hide();
    QObject::connect(fold, &QToolButton::toggled, body, [fold, body](bool open) {
        body->setVisible(open);
        fold->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    });
    return fold;
}

} // namespace xyt::ui
