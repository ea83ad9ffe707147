// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/sensitivity_plot.h"

#include "ui/plots/plot_tools.h"

namespace xyt::ui {

namespace {

QCPGraph* line(QCustomPlot* plot, const QColor& color, const QString& name, bool band) {
    QCPGraph* g = plot->addGraph();
    g->setPen(band ? QPen(Qt::NoPen) : QPen(color, 1.8));
    if (!band)
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
    g->setName(name);
    if (name.isEmpty())
        g->removeFromLegend();
    return g;
}

} // namespace

SensitivityPlot::SensitivityPlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("ZPETC sensitivity: the RMSE (mm) of the run with and without the feedforward as "
                  "the plant mismatch grows from the nominal model (0 %) to the ranges set (100 "
                  "%), each point over the same seeded plants."));
    setObjectName("zpetc-sensitivity");
    plotLayout()->insertRow(0);
    plotLayout()->addElement(
        0, 0,
        new QCPTextElement(this, tr("ZPETC sensitivity"), QFont(font().family(), 10, QFont::Bold)));
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("mismatch (% of ranges)"));
    xAxis->ticker()->setTickCount(3); // 0, 50, 100: readable in a narrow plot
    yAxis->setLabel(tr("RMSE (mm)"));
    const QColor withColor = colors::output, withoutColor = colors::axisY;
    withLow_ = line(this, withColor, QString(), true);
    withHigh_ = line(this, withColor, QString(), true);
    withHigh_->setBrush(QColor(withColor.red(), withColor.green(), withColor.blue(), 50));
    withHigh_->setChannelFillGraph(withLow_);
    withoutLow_ = line(this, withoutColor, QString(), true);
    withoutHigh_ = line(this, withoutColor, QString(), true);
    withoutHigh_->setBrush(
        QColor(withoutColor.red(), withoutColor.green(), withoutColor.blue(), 50));
    withoutHigh_->setChannelFillGraph(withoutLow_);
    with_ = line(this, withColor, tr("with ZPETC"), false);
    without_ = line(this, withoutColor, tr("loop alone"), false);
    placeLegendBelow(this, 2, 2);
    compactLegend(legend);
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignTop | Qt::AlignLeft);
    setupInteractivePlot(this);
    showNoResult(tr("Not computed yet."));
}

SensitivityPlot::~SensitivityPlot() = default;

void SensitivityPlot::showCurve(const std::vector<ZpetcSensitivityPoint>& curve) {
    for (QCPGraph* g : {with_, without_, withLow_, withHigh_, withoutLow_, withoutHigh_})
        g->data()->clear();
    for (const ZpetcSensitivityPoint& p : curve) {
        const double x = 100.0 * p.scale;
        if (p.rmseWithFf.count > 0) {
            with_->addData(x, p.rmseWithFf.p50);
            withLow_->addData(x, p.rmseWithFf.p05);
            withHigh_->addData(x, p.rmseWithFf.p95);
        }
        if (p.rmseWithoutFf.count > 0) {
            without_->addData(x, p.rmseWithoutFf.p50);
            withoutLow_->addData(x, p.rmseWithoutFf.p05);
            withoutHigh_->addData(x, p.rmseWithoutFf.p95);
        }
    }
    hasResult_ = !with_->data()->isEmpty();
    notice_->setSevere(!hasResult_);
    notice_->setLines(hasResult_ ? QStringList{}
                                 : QStringList{tr("No stable plant at any mismatch.")});
    rescaleAxes();
    yAxis->setRangeLower(0.0);
    replot(QCustomPlot::rpQueuedReplot);
}

void SensitivityPlot::showNoResult(const QString& reason) {
    hasResult_ = false;
    clearWithNotice(this, *notice_,
                    {with_, without_, withLow_, withHigh_, withoutLow_, withoutHigh_}, reason);
}

} // namespace xyt::ui
