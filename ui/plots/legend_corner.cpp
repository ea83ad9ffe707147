// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/legend_corner.h"

#include <qcustomplot.h>

#include <algorithm>
#include <array>

namespace xyt::ui {

namespace {

constexpr int kMostSampled = 4000; ///< points looked at per trace (a trace can hold 50 000)

template <typename Data> int countIn(QCPAbstractPlottable* p, const Data& data, const QRect& area) {
    const int n = data->size();
    const int stride = std::max(1, n / kMostSampled);
    // In floating point: a diverging trace maps to pixels far beyond an int's range.
    const QRectF inside(area);
    int count = 0;
    for (int i = 0; i < n; i += stride) {
        const auto it = data->at(i);
        const QPointF at = p->coordsToPixels(it->mainKey(), it->mainValue());
        count += inside.contains(at) ? stride : 0; // false for NaN coordinates
    }
    return count;
}

constexpr char kHiddenUnderText[] = "xyt-legend-hidden-under-text";
constexpr int kTextCost = 1 << 24; ///< a text under a legend weighs more than any trace

/// Whether a visible text annotation of @p rect overlaps @p area.
bool textsIn(QCustomPlot* plot, QCPAxisRect* rect, const QRect& area) {
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto* text = qobject_cast<QCPItemText*>(plot->item(i));
        if (!text || !text->visible() || text->text().isEmpty() || text->clipAxisRect() != rect)
            continue;
        const QRectF r =
            QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition()).normalized();
        if (r.intersects(area))
            return true;
    }
    return false;
}

/// @p size placed in corner @p align of @p rect.
QRect inCorner(const QRect& rect, const QSize& size, Qt::Alignment align) {
    const int x = (align & Qt::AlignLeft) ? rect.left() : rect.right() - size.width() + 1;
    const int y = (align & Qt::AlignTop) ? rect.top() : rect.bottom() - size.height() + 1;
    return {QPoint(x, y), size};
}

} // namespace

int pointsIn(QCPAxisRect* rect, const QRect& area) {
    int count = 0;
    for (QCPAbstractPlottable* p : rect->plottables()) {
        if (!p->visible())
            continue;
        if (auto* g = qobject_cast<QCPGraph*>(p))
            count += countIn(p, g->data(), area);
        else if (auto* c = qobject_cast<QCPCurve*>(p))
            count += countIn(p, c->data(), area);
    }
    return count;
}

bool placeInsetLegends(QCustomPlot* plot) {
    constexpr std::array<Qt::Alignment, 4> corners{
        Qt::AlignTop | Qt::AlignRight, Qt::AlignTop | Qt::AlignLeft,
        Qt::AlignBottom | Qt::AlignRight, Qt::AlignBottom | Qt::AlignLeft};
    bool changed = false;
    for (QCPAxisRect* rect : plot->axisRects()) {
        QCPLayoutInset* inset = rect->insetLayout();
        for (int k = 0; k < inset->elementCount(); ++k) {
            auto* legend = qobject_cast<QCPLegend*>(inset->elementAt(k));
            if (!legend || legend->itemCount() == 0 ||
                inset->insetPlacement(k) != QCPLayoutInset::ipBorderAligned)
                continue;
            const bool hiddenHere = legend->property(kHiddenUnderText).toBool();
            if (!legend->visible() && !hiddenHere)
                continue; // hidden by its plot
            const QSize size = legend->outerRect().size();
            const Qt::Alignment now = inset->insetAlignment(k);
            // A notice or a marker's label in a corner rules it out: text on text is unreadable.
            const auto cost = [&](Qt::Alignment corner) {
                const QRect area = inCorner(rect->rect(), size, corner);
                return pointsIn(rect, area) + (textsIn(plot, rect, area) ? kTextCost : 0);
            };
            Qt::Alignment best = now;
            int fewest = cost(now);
            for (Qt::Alignment corner : corners) {
                const int n = fewest == 0 ? 0 : cost(corner);
                if (n < fewest) {
                    fewest = n;
                    best = corner;
                }
            }
            // Texts in every corner (a notice as wide as the plane): the notice is what the
            // plane has to say, the legend waits until it is gone.
            // (The plot may have shown it again since: its visibility is what counts.)
            const bool hide = fewest >= kTextCost;
            if (hide == legend->visible()) {
                legend->setVisible(!hide);
                changed = true;
            }
            legend->setProperty(kHiddenUnderText, hide);
            if (best != now && !hide) {
                inset->setInsetAlignment(k, best);
                changed = true;
            }
        }
    }
    return changed;
}

} // namespace xyt::ui
