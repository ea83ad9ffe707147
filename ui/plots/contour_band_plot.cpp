// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/contour_band_plot.h"

#include "ui/plots/plot_tools.h"

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {

/// The largest 1-2-5 step <= v (v > 0).
double niceFloor(double v) {
    const double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * decade <= v)
            return m * decade;
    return decade;
}

/// The index ranges [first, last] of the pieces of the judged contour: a new piece starts where
/// two consecutive base points lie more than 5 median spacings apart (the samples between were
/// not judged: a rapid of a program).
std::vector<std::pair<std::size_t, std::size_t>> pieces(const std::vector<Point2>& base) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    if (base.empty())
        return out;
    std::vector<double> gaps;
    for (std::size_t j = 1; j < base.size(); ++j)
        gaps.push_back(norm(base[j] - base[j - 1]));
    std::vector<double> sorted = gaps;
    std::nth_element(sorted.begin(),
                     sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
    std::size_t first = 0;
    for (std::size_t j = 1; j < base.size(); ++j)
        if (median > 0.0 && gaps[j - 1] > 5.0 * median) {
            out.emplace_back(first, j - 1);
            first = j;
        }
    out.emplace_back(first, base.size() - 1);
    return out;
}

} // namespace

ContourBandPlot::ContourBandPlot(QWidget* parent) : PlotWidget(parent) {
    setObjectName("robustness-contour-band");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("XY contour"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("x (mm)"));
    yAxis->setLabel(tr("y (mm)"));
    legend->setVisible(false); // the plot is narrow: the tooltip says what is drawn
    setToolTip(
        tr("The programmed contour dashed, the nominal design's traced contour solid, and the band "
           "the mismatched plant pairs trace (min–max light, 5–95 % darker); the contour error is "
           "magnified about the contour by the factor in the title."));
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
    // The axis rect has its final size only once the layout has run (a hidden page of a stack
    // has none before): fit then, once per new result or size.
    connect(this, &QCustomPlot::afterLayout, this, [this] {
        if (fitPending_)
            fitEqualScale();
    });
    showNoResult(tr("Not computed yet."));
}

ContourBandPlot::~ContourBandPlot() = default;

QCPCurve* ContourBandPlot::addCurve(const QPen& pen, const QBrush& brush) {
    auto* c = new QCPCurve(xAxis, yAxis);
    c->setPen(pen);
    c->setBrush(brush);
    c->removeFromLegend();
    return c;
}

void ContourBandPlot::clearCurves() {
    for (auto* list : {&outer_, &inner_, &programmed_, &nominal_}) {
        for (QCPCurve* c : *list)
            removePlottable(c);
        list->clear();
    }
}

void ContourBandPlot::showResult(const ContourRobustnessResult& r) {
    clearCurves();
    const SignalEnvelope& e = r.error;
    hasResult_ = !e.t.empty() && r.base.size() == e.t.size();
    if (!hasResult_) {
        showNoResult(tr("No stable plant pair: no band."));
        return;
    }
    // Magnify so that the band's outer edge spans about a tenth of the contour's size for 90 % of
    // the time: a short transient (the end of a circle's ramp-in, a corner) may reach farther,
    // rather than flatten the band everywhere else to nothing.
    double minX = r.base[0].x, maxX = minX, minY = r.base[0].y, maxY = minY;
    std::vector<double> outer;
    for (std::size_t j = 0; j < r.base.size(); ++j) {
        minX = std::min(minX, r.base[j].x), maxX = std::max(maxX, r.base[j].x);
        minY = std::min(minY, r.base[j].y), maxY = std::max(maxY, r.base[j].y);
        outer.push_back(std::max({std::abs(e.min[j]), std::abs(e.max[j]), std::abs(e.nominal[j])}));
    }
    std::sort(outer.begin(), outer.end());
    const double typical =
        outer[static_cast<std::size_t>(0.9 * static_cast<double>(outer.size() - 1))];
    const double size = std::max(maxX - minX, maxY - minY);
    magnification_ =
        typical > 0.0 && size > 0.0 ? std::max(1.0, niceFloor(0.1 * size / typical)) : 1.0;
    const double m = magnification_;
    const auto at = [&](std::size_t j, double err) {
        return QCPCurveData(0.0, r.base[j].x + m * err * r.normal[j].x,
                            r.base[j].y + m * err * r.normal[j].y);
    };
    const QColor band = colors::output;
    for (const auto& piece : pieces(r.base)) {
        const std::size_t first = piece.first,
                          last = piece.second; // (clang 14 cannot capture bindings)
        // A band is one closed polygon: its upper edge forward, its lower edge back.
        const auto polygon = [&](const std::vector<double>& lo, const std::vector<double>& hi,
                                 int alpha) {
            QVector<QCPCurveData> d;
            for (std::size_t j = first; j <= last; ++j)
                d.append(at(j, hi[j]));
            for (std::size_t j = last + 1; j-- > first;)
                d.append(at(j, lo[j]));
            for (int i = 0; i < d.size(); ++i)
                d[i].t = i;
            QCPCurve* c =
                addCurve(QPen(Qt::NoPen), QColor(band.red(), band.green(), band.blue(), alpha));
            c->data()->set(d, true);
            return c;
        };
        outer_.push_back(polygon(e.min, e.max, 45));
        inner_.push_back(polygon(e.p05, e.p95, 90));
        QVector<QCPCurveData> programmed, nominal;
        for (std::size_t j = first; j <= last; ++j) {
            programmed.append({static_cast<double>(j), r.base[j].x, r.base[j].y});
            QCPCurveData n = at(j, e.nominal[j]);
            n.t = static_cast<double>(j);
            nominal.append(n);
        }
        programmed_.push_back(addCurve(QPen(colors::reference, 1.2, Qt::DashLine), Qt::NoBrush));
        programmed_.back()->data()->set(programmed, true);
        nominal_.push_back(addCurve(QPen(colors::reference.darker(150), 1.6), Qt::NoBrush));
        nominal_.back()->data()->set(nominal, true);
    }
    title_->setText(tr("XY contour, error ×%1").arg(QString::number(m, 'g', 4)));
    notice_->setSevere(false);
    notice_->setLines({});
    fitPending_ = true;
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourBandPlot::showNoResult(const QString& reason) {
    clearCurves();
    hasResult_ = false;
    title_->setText(tr("XY contour"));
    clearWithNotice(this, *notice_, {}, reason);
}

void ContourBandPlot::fitEqualScale() {
    QCPRange xr, yr;
    const bool found = curvesBoundingBox(outer_, xr, yr);
    const double w = axisRect()->width(), h = axisRect()->height();
    if (!found || w <= 0 || h <= 0)
        return;
    fitPending_ = false;
    const double span = std::max({xr.size() / w, yr.size() / h, 1e-9}) * 1.08;
    xAxis->setRange(xr.center(), span * w, Qt::AlignCenter);
    yAxis->setRange(yr.center(), span * h, Qt::AlignCenter);
}

void ContourBandPlot::resizeEvent(QResizeEvent* event) {
    fitPending_ = hasResult_;
    QCustomPlot::resizeEvent(event);
}

} // namespace xyt::ui
