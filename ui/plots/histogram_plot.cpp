// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/histogram_plot.h"

#include "ui/plots/plot_tools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt::ui {

namespace {

QCPItemStraightLine* verticalLine(QCustomPlot* plot, const QPen& pen) {
    auto* line = new QCPItemStraightLine(plot);
    line->setPen(pen);
    line->setVisible(false);
    return line;
}

void placeVertical(QCPItemStraightLine* line, double x) {
    line->point1->setCoords(x, 0.0);
    line->point2->setCoords(x, 1.0);
    line->setVisible(std::isfinite(x));
}

} // namespace

HistogramPlot::HistogramPlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Histogram of the chosen figure (RMSE or max |e| in mm, max |u| in V) over the "
                  "stable perturbed plants, with the specification's limit drawn."));
    setObjectName("robustness-histogram");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Distribution"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    yAxis->setLabel(tr("plants"));
    bars_ = new QCPBars(xAxis, yAxis);
    bars_->setName(tr("plants"));
    bars_->setPen(QPen(colors::output.darker(120)));
    bars_->setBrush(
        QColor(colors::output.red(), colors::output.green(), colors::output.blue(), 120));
    bars_->setWidthType(QCPBars::wtPlotCoords);
    limit_ = verticalLine(this, QPen(colors::limit, 1.6, Qt::DashLine));
    nominal_ = verticalLine(this, QPen(colors::reference, 1.6));
    // Legend entries for the two lines: empty graphs with their pens.
    QCPGraph* limitKey = addGraph();
    limitKey->setPen(limit_->pen());
    limitKey->setName(tr("limit"));
    QCPGraph* nominalKey = addGraph();
    nominalKey->setPen(nominal_->pen());
    nominalKey->setName(tr("nominal"));
    placeLegendBelow(this, 2, 2);
    // Two entries a row (the plot may be narrow): rearranged, as the entries exist already.
    legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);
    compactLegend(legend);
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
    showNoResult(tr("Distribution"), tr("Not computed yet."));
}

HistogramPlot::~HistogramPlot() = default;

double HistogramPlot::limitDrawn() const {
    return limit_->visible() ? limit_->point1->coords().x()
                             : std::numeric_limits<double>::quiet_NaN();
}

double HistogramPlot::nominalDrawn() const {
    return nominal_->visible() ? nominal_->point1->coords().x()
                               : std::numeric_limits<double>::quiet_NaN();
}

void HistogramPlot::showHistogram(const Histogram& h, double nominal, std::optional<double> limit,
                                  const QString& title, const QString& unitLabel) {
    title_->setText(title);
    xAxis->setLabel(unitLabel);
    QVector<double> keys, values;
    for (std::size_t i = 0; i < h.counts.size(); ++i) {
        keys.append(0.5 * (h.edges[i] + h.edges[i + 1]));
        values.append(h.counts[i]);
    }
    bars_->setWidth(h.counts.empty() ? 1.0 : h.edges[1] - h.edges[0]);
    bars_->setData(keys, values, true);
    placeVertical(nominal_, nominal);
    placeVertical(limit_, limit.value_or(std::numeric_limits<double>::quiet_NaN()));
    hasResult_ = !h.counts.empty();
    notice_->setSevere(!hasResult_);
    notice_->setLines(hasResult_ ? QStringList{}
                                 : QStringList{tr("No stable plant: no distribution.")});
    // The range holds the bins and both lines.
    double lo = h.edges.empty() ? nominal : h.edges.front(),
           hi = h.edges.empty() ? nominal : h.edges.back();
    for (double x : {nominal, limit.value_or(lo)})
        if (std::isfinite(x)) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
    // A spread below what four significant digits tell apart (every plant the nominal one:
    // the core's single bin is a round-off wide) is shown as a bar of a tenth of a view 10 %
    // of the value wide: tick labels a round-off apart ran together ("3.348653.34865").
    const double scale = std::max({std::abs(lo), std::abs(hi), 1e-12});
    if (hi - lo < 1e-4 * scale) {
        const double centre = 0.5 * (lo + hi), half = 0.05 * scale;
        lo = centre - half;
        hi = centre + half;
        if (!h.counts.empty())
            bars_->setWidth(0.1 * (hi - lo));
    }
    const double pad = 0.05 * (hi - lo);
    xAxis->setRange(lo - pad, hi + pad);
    const int top = h.counts.empty() ? 1 : *std::max_element(h.counts.begin(), h.counts.end());
    yAxis->setRange(0.0, 1.1 * top + 0.5);
    replot(QCustomPlot::rpQueuedReplot);
}

void HistogramPlot::showNoResult(const QString& title, const QString& reason) {
    title_->setText(title);
    bars_->data()->clear();
    limit_->setVisible(false);
    nominal_->setVisible(false);
    hasResult_ = false;
    notice_->setSevere(true);
    notice_->setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
