// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/envelope_plot.h"

#include "ui/plots/plot_tools.h"

namespace xyt::ui {

namespace {

QCPGraph* addCurve(QCustomPlot* plot, const QPen& pen, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setPen(pen);
    g->setName(name);
    g->setAdaptiveSampling(true);
    if (name.isEmpty())
        g->removeFromLegend();
    return g;
}

void setCurve(QCPGraph* g, const std::vector<double>& t, const std::vector<double>& y) {
    QVector<QCPGraphData> data;
    data.reserve(static_cast<int>(t.size()));
    for (std::size_t k = 0; k < t.size() && k < y.size(); ++k)
        data.append({t[k], y[k]});
    g->data()->set(data, true);
}

} // namespace

EnvelopePlot::EnvelopePlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Envelope of the perturbed plants' runs: the range (min to max over the stable "
                  "plants) of the chosen signal (error or output in mm, command in V) around the "
                  "nominal run, against time (s)."));
    setObjectName("robustness-envelope");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Envelope"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("time (s)"));
    const QColor band = colors::output;
    // min/max first (the light band), then 5-95 % (darker), then the lines on top.
    min_ = addCurve(this, QPen(Qt::NoPen), QString());
    max_ = addCurve(this, QPen(Qt::NoPen), tr("min–max"));
    max_->setBrush(QColor(band.red(), band.green(), band.blue(), 45));
    max_->setChannelFillGraph(min_);
    p05_ = addCurve(this, QPen(Qt::NoPen), QString());
    p95_ = addCurve(this, QPen(Qt::NoPen), tr("5–95 %"));
    p95_->setBrush(QColor(band.red(), band.green(), band.blue(), 90));
    p95_->setChannelFillGraph(p05_);
    p50_ = addCurve(this, QPen(band.darker(130), 1.2, Qt::DashLine), tr("median"));
    nominal_ = addCurve(this, QPen(colors::reference, 1.6), tr("nominal"));
    placeLegendBelow(this, 2, 2);
    // Two entries a row (the plot may be narrow): rearranged, as the entries exist already.
    legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);
    compactLegend(legend);
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
    showNoResult(tr("Envelope"), tr("Not computed yet."));
}

EnvelopePlot::~EnvelopePlot() = default;

void EnvelopePlot::showEnvelope(const SignalEnvelope& e, const QString& title,
                                const QString& unitLabel) {
    title_->setText(title);
    yAxis->setLabel(unitLabel);
    setCurve(min_, e.t, e.min);
    setCurve(max_, e.t, e.max);
    setCurve(p05_, e.t, e.p05);
    setCurve(p95_, e.t, e.p95);
    setCurve(p50_, e.t, e.p50);
    setCurve(nominal_, e.t, e.nominal);
    hasResult_ = !e.t.empty();
    notice_->setSevere(!hasResult_);
    notice_->setLines(hasResult_ ? QStringList{}
                                 : QStringList{tr("No stable plant: no envelope.")});
    rescaleAxes();
    replot(QCustomPlot::rpQueuedReplot);
}

void EnvelopePlot::showNoResult(const QString& title, const QString& reason) {
    title_->setText(title);
    hasResult_ = false;
    clearWithNotice(this, *notice_, {min_, max_, p05_, p95_, p50_, nominal_}, reason);
}

} // namespace xyt::ui
