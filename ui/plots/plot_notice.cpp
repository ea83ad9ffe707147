// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/plot_notice.h"

#include "ui/plots/annotation_guard.h"

#include <qcustomplot.h>

namespace xyt::ui {

PlotNotice::PlotNotice(QCustomPlot* plot, QCPAxisRect* rect, Qt::Alignment corner) {
    item_ = new QCPItemText(plot);
    item_->setClipToAxisRect(true);
    item_->setClipAxisRect(rect);
    item_->position->setType(QCPItemPosition::ptAxisRectRatio);
    item_->position->setAxisRect(rect);
    const double x = (corner & Qt::AlignRight) ? 0.99 : (corner & Qt::AlignHCenter) ? 0.5 : 0.01;
    const double y = (corner & Qt::AlignBottom) ? 0.99 : (corner & Qt::AlignVCenter) ? 0.5 : 0.01;
    item_->position->setCoords(x, y);
    item_->setPositionAlignment(corner);
    item_->setTextAlignment(Qt::AlignLeft);
    item_->setBrush(QColor(0xff, 0xf4, 0xd6, 235));
    item_->setPen(QPen(QColor(0xe0, 0xb2, 0x4a)));
    item_->setPadding(QMargins(5, 3, 5, 3));
    QFont font = plot->font();
    font.setPointSizeF(8.5);
    item_->setFont(font);
    item_->setLayer(QStringLiteral("legend")); // above the data
    item_->setVisible(false);
}

void PlotNotice::setLines(const QStringList& lines) {
    // Broken at spaces to the width of the axis rect when drawn (annotation_guard.h).
    lines_ = lines;
    setWrappedLines(item_, lines, QStringLiteral("    "));
    item_->setVisible(!lines.isEmpty());
}

void PlotNotice::setSevere(bool severe) {
    item_->setColor(severe ? QColor(0xb7, 0x1c, 0x1c) : QColor(0x3a, 0x2a, 0x00));
}

QString PlotNotice::text() const {
    return item_->visible() ? lines_.join(QLatin1Char('\n')) : QString();
}

bool PlotNotice::isShown() const {
    return item_->visible();
}

void clearWithNotice(QCustomPlot* plot, PlotNotice& notice, std::initializer_list<QCPGraph*> graphs,
                     const QString& reason) {
    for (QCPGraph* g : graphs)
        g->data()->clear();
    notice.setSevere(true);
    notice.setLines({reason});
    plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
