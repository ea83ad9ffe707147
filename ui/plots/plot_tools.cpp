// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/plot_tools.h"
#include "ui/plots/annotation_guard.h"
#include "ui/plots/legend_columns.h"
#include "ui/plots/plot_widget.h"

#include "ui/plots/plane_grid.h"

#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {
std::size_t bucketSize(std::size_t n, int buckets) {
    return buckets > 0
               ? (n + static_cast<std::size_t>(buckets) - 1) / static_cast<std::size_t>(buckets)
               : n;
}
} // namespace

QVector<QCPGraphData> minMaxDecimated(const std::vector<double>& t, const std::vector<double>& y,
                                      int buckets) {
    const std::size_t n = std::min(t.size(), y.size());
    QVector<QCPGraphData> out;
    if (n <= 2 * static_cast<std::size_t>(std::max(buckets, 1))) {
        out.reserve(static_cast<qsizetype>(n));
        for (std::size_t k = 0; k < n; ++k)
            out.append(QCPGraphData(t[k], y[k]));
        return out;
    }
    const std::size_t size = bucketSize(n, buckets);
    out.reserve(2 * buckets + 2);
    for (std::size_t begin = 0; begin < n; begin += size) {
        const std::size_t end = std::min(n, begin + size);
        std::size_t lo = begin, hi = begin;
        for (std::size_t k = begin; k < end; ++k) {
            // A non-finite sample is kept as such: the line shows a gap, not a made-up value.
            if (!std::isfinite(y[k])) {
                lo = hi = k;
                break;
            }
            if (y[k] < y[lo])
                lo = k;
            if (y[k] > y[hi])
                hi = k;
        }
        const std::size_t first = std::min(lo, hi), second = std::max(lo, hi);
        out.append(QCPGraphData(t[first], y[first]));
        if (second != first)
            out.append(QCPGraphData(t[second], y[second]));
    }
    // The last sample ends the line where the run ends.
    if (out.last().key != t[n - 1])
        out.append(QCPGraphData(t[n - 1], y[n - 1]));
    return out;
}

QVector<QCPGraphData> flagDecimated(const std::vector<double>& t, const std::vector<bool>& flags,
                                    double valueWhenSet, int buckets) {
    const std::size_t n = std::min(t.size(), flags.size());
    const bool decimate = n > 2 * static_cast<std::size_t>(std::max(buckets, 1));
    const std::size_t size = decimate ? bucketSize(n, buckets) : 1;
    QVector<QCPGraphData> out;
    out.reserve(static_cast<qsizetype>(decimate ? 2 * buckets + 2 : n));
    for (std::size_t begin = 0; begin < n; begin += size) {
        const std::size_t end = std::min(n, begin + size);
        bool any = false;
        for (std::size_t k = begin; k < end && !any; ++k)
            any = flags[k];
        const double v = any ? valueWhenSet : qQNaN();
        out.append(QCPGraphData(t[begin], v));
        if (end - 1 != begin)
            out.append(QCPGraphData(t[end - 1], v));
    }
    return out;
}

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
    if (auto* widget = qobject_cast<PlotWidget*>(plot))
        widget->releaseView();  // the automatic fit takes over again
    if (resetPlaneView(plot)) { // a complex plane returns to its fitted, equal-aspect view
        plot->replot();
        return;
    }
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
    const QString path =
        QFileDialog::getSaveFileName(plot, QObject::tr("Save plot"), suggestedName,
                                     QObject::tr("PNG image (*.png);;PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!savePlot(plot, path, &error))
        QMessageBox::warning(plot, QObject::tr("Save plot"), error);
}

void placeLegendBelow(QCustomPlot* plot, int row, int columns) {
    QCPLegend* legend = plot->legend;
    legend->setVisible(true);
    legend->setFont(QFont(plot->font().family(), 8));
    legend->setBorderPen(Qt::NoPen);
    setMaxLegendColumns(legend, columns); // fewer when the row is narrow (fitLegendColumns)
    plot->axisRect()->insetLayout()->take(legend);
    plot->plotLayout()->addElement(row, 0, legend);
    plot->plotLayout()->setRowStretchFactor(row, 0.001);
}

void setupInteractivePlot(QCustomPlot* plot) {
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    // Fast polylines: a slider drag redraws several 13 000-point graphs per step.
    plot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
    plot->setNotAntialiasedElements(QCP::aePlottables);
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    plot->setMinimumSize(240, 180);
    plot->setNoAntialiasingOnDrag(true);
    guardAnnotations(plot); // marker labels and notices inside the frame, none on another
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

QCPTextElement* addTextRow(QCustomPlot* plot, int row, const QString& text) {
    auto* element = new QCPTextElement(plot, text, QFont(plot->font().family(), 8));
    element->setTextFlags(Qt::AlignLeft | Qt::AlignVCenter);
    element->setMargins(QMargins(8, 0, 8, 2));
    plot->plotLayout()->addElement(row, 0, element);
    plot->plotLayout()->setRowStretchFactor(row, 0.001);
    return element;
}

QCPItemText* addAnnotation(QCustomPlot* plot, QCPAxisRect* rect, double x, double y,
                           const QString& text, const QColor& color, Qt::Alignment align,
                           bool rightHalf) {
    auto* label = new QCPItemText(plot);
    label->setClipAxisRect(rect);
    label->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    label->position->setCoords(x, y);
    label->setPositionAlignment(rightHalf ? (align & ~Qt::AlignLeft) | Qt::AlignRight : align);
    label->setText(text);
    label->setColor(color);
    label->setFont(QFont(plot->font().family(), 8));
    label->setBrush(QColor(255, 255, 255, 210));
    label->setPadding(QMargins(3, 1, 3, 1));
    return label;
}

void setReadoutText(QCustomPlot* plot, QCPTextElement* readout, const QString& text) {
    if (readout->text() == text)
        return;
    readout->setText(text);
    plot->replot(QCustomPlot::rpQueuedReplot);
}

void compactLegend(QCPLegend* legend) {
    legend->setIconSize(14, 12);
    legend->setIconTextPadding(4);
    legend->setColumnSpacing(6);
}

bool curvesBoundingBox(const std::vector<QCPCurve*>& curves, QCPRange& xRange, QCPRange& yRange) {
    bool found = false;
    for (QCPCurve* c : curves) {
        bool okX = false, okY = false;
        const QCPRange cx = c->getKeyRange(okX);
        const QCPRange cy = c->getValueRange(okY);
        if (!okX || !okY)
            continue;
        xRange = found
                     ? QCPRange(std::min(xRange.lower, cx.lower), std::max(xRange.upper, cx.upper))
                     : cx;
        yRange = found
                     ? QCPRange(std::min(yRange.lower, cy.lower), std::max(yRange.upper, cy.upper))
                     : cy;
        found = true;
    }
    return found;
}

QCPColorGradient viridisGradient() {
    QCPColorGradient g;
    g.clearColorStops();
    g.setColorStopAt(0.0, QColor(0x44, 0x01, 0x54));
    g.setColorStopAt(0.25, QColor(0x3b, 0x52, 0x8b));
    g.setColorStopAt(0.5, QColor(0x21, 0x91, 0x8c));
    g.setColorStopAt(0.75, QColor(0x5e, 0xc9, 0x62));
    g.setColorStopAt(1.0, QColor(0xfd, 0xe7, 0x25));
    g.setColorInterpolation(QCPColorGradient::ciRGB);
    g.setNanHandling(QCPColorGradient::nhTransparent);
    g.setLevelCount(256);
    return g;
}

} // namespace xyt::ui
