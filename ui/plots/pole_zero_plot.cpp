// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/pole_zero_plot.h"

#include "ui/plots/plot_tools.h"

#include <cmath>

namespace xyt::ui {

namespace {
const QList<QColor> kSetColors = {QColor(0x1f, 0x77, 0xb4), QColor(0x2c, 0xa0, 0x2c),
                                  QColor(0x7f, 0x7f, 0x7f), QColor(0xd6, 0x27, 0x28),
                                  QColor(0x94, 0x67, 0xbd), QColor(0xff, 0x7f, 0x0e)};

/**
 * Marks by set index, so that sets sharing a pole stay distinguishable: the Guillemin-Truxal
 * closed loop IS the reference model (Braga et al. Eq. 3), so its crosses sit exactly on the
 * model's poles. Each set gets its own pole shape and a zero ring of its own size (coincident
 * zeros become concentric rings).
 */
QCPScatterStyle poleStyle(int index, const QColor& color) {
    static const QList<QCPScatterStyle::ScatterShape> shapes = {
        QCPScatterStyle::ssCross, QCPScatterStyle::ssPlus,   QCPScatterStyle::ssStar,
        QCPScatterStyle::ssCross, QCPScatterStyle::ssSquare, QCPScatterStyle::ssTriangle};
    static const QList<double> sizes = {10, 10, 11, 9, 15, 13};
    return QCPScatterStyle(shapes[index % shapes.size()], QPen(color, 2), Qt::NoBrush,
                           sizes[index % sizes.size()]);
}

QCPScatterStyle zeroStyle(int index, const QColor& color) {
    return QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(color, 2), Qt::NoBrush,
                           7 + 3 * (index % 6));
}
} // namespace

PoleZeroPlot::PoleZeroPlot(QWidget* parent)
    : PlotWidget(parent), grid_(this), notice_(this, axisRect(), Qt::AlignTop | Qt::AlignRight) {
    setToolTip(tr("Pole-zero map: the plant's, controller's and closed loop's poles (×) and zeros "
                  "(○) in the s-plane, or in the z-plane for the digital loop (View › Pole-zero "
                  "map of the digital loop), with lines of constant damping."));
    setObjectName("pole-zero");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Pole-zero map"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("real"));
    yAxis->setLabel(tr("imaginary"));
    // The legend sits in a row under the plane, where it hides no branch or pole.
    placeLegendBelow(this, 2);
    legend->setSelectableParts(QCPLegend::spItems);
    setupInteractivePlot(this);
    setInteraction(QCP::iSelectLegend, true);
    connect(this, &QCustomPlot::legendClick, this,
            [this](QCPLegend*, QCPAbstractLegendItem* item, QMouseEvent*) {
                auto* pi = qobject_cast<QCPPlottableLegendItem*>(item);
                if (!pi)
                    return;
                for (auto it = graphs_.begin(); it != graphs_.end(); ++it)
                    if (it->poles == pi->plottable())
                        setSetVisible(it.key(), hidden_.contains(it.key()));
                item->setSelected(false);
            });
}

QCPGraph* PoleZeroPlot::polesGraph(const QString& name) const {
    return graphs_.contains(name) ? graphs_[name].poles : nullptr;
}

QCPGraph* PoleZeroPlot::zerosGraph(const QString& name) const {
    return graphs_.contains(name) ? graphs_[name].zeros : nullptr;
}

void PoleZeroPlot::setSetVisible(const QString& name, bool visible) {
    if (!graphs_.contains(name))
        return;
    if (visible)
        hidden_.remove(name);
    else
        hidden_.insert(name);
    const SetGraphs& g = graphs_[name];
    g.poles->setVisible(visible);
    g.zeros->setVisible(visible);
    // A hidden set stays in the legend, greyed, so it can be shown again.
    if (auto* item = legend->itemWithPlottable(g.poles))
        item->setTextColor(visible ? Qt::black : QColor(0xaa, 0xaa, 0xaa));
    replot(QCustomPlot::rpQueuedReplot);
}

void PoleZeroPlot::showNoResult(const QString& title, const QString& reason) {
    title_->setText(title);
    title_->setTextColor(colors::error);
    for (const SetGraphs& g : graphs_) {
        removePlottable(g.poles);
        removePlottable(g.zeros);
    }
    graphs_.clear();
    legend->setVisible(false);
    notice_.setSevere(true);
    notice_.setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

void PoleZeroPlot::setNotes(const QStringList& lines) {
    notice_.setSevere(false);
    notice_.setLines(lines);
    replot(QCustomPlot::rpQueuedReplot);
}

void PoleZeroPlot::showSets(const std::vector<PoleZeroSet>& sets, const QString& title) {
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    legend->setVisible(true);
    notice_.setSevere(false);
    notice_.setLines({});
    std::vector<std::complex<double>> all;
    QSet<QString> names;
    double extent = 1e-6;
    double ts = 0.0;
    for (std::size_t i = 0; i < sets.size(); ++i) {
        const PoleZeroSet& set = sets[i];
        const QString name = QString::fromStdString(set.name);
        names.insert(name);
        ts = set.tsSeconds;
        if (!graphs_.contains(name)) {
            const int index = static_cast<int>(i);
            const QColor color = kSetColors[index % kSetColors.size()];
            QCPGraph* poles = addGraph();
            poles->setLineStyle(QCPGraph::lsNone);
            poles->setScatterStyle(poleStyle(index, color));
            poles->setName(name);
            QCPGraph* zeros = addGraph();
            zeros->setLineStyle(QCPGraph::lsNone);
            zeros->setScatterStyle(zeroStyle(index, color));
            zeros->removeFromLegend();
            graphs_.insert(name, {poles, zeros});
        }
        setComplexPoints(graphs_[name].poles, set.poles);
        setComplexPoints(graphs_[name].zeros, set.zeros);
        for (const auto* list : {&set.poles, &set.zeros})
            for (const auto& p : *list)
                if (std::isfinite(std::abs(p))) {
                    extent = std::max(extent, std::abs(p));
                    all.push_back(p);
                }
    }
    for (auto it = graphs_.begin(); it != graphs_.end();) {
        if (!names.contains(it.key())) {
            removePlottable(it->poles);
            removePlottable(it->zeros);
            it = graphs_.erase(it);
        } else {
            ++it;
        }
    }
    grid_.show(ts, ts > 0 ? M_PI / ts : 1.2 * extent);
    // The default view on a change of plane; afterwards it is re-fitted when some pole or zero
    // leaves it (a pole at -103 must not stay off-screen), unless the user zoomed or panned it.
    if (ts != lastTs_)
        releaseView();
    if (ts != lastTs_ || (!viewHeld() && anyOutsideView(this, all))) {
        lastTs_ = ts;
        const double r = ts > 0 ? std::max(1.2, 1.1 * extent) : 1.15 * extent;
        setView(this, fittedBox({-r, ts > 0 ? r : 0.25 * r, -0.6 * r, 0.6 * r}, all));
    }
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
