// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plot_tools.h"

#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>

#include <qcustomplot.h>

namespace xyt::ui {

void styleAxisRect(QCPAxisRect* rect) {
    for (QCPAxis* axis : rect->axes()) {
        // Solid, light grid lines: dotted pens are several times slower to rasterize.
        axis->grid()->setPen(QPen(QColor(0xe6, 0xe6, 0xe6), 0, Qt::SolidLine));
        axis->grid()->setZeroLinePen(QPen(QColor(0xb0, 0xb0, 0xb0)));
        QFont f = axis->labelFont();
        f.setPointSizeF(9);
        axis->setLabelFont(f);
        axis->setTickLabelFont(f);
    }
}

void resetView(QCustomPlot* plot) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        bool any = false;
        for (QCPAxis* axis : rect->axes())
            for (QCPAbstractPlottable* p : axis->plottables())
                if (p->visible()) {
                    any = true;
                    break;
                }
        if (!any)
            continue;
        for (QCPAxis* axis : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)}) {
            axis->rescale(true);
            const QCPRange r = axis->range();
            const double pad = r.size() > 0 ? 0.05 * r.size() : 1.0;
            axis->setRange(r.lower - pad, r.upper + pad);
        }
    }
    plot->replot();
}

bool savePlot(QCustomPlot* plot, const QString& path, QString* error) {
    const bool pdf = path.endsWith(".pdf", Qt::CaseInsensitive);
    const bool ok = pdf ? plot->savePdf(path) : plot->savePng(path, 0, 0, 2.0);
    if (!ok && error)
        *error = QObject::tr("Could not write %1").arg(path);
    return ok;
}

void savePlotDialog(QCustomPlot* plot, const QString& suggestedName) {
    const QString path = QFileDialog::getSaveFileName(
        plot, QObject::tr("Save plot"), suggestedName,
        QObject::tr("PNG image (*.png);;PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!savePlot(plot, path, &error))
        QMessageBox::warning(plot, QObject::tr("Save plot"), error);
}

void setupInteractivePlot(QCustomPlot* plot) {
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    // Fast polylines: a slider drag redraws several 13 000-point graphs per step.
    plot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
    plot->setNotAntialiasedElements(QCP::aePlottables);
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    plot->setMinimumSize(240, 180);
    plot->setNoAntialiasingOnDrag(true);
    QObject::connect(plot, &QCustomPlot::mouseDoubleClick, plot,
                     [plot](QMouseEvent*) { resetView(plot); });
    QObject::connect(plot, &QWidget::customContextMenuRequested, plot, [plot](const QPoint& pos) {
        QMenu menu(plot);
        menu.addAction(QObject::tr("Reset view"), plot, [plot] { resetView(plot); });
        menu.addSeparator();
        menu.addAction(QObject::tr("Save as PNG..."), plot,
                       [plot] { savePlotDialog(plot, plot->objectName() + ".png"); });
        menu.addAction(QObject::tr("Save as PDF..."), plot,
                       [plot] { savePlotDialog(plot, plot->objectName() + ".pdf"); });
        menu.exec(plot->mapToGlobal(pos));
    });
}

} // namespace xyt::ui
