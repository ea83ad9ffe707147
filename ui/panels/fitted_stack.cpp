// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/fitted_stack.h"

#include <QStackedWidget>

namespace xyt::ui {

namespace {
void fitNow(QStackedWidget* stack) {
    for (int i = 0; i < stack->count(); ++i) {
        QWidget* page = stack->widget(i);
        const bool current = i == stack->currentIndex();
        // A page Ignored vertically adds nothing to the stack's height hint; every page keeps
        // its width, so the panel is as wide as its widest page and never clips one.
        page->setSizePolicy(QSizePolicy::Preferred,
                            current ? QSizePolicy::Preferred : QSizePolicy::Ignored);
        if (current)
            page->adjustSize();
    }
    stack->updateGeometry();
}
} // namespace

void fitStackToCurrentPage(QStackedWidget* stack) {
    fitNow(stack);
    QObject::connect(stack, &QStackedWidget::currentChanged, stack, [stack] { fitNow(stack); });
}

} // namespace xyt::ui
