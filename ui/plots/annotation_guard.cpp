// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/annotation_guard.h"

#include "ui/plots/legend_columns.h"
#include "ui/plots/legend_corner.h"
#include "ui/plots/tick_spacing.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace xyt::ui {

namespace {

/// Narrower than this a plot is taken as not laid out yet (a widget is 100 px wide until its
/// layout sizes it); the robustness view's plots are from about 150 px at 1366x768.
constexpr int kLaidOutWidth = 120;
constexpr char kAnchor[] = "xyt-annotation-anchor"; ///< the coordinates the plot gave
constexpr char kPlaced[] = "xyt-annotation-placed"; ///< the coordinates the guard moved it to
constexpr char kLines[] = "xyt-wrapped-lines";      ///< a notice's lines, wrapped to its rect
constexpr char kIndent[] = "xyt-wrapped-indent";
constexpr char kTitle[] = "xyt-title-text";       ///< a layout element's text as the plot set it
constexpr char kTitleShown[] = "xyt-title-shown"; ///< the same, broken into lines by the guard

/// @p line broken at spaces into pieces no wider than @p width pixels (a long word stays
/// whole); continuation pieces start with @p indent.
QStringList wrapLine(const QString& line, const QFontMetricsF& metrics, double width,
                     const QString& indent) {
    QStringList out;
    QString current;
    for (const QString& word : line.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QString prefix = out.isEmpty() ? QString() : indent;
        const QString candidate =
            current.isEmpty() ? prefix + word : current + QLatin1Char(' ') + word;
        if (!current.isEmpty() && metrics.horizontalAdvance(candidate) > width) {
            out << current;
            current = indent + word;
        } else {
            current = candidate;
        }
    }
    if (!current.isEmpty())
        out << current;
    return out;
}

/// A notice's lines wrapped to its axis rect (less its padding).
void wrapNotice(QCPItemText* text) {
    const QStringList lines = text->property(kLines).toStringList();
    const QString indent = text->property(kIndent).toString();
    const double width = text->clipAxisRect()->rect().width() - text->padding().left() -
                         text->padding().right() - 4.0;
    const QFontMetricsF metrics(text->font());
    QStringList shown;
    for (const QString& line : lines)
        shown << wrapLine(line, metrics, width, indent);
    const QString joined = shown.join(QLatin1Char('\n'));
    if (text->text() != joined)
        text->setText(joined);
}

/// Breaks the layout's titles and readouts that are wider than their row; true when one
/// changed (the layout must run again).
bool wrapTitles(QCustomPlot* plot) {
    bool changed = false;
    for (int k = 0; k < plot->plotLayout()->elementCount(); ++k) {
        auto* element = qobject_cast<QCPTextElement*>(plot->plotLayout()->elementAt(k));
        if (!element || !element->visible())
            continue;
        QString original = element->text();
        if (element->property(kTitleShown).toString() == original)
            original = element->property(kTitle).toString(); // the guard's own breaks: start over
        const double width = element->rect().width() - 8.0;
        if (width <= 0.0)
            continue;
        const QFontMetricsF metrics(element->font());
        QStringList shown;
        for (const QString& line : original.split(QLatin1Char('\n')))
            shown << wrapLine(line, metrics, width, QString());
        const QString joined = shown.join(QLatin1Char('\n'));
        element->setProperty(kTitle, original);
        element->setProperty(kTitleShown, joined);
        if (element->text() != joined) {
            element->setText(joined);
            changed = true;
        }
    }
    return changed;
}

QRectF rectOf(QCPItemText* text) {
    return QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition()).normalized();
}

/// The least shift that brings @p r inside @p area (its top left corner when it is larger).
QPointF intoArea(const QRectF& r, const QRectF& area) {
    double dx = 0.0, dy = 0.0;
    if (r.right() > area.right())
        dx = area.right() - r.right();
    if (r.left() + dx < area.left())
        dx = area.left() - r.left();
    if (r.bottom() > area.bottom())
        dy = area.bottom() - r.bottom();
    if (r.top() + dy < area.top())
        dy = area.top() - r.top();
    return {dx, dy};
}

bool overlapsAny(const QRectF& r, const std::vector<QRectF>& placed) {
    for (const QRectF& p : placed)
        if (r.intersects(p))
            return true;
    return false;
}

/// @p r moved clear of the rects in @p placed within @p area: just below or just above one
/// of them, the nearest such place; unchanged when none has room.
QRectF apart(const QRectF& r, const QRectF& area, const std::vector<QRectF>& placed) {
    if (!overlapsAny(r, placed))
        return r;
    std::vector<QRectF> candidates;
    for (const QRectF& p : placed) {
        candidates.push_back(r.translated(0.0, p.bottom() + 1.0 - r.top()));
        candidates.push_back(r.translated(0.0, p.top() - 1.0 - r.bottom()));
    }
    std::sort(candidates.begin(), candidates.end(), [&r](const QRectF& a, const QRectF& b) {
        return std::abs(a.top() - r.top()) < std::abs(b.top() - r.top());
    });
    for (const QRectF& c : candidates)
        if (area.contains(c) && !overlapsAny(c, placed))
            return c;
    return r;
}

void placeAnnotations(QCustomPlot* plot) {
    // Titles only on a plot laid out in its window: before it is shown a plot is a default
    // 100 px wide, and rows made tall there would shrink the plane its first view is fitted to.
    if (plot->isVisible() && plot->width() >= kLaidOutWidth) {
        const bool legends = fitLegendColumns(plot);
        const bool ticks = fitTickCounts(plot);
        if (wrapTitles(plot) || legends || ticks)
            plot->replot(QCustomPlot::rpQueuedReplot); // the rows' heights follow on the next pass
    }
    std::vector<QRectF> placed;
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto* text = qobject_cast<QCPItemText*>(plot->item(i));
        if (!text || !text->visible() || !text->clipToAxisRect() || !text->clipAxisRect())
            continue;
        // Back to the plot's own point, unless the plot has set a new one since.
        QPointF coords = text->position->coords();
        const QVariant moved = text->property(kPlaced);
        if (moved.isValid() && moved.toPointF() == coords)
            coords = text->property(kAnchor).toPointF();
        text->position->setCoords(coords);
        text->setProperty(kAnchor, coords);
        if (text->property(kLines).isValid())
            wrapNotice(text);
        text->setProperty(kPlaced, QVariant());
        const QRectF area = text->clipAxisRect()->rect();
        const QRectF from = rectOf(text);
        QRectF r = from.translated(intoArea(from, area));
        r = apart(r, area, placed);
        placed.push_back(r);
        const QPointF shift = r.topLeft() - from.topLeft();
        if (shift.isNull())
            continue;
        text->position->setPixelPosition(text->position->pixelPosition() + shift);
        text->setProperty(kPlaced, text->position->coords());
    }
    // The texts placed, a legend in a plane takes a corner clear of them (and of the traces);
    // it moves at the next layout, which places the texts as now.
    if (plot->isVisible() && plot->width() >= kLaidOutWidth && placeInsetLegends(plot))
        plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace

void setWrappedLines(QCPItemText* text, const QStringList& lines, const QString& indent) {
    text->setProperty(kLines, lines);
    text->setProperty(kIndent, indent);
    text->setText(lines.join(QLatin1Char('\n'))); // until the next drawing wraps them
}

void guardAnnotations(QCustomPlot* plot) {
    // The legends' columns and the value ticks before the layout too: the entries a new design
    // adds or takes out, and the ranges it moves, then cost no second drawing.
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot, [plot] {
        fitLegendColumns(plot);
        if (plot->isVisible() && plot->width() >= kLaidOutWidth)
            fitVerticalTickCounts(plot);
    });
    QObject::connect(plot, &QCustomPlot::afterLayout, plot, [plot] { placeAnnotations(plot); });
}

} // namespace xyt::ui
