// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/design_space_plot.h"
#include "ui/plots/legend_columns.h"

#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_tools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace xyt::ui {

std::vector<std::vector<GridCorner>> feasibleOutline(const std::vector<std::uint8_t>& mask,
                                                     int wnCount, int kpCount) {
    const auto feasible = [&](int a, int b) {
        return a >= 0 && b >= 0 && a < wnCount && b < kpCount &&
               mask[static_cast<std::size_t>(a) * static_cast<std::size_t>(kpCount) +
                    static_cast<std::size_t>(b)] != 0;
    };
    // Directed edges with the feasible cell on their left: a corner has as many edges leaving
    // as arriving, so a walk along unused edges can only stop where it started.
    struct Edge {
        GridCorner from, to;
        bool used = false;
    };
    std::vector<Edge> edges;
    for (int a = 0; a < wnCount; ++a)
        for (int b = 0; b < kpCount; ++b) {
            if (!feasible(a, b))
                continue;
            if (!feasible(a, b - 1))
                edges.push_back({{a, b}, {a + 1, b}});
            if (!feasible(a + 1, b))
                edges.push_back({{a + 1, b}, {a + 1, b + 1}});
            if (!feasible(a, b + 1))
                edges.push_back({{a + 1, b + 1}, {a, b + 1}});
            if (!feasible(a - 1, b))
                edges.push_back({{a, b + 1}, {a, b}});
        }
    std::multimap<std::pair<int, int>, std::size_t> leaving;
    for (std::size_t e = 0; e < edges.size(); ++e)
        leaving.emplace(std::make_pair(edges[e].from.iWn, edges[e].from.iKp), e);

    std::vector<std::vector<GridCorner>> loops;
    for (std::size_t start = 0; start < edges.size(); ++start) {
        if (edges[start].used)
            continue;
        std::vector<GridCorner> loop{edges[start].from};
        std::size_t e = start;
        while (true) {
            edges[e].used = true;
            loop.push_back(edges[e].to);
            const auto [first, last] = leaving.equal_range({edges[e].to.iWn, edges[e].to.iKp});
            const auto next =
                std::find_if(first, last, [&](const auto& kv) { return !edges[kv.second].used; });
            if (next == last)
                break;
            e = next->second;
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

std::vector<double> cellEdges(const std::vector<double>& values, bool logarithmic) {
    const std::size_t n = values.size();
    if (n == 0)
        return {};
    if (n == 1)
        return {values[0] / 1.1, values[0] * 1.1};
    std::vector<double> edges(n + 1);
    for (std::size_t i = 0; i + 1 < n; ++i)
        edges[i + 1] =
            logarithmic ? std::sqrt(values[i] * values[i + 1]) : 0.5 * (values[i] + values[i + 1]);
    edges[0] = logarithmic ? values[0] * values[0] / edges[1] : 2.0 * values[0] - edges[1];
    edges[n] = logarithmic ? values[n - 1] * values[n - 1] / edges[n - 1]
                           : 2.0 * values[n - 1] - edges[n - 1];
    return edges;
}

QString metricLabel(SweepCriterion metric) {
    switch (metric) {
    case SweepCriterion::Itae:
        return QObject::tr("ITAE");
    case SweepCriterion::MaxError:
        return QObject::tr("max |e|");
    case SweepCriterion::Rmse:
        return QObject::tr("RMSE");
    case SweepCriterion::MaxU:
        return QObject::tr("max |u|");
    case SweepCriterion::Settle:
        return QObject::tr("settle time");
    case SweepCriterion::PhaseMargin:
        return QObject::tr("phase margin");
    case SweepCriterion::GainMargin:
        return QObject::tr("gain margin");
    }
    return {};
}

QString metricAxisLabel(SweepCriterion metric) {
    // ITAE = integral of t |e| dt: trajectory unit (mm) times s^2.
    const bool itae = metric == SweepCriterion::Itae;
    const QString unit =
        itae                                    ? QObject::tr("mm·s²")
        : metric == SweepCriterion::MaxU        ? QObject::tr("V")
        : metric == SweepCriterion::Settle      ? QObject::tr("s after tf")
        : metric == SweepCriterion::PhaseMargin ? QObject::tr("deg, larger is better")
        : metric == SweepCriterion::GainMargin  ? QObject::tr("dB, larger is better")
                                                : QObject::tr("mm");
    return QObject::tr("%1%2 (%3)")
        .arg(metricLabel(metric), itae ? QObject::tr(" ∫t|e|dt") : QString(), unit);
}

namespace {

/// Four levels, one per CellStatus: clear, a white veil, grey, light grey.
QCPColorGradient statusGradient() {
    QCPColorGradient g;
    g.clearColorStops();
    g.setColorStopAt(0.0, QColor(255, 255, 255, 0));
    g.setColorStopAt(1.0 / 3.0, QColor(255, 255, 255, 130));
    g.setColorStopAt(2.0 / 3.0, QColor(0x90, 0x90, 0x90));
    g.setColorStopAt(1.0, QColor(0xe4, 0xe4, 0xe4));
    g.setColorInterpolation(QCPColorGradient::ciRGB);
    g.setLevelCount(4);
    return g;
}

QCPGraph* marker(QCustomPlot* plot, const QCPScatterStyle& style, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(style);
    g->setName(name);
    return g;
}

/// Log ticks at 1, 2, 5 x 10^k when the range spans fewer than three decades (a decade-only
/// ticker labels just "1" and "10" on the default wn range), at the decades otherwise.
class OneTwoFiveLogTicker : public QCPAxisTickerLog {
public:
    explicit OneTwoFiveLogTicker(QCPAxis* axis) : axis_(axis) {}

protected:
    QVector<double> createTickVector(double tickStep, const QCPRange& range) override {
        // 1-2-5 labels need room: about 110 px per decade, else they run into each other.
        const double decades = range.lower > 0.0 ? std::log10(range.upper / range.lower) : 0.0;
        const double pixels = axis_->orientation() == Qt::Horizontal ? axis_->axisRect()->width()
                                                                     : axis_->axisRect()->height();
        oneTwoFive_ = range.lower > 0.0 && decades < 3.0 && pixels >= 110.0 * decades;
        if (!oneTwoFive_)
            return QCPAxisTickerLog::createTickVector(tickStep, range);
        QVector<double> ticks;
        for (double decade = std::pow(10.0, std::floor(std::log10(range.lower)));
             decade <= range.upper; decade *= 10.0)
            for (double m : {1.0, 2.0, 5.0})
                if (m * decade >= range.lower && m * decade <= range.upper)
                    ticks.append(m * decade);
        return ticks;
    }
    int getSubTickCount(double tickStep) override {
        return oneTwoFive_ ? 0 : QCPAxisTickerLog::getSubTickCount(tickStep);
    }

private:
    QCPAxis* axis_;
    bool oneTwoFive_ = false;
};

void setScale(QCPAxis* axis, bool logarithmic) {
    axis->setScaleType(logarithmic ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (logarithmic) {
        auto ticker = QSharedPointer<OneTwoFiveLogTicker>::create(axis);
        ticker->setSubTickCount(8);
        axis->setTicker(ticker);
        axis->setNumberFormat("g");
    } else {
        axis->setTicker(QSharedPointer<QCPAxisTicker>::create());
        axis->setNumberFormat("g");
    }
}

} // namespace

DesignSpacePlot::DesignSpacePlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Design space: each cell of the (ωn, kp) grid is one Guillemin–Truxal design run "
                  "on the session's trajectory, coloured by the chosen criterion; feasible cells "
                  "meet every limit of the specification. Click a cell to take its ωn and kp."));
    setObjectName("design-space");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Design space"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("ωn (rad/s)"));
    yAxis->setLabel(tr("kp (V per model unit)"));
    setScale(xAxis, true);
    setScale(yAxis, true);
    xAxis->setRange(0.2, 20.0);
    yAxis->setRange(3.0, 3000.0);
    // The map covers the axis rect: draw the grid lines above it.
    addLayer("overlay-grid", layer("main"), QCustomPlot::limAbove);
    xAxis->grid()->setLayer("overlay-grid");
    yAxis->grid()->setLayer("overlay-grid");
    for (QCPAxis* axis : {xAxis, yAxis})
        axis->grid()->setPen(QPen(QColor(255, 255, 255, 70), 0, Qt::DotLine));

    map_ = new QCPColorMap(xAxis, yAxis);
    map_->setName(tr("metric"));
    map_->setInterpolate(false);
    map_->setGradient(viridisGradient());
    map_->removeFromLegend();
    status_ = new QCPColorMap(xAxis, yAxis);
    status_->setInterpolate(false);
    status_->setGradient(statusGradient());
    status_->setDataRange(QCPRange(0.0, 3.0));
    status_->removeFromLegend();

    scale_ = new QCPColorScale(this);
    scale_->setType(QCPAxis::atRight);
    scale_->setBarWidth(14);
    plotLayout()->addElement(1, 1, scale_);
    map_->setColorScale(scale_);
    scale_->setGradient(viridisGradient());
    styleAxisRect(axisRect());
    QFont f = scale_->axis()->labelFont();
    f.setPointSizeF(9);
    scale_->axis()->setLabelFont(f);
    scale_->axis()->setTickLabelFont(f);
    auto* margins = new QCPMarginGroup(this);
    axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    scale_->setMarginGroup(QCP::msBottom | QCP::msTop, margins);

    current_ = marker(
        this, QCPScatterStyle(QCPScatterStyle::ssCross, QPen(colors::error, 3), Qt::NoBrush, 16),
        tr("current"));
    best_ = marker(this,
                   QCPScatterStyle(QCPScatterStyle::ssStar, QPen(QColor(0xff, 0x30, 0xd0), 3),
                                   Qt::NoBrush, 20),
                   tr("best"));
    refined_ = marker(this,
                      QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(Qt::black, 1.2),
                                      QBrush(QColor(0xff, 0x30, 0xd0)), 10),
                      tr("refined"));
    leastViolating_ = marker(this,
                             QCPScatterStyle(QCPScatterStyle::ssTriangle, QPen(Qt::black, 2),
                                             QBrush(QColor(0xff, 0xd0, 0x30)), 13),
                             tr("least violating"));
    addLayer("markers", layer("overlay-grid"), QCustomPlot::limAbove);
    for (QCPGraph* g : {current_, best_, refined_, leastViolating_})
        g->setLayer("markers");
    // The legend goes in a row under the map, where it hides no cell.
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    legend->setBorderPen(Qt::NoPen);
    setMaxLegendColumns(legend, 4); // one row of short names; two where the map is narrow
    // The row has only the map's column (not the colour scale's): "least violating" clipped.
    compactLegend(legend);
    axisRect()->insetLayout()->take(legend);
    plotLayout()->addElement(2, 0, legend);
    plotLayout()->setRowStretchFactor(2, 0.001);

    // Until a study has run there is no map to show: no cells, no colour scale, and a notice.
    map_->setVisible(false);
    status_->setVisible(false);
    scale_->setVisible(false);
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignCenter);
    notice_->setLines({tr("Not computed yet: set the grid and press Run.")});

    setupInteractivePlot(this);
    // The shared "reset view" rescales with a linear margin, which goes below zero on the log
    // axes of this plot: use the grid's own extent instead.
    disconnect(this, &QCustomPlot::mouseDoubleClick, nullptr, nullptr);
    disconnect(this, &QWidget::customContextMenuRequested, nullptr, nullptr);
    connect(this, &QCustomPlot::mouseDoubleClick, this, [this](QMouseEvent*) { showWholeGrid(); });
    connect(this, &QWidget::customContextMenuRequested, this, &DesignSpacePlot::showContextMenu);
    connect(this, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) {
        if (event->buttons() == Qt::NoButton)
            emit cellHovered(cellAtPixel(event->position()));
    });
    connect(this, &QCustomPlot::mousePress, this,
            [this](QMouseEvent* event) { pressPos_ = event->pos(); });
    connect(this, &QCustomPlot::mouseRelease, this, [this](QMouseEvent* event) {
        if (event->button() != Qt::LeftButton || (event->pos() - pressPos_).manhattanLength() > 4)
            return; // a drag pans the view
        if (const auto cell = cellAtPixel(event->position()))
            emit cellClicked(cell->first, cell->second);
    });
}

QString DesignSpacePlot::noticeText() const {
    return notice_->text();
}

void DesignSpacePlot::setLeastViolating(std::optional<std::pair<double, double>> wnKp) {
    leastViolating_->data()->clear();
    if (wnKp)
        leastViolating_->addData(wnKp->first, wnKp->second);
    if (wnKp)
        leastViolating_->addToLegend();
    else
        leastViolating_->removeFromLegend();
    replot(QCustomPlot::rpQueuedReplot);
}

void DesignSpacePlot::showContextMenu(const QPoint& pos) {
    QMenu menu(this);
    menu.addAction(tr("Show the whole grid"), this, [this] { showWholeGrid(); });
    menu.addSeparator();
    menu.addAction(tr("Save as PNG..."), this,
                   [this] { savePlotDialog(this, objectName() + ".png"); });
    menu.addAction(tr("Save as PDF..."), this,
                   [this] { savePlotDialog(this, objectName() + ".pdf"); });
    menu.exec(mapToGlobal(pos));
}

void DesignSpacePlot::showResult(const DesignSweepResult& result, bool logGrid,
                                 SweepCriterion metric, bool logColor, const QString& title) {
    result_ = result;
    hasResult_ = true;
    map_->setVisible(true);
    status_->setVisible(true);
    scale_->setVisible(true);
    notice_->setLines({});
    logGrid_ = logGrid;
    metric_ = metric;
    logColor_ = logColor;
    title_->setText(title);
    wnEdges_ = cellEdges(result.wnValues, logGrid);
    kpEdges_ = cellEdges(result.kpValues, logGrid);
    setScale(xAxis, logGrid);
    setScale(yAxis, logGrid);

    const int nWn = static_cast<int>(result.wnValues.size());
    const int nKp = static_cast<int>(result.kpValues.size());
    // QCPColorMap spreads its cells evenly in PIXELS between the first and last cell centres,
    // so on a logarithmic axis the centres are log-spaced and fall on the log grid's values.
    const QCPRange wnRange(result.wnValues.front(), result.wnValues.back());
    const QCPRange kpRange(result.kpValues.front(), result.kpValues.back());
    status_->data()->setSize(nWn, nKp);
    status_->data()->setRange(wnRange, kpRange);
    for (int a = 0; a < nWn; ++a)
        for (int b = 0; b < nKp; ++b) {
            const DesignPoint& p =
                result.at(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
            const CellStatus s = !p.computed                       ? NotComputed
                                 : (!p.stable || !p.metricsFinite) ? Failed
                                 : p.feasible                      ? Feasible
                                                                   : Infeasible;
            status_->data()->setCell(a, b, s);
        }
    drawMetric();
    drawOutline();

    best_->data()->clear();
    if (result.bestIndex) {
        const DesignPoint& b = result.points[*result.bestIndex];
        best_->addData(b.wn, b.kp);
    }
    refined_->data()->clear();
    if (result.refined)
        refined_->addData(result.refined->point.wn, result.refined->point.kp);
    // The legend lists only the markers drawn.
    leastViolating_->data()->clear();
    for (QCPGraph* g : {best_, refined_, leastViolating_}) {
        if (g->dataCount() > 0)
            g->addToLegend();
        else
            g->removeFromLegend();
    }
    showWholeGrid();
}

void DesignSpacePlot::setMetric(SweepCriterion metric, bool logColor) {
    metric_ = metric;
    logColor_ = logColor;
    if (hasResult_) {
        drawMetric();
        replot(QCustomPlot::rpQueuedReplot);
    }
}

void DesignSpacePlot::drawMetric() {
    const int nWn = static_cast<int>(result_.wnValues.size());
    const int nKp = static_cast<int>(result_.kpValues.size());
    map_->data()->setSize(nWn, nKp);
    map_->data()->setRange(QCPRange(result_.wnValues.front(), result_.wnValues.back()),
                           QCPRange(result_.kpValues.front(), result_.kpValues.back()));
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (int a = 0; a < nWn; ++a)
        for (int b = 0; b < nKp; ++b) {
            double v = criterionMetric(
                result_.at(static_cast<std::size_t>(a), static_cast<std::size_t>(b)), metric_);
            // Not computed, diverged, or not drawable on a log scale: the status layer shows it.
            if (!std::isfinite(v) || (logColor_ && v <= 0.0))
                v = std::numeric_limits<double>::quiet_NaN();
            else {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
            map_->data()->setCell(a, b, v);
        }
    if (!(lo <= hi)) {
        lo = 1.0;
        hi = 10.0;
    } else if (lo == hi) {
        lo *= 0.9;
        hi *= 1.1;
    }
    const auto type = logColor_ ? QCPAxis::stLogarithmic : QCPAxis::stLinear;
    scale_->setDataScaleType(type);
    map_->setDataScaleType(type);
    setScale(scale_->axis(), logColor_);
    map_->setDataRange(QCPRange(lo, hi));
    scale_->setLabel(metricAxisLabel(metric_));
}

void DesignSpacePlot::drawOutline() {
    const auto loops =
        feasibleOutline(result_.feasibleMask, static_cast<int>(result_.wnValues.size()),
                        static_cast<int>(result_.kpValues.size()));
    while (outline_.size() > loops.size()) {
        removePlottable(outline_.back());
        removePlottable(outlineHalo_.back());
        outline_.pop_back();
        outlineHalo_.pop_back();
    }
    while (outline_.size() < loops.size()) {
        // A dark halo under a white line: visible on every colour of the map.
        auto* halo = new QCPCurve(xAxis, yAxis);
        halo->setPen(QPen(QColor(0, 0, 0, 200), 4.5));
        halo->setName(tr("feasible region"));
        if (!outline_.empty())
            halo->removeFromLegend();
        auto* line = new QCPCurve(xAxis, yAxis);
        line->setPen(QPen(Qt::white, 2.0));
        line->removeFromLegend();
        outlineHalo_.push_back(halo);
        outline_.push_back(line);
    }
    for (std::size_t l = 0; l < loops.size(); ++l) {
        QVector<QCPCurveData> data;
        data.reserve(static_cast<qsizetype>(loops[l].size()));
        for (std::size_t k = 0; k < loops[l].size(); ++k)
            data.append(QCPCurveData(static_cast<double>(k),
                                     wnEdges_[static_cast<std::size_t>(loops[l][k].iWn)],
                                     kpEdges_[static_cast<std::size_t>(loops[l][k].iKp)]));
        outlineHalo_[l]->data()->set(data, true);
        outline_[l]->data()->set(data, true);
    }
}

void DesignSpacePlot::setCurrentDesign(double wn, double kp) {
    current_->data()->clear();
    current_->addData(wn, kp);
    replot(QCustomPlot::rpQueuedReplot);
}

std::optional<std::pair<std::size_t, std::size_t>>
DesignSpacePlot::cellAtPixel(const QPointF& pixel) const {
    if (!hasResult_ || !axisRect()->rect().contains(pixel.toPoint()))
        return std::nullopt;
    const auto find = [](const std::vector<double>& edges, double v) -> std::optional<std::size_t> {
        if (!std::isfinite(v) || v < edges.front() || v >= edges.back())
            return std::nullopt;
        const auto it = std::upper_bound(edges.begin(), edges.end(), v);
        return static_cast<std::size_t>(it - edges.begin()) - 1;
    };
    const auto a = find(wnEdges_, xAxis->pixelToCoord(pixel.x()));
    const auto b = find(kpEdges_, yAxis->pixelToCoord(pixel.y()));
    if (!a || !b)
        return std::nullopt;
    return std::make_pair(*a, *b);
}

QPointF DesignSpacePlot::pixelOfCell(std::size_t iWn, std::size_t iKp) const {
    return {xAxis->coordToPixel(result_.wnValues.at(iWn)),
            yAxis->coordToPixel(result_.kpValues.at(iKp))};
}

void DesignSpacePlot::showWholeGrid() {
    if (hasResult_) {
        xAxis->setRange(wnEdges_.front(), wnEdges_.back());
        yAxis->setRange(kpEdges_.front(), kpEdges_.back());
    }
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
