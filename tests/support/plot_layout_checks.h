// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a person reading a plot needs of its layout: every annotation (a marker's label, a
// notice, a ζ label) inside its axis rect and none on another, a legend set in the plane inside
// it and on no trace where a corner is free, every legend entry whole, and every title or readout
// line as wide as its text.
#include "ui/plots/damping_labels.h"
#include "ui/plots/legend_corner.h"

#include <QFontMetricsF>
#include <QStringList>
#include <qcustomplot.h>

#include <algorithm>
#include <vector>

namespace xyt::test {

namespace detail {

inline QString shortText(const QString& text) {
    const QString line = text.section(QLatin1Char('\n'), 0, 0);
    return line.size() > 40 ? line.left(40) + QStringLiteral("…") : line;
}

/// Rectangles with a half-pixel allowance for the round-off of the anchors' positions.
inline bool inside(const QRectF& r, const QRectF& area) {
    return area.adjusted(-0.5, -0.5, 0.5, 0.5).contains(r);
}
inline bool overlap(const QRectF& a, const QRectF& b) {
    return a.adjusted(0.5, 0.5, -0.5, -0.5).intersects(b.adjusted(0.5, 0.5, -0.5, -0.5));
}

} // namespace detail

/// The layout faults of @p plot as drawn last, one line each ("" when none).
inline QStringList annotationProblems(QCustomPlot* plot) {
    using detail::shortText;
    QStringList problems;
    const QString where = plot->objectName().isEmpty() ? QString(plot->metaObject()->className())
                                                       : plot->objectName();
    struct Placed {
        QString text;
        QRectF rect;
    };
    std::vector<Placed> texts;
    for (int i = 0; i < plot->itemCount(); ++i) {
        QCPAbstractItem* item = plot->item(i);
        if (!item->visible() || !item->clipAxisRect())
            continue;
        const QRectF area = item->clipAxisRect()->rect();
        if (auto* labels = dynamic_cast<ui::DampingLabels*>(item)) {
            for (const auto& p : labels->placed()) {
                if (!detail::inside(p.rect, area))
                    problems << QString("%1: ζ label '%2' leaves the axis rect").arg(where, p.text);
                texts.push_back({p.text, p.rect});
            }
            continue;
        }
        auto* text = qobject_cast<QCPItemText*>(item);
        if (!text || text->text().isEmpty() || !text->clipToAxisRect())
            continue;
        const QRectF r =
            QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition()).normalized();
        if (!detail::inside(r, area))
            problems << QString(
                            "%1: '%2' at (%3, %4, %5 x %6) leaves the axis rect (%7, %8, %9 x %10)")
                            .arg(where, shortText(text->text()))
                            .arg(r.left())
                            .arg(r.top())
                            .arg(r.width())
                            .arg(r.height())
                            .arg(area.left())
                            .arg(area.top())
                            .arg(area.width())
                            .arg(area.height());
        texts.push_back({text->text(), r});
    }
    for (std::size_t i = 0; i < texts.size(); ++i)
        for (std::size_t j = i + 1; j < texts.size(); ++j)
            if (detail::overlap(texts[i].rect, texts[j].rect))
                problems << QString("%1: '%2' overlaps '%3'")
                                .arg(where, shortText(texts[i].text), shortText(texts[j].text));
    // A legend inside a plane (an axis rect's inset) stays in it, up to the pixel the inset
    // layout's integer rectangles give (QRect's right and bottom are one short of x + width).
    for (QCPAxisRect* rect : plot->axisRects())
        for (int k = 0; k < rect->insetLayout()->elementCount(); ++k)
            if (auto* legend = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(k));
                legend && legend->visible() && legend->itemCount() > 0 &&
                !detail::inside(legend->outerRect(),
                                QRectF(rect->rect()).adjusted(-1.0, -1.0, 1.0, 1.0))) {
                const QRect r = legend->outerRect(), a = rect->rect();
                problems << QString("%1: the legend (%2, %3, %4 x %5) leaves its axis rect (%6, "
                                    "%7, %8 x %9)")
                                .arg(where)
                                .arg(r.left())
                                .arg(r.top())
                                .arg(r.width())
                                .arg(r.height())
                                .arg(a.left())
                                .arg(a.top())
                                .arg(a.width())
                                .arg(a.height());
            }
    // Every legend entry as wide as its icon and text: a row too narrow for its columns cuts
    // the entries' text ("closed-loop unit ste"). One pixel of allowance for the layout's
    // integer round-off.
    if (QCPLegend* legend = plot->legend; legend && legend->visible()) {
        for (int i = 0; i < legend->itemCount(); ++i) {
            QCPAbstractLegendItem* item = legend->item(i);
            if (!item)
                continue; // an empty cell
            const QCPLayoutElement* element = item;
            const int needs = element->minimumOuterSizeHint().width();
            const QRect r = item->outerRect();
            QString text;
            if (auto* p = qobject_cast<QCPPlottableLegendItem*>(item))
                text = p->plottable()->name();
            if (r.width() + 1 < needs || r.right() > plot->viewport().right() + 1)
                problems << QString("%1: the legend entry '%2' needs %3 px, has %4 (from x = %5, "
                                    "plot %6 px)")
                                .arg(where, shortText(text))
                                .arg(needs)
                                .arg(r.width())
                                .arg(r.left())
                                .arg(plot->viewport().width());
        }
    }
    // Tick labels apart along their axis ("3.34853.34863.3487" where a histogram's range was
    // a round-off wide). One pixel of allowance.
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes()) {
            if (!axis->visible() || !axis->tickLabels())
                continue;
            const QFontMetricsF metrics(axis->tickLabelFont());
            const bool horizontal = axis->orientation() == Qt::Horizontal;
            const QVector<double> ticks = axis->tickVector();
            const QVector<QString> labels = axis->tickVectorLabels();
            struct Span {
                double start, end;
                QString text;
            };
            std::vector<Span> spans;
            for (int i = 0; i < ticks.size() && i < labels.size(); ++i) {
                if (!axis->range().contains(ticks[i]) || labels[i].isEmpty())
                    continue;
                const double centre = axis->coordToPixel(ticks[i]);
                const double extent =
                    horizontal ? metrics.horizontalAdvance(labels[i]) : metrics.height();
                spans.push_back({centre - extent / 2, centre + extent / 2, labels[i]});
            }
            std::sort(spans.begin(), spans.end(),
                      [](const Span& a, const Span& b) { return a.start < b.start; });
            for (std::size_t i = 1; i < spans.size(); ++i)
                if (spans[i].start + 1.0 < spans[i - 1].end)
                    problems << QString("%1: tick labels '%2' and '%3' overlap on the axis '%4'")
                                    .arg(where, spans[i - 1].text, spans[i].text, axis->label());
        }
    // A legend in a corner of a plane sits on no trace where another corner is clearer.
    for (QCPAxisRect* rect : plot->axisRects()) {
        QCPLayoutInset* inset = rect->insetLayout();
        for (int k = 0; k < inset->elementCount(); ++k) {
            auto* legend = qobject_cast<QCPLegend*>(inset->elementAt(k));
            if (!legend || !legend->visible() || legend->itemCount() == 0 ||
                inset->insetPlacement(k) != QCPLayoutInset::ipBorderAligned)
                continue;
            const QRect at = legend->outerRect(), area = rect->rect();
            for (const Placed& t : texts)
                if (detail::overlap(t.rect, at))
                    problems
                        << QString("%1: the legend overlaps '%2'").arg(where, shortText(t.text));
            const int covered = ui::pointsIn(rect, at);
            for (const QPoint corner :
                 {area.topLeft(), QPoint(area.right() - at.width() + 1, area.top()),
                  QPoint(area.left(), area.bottom() - at.height() + 1),
                  QPoint(area.right() - at.width() + 1, area.bottom() - at.height() + 1)})
                if (const int there = ui::pointsIn(rect, QRect(corner, at.size())); there < covered)
                    problems
                        << QString("%1: the legend covers %2 trace points where a corner covers %3")
                               .arg(where)
                               .arg(covered)
                               .arg(there);
        }
    }
    // Titles and readouts of the layout: each line as wide as its element.
    for (int k = 0; k < plot->plotLayout()->elementCount(); ++k) {
        auto* element = qobject_cast<QCPTextElement*>(plot->plotLayout()->elementAt(k));
        if (!element || !element->visible() || element->text().isEmpty())
            continue;
        const QFontMetricsF metrics(element->font());
        const double room = element->rect().width();
        for (const QString& line : element->text().split(QLatin1Char('\n')))
            if (metrics.horizontalAdvance(line) > room + 1.0)
                problems << QString("%1: '%2' needs %3 px, has %4")
                                .arg(where, shortText(line))
                                .arg(metrics.horizontalAdvance(line))
                                .arg(room);
    }
    return problems;
}

} // namespace xyt::test
