// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/contour_plot.h"

#include "ui/plots/plot_tools.h"

#include <cmath>

namespace xyt::ui {

ContourPlot::ContourPlot(QWidget* parent) : PlotWidget(parent) {
    setObjectName("xy-contour");
    plotLayout()->insertRow(0);
    figures_ = new QCPTextElement(this, QString(), QFont(font().family(), 9));
    plotLayout()->addElement(0, 0, figures_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("x (mm)"));
    yAxis->setLabel(tr("y (mm)"));
    commanded_ = new QCPCurve(xAxis, yAxis);
    commanded_->setPen(QPen(colors::reference, 1.2, Qt::DashLine));
    commanded_->setName(tr("commanded"));
    traced_ = new QCPCurve(xAxis, yAxis);
    traced_->setPen(QPen(colors::output, 1.8));
    traced_->setName(tr("traced"));
    magnified_ = new QCPCurve(xAxis, yAxis);
    magnified_->setPen(QPen(colors::error, 1.2));
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    legend->setBrush(QColor(255, 255, 255, 210));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
}

void ContourPlot::setMagnification(double factor) {
    if (!(factor >= 1.0) || !std::isfinite(factor))
        return;
    magnification_ = factor;
    redraw();
}

void ContourPlot::showSession(const Session& session, const SessionEvaluation& evaluation) {
    session_ = session;
    evaluation_ = evaluation;
    hasData_ = true;
    redraw();
    fitEqualScale();
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::redraw() {
    commanded_->data()->clear();
    traced_->data()->clear();
    magnified_->data()->clear();
    const auto& x = evaluation_.axes[0];
    const auto& y = evaluation_.axes[1];
    if (!hasData_ || !x.ok || !y.ok) {
        figures_->setText(tr("XY contour: an axis could not be simulated"));
        replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    const std::vector<double> yr = resampleLinear(y.run.t, y.run.r, x.run.t);
    const std::vector<double> yy = resampleLinear(y.run.t, y.run.y, x.run.t);
    const bool circle = session_.trajectory.kind == TrajectoryKind::Circle;
    const double radius = session_.trajectory.radius;
    const double ramp = session_.trajectory.rampInSeconds;
    const std::size_t n = x.run.t.size();
    QVector<double> t(static_cast<qsizetype>(n)), cx(t.size()), cy(t.size()), tx(t.size()),
        ty(t.size()), mx(t.size()), my(t.size());
    for (std::size_t k = 0; k < n; ++k) {
        const auto i = static_cast<qsizetype>(k);
        t[i] = x.run.t[k];
        cx[i] = x.run.r[k];
        cy[i] = yr[k];
        tx[i] = x.run.y[k];
        ty[i] = yy[k];
        if (circle && x.run.t[k] >= ramp) {
            const double rho = std::hypot(tx[i], ty[i]);
            const double scaled = radius + magnification_ * (rho - radius);
            const double angle = std::atan2(ty[i], tx[i]);
            mx[i] = scaled * std::cos(angle);
            my[i] = scaled * std::sin(angle);
        } else if (circle) {
            mx[i] = qQNaN(); // no contour during the ramp-in
            my[i] = qQNaN();
        } else {
            mx[i] = cx[i] + magnification_ * (tx[i] - cx[i]);
            my[i] = cy[i] + magnification_ * (ty[i] - cy[i]);
        }
    }
    commanded_->setData(t, cx, cy, true);
    traced_->setData(t, tx, ty, true);
    magnified_->setData(t, mx, my, true);
    magnified_->setName(tr("error × %1").arg(magnification_));
    if (evaluation_.contour)
        figures_->setText(tr("Contour error (radial, after the ramp-in): max %1 mm, RMS %2 mm")
                              .arg(evaluation_.contour->maxAbs, 0, 'f', 4)
                              .arg(evaluation_.contour->rms, 0, 'f', 4));
    else
        figures_->setText(tr("Tracking error: max |e_x| %1 mm, max |e_y| %2 mm")
                              .arg(x.metrics.maxAbsError, 0, 'f', 4)
                              .arg(y.metrics.maxAbsError, 0, 'f', 4));
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::fitEqualScale() {
    // Fit the commanded and traced paths with one scale (mm per pixel) on both axes, so a
    // circle looks round.
    bool found = false;
    QCPRange xr, yr;
    for (QCPCurve* c : {commanded_, traced_}) {
        bool okX = false, okY = false;
        const QCPRange cx = c->getKeyRange(okX);
        const QCPRange cy = c->getValueRange(okY);
        if (!okX || !okY)
            continue;
        xr = found ? QCPRange(std::min(xr.lower, cx.lower), std::max(xr.upper, cx.upper)) : cx;
        yr = found ? QCPRange(std::min(yr.lower, cy.lower), std::max(yr.upper, cy.upper)) : cy;
        found = true;
    }
    const double w = axisRect()->width(), h = axisRect()->height();
    if (!found || w <= 0 || h <= 0)
        return;
    const double span = std::max({xr.size() / w, yr.size() / h, 1e-9}) * 1.12;
    xAxis->setRange(xr.center(), span * w, Qt::AlignCenter);
    yAxis->setRange(yr.center(), span * h, Qt::AlignCenter);
}

void ContourPlot::resizeEvent(QResizeEvent* event) {
    QCustomPlot::resizeEvent(event);
    fitEqualScale();
}

} // namespace xyt::ui
