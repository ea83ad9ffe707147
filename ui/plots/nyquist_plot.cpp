// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/nyquist_plot.h"

#include "ui/plots/plane_grid.h"
#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"

#include <cmath>
#include <numbers>

namespace xyt::ui {

namespace {
std::vector<std::complex<double>> circle(std::complex<double> centre, double radius) {
    std::vector<std::complex<double>> points;
    for (int i = 0; i <= 180; ++i)
        points.push_back(centre + std::polar(radius, 2.0 * std::numbers::pi * i / 180.0));
    return points;
}

void setCurve(QCPCurve* curve, const std::vector<std::complex<double>>& points) {
    QVector<QCPCurveData> data;
    data.reserve(static_cast<qsizetype>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        if (std::isfinite(points[i].real()) && std::isfinite(points[i].imag()))
            data.append(QCPCurveData(static_cast<double>(i), points[i].real(), points[i].imag()));
    curve->data()->set(data, true);
}
} // namespace

NyquistPlot::NyquistPlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(
        tr("Nyquist diagram: L(jω) in the complex plane for ω from 0 to ∞ (mirrored for negative "
           "ω), with the critical point −1; Z = N + P counts the closed-loop unstable poles from "
           "the encirclements N of −1 and the open-loop unstable poles P."));
    setObjectName("nyquist");
    setAutoAddPlottableToLegend(true);
    plotLayout()->insertRow(0);
    title_ =
        new QCPTextElement(this, tr("Nyquist diagram"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("Re L"));
    yAxis->setLabel(tr("Im L"));
    unitCircle_ = new QCPCurve(xAxis, yAxis);
    unitCircle_->setPen(QPen(QColor(0xc8, 0xc8, 0xc8), 1, Qt::DashLine));
    unitCircle_->setName(tr("|L| = 1"));
    msCircle_ = new QCPCurve(xAxis, yAxis);
    msCircle_->setPen(QPen(QColor(0xd6, 0x27, 0x28, 150), 1, Qt::DotLine));
    msCircle_->setName(tr("distance 1/Ms to −1"));
    curve_ = new QCPCurve(xAxis, yAxis);
    curve_->setPen(QPen(colors::output, 1.8));
    curve_->setName(tr("L(jω), ω ≥ 0"));
    mirror_ = new QCPCurve(xAxis, yAxis);
    mirror_->setPen(QPen(colors::output, 1.2, Qt::DashLine));
    mirror_->setName(tr("ω < 0 (mirror)"));
    critical_ = addGraph();
    critical_->setLineStyle(QCPGraph::lsNone);
    critical_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssPlus, QPen(colors::error, 2.5), Qt::NoBrush, 12));
    critical_->setName(tr("−1"));
    critical_->addData(-1.0, 0.0);
    placeLegendBelow(this, 2, 5);
    criterion_ = addTextRow(this, 3, QString());
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
    setCurve(unitCircle_, circle(0.0, 1.0));
}

NyquistPlot::~NyquistPlot() = default;

void NyquistPlot::showCurve(const NyquistCurve& c, const StabilityMargins& margins,
                            const QString& title) {
    hasResult_ = true;
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    legend->setVisible(true);
    setCurve(curve_, c.points);
    std::vector<std::complex<double>> mirror;
    mirror.reserve(c.points.size());
    for (auto it = c.points.rbegin(); it != c.points.rend(); ++it)
        mirror.push_back(std::conj(*it));
    setCurve(mirror_, mirror);
    // Ms is a distance from -1 only for a stable closed loop; an unstable one has no Ms circle.
    const bool msKnown = margins.closedLoopStable && std::isfinite(margins.peakSensitivity) &&
                         margins.peakSensitivity > 0.0;
    setCurve(msCircle_, msKnown ? circle(-1.0, 1.0 / margins.peakSensitivity)
                                : std::vector<std::complex<double>>{});
    const int z = c.closedLoopUnstablePoles;
    QString verdict =
        c.passesThroughMinusOne
            ? tr("the curve passes through −1: a closed-loop pole on the stability boundary")
        : z == 0 ? tr("closed loop stable")
                 : tr("%1 closed-loop pole(s) unstable").arg(z);
    criterion_->setText(
        tr("Nyquist: N = %1 clockwise encirclements of −1, P = %2 unstable open-loop "
           "poles → Z = N + P = %3: %4   (Ms = %5)")
            .arg(c.clockwiseEncirclements)
            .arg(c.openLoopUnstablePoles)
            .arg(z)
            .arg(verdict)
            .arg(msKnown                    ? QString::number(margins.peakSensitivity, 'g', 4)
                 : margins.closedLoopStable ? tr("∞")
                                            : tr("n/a, the closed loop is unstable")));
    criterion_->setTextColor(
        z == 0 && !c.passesThroughMinusOne ? palette().color(QPalette::WindowText) : colors::error);
    QStringList notes;
    for (const auto& w : c.warnings)
        notes << diagnosticText(w);
    if (!c.indentations.empty())
        notes << tr("poles on the boundary are passed on small indentations: the curve closes at "
                    "infinity there");
    notice_->setSevere(false);
    notice_->setLines(notes);
    // The region that decides stability: around -1 and the origin, out to where the curve
    // leaves a few units (an integrator sends it to infinity, which would hide -1).
    std::vector<std::complex<double>> framed{{-1.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}};
    for (const auto& p : c.points)
        if (std::abs(p) <= 4.0)
            framed.push_back(p), framed.push_back(std::conj(p));
    if (c.tsSeconds != lastTs_)
        releaseView();
    if (!ranged_ || c.tsSeconds != lastTs_ ||
        (!viewHeld() && anyOutsideView(this, {{-1.0, 0.0}}))) {
        setView(this, fittedBox({}, framed));
        ranged_ = true;
        lastTs_ = c.tsSeconds;
    }
    replot(QCustomPlot::rpQueuedReplot);
}

void NyquistPlot::showNoResult(const QString& title, const QString& reason) {
    hasResult_ = false;
    title_->setText(title);
    title_->setTextColor(colors::error);
    for (QCPCurve* c : {curve_, mirror_, msCircle_})
        c->data()->clear();
    criterion_->setText(QString());
    legend->setVisible(false);
    notice_->setSevere(true);
    notice_->setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
