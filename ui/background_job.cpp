// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/background_job.h"

#include <QLabel>

namespace xyt::ui {

void setStatusText(QLabel* label, const QString& text, bool isError) {
    label->setText(text);
    label->setToolTip(text);
    label->setStyleSheet(isError ? QStringLiteral("color: #b00020;") : QString());
}

} // namespace xyt::ui
