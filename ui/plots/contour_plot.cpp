// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/contour_plot.h"
#include "ui/plots/legend_columns.h"

#include "ui/plots/contour_points.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {

QCPCurve* newCurve(QCustomPlot* plot, const QPen& pen, const QString& name) {
    auto* c = new QCPCurve(plot->xAxis, plot->yAxis);
    c->setPen(pen);
    c->setName(name);
    return c;
}

void setPoints(QCPCurve* curve, const XyPoints& p) {
    curve->setData(p.x, p.y);
}

/// The colours of the error bands, from small to large |e| (the base curve is the first).
const std::array<QColor, 4> kBandColors = {QColor(0x2e, 0x7d, 0x32), QColor(0xc0, 0x9a, 0x00),
                                           QColor(0xef, 0x6c, 0x00), QColor(0xc6, 0x28, 0x28)};
constexpr std::array<double, 3> kBandFractions = {0.25, 0.5, 0.75};

QString mm(double v) {
    return QString::number(v, 'f', 4);
}

} // namespace

ContourPlot::ContourPlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("The XY contour: the programmed path, the traced path of both axes' run, and the "
                  "contour error (mm, the signed distance from each traced point to the nearest "
                  "point of the path) magnified along the path normal by the \"error ×\" factor."));
    setObjectName("xy-contour");
    plotLayout()->insertRow(0);
    figures_ = new QCPTextElement(this, QString(), QFont(font().family(), 9));
    reserveTitleRoom(0);
    plotLayout()->addElement(0, 0, figures_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("x (mm)"));
    yAxis->setLabel(tr("y (mm)"));
    commanded_ = newCurve(this, QPen(colors::reference, 1.2, Qt::DashLine), tr("commanded"));
    traced_ = newCurve(this, QPen(colors::output, 1.8), tr("traced"));
    magnified_ = newCurve(this, QPen(colors::error, 1.2), QString());
    for (std::size_t b = 0; b < bands_.size(); ++b)
        bands_[b] = newCurve(this, QPen(kBandColors[b + 1], 2.0), QString());
    reverse_ = newCurve(this, QPen(colors::axisY, 1.2), QString());
    uncompensated_ = newCurve(this, QPen(colors::reference, 1.2, Qt::DashDotLine), QString());
    // The same run with the axes independent, beside a cross-coupled one.
    independent_ = newCurve(this, QPen(QColor(0x9e, 0x9e, 0x9e), 1.2, Qt::DotLine), QString());
    // ... and without the axes' feedforward (ZPETC, a PID's FF0..FF3): the feedback alone.
    feedbackOnly_ = newCurve(this, QPen(QColor(0xe5, 0x73, 0x73), 1.2, Qt::DotLine), QString());
    fMax_ = newCurve(this, QPen(colors::reference, 1.2, Qt::DotLine), tr("F max/min"));
    fMin_ = newCurve(this, QPen(colors::reference, 1.2, Qt::DotLine), QString());
    gOuter_ = newCurve(this, QPen(colors::error, 1.0, Qt::DashDotLine), tr("G (LS centre)"));
    gInner_ = newCurve(this, QPen(colors::error, 1.0, Qt::DashDotLine), QString());
    corners_ = addGraph();
    corners_->setLineStyle(QCPGraph::lsNone);
    corners_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, colors::reference, 6));
    corners_->setName(tr("sharp corners"));
    worst_ = addGraph();
    worst_->setLineStyle(QCPGraph::lsNone);
    worst_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 1.5),
                                            QColor(0xc6, 0x28, 0x28), 9));
    worst_->setName(tr("largest error"));
    // One scale on both axes holds for the axis rect as laid out. A resize, or a legend that
    // wraps to another row, changes that size only in the next replot's layout (after the fit
    // that the resize or the new run made): the fit is made again there, before drawing.
    connect(this, &QCustomPlot::afterLayout, this, [this] {
        if (viewHeld() || axisRect()->rect().size() == fittedRectSize_)
            return;
        if (corner_ >= 0 && corner_ < cornerCount())
            showCornerBox();
        else
            fitEqualScale();
    });
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    legend->setBrush(QColor(255, 255, 255, 210));
    // A program's legend has up to nine entries: in rows of four above the plot, not over
    // the path.
    axisRect()->insetLayout()->take(legend);
    axisRect()->insetLayout()->simplify();
    plotLayout()->insertRow(1);
    plotLayout()->addElement(1, 0, legend);
    setMaxLegendColumns(legend, 4); // fewer where the row is narrow
    legend->setBorderPen(Qt::NoPen);
    legend->setRowSpacing(0);
    legend->setMargins(QMargins(4, 0, 4, 0));
    plotLayout()->setRowStretchFactor(1, 0.001);
    legendSpacer_ = new QCPLayoutElement(this);
    legendSpacer_->setMargins(QMargins());
    legendSpacer_->setMinimumMargins(QMargins());
    legendSpacer_->setMaximumSize(QWIDGETSIZE_MAX, 0);
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignBottom | Qt::AlignLeft);
    setupInteractivePlot(this);
}

ContourPlot::~ContourPlot() {
    // The layout deletes what it holds: the legend goes back in, the spacer is deleted here.
    showLegendRow(true);
    delete legendSpacer_;
}

void ContourPlot::reserveTitleRoom(int px) {
    // The right end of the title row holds the corner and ballbar buttons (ContourControls);
    // the title is centred in the rest.
    const QMargins margins(4, 4, 4 + std::max(0, px), 4);
    if (figures_->margins() == margins)
        return;
    figures_->setMargins(margins);
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::setMagnification(double factor) {
    if (!(factor >= 1.0) || !std::isfinite(factor))
        return;
    magnification_ = factor;
    redraw();
}

void ContourPlot::setPolar(bool polar) {
    if (polar == polar_)
        return;
    polar_ = polar;
    corner_ = -1;
    redraw();
    fitEqualScale();
    replot(QCustomPlot::rpQueuedReplot);
}

bool ContourPlot::polarAvailable() const {
    return hasData_ && evaluation_.program && evaluation_.program->circular.has_value();
}

int ContourPlot::cornerCount() const {
    return hasData_ && evaluation_.program && !polar()
               ? static_cast<int>(evaluation_.program->contour.corners.size())
               : 0;
}

QString ContourPlot::figuresText() const {
    return figures_->text();
}
QString ContourPlot::noticeText() const {
    return notice_->text();
}

void ContourPlot::showSession(const Session& session, const SessionEvaluation& evaluation,
                              const QStringList& notices) {
    session_ = session;
    evaluation_ = evaluation;
    notices_ = notices;
    hasData_ = true;
    redraw();
    // The view follows the run unless the user zoomed or panned it (kept until it is reset).
    if (!viewHeld()) {
        if (corner_ >= 0 && corner_ < cornerCount())
            zoomToCorner(corner_);
        else
            fitAll();
    }
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::clearCurves() {
    for (QCPCurve* c : {commanded_, traced_, magnified_, reverse_, uncompensated_, independent_,
                        feedbackOnly_, fMax_, fMin_, gInner_, gOuter_})
        c->data()->clear();
    for (QCPCurve* c : bands_)
        c->data()->clear();
    worst_->data()->clear();
    corners_->data()->clear();
}

void ContourPlot::redraw() {
    clearCurves();
    QStringList notices = notices_;
    const auto& x = evaluation_.axes[0];
    const auto& y = evaluation_.axes[1];
    magnified_->setPen(QPen(colors::error, 1.2));
    if (!hasData_ || !x.ok || !y.ok) {
        figures_->setText(tr("XY contour: an axis could not be simulated"));
    } else if (session_.trajectory.kind == TrajectoryKind::Gcode && !evaluation_.program) {
        figures_->setText(tr("XY contour: the program could not be run"));
        notices << diagnosticText(evaluation_.programError);
    } else if (evaluation_.program) {
        for (const auto& w : evaluation_.program->warnings)
            notices << diagnosticText(w);
        if (polar())
            drawCircularTest();
        else
            drawProgram();
    } else {
        drawPresetRun();
    }
    notice_->setLines(notices);
    // The legend lists what is drawn, in the order of the plottables.
    legend->clearItems();
    for (int i = 0; i < plottableCount(); ++i) {
        QCPAbstractPlottable* p = plottable(i);
        bool empty = true;
        if (auto* c = qobject_cast<QCPCurve*>(p))
            empty = c->data()->isEmpty();
        else if (auto* g = qobject_cast<QCPGraph*>(p))
            empty = g->data()->isEmpty();
        if (!empty && !p->name().isEmpty())
            p->addToLegend();
    }
    showLegendRow(legend->itemCount() > 0);
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::showLegendRow(bool show) {
    // An empty legend's largest size is its margins (8 px): in the layout it would cap the
    // whole column, the plane and its title, at the title's least width. Without entries its
    // row holds a spacer of no height and no width limit instead.
    QCPLayoutElement* now = plotLayout()->element(1, 0);
    QCPLayoutElement* wanted = show ? static_cast<QCPLayoutElement*>(legend) : legendSpacer_;
    if (now == wanted)
        return;
    plotLayout()->take(now);
    plotLayout()->addElement(1, 0, wanted);
    legend->setVisible(show);
}

namespace {

/// The magnified contour of a preset run: the traced (tx, ty) about the commanded (cx, cy),
/// radially about the circle after its ramp-in (none drawn during it), else along the error.
XyPoints magnifiedPresetPoints(const QVector<double>& t, const QVector<double>& cx,
                               const QVector<double>& cy, const QVector<double>& tx,
                               const QVector<double>& ty, bool circle, double radius, double ramp,
                               double magnification) {
    XyPoints out;
    for (qsizetype i = 0; i < t.size(); ++i) {
        if (circle && t[i] >= ramp) {
            const double rho = std::hypot(tx[i], ty[i]);
            const double scaled = radius + magnification * (rho - radius);
            const double angle = std::atan2(ty[i], tx[i]);
            out.x.append(scaled * std::cos(angle));
            out.y.append(scaled * std::sin(angle));
        } else if (circle) {
            out.x.append(qQNaN());
            out.y.append(qQNaN());
        } else {
            out.x.append(cx[i] + magnification * (tx[i] - cx[i]));
            out.y.append(cy[i] + magnification * (ty[i] - cy[i]));
        }
    }
    return out;
}

QVector<double> toVector(const std::vector<double>& v) {
    return QVector<double>(v.begin(), v.end());
}

} // namespace

void ContourPlot::drawPresetRun() {
    const auto& x = evaluation_.axes[0];
    const auto& y = evaluation_.axes[1];
    const bool circle = session_.trajectory.kind == TrajectoryKind::Circle;
    const double radius = session_.trajectory.radius;
    const double ramp = session_.trajectory.rampInSeconds;
    const auto& coupled = evaluation_.coupledTrajectory;
    QVector<double> t, cx, cy, tx, ty;
    if (coupled) {
        // Cross-coupled: the coupled trace, and the independent axes' for the comparison.
        t = toVector(coupled->t);
        cx = toVector(coupled->referenceX);
        cy = toVector(coupled->referenceY);
        tx = toVector(coupled->coupled[0].y);
        ty = toVector(coupled->coupled[1].y);
    } else {
        t = toVector(x.run.t);
        cx = toVector(x.run.r);
        cy = toVector(resampleLinear(y.run.t, y.run.r, x.run.t));
        tx = toVector(x.run.y);
        ty = toVector(resampleLinear(y.run.t, y.run.y, x.run.t));
    }
    commanded_->setName(tr("commanded"));
    commanded_->setData(t, cx, cy, true);
    traced_->setData(t, tx, ty, true);
    const XyPoints m =
        magnifiedPresetPoints(t, cx, cy, tx, ty, circle, radius, ramp, magnification_);
    magnified_->setData(t, m.x, m.y, true);
    magnified_->setName(tr("error × %1").arg(magnification_));
    if (coupled) {
        const XyPoints alone = magnifiedPresetPoints(t, cx, cy, toVector(coupled->independent[0].y),
                                                     toVector(coupled->independent[1].y), circle,
                                                     radius, ramp, magnification_);
        independent_->setData(t, alone.x, alone.y, true);
        independent_->setName(tr("independent axes, error × %1").arg(magnification_));
        const QString what = circle ? tr("radial, after the ramp-in") : tr("from the line");
        figures_->setText(
            tr("Cross-coupled contour error (%1): max %2 mm, RMS %3 mm; independent axes: max "
               "%4 mm")
                .arg(what, mm(coupled->coupledError.maxAbs), mm(coupled->coupledError.rms),
                     mm(coupled->independentError.maxAbs)));
    } else if (evaluation_.contour) {
        figures_->setText(tr("Contour error (radial, after the ramp-in): max %1 mm, RMS %2 mm")
                              .arg(mm(evaluation_.contour->maxAbs), mm(evaluation_.contour->rms)));
    } else {
        figures_->setText(tr("Tracking error: max |e_x| %1 mm, max |e_y| %2 mm")
                              .arg(mm(x.metrics.maxAbsError), mm(y.metrics.maxAbsError)));
    }
}

void ContourPlot::drawProgram() {
    const ContourRun& run = *evaluation_.program;
    const Path& path = *evaluation_.programPath;
    const ContourErrorResult& c = run.contour;
    commanded_->setName(tr("programmed"));
    setPoints(commanded_, programmedPathPoints(path));
    traced_->setData(QVector<double>(run.trace.x.begin(), run.trace.x.end()),
                     QVector<double>(run.trace.y.begin(), run.trace.y.end()));
    const XyPoints magnified = magnifiedContourPoints(path, c, magnification_);
    setPoints(magnified_, magnified);
    magnified_->setPen(QPen(kBandColors[0], 1.2));
    magnified_->setName(tr("error × %1, |e| (mm) < %2")
                            .arg(magnification_)
                            .arg(QString::number(kBandFractions[0] * c.maxAbs, 'g', 3)));
    for (std::size_t b = 0; b < bands_.size(); ++b) {
        const double threshold = kBandFractions[b] * c.maxAbs;
        XyPoints band;
        for (qsizetype k = 0; k < magnified.x.size(); ++k) {
            const bool in =
                c.maxAbs > 0.0 && std::abs(c.error[static_cast<std::size_t>(k)]) >= threshold;
            band.x.append(in ? magnified.x[k] : qQNaN());
            band.y.append(in ? magnified.y[k] : qQNaN());
        }
        setPoints(bands_[b], band);
        bands_[b]->setName(tr("≥ %1").arg(QString::number(threshold, 'g', 3)));
    }
    if (c.measuredSamples > 0) // the traced point, which stays in view at any magnification
        worst_->setData({c.maxPoint.x}, {c.maxPoint.y});
    QVector<double> cornerX, cornerY;
    for (const CornerOvershoot& corner : c.corners) {
        cornerX.append(corner.corner.x);
        cornerY.append(corner.corner.y);
    }
    corners_->setData(cornerX, cornerY);
    QString text = tr("Contour error max %1, RMS %2 mm")
                       .arg(QString::number(c.maxAbs, 'g', 3), QString::number(c.rms, 'g', 3));
    if (corner_ >= 0 && corner_ < static_cast<int>(c.corners.size())) {
        const CornerOvershoot& corner = c.corners[static_cast<std::size_t>(corner_)];
        text +=
            corner.samples > 0
                ? tr("; corner %1/%2: %3 mm")
                      .arg(corner_ + 1)
                      .arg(c.corners.size())
                      .arg(QString::number(corner.maxAbsError, 'g', 3))
                : tr("; corner %1/%2: no sample near it").arg(corner_ + 1).arg(c.corners.size());
    } else if (!c.corners.empty()) {
        text += tr("; %n corner(s)", nullptr, static_cast<int>(c.corners.size()));
    }
    if (run.independent) {
        // The comparison: the same program with the axes independent, magnified alike.
        const ContourErrorResult& alone = run.independent->contour;
        setPoints(independent_, magnifiedContourPoints(path, alone, magnification_));
        independent_->setName(tr("independent axes, error × %1").arg(magnification_));
        text = tr("Cross-coupled: ") + text +
               tr("; independent axes: max %1 mm").arg(QString::number(alone.maxAbs, 'g', 3));
        if (run.feedbackOnly) {
            const ContourErrorResult& feedback = run.feedbackOnly->contour;
            setPoints(feedbackOnly_, magnifiedContourPoints(path, feedback, magnification_));
            feedbackOnly_->setName(tr("without feedforward, error × %1").arg(magnification_));
            text += tr("; without feedforward: max %1 mm")
                        .arg(QString::number(feedback.maxAbs, 'g', 3));
        }
    }
    figures_->setText(text);
}

void ContourPlot::drawCircularTest() {
    const ContourCircularTest& test = *evaluation_.program->circular;
    const Iso230Circular& iso = test.iso;
    const NominalCircle& n = test.nominal;
    const double m = magnification_;
    commanded_->setName(tr("nominal"));
    setPoints(commanded_, circlePoints(n.centre, n.radius));
    const QString forward = test.clockwise ? tr("CW run") : tr("CCW run");
    const QString backward = test.clockwise ? tr("CCW run") : tr("CW run");
    setPoints(magnified_, polarDeviationPoints(test.x, test.y, n, m));
    magnified_->setPen(QPen(colors::output, 1.4));
    magnified_->setName(tr("%1 ×%2").arg(forward).arg(m));
    setPoints(reverse_, polarDeviationPoints(test.reverseX, test.reverseY, n, m));
    reverse_->setName(tr("%1 ×%2").arg(backward).arg(m));
    setPoints(fMax_, circlePoints(n.centre, n.radius + m * iso.radialDeviationFMax));
    setPoints(fMin_, circlePoints(n.centre, n.radius + m * iso.radialDeviationFMin));
    const Point2 lsCentre = n.centre + m * (iso.leastSquares.centre - n.centre);
    setPoints(gOuter_,
              circlePoints(lsCentre, n.radius + m * (iso.maxRadiusAboutLeastSquares - n.radius)));
    setPoints(gInner_,
              circlePoints(lsCentre, n.radius + m * (iso.minRadiusAboutLeastSquares - n.radius)));
    QString text = tr("ISO 230-4 (mm): G %1, F max %2, F min %3")
                       .arg(mm(iso.circularDeviationG), mm(iso.radialDeviationFMax),
                            mm(iso.radialDeviationFMin));
    if (iso.hysteresisH)
        text += tr(", H %1").arg(mm(*iso.hysteresisH));
    if (test.uncompensatedIso) {
        // The comparison: the first run again without the friction compensation.
        setPoints(uncompensated_,
                  polarDeviationPoints(test.uncompensatedX, test.uncompensatedY, n, m));
        uncompensated_->setName(tr("%1 without friction compensation ×%2").arg(forward).arg(m));
        text += tr("; without friction compensation G %1")
                    .arg(mm(test.uncompensatedIso->circularDeviationG));
    }
    const auto& independent = evaluation_.program->independent;
    if (independent && independent->iso) {
        // The comparison: the first run with the axes independent.
        setPoints(independent_,
                  polarDeviationPoints(independent->circleX, independent->circleY, n, m));
        independent_->setName(tr("%1 with independent axes ×%2").arg(forward).arg(m));
        text += tr("; independent axes G %1").arg(mm(independent->iso->circularDeviationG));
    }
    const auto& feedback = evaluation_.program->feedbackOnly;
    if (feedback && feedback->iso) {
        setPoints(feedbackOnly_, polarDeviationPoints(feedback->circleX, feedback->circleY, n, m));
        feedbackOnly_->setName(tr("%1 without feedforward ×%2").arg(forward).arg(m));
        text += tr("; without feedforward G %1").arg(mm(feedback->iso->circularDeviationG));
    }
    figures_->setText(text);
}

bool ContourPlot::zoomToCorner(int index) {
    if (index < 0 || index >= cornerCount())
        return false;
    corner_ = index;
    redraw(); // the figures name the corner
    showCornerBox();
    replot(QCustomPlot::rpQueuedReplot);
    emit cornerChanged(corner_, cornerCount());
    return true;
}

void ContourPlot::fitAll() {
    releaseView();
    const bool changed = corner_ != -1;
    corner_ = -1;
    if (changed)
        redraw();
    fitEqualScale();
    replot(QCustomPlot::rpQueuedReplot);
    emit cornerChanged(-1, cornerCount());
}

void ContourPlot::fitEqualScale() {
    // Fit everything drawn with one scale (mm per pixel) on both axes, so a circle looks round:
    // the commanded and traced paths, the magnified error (which leaves the path by
    // magnification times the error), and in the polar view both runs and the F and G circles.
    QCPRange xr, yr;
    const bool found = curvesBoundingBox(
        polar()
            ? std::vector<QCPCurve*>{commanded_, traced_, magnified_, reverse_, uncompensated_,
                                     independent_, feedbackOnly_, fMax_, fMin_, gInner_, gOuter_}
            : std::vector<QCPCurve*>{commanded_, traced_, magnified_, independent_, feedbackOnly_},
        xr, yr);
    if (found)
        showBox(xr.lower, xr.upper, yr.lower, yr.upper);
}

void ContourPlot::showBox(double minX, double maxX, double minY, double maxY) {
    const double w = axisRect()->width(), h = axisRect()->height();
    if (w <= 0 || h <= 0)
        return;
    fittedRectSize_ = axisRect()->rect().size();
    const double span = std::max({(maxX - minX) / w, (maxY - minY) / h, 1e-9}) * 1.12;
    xAxis->setRange((minX + maxX) / 2.0, span * w, Qt::AlignCenter);
    yAxis->setRange((minY + maxY) / 2.0, span * h, Qt::AlignCenter);
}

void ContourPlot::resizeEvent(QResizeEvent* event) {
    QCustomPlot::resizeEvent(event);
    if (corner_ >= 0 && corner_ < cornerCount())
        showCornerBox();
    else
        fitEqualScale();
}

void ContourPlot::showCornerBox() {
    const ContourErrorResult& contour = evaluation_.program->contour;
    const CornerOvershoot& c = contour.corners[static_cast<std::size_t>(corner_)];
    // The corner's magnified error, and the traced path however far it cuts the corner (the
    // largest error of the run), at least 1 mm each way.
    const double half = std::max({1.0, 1.5 * magnification_ * c.maxAbsError, 1.5 * contour.maxAbs});
    showBox(c.corner.x - half, c.corner.x + half, c.corner.y - half, c.corner.y + half);
}

} // namespace xyt::ui
