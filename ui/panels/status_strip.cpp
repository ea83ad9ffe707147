// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/status_strip.h"

#include <QLabel>
#include <QProgressBar>

#include <cmath>

namespace xyt::ui {

void setStatusText(QLabel* label, const QString& text, bool isError) {
    label->setText(text);
    label->setToolTip(text);
    label->setStyleSheet(isError ? QStringLiteral("color: #b00020;") : QString());
}

void showProgress(QProgressBar* bar, double fraction) {
    bar->setValue(static_cast<int>(std::lround(100.0 * fraction)));
}

} // namespace xyt::ui
