// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/plane_grid.h"

#include "ui/plots/damping_labels.h"

#include "core/analysis/damping_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace xyt::ui {

QCPCurve* addComplexCurve(QCustomPlot* plot, const std::vector<std::complex<double>>& points,
                          const QPen& pen) {
    auto* curve = new QCPCurve(plot->xAxis, plot->yAxis);
    QVector<double> t(static_cast<qsizetype>(points.size())), x(t.size()), y(t.size());
    for (qsizetype i = 0; i < t.size(); ++i) {
        t[i] = static_cast<double>(i);
        x[i] = points[static_cast<std::size_t>(i)].real();
        y[i] = points[static_cast<std::size_t>(i)].imag();
    }
    curve->setData(t, x, y, true);
    curve->setPen(pen);
    return curve;
}

void showBranches(QCustomPlot* plot, std::vector<QCPCurve*>& curves,
                  const std::vector<std::vector<std::complex<double>>>& branches,
                  const std::function<QPen(std::size_t)>& penFor) {
    while (curves.size() > branches.size()) {
        plot->removePlottable(curves.back());
        curves.pop_back();
    }
    while (curves.size() < branches.size()) {
        auto* c = new QCPCurve(plot->xAxis, plot->yAxis);
        c->setPen(penFor(curves.size()));
        c->removeFromLegend();
        curves.push_back(c);
    }
    for (std::size_t b = 0; b < branches.size(); ++b) {
        const auto& roots = branches[b];
        QVector<QCPCurveData> data;
        data.reserve(static_cast<qsizetype>(roots.size()));
        for (std::size_t i = 0; i < roots.size(); ++i)
            data.append(QCPCurveData(static_cast<double>(i), roots[i].real(), roots[i].imag()));
        curves[b]->data()->set(data, true);
    }
}

void setComplexPoints(QCPGraph* graph, const std::vector<std::complex<double>>& points) {
    // QCPGraph sorts by key; points with equal real parts are kept (it is a scatter only).
    QVector<QCPGraphData> data;
    data.reserve(static_cast<qsizetype>(points.size()));
    for (const auto& p : points)
        if (std::isfinite(p.real()) && std::isfinite(p.imag()))
            data.append(QCPGraphData(p.real(), p.imag()));
    graph->data()->set(data, false);
}

bool anyOutsideView(const QCustomPlot* plot, const std::vector<std::complex<double>>& points) {
    const QCPRange re = plot->xAxis->range(), im = plot->yAxis->range();
    for (const auto& p : points)
        if (std::isfinite(p.real()) && std::isfinite(p.imag()) &&
            (!re.contains(p.real()) || !im.contains(p.imag())))
            return true;
    return false;
}

PlaneBox fittedBox(PlaneBox base, const std::vector<std::complex<double>>& points) {
    PlaneBox b = base;
    bool first = !(b.reMax > b.reMin && b.imMax > b.imMin);
    for (const auto& p : points) {
        if (!std::isfinite(p.real()) || !std::isfinite(p.imag()))
            continue;
        if (first) {
            b = {p.real(), p.real(), p.imag(), p.imag()};
            first = false;
            continue;
        }
        b.reMin = std::min(b.reMin, p.real());
        b.reMax = std::max(b.reMax, p.real());
        b.imMin = std::min(b.imMin, p.imag());
        b.imMax = std::max(b.imMax, p.imag());
    }
    if (first)
        return {-1.0, 1.0, -1.0, 1.0};
    const double extent = std::max({b.reMax - b.reMin, b.imMax - b.imMin,
                                    1e-3 * std::max({std::abs(b.reMin), std::abs(b.reMax), 1.0})});
    const double pad = 0.08 * extent;
    // Keep the imaginary axis symmetric: conjugate pairs then sit at equal heights.
    const double im = std::max(std::abs(b.imMin), std::abs(b.imMax)) + pad;
    return {b.reMin - pad, b.reMax + pad, -std::max(im, 0.3 * extent), std::max(im, 0.3 * extent)};
}

namespace {
/**
 * Keeps a complex-plane view at equal aspect (one unit is as many pixels on both axes, so the
 * unit circle is a circle and the damping lines have their true angles). It remembers the box
 * wanted (the last fit, or the user's drag and zoom) and shows the smallest equal-aspect view
 * around it, again whenever the plot's size changes.
 */
class AspectKeeper : public QObject {
public:
    explicit AspectKeeper(QCustomPlot* plot) : QObject(plot), plot_(plot) {
        setObjectName(QStringLiteral("xyt-aspect-keeper"));
        const auto userChange = [this] {
            if (!applying_)
                wanted_ = current();
        };
        connect(plot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, userChange);
        connect(plot->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, userChange);
        connect(plot, &QCustomPlot::afterLayout, this, [this] {
            if (plot_->axisRect()->size() != lastSize_)
                apply();
        });
    }
    void fit(const PlaneBox& box) {
        fitted_ = wanted_ = box;
        apply();
    }
    void reset() { fit(fitted_); }

private:
    PlaneBox current() const {
        const QCPRange x = plot_->xAxis->range(), y = plot_->yAxis->range();
        return {x.lower, x.upper, y.lower, y.upper};
    }
    void apply() {
        applying_ = true;
        const QSize px = plot_->axisRect()->size();
        lastSize_ = px;
        PlaneBox b = wanted_;
        if (px.width() > 10 && px.height() > 10) {
            const double unitsPerPixel =
                std::max((b.reMax - b.reMin) / px.width(), (b.imMax - b.imMin) / px.height());
            const double cx = 0.5 * (b.reMin + b.reMax), cy = 0.5 * (b.imMin + b.imMax);
            const double hx = 0.5 * unitsPerPixel * px.width(),
                         hy = 0.5 * unitsPerPixel * px.height();
            b = {cx - hx, cx + hx, cy - hy, cy + hy};
        }
        plot_->xAxis->setRange(b.reMin, b.reMax);
        plot_->yAxis->setRange(b.imMin, b.imMax);
        applying_ = false;
    }
    QCustomPlot* plot_;
    PlaneBox fitted_{-1.0, 1.0, -1.0, 1.0}, wanted_ = fitted_;
    QSize lastSize_;
    bool applying_ = false;
};

AspectKeeper* keeperOf(QCustomPlot* plot) {
    if (auto* k = plot->findChild<AspectKeeper*>(QStringLiteral("xyt-aspect-keeper"),
                                                 Qt::FindDirectChildrenOnly))
        return k;
    return new AspectKeeper(plot);
}
} // namespace

void setView(QCustomPlot* plot, const PlaneBox& box) {
    keeperOf(plot)->fit(box);
}

bool resetPlaneView(QCustomPlot* plot) {
    auto* k = plot->findChild<AspectKeeper*>(QStringLiteral("xyt-aspect-keeper"),
                                             Qt::FindDirectChildrenOnly);
    if (!k)
        return false;
    k->reset();
    return true;
}

PlaneGrid::PlaneGrid(QCustomPlot* plot) : plot_(plot) {}

void PlaneGrid::clear() {
    for (QCPCurve* c : curves_)
        plot_->removePlottable(c);
    if (labels_)
        plot_->removeItem(labels_);
    curves_.clear();
    labels_ = nullptr;
}

void PlaneGrid::setVisible(bool visible) {
    visible_ = visible;
    for (QCPCurve* c : curves_)
        c->setVisible(visible);
    if (labels_)
        labels_->setVisible(visible);
}

void PlaneGrid::show(double tsSeconds, double maxOmegaRadPerSec) {
    // Rebuild only when the plane or the frequency scale changes by more than a factor 2:
    // a slider drag must not rebuild the grid on every step.
    if (tsSeconds == ts_ && maxOmega_ > 0 && maxOmegaRadPerSec <= maxOmega_ &&
        maxOmegaRadPerSec > maxOmega_ / 2)
        return;
    clear();
    ts_ = tsSeconds;
    maxOmega_ = maxOmegaRadPerSec;
    const QPen pen(QColor(0xdc, 0xdc, 0xdc), 0,
                   Qt::SolidLine); // solid: dotted pens rasterize slowly
    const DampingGrid grid =
        tsSeconds > 0.0
            ? zPlaneDampingGrid(defaultGridZetas(), defaultZGridFrequencies(tsSeconds), tsSeconds)
            : sPlaneDampingGrid(defaultGridZetas(), niceGridFrequencies(maxOmegaRadPerSec),
                                maxOmegaRadPerSec);
    for (const GridLine& line : grid.dampingLines)
        curves_.push_back(addComplexCurve(plot_, line.points, pen));
    for (const GridLine& line : grid.frequencyLines)
        curves_.push_back(addComplexCurve(plot_, line.points, pen));
    if (tsSeconds > 0.0) {
        std::vector<std::complex<double>> circle;
        for (int i = 0; i <= 180; ++i)
            circle.push_back(std::polar(1.0, 2.0 * std::numbers::pi * i / 180.0));
        curves_.push_back(addComplexCurve(plot_, circle, QPen(QColor(0x60, 0x60, 0x60), 1.2)));
    }
    // s-plane: each ray from the origin, labelled where it leaves the view. z-plane: every line
    // starts at z = 1 (s = 0), where the labels would pile up; the top of each spiral is a
    // point of its own.
    std::vector<DampingLabels::Label> labels;
    for (const GridLine& line : grid.dampingLines) {
        if (line.points.empty())
            continue;
        const QString text = QStringLiteral("ζ=%1").arg(line.value);
        if (tsSeconds > 0.0)
            labels.push_back({text,
                              *std::max_element(
                                  line.points.begin(), line.points.end(),
                                  [](const auto& a, const auto& b) { return a.imag() < b.imag(); }),
                              0.0});
        else
            labels.push_back({text, 0.0, line.points.front()});
    }
    labels_ = new DampingLabels(plot_);
    labels_->setLayer("grid");
    labels_->setLabels(std::move(labels));
    for (QCPCurve* c : curves_) {
        c->setLayer("grid");
        c->removeFromLegend();
        c->setSelectable(QCP::stNone);
    }
    setVisible(visible_);
}

} // namespace xyt::ui
