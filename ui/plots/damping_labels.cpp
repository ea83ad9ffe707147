// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/damping_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt::ui {

namespace {

constexpr double kInset = 2.0; ///< pixels kept between a label and the axis rect's edge

} // namespace

DampingLabels::DampingLabels(QCustomPlot* plot) : QCPAbstractItem(plot) {
    setSelectable(false);
    setClipToAxisRect(true);
}

void DampingLabels::setLabels(std::vector<Label> labels) {
    labels_ = std::move(labels);
}

double DampingLabels::selectTest(const QPointF&, bool, QVariant*) const {
    return -1.0;
}

QRectF DampingLabels::rectFor(const Label& label, const QSizeF& size, const QRectF& area) const {
    const QCPAxis* x = parentPlot()->xAxis;
    const QCPAxis* y = parentPlot()->yAxis;
    const auto pixel = [&](std::complex<double> z) {
        return QPointF(x->coordToPixel(z.real()), y->coordToPixel(z.imag()));
    };
    const QPointF anchor = pixel(label.anchor);
    if (label.direction == 0.0) { // centred above its point
        return QRectF(anchor.x() - size.width() / 2.0, anchor.y() - size.height(), size.width(),
                      size.height());
    }
    // The ray o + t d (t >= 0, pixels) clipped to the area: the label goes where it leaves.
    const QPointF d = pixel(label.anchor + label.direction) - anchor;
    const double length = std::hypot(d.x(), d.y());
    if (!(length > 0.0))
        return {};
    const QPointF u = d / length;
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    const auto slab = [&](double o, double du, double lo, double hi) {
        if (du == 0.0)
            return o >= lo && o <= hi;
        double a = (lo - o) / du, b = (hi - o) / du;
        if (a > b)
            std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        return t0 <= t1;
    };
    if (!slab(anchor.x(), u.x(), area.left(), area.right()) ||
        !slab(anchor.y(), u.y(), area.top(), area.bottom()))
        return {};
    const QPointF exit = anchor + t1 * u;
    // Back along the ray by half the label's extent in that direction, then into the area.
    const double back =
        0.5 * (size.width() * std::abs(u.x()) + size.height() * std::abs(u.y())) + kInset;
    QRectF r(QPointF(), size);
    r.moveCenter(exit - back * u);
    r.moveLeft(std::clamp(r.left(), area.left(), area.right() - r.width()));
    r.moveTop(std::clamp(r.top(), area.top(), area.bottom() - r.height()));
    return r;
}

void DampingLabels::draw(QCPPainter* painter) {
    placed_.clear();
    const QRectF area = clipRect().toRectF().adjusted(kInset, kInset, -kInset, -kInset);
    const QFont font(parentPlot()->font().family(), 7);
    const QFontMetricsF metrics(font);
    painter->setFont(font);
    painter->setPen(QColor(0x9a, 0x9a, 0x9a));
    // The plot's annotations (notices, marker labels) are placed before the drawing
    // (annotation_guard.h): a ζ label gives way to them.
    std::vector<QRectF> taken;
    for (int i = 0; i < parentPlot()->itemCount(); ++i)
        if (auto* text = qobject_cast<QCPItemText*>(parentPlot()->item(i));
            text && text->visible() && !text->text().isEmpty() &&
            text->clipAxisRect() == clipAxisRect())
            taken.push_back(
                QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition())
                    .normalized());
    for (const Label& label : labels_) {
        const QSizeF size(metrics.horizontalAdvance(label.text) + 2.0, metrics.height());
        const QRectF r = rectFor(label, size, area);
        if (r.isEmpty() || !area.contains(r))
            continue;
        const bool overlaps = std::any_of(placed_.begin(), placed_.end(),
                                          [&](const Placed& p) {
                                              return p.rect.adjusted(-1, -1, 1, 1).intersects(r);
                                          }) ||
                              std::any_of(taken.begin(), taken.end(),
                                          [&](const QRectF& t) { return t.intersects(r); });
        if (overlaps)
            continue;
        painter->drawText(r, Qt::AlignCenter, label.text);
        placed_.push_back({label.text, r});
    }
}

} // namespace xyt::ui
