// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/root_locus_plot.h"

#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"

#include <cmath>

namespace xyt::ui {

namespace {
const QList<QColor> kBranchColors = {QColor(0x1f, 0x77, 0xb4), QColor(0x2c, 0xa0, 0x2c),
                                     QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                     QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf),
                                     QColor(0xbc, 0xbd, 0x22), QColor(0x7f, 0x7f, 0x7f)};

QCPGraph* scatterGraph(QCustomPlot* plot, QCPScatterStyle style, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(style);
    g->setName(name);
    return g;
}

QString formatGain(double k) {
    return QString::number(k, 'g', 5);
}
} // namespace

RootLocusPlot::RootLocusPlot(QWidget* parent)
    : PlotWidget(parent), grid_(this), overlay_(this),
      notice_(this, axisRect(), Qt::AlignTop | Qt::AlignRight) {
    setToolTip(
        tr("Root locus: the closed-loop poles of 1 + K L(s) = 0 as the loop gain K goes from 0 to "
           "∞ (K = 1 is the design), with the specification's ζ wedge and settling line; click a "
           "point to apply its gain, drag a closed-loop pole along the locus or a PID's zero."));
    setObjectName("root-locus");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Root locus"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("real"));
    yAxis->setLabel(tr("imaginary"));
    poles_ = scatterGraph(
        this, QCPScatterStyle(QCPScatterStyle::ssCross, QPen(Qt::black, 2), Qt::NoBrush, 10),
        tr("open-loop poles"));
    zeros_ = scatterGraph(
        this, QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 2), Qt::NoBrush, 9),
        tr("open-loop zeros"));
    current_ = scatterGraph(this,
                            QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(colors::error, 1.5),
                                            QBrush(colors::error), 10),
                            tr("closed-loop poles"));
    hover_ = scatterGraph(this,
                          QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 1.5),
                                          QBrush(QColor(255, 255, 0, 200)), 9),
                          QString());
    hover_->removeFromLegend();
    // Under the plane, in rows of their own, the legend and then the hover readout: there
    // they can hide neither a branch nor a damping label.
    placeLegendBelow(this, 2, 4);
    legend->setIconSize(20, 10); // four columns of entries fit a 1366 px wide window
    readout_ = addTextRow(this, 3, readoutHint());
    setupInteractivePlot(this);
    connect(this, &QCustomPlot::mouseMove, this, &RootLocusPlot::onMouseMove);
    connect(this, &QCustomPlot::mousePress, this, &RootLocusPlot::onMousePress);
    connect(this, &QCustomPlot::mouseRelease, this, &RootLocusPlot::onMouseRelease);
}

QString RootLocusPlot::readoutHint() {
    return tr("hover a branch: K, ζ, ωn; click: use that gain");
}

void RootLocusPlot::setZerosDraggable(bool draggable) {
    zerosDraggable_ = draggable;
    zeros_->setName(draggable ? tr("open-loop zeros (drag to move)") : tr("open-loop zeros"));
}

std::optional<std::complex<double>> RootLocusPlot::zeroAtPixel(const QPointF& pixel,
                                                               double maxPixels) const {
    std::optional<std::complex<double>> best;
    double nearest = maxPixels;
    for (const std::complex<double>& z : locus_.zeros) {
        const double d = std::hypot(xAxis->coordToPixel(z.real()) - pixel.x(),
                                    yAxis->coordToPixel(z.imag()) - pixel.y());
        if (d <= nearest) {
            nearest = d;
            best = z;
        }
    }
    return best;
}

void RootLocusPlot::showLocus(const RootLocus& locus,
                              const std::vector<std::complex<double>>& currentPoles,
                              const QString& title) {
    const bool newPlane = !hasLocus_ || locus.tsSeconds != lastTs_;
    locus_ = locus;
    hasLocus_ = true;
    lastTs_ = locus.tsSeconds;
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    std::vector<std::vector<std::complex<double>>> branches;
    branches.reserve(locus.branches.size());
    for (const auto& b : locus.branches)
        branches.push_back(b.roots);
    showBranches(this, branches_, branches, [](std::size_t i) {
        return QPen(kBranchColors[static_cast<int>(i) % kBranchColors.size()], 1.6);
    });
    setComplexPoints(poles_, locus.poles);
    setComplexPoints(zeros_, locus.zeros);
    setComplexPoints(current_, currentPoles);
    currentPoles_ = currentPoles;
    // A readout of K belongs to the locus it was read on: any new locus (design, axis or plane
    // changed) starts without one.
    clearHover();
    readout_->setVisible(true);
    legend->setVisible(true);
    QStringList warnings;
    for (const auto& w : locus.warnings)
        warnings << diagnosticText(w);
    if (locus.status != RootLocusStatus::Complete && warnings.isEmpty())
        warnings << tr("the locus is incomplete");
    notice_.setSevere(false);
    notice_.setLines(warnings);
    const LocusView& v = locus.view;
    const double extent = std::max(
        {std::abs(v.reMin), std::abs(v.reMax), std::abs(v.imMin), std::abs(v.imMax), 1e-6});
    grid_.show(locus.tsSeconds, extent);
    overlay_.show(requirements_, locus.tsSeconds, extent, currentPoles);
    // Fitted on a change of plane, and when a pole or zero (or a closed-loop pole of the
    // design) leaves the view; a view the user zoomed or panned is kept until it is reset.
    std::vector<std::complex<double>> markers = locus.poles;
    markers.insert(markers.end(), locus.zeros.begin(), locus.zeros.end());
    markers.insert(markers.end(), currentPoles.begin(), currentPoles.end());
    if (newPlane)
        releaseView();
    if (newPlane || (!viewHeld() && anyOutsideView(this, markers)))
        setView(this, fittedBox({v.reMin, v.reMax, v.imMin, v.imMax}, markers));
    replot(QCustomPlot::rpQueuedReplot);
}

void RootLocusPlot::showNoResult(const QString& title, const QString& reason) {
    hasLocus_ = false;
    locus_ = RootLocus{};
    title_->setText(title);
    title_->setTextColor(colors::error);
    showBranches(this, branches_, {}, [](std::size_t) { return QPen(); });
    for (QCPGraph* g : {poles_, zeros_, current_})
        g->data()->clear();
    overlay_.clear();
    clearHover();
    readout_->setVisible(false);
    legend->setVisible(false);
    notice_.setSevere(true);
    notice_.setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

void RootLocusPlot::clearHover() {
    hover_->data()->clear();
    readout_->setText(readoutHint());
}

void RootLocusPlot::leaveEvent(QEvent* event) {
    QCustomPlot::leaveEvent(event);
    if (!hover_->data()->isEmpty() || readout_->text() != readoutHint()) {
        clearHover();
        replot(QCustomPlot::rpQueuedReplot);
    }
}

std::optional<LocusPick> RootLocusPlot::pickAtPixel(const QPointF& pixel, double maxPixels) const {
    if (!hasLocus_)
        return std::nullopt;
    const std::complex<double> clicked(xAxis->pixelToCoord(pixel.x()),
                                       yAxis->pixelToCoord(pixel.y()));
    if (!std::isfinite(clicked.real()) || !std::isfinite(clicked.imag()))
        return std::nullopt;
    const auto pick = pickLocusPoint(locus_, clicked);
    if (!pick)
        return std::nullopt;
    const QPointF at(xAxis->coordToPixel(pick->point.real()),
                     yAxis->coordToPixel(pick->point.imag()));
    if (std::hypot(at.x() - pixel.x(), at.y() - pixel.y()) > maxPixels)
        return std::nullopt;
    return pick;
}

std::optional<double> RootLocusPlot::dragGainAt(const QPointF& pixel) const {
    const std::complex<double> at(xAxis->pixelToCoord(pixel.x()), yAxis->pixelToCoord(pixel.y()));
    if (!gainDragLocus_ || !std::isfinite(at.real()) || !std::isfinite(at.imag()))
        return std::nullopt;
    const auto pick = pickLocusPoint(*gainDragLocus_, at);
    if (!pick || !(pick->gain > 0.0) || !std::isfinite(pick->gain))
        return std::nullopt;
    return pick->gain;
}

void RootLocusPlot::onMouseMove(QMouseEvent* event) {
    if (gainDragLocus_ && (event->buttons() & Qt::LeftButton)) {
        if (const auto gain = dragGainAt(event->position()))
            emit gainDragged(*gain, false);
        return;
    }
    if (draggedZero_ && (event->buttons() & Qt::LeftButton)) {
        const std::complex<double> to(xAxis->pixelToCoord(event->position().x()),
                                      yAxis->pixelToCoord(event->position().y()));
        const std::complex<double> from = *draggedZero_;
        draggedZero_ = to;
        emit zeroDragged(from, to, false);
        return;
    }
    if (event->buttons() != Qt::NoButton)
        return; // dragging pans the view
    const auto pick = pickAtPixel(event->position());
    if (!pick) {
        if (!hover_->data()->isEmpty() || readout_->text() != readoutHint()) {
            clearHover();
            replot(QCustomPlot::rpQueuedReplot);
        }
        return;
    }
    setComplexPoints(hover_, {pick->point});
    readout_->setText(tr("K = %1   ζ = %2   ωn = %3 rad/s   s = %4 %5 %6j")
                          .arg(formatGain(pick->gain))
                          .arg(pick->damping.zeta, 0, 'f', 3)
                          .arg(QString::number(pick->damping.omegaNRadPerSec, 'g', 4))
                          .arg(QString::number(pick->point.real(), 'g', 4))
                          .arg(pick->point.imag() < 0 ? "−" : "+")
                          .arg(QString::number(std::abs(pick->point.imag()), 'g', 4)));
    replot(QCustomPlot::rpQueuedReplot);
}

void RootLocusPlot::onMousePress(QMouseEvent* event) {
    pressPos_ = event->pos();
    draggedZero_.reset();
    gainDragLocus_.reset();
    if (zerosDraggable_ && hasLocus_ && event->button() == Qt::LeftButton)
        draggedZero_ = zeroAtPixel(event->position());
    if (!draggedZero_ && hasLocus_ && event->button() == Qt::LeftButton)
        for (const std::complex<double>& p : currentPoles_)
            if (std::hypot(xAxis->coordToPixel(p.real()) - event->position().x(),
                           yAxis->coordToPixel(p.imag()) - event->position().y()) <= 8.0) {
                gainDragLocus_ = locus_; // the gains of the design at the press
                break;
            }
    // A zero or a pole is dragged, not the view.
    setInteraction(QCP::iRangeDrag, !draggedZero_ && !gainDragLocus_);
}

void RootLocusPlot::onMouseRelease(QMouseEvent* event) {
    if (gainDragLocus_) {
        const auto gain = dragGainAt(event->position());
        const bool moved = (event->pos() - pressPos_).manhattanLength() > 4;
        setInteraction(QCP::iRangeDrag, true);
        gainDragLocus_.reset();
        if (moved) {
            if (gain)
                emit gainDragged(*gain, true);
            return;
        }
        // A click on a pole without a drag: a gain pick, as anywhere on a branch.
    }
    if (draggedZero_) {
        const std::complex<double> from = *draggedZero_;
        const std::complex<double> to(xAxis->pixelToCoord(event->position().x()),
                                      yAxis->pixelToCoord(event->position().y()));
        draggedZero_.reset();
        setInteraction(QCP::iRangeDrag, true);
        emit zeroDragged(from, to, true);
        return;
    }
    if (event->button() != Qt::LeftButton || (event->pos() - pressPos_).manhattanLength() > 4)
        return; // a drag, not a click
    const auto pick = pickAtPixel(event->position());
    if (pick && pick->gain > 0.0 && std::isfinite(pick->gain))
        emit gainPicked(pick->gain);
}

LocusRequirements axisLocusRequirements(const Session& session, int axis) {
    const AxisSettings& a = session.axes.at(static_cast<std::size_t>(axis));
    LocusRequirements req;
    req.active = true;
    req.maxOvershootPct = session.spec.maxOvershootPct;
    req.maxSettlingTimeSeconds = session.spec.maxSettlingTimeSeconds;
    if (a.method == DesignMethod::GuilleminTruxal)
        req.designOmegaNRadPerSec = a.gt.omegaNRadPerSec;
    return req;
}

std::vector<std::complex<double>> designClosedLoopPoles(const AxisEvaluation& evaluation) {
    try {
        return evaluation.closedLoop().poles();
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace xyt::ui
