// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/stale_veil.h"

#include <QEvent>
#include <QLabel>
#include <QPainter>

#include <algorithm>

namespace xyt::ui {

StaleVeil::StaleVeil(QWidget* covered) : QWidget(covered) {
    note_ = new QLabel(this);
    note_->setWordWrap(true);
    note_->setAlignment(Qt::AlignCenter);
    note_->setStyleSheet(QStringLiteral("QLabel { background: #fff8e1; color: #5d4037; "
                                        "border: 1px solid #e0a800; border-radius: 4px; "
                                        "padding: 8px; }"));
    covered->installEventFilter(this);
    setGeometry(covered->rect());
    hide();
}

void StaleVeil::veil(const QString& note) {
    note_->setText(note);
    note_->setToolTip(note);
    setGeometry(parentWidget()->rect());
    fitNote();
    raise();
    show();
}

void StaleVeil::lift() {
    hide();
}

QString StaleVeil::note() const {
    return note_->text();
}

bool StaleVeil::eventFilter(QObject* watched, QEvent* event) {
    if (watched == parentWidget() && event->type() == QEvent::Resize) {
        setGeometry(parentWidget()->rect());
        fitNote();
    }
    return QWidget::eventFilter(watched, event);
}

void StaleVeil::fitNote() {
    const int margin = 12;
    const int w = std::max(60, std::min(440, width() - 2 * margin));
    const int h = std::min(note_->heightForWidth(w), std::max(20, height() - 2 * margin));
    note_->setGeometry((width() - w) / 2, std::max(0, (height() - h) / 2), w, h);
}

void StaleVeil::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    // Light enough to read the result through, dense enough that it does not look current.
    painter.fillRect(rect(), QColor(255, 255, 255, 170));
}

} // namespace xyt::ui
