// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/fold_button.h"

#include <QCoreApplication>
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
    // The caller's own tooltip (what the fold holds, its state) replaces this one.
    fold->setToolTip(
        QCoreApplication::translate("FoldButton", "%1: click to show or hide these settings")
            .arg(accessibleName));
    body->hide();
    QObject::connect(fold, &QToolButton::toggled, body, [fold, body](bool open) {
        body->setVisible(open);
        fold->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    });
    return fold;
}

} // namespace xyt::ui
