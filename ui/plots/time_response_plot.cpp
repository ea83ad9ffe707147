// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/time_response_plot.h"

#include "ui/plots/tick_spacing.h"
#include "ui/session/diagnostic_text.h"

#include "ui/plots/plot_tools.h"

#include <algorithm>

namespace xyt::ui {

namespace {
QCPGraph* makeGraph(QCPAxisRect* rect, const QColor& color, const QString& name,
                    qreal width = 1.5) {
    auto* g = new QCPGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    g->setPen(QPen(color, width));
    g->setName(name);
    g->setAdaptiveSampling(true);
    return g;
}
} // namespace

TimeResponsePlot::TimeResponsePlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Time response of the selected axis on the trajectory: reference r, output y and "
                  "error e = r − y (mm), and the command u (V) with the ±umax band and clipped "
                  "intervals shaded; the digital implementation's run as a translucent band."));
    setObjectName("time-response");
    plotLayout()->clear();
    title_ = new QCPTextElement(this, QString(), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    positionRect_ = new QCPAxisRect(this);
    errorRect_ = new QCPAxisRect(this);
    controlRect_ = new QCPAxisRect(this);
    plotLayout()->addElement(1, 0, positionRect_);
    plotLayout()->addElement(2, 0, errorRect_);
    plotLayout()->addElement(3, 0, controlRect_);
    plotLayout()->setRowStretchFactor(0, 0.01);
    plotLayout()->setRowStretchFactor(1, 1.4);
    auto* margins = new QCPMarginGroup(this);
    for (QCPAxisRect* rect : {positionRect_, errorRect_, controlRect_}) {
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->setRangeDrag(Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(Qt::Horizontal | Qt::Vertical);
        styleAxisRect(rect);
        // Shared time axis: panning or zooming one panel moves all three.
        connect(rect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                this, [this, rect](const QCPRange& r) {
                    for (QCPAxisRect* other : {positionRect_, errorRect_, controlRect_})
                        if (other != rect && other->axis(QCPAxis::atBottom)->range() != r)
                            other->axis(QCPAxis::atBottom)->setRange(r);
                });
    }
    // Value ticks by the panel's height (about one per 30 px): the short u and error panels at
    // 1366x768 would otherwise crowd five labels into 60 px.
    for (QCPAxisRect* rect : {positionRect_, errorRect_, controlRect_})
        setLeastTickSpacing(rect->axis(QCPAxis::atLeft), 30);
    positionRect_->axis(QCPAxis::atLeft)->setLabel(tr("position (mm)"));
    errorRect_->axis(QCPAxis::atLeft)->setLabel(tr("error (mm)"));
    controlRect_->axis(QCPAxis::atLeft)->setLabel(tr("u (V)"));
    controlRect_->axis(QCPAxis::atBottom)->setLabel(tr("time (s)"));

    reference_ = makeGraph(positionRect_, colors::reference, tr("reference r"), 1.2);
    reference_->setPen(QPen(colors::reference, 1.2, Qt::DashLine));
    snapshotOutput_ = makeGraph(positionRect_, colors::snapshot, tr("snapshot"), 1.2);
    // The digital implementation under the design: a wide translucent band, created before the
    // design's lines so that they are drawn over it. Where the two coincide the band is a halo
    // around the design's line; where they differ it separates (a dashed line over the design
    // hid the design where the two coincide).
    QColor band = colors::digital;
    band.setAlpha(110);
    digitalOutput_ = makeGraph(positionRect_, band, tr("digital y"), 3.5);
    digitalError_ = makeGraph(errorRect_, band, tr("digital e"), 3.5);
    digitalControl_ = makeGraph(controlRect_, band, tr("digital u (held)"), 2.5);
    for (QCPGraph* g : {digitalOutput_, digitalError_, digitalControl_})
        g->setVisible(false);
    // The run without the input shaper, under the shaped one.
    unshapedOutput_ = makeGraph(positionRect_, colors::unshaped, tr("y without the shaper"), 1.3);
    unshapedError_ = makeGraph(errorRect_, colors::unshaped, tr("e without the shaper"), 1.3);
    for (QCPGraph* g : {unshapedOutput_, unshapedError_}) {
        g->setPen(QPen(colors::unshaped, 1.3, Qt::DotLine));
        g->setVisible(false);
    }
    unshapedError_->removeFromLegend();
    output_ = makeGraph(positionRect_, colors::output, tr("output y"));
    error_ = makeGraph(errorRect_, colors::error, tr("error e"));
    // Where the table sticks (a table with dry friction): a band over the error plot.
    stuckUpper_ = makeGraph(errorRect_, Qt::transparent, tr("table stuck"));
    stuckLower_ = makeGraph(errorRect_, Qt::transparent, QString());
    stuckUpper_->setBrush(QColor(0x7f, 0x7f, 0x7f, 70)); // visible as a legend swatch too
    stuckUpper_->setChannelFillGraph(stuckLower_);
    for (QCPGraph* g : {stuckUpper_, stuckLower_}) {
        g->setAdaptiveSampling(false);
        g->removeFromLegend();
    }
    clipUpper_ = makeGraph(controlRect_, Qt::transparent, tr("clipped"));
    clipLower_ = makeGraph(controlRect_, Qt::transparent, QString());
    clipUpper_->setBrush(QColor(0xd6, 0x27, 0x28, 50));
    clipUpper_->setChannelFillGraph(clipLower_);
    clipUpper_->setAdaptiveSampling(false);
    clipLower_->setAdaptiveSampling(false);
    snapshotControl_ = makeGraph(controlRect_, colors::snapshot, tr("snapshot u"), 1.2);
    snapshotError_ = makeGraph(errorRect_, colors::snapshot, tr("snapshot e"), 1.2);
    for (QCPGraph* g : {snapshotOutput_, snapshotControl_, snapshotError_})
        g->setPen(QPen(colors::snapshot, 1.4, Qt::DashLine));
    error_->setLayer(QStringLiteral("main")); // drawn over the snapshot's error
    // u split into its parts when the controller has a command feedforward.
    feedforward_ = makeGraph(controlRect_, colors::feedforward, tr("feedforward part"), 1.3);
    feedforward_->setPen(QPen(colors::feedforward, 1.3, Qt::DashLine));
    feedbackPart_ = makeGraph(controlRect_, colors::output, tr("feedback part"), 1.2);
    control_ = makeGraph(controlRect_, colors::control, tr("control u"));
    digitalControl_->setLineStyle(QCPGraph::lsStepLeft); // zero-order hold
    upperLimit_ = new QCPItemStraightLine(this);
    lowerLimit_ = new QCPItemStraightLine(this);
    for (QCPItemStraightLine* line : {upperLimit_, lowerLimit_}) {
        line->setClipAxisRect(controlRect_);
        line->point1->setAxes(controlRect_->axis(QCPAxis::atBottom),
                              controlRect_->axis(QCPAxis::atLeft));
        line->point2->setAxes(controlRect_->axis(QCPAxis::atBottom),
                              controlRect_->axis(QCPAxis::atLeft));
        line->setPen(QPen(colors::limit, 1, Qt::DashDotLine));
    }
    snapshotOutput_->setVisible(false);
    snapshotControl_->setVisible(false);
    snapshotError_->setVisible(false);

    auto* legend = new QCPLegend;
    legend_ = legend;
    positionRect_->insetLayout()->addElement(legend, Qt::AlignBottom | Qt::AlignRight);
    legend->setLayer("legend");
    legend->setFont(QFont(font().family(), 8));
    legend->setBrush(QColor(255, 255, 255, 210));
    // Compact: up to four rows fit the position plot's 100 px at 1366x768.
    compactLegend(legend);
    legend->setRowSpacing(0);
    legend->setMargins(QMargins(4, 1, 4, 1));
    legend->addItem(new QCPPlottableLegendItem(legend, reference_));
    legend->addItem(new QCPPlottableLegendItem(legend, output_));
    controlLegend_ = new QCPLegend;
    controlRect_->insetLayout()->addElement(controlLegend_, Qt::AlignTop | Qt::AlignRight);
    controlLegend_->setLayer("legend");
    controlLegend_->setFont(QFont(font().family(), 8));
    controlLegend_->setBrush(QColor(255, 255, 255, 210));
    compactLegend(controlLegend_);
    controlLegend_->setRowSpacing(0);
    controlLegend_->setMargins(QMargins(4, 1, 4, 1));
    controlLegend_->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    for (QCPGraph* g : {control_, feedforward_, feedbackPart_})
        controlLegend_->addItem(new QCPPlottableLegendItem(controlLegend_, g));
    controlLegend_->setVisible(false);
    notice_ = std::make_unique<PlotNotice>(this, positionRect_, Qt::AlignTop | Qt::AlignLeft);
    controlNotice_ = std::make_unique<PlotNotice>(this, controlRect_, Qt::AlignTop | Qt::AlignLeft);
    setupInteractivePlot(this);
}

void TimeResponsePlot::showAxis(const AxisEvaluation& axis, const QString& axisTitle,
                                double umaxVolts, const QStringList& extraNotices) {
    QStringList notices = extraNotices;
    for (const Diagnostic& w : axis.warnings)
        notices << diagnosticText(w);
    notice_->setSevere(!axis.ok || axis.metrics.diverged);
    notice_->setLines(notices);
    // Patrick, Ishak and Adnan's loop has no actuator limit: the command is shown unclipped, and
    // says so where the user reads it.
    controlNotice_->setLines(axis.ok && axis.pp && axis.metrics.saturated
                                 ? QStringList{tr("linear loop: |u| is not clipped at ±%1 V here "
                                                  "(the shaded time would saturate)")
                                                   .arg(umaxVolts)}
                                 : QStringList{});
    if (!axis.ok) {
        title_->setText(tr("%1: not simulated (%2: %3)")
                            .arg(axisTitle, QString::fromStdString(axis.errorField),
                                 diagnosticText(axis.error)));
        title_->setTextColor(colors::error);
        for (QCPGraph* g : {reference_, output_, error_, control_, clipUpper_, clipLower_,
                            digitalOutput_, digitalError_, digitalControl_, feedforward_,
                            feedbackPart_, unshapedOutput_, unshapedError_})
            g->data()->clear();
        controlLegend_->setVisible(false);
        upperLimit_->setVisible(false);
        lowerLimit_->setVisible(false);
        legend_->setVisible(false);
        replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    legend_->setVisible(true);
    const SimulationResult& run = axis.run;
    QString title = tr("%1 — time response").arg(axisTitle);
    if (!axis.step.stable)
        title += tr("  (UNSTABLE closed loop)");
    title_->setText(title);
    title_->setTextColor(axis.step.stable ? palette().color(QPalette::WindowText) : colors::error);
    // At most a few thousand points per line whatever the run's length (minMaxDecimated).
    reference_->data()->set(minMaxDecimated(run.t, run.r), true);
    output_->data()->set(minMaxDecimated(run.t, run.y), true);
    error_->data()->set(minMaxDecimated(run.t, run.e), true);
    control_->data()->set(minMaxDecimated(run.t, run.u), true);
    const bool split = run.uFeedforward.size() == run.u.size() && !run.u.empty();
    feedforward_->setVisible(split);
    feedbackPart_->setVisible(split);
    controlLegend_->setVisible(split);
    if (split) {
        std::vector<double> rest(run.u.size());
        for (std::size_t k = 0; k < rest.size(); ++k)
            rest[k] = run.u[k] - run.uFeedforward[k];
        feedforward_->data()->set(minMaxDecimated(run.t, run.uFeedforward), true);
        feedbackPart_->data()->set(minMaxDecimated(run.t, rest), true);
    } else {
        feedforward_->data()->clear();
        feedbackPart_->data()->clear();
    }
    const bool digital = digitalVisible_ && axis.digital != nullptr;
    for (QCPGraph* g : {digitalOutput_, digitalError_, digitalControl_})
        g->setVisible(digital);
    if (digital) {
        const SampledDataRun& d = axis.digital->run;
        digitalOutput_->data()->set(minMaxDecimated(d.result.t, d.result.y), true);
        digitalError_->data()->set(minMaxDecimated(d.result.t, d.result.e), true);
        digitalControl_->data()->set(minMaxDecimated(d.result.t, d.applied), true);
        digitalOutput_->setName(axis.gt
                                    ? tr("digital y (Ts %1 s, held u)").arg(axis.digital->tsSeconds)
                                    : tr("digital y (encoder, DAC, limit)"));
        if (!legend_->hasItemWithPlottable(digitalOutput_))
            legend_->addItem(new QCPPlottableLegendItem(legend_, digitalOutput_));
    } else {
        for (QCPGraph* g : {digitalOutput_, digitalError_, digitalControl_})
            g->data()->clear();
        if (legend_->hasItemWithPlottable(digitalOutput_))
            legend_->removeItem(legend_->itemWithPlottable(digitalOutput_));
    }
    // With an input shaper on the reference: the tool point and its error without it.
    const bool unshaped = axis.shaping != nullptr && !axis.shaping->unshapedRun.t.empty();
    for (QCPGraph* g : {unshapedOutput_, unshapedError_})
        g->setVisible(unshaped);
    if (unshaped) {
        const SimulationResult& u = axis.shaping->unshapedRun;
        unshapedOutput_->data()->set(minMaxDecimated(u.t, u.y), true);
        unshapedError_->data()->set(minMaxDecimated(u.t, u.e), true);
        if (!legend_->hasItemWithPlottable(unshapedOutput_))
            legend_->addItem(new QCPPlottableLegendItem(legend_, unshapedOutput_));
    } else {
        for (QCPGraph* g : {unshapedOutput_, unshapedError_})
            g->data()->clear();
        if (legend_->hasItemWithPlottable(unshapedOutput_))
            legend_->removeItem(legend_->itemWithPlottable(unshapedOutput_));
    }
    // Shade the samples where the table sticks, over the error's range.
    if (!run.sliding.empty()) {
        double peak = 0.0;
        for (double e : run.e)
            if (std::isfinite(e))
                peak = std::max(peak, std::abs(e));
        std::vector<bool> stuck(run.sliding.size());
        for (std::size_t k = 0; k < stuck.size(); ++k)
            stuck[k] = run.sliding[k] == 0;
        const double half = peak > 0.0 ? 1.05 * peak : 1.0;
        stuckUpper_->data()->set(flagDecimated(run.t, stuck, half), true);
        stuckLower_->data()->set(flagDecimated(run.t, stuck, -half), true);
        if (!legend_->hasItemWithPlottable(stuckUpper_))
            legend_->addItem(new QCPPlottableLegendItem(legend_, stuckUpper_));
    } else {
        stuckUpper_->data()->clear();
        stuckLower_->data()->clear();
        if (legend_->hasItemWithPlottable(stuckUpper_))
            legend_->removeItem(legend_->itemWithPlottable(stuckUpper_));
    }
    // Shade the clipped samples: a band from -1.1 umax to 1.1 umax, NaN (a gap) elsewhere.
    const double band = std::isfinite(umaxVolts) ? 1.1 * umaxVolts : 0.0;
    clipUpper_->data()->set(flagDecimated(run.t, run.clipped, band), true);
    clipLower_->data()->set(flagDecimated(run.t, run.clipped, -band), true);
    const bool limited = std::isfinite(umaxVolts);
    upperLimit_->setVisible(limited);
    lowerLimit_->setVisible(limited);
    if (limited) {
        upperLimit_->point1->setCoords(0, umaxVolts);
        upperLimit_->point2->setCoords(1, umaxVolts);
        lowerLimit_->point1->setCoords(0, -umaxVolts);
        lowerLimit_->point2->setCoords(1, -umaxVolts);
    }
    // The view follows the run unless the user zoomed or panned it (until it is reset).
    for (QCPAxisRect* rect : {positionRect_, errorRect_, controlRect_}) {
        if (viewHeld())
            break;
        rect->axis(QCPAxis::atBottom)->setRange(run.t.front(), run.t.back());
        rect->axis(QCPAxis::atLeft)->rescale(true);
        const QCPRange r = rect->axis(QCPAxis::atLeft)->range();
        const double pad = r.size() > 0 ? 0.08 * r.size() : 1.0;
        rect->axis(QCPAxis::atLeft)->setRange(r.lower - pad, r.upper + pad);
    }
    if (limited && !viewHeld()) {
        // Keep the limit band in view so the margin to saturation is readable.
        QCPAxis* u = controlRect_->axis(QCPAxis::atLeft);
        const double top = std::max(u->range().upper, 1.15 * umaxVolts);
        const double bottom = std::min(u->range().lower, -1.15 * umaxVolts);
        u->setRange(bottom, top);
    }
    replot(QCustomPlot::rpQueuedReplot);
}

void TimeResponsePlot::setDigitalVisible(bool visible) {
    digitalVisible_ = visible;
}

void TimeResponsePlot::showSnapshot(const SimulationResult& run, const QString& name) {
    const bool show = !run.t.empty();
    for (QCPGraph* g : {snapshotOutput_, snapshotError_, snapshotControl_}) {
        g->setVisible(show);
        if (!show)
            g->data()->clear();
    }
    if (show) {
        snapshotOutput_->data()->set(minMaxDecimated(run.t, run.y), true);
        snapshotError_->data()->set(minMaxDecimated(run.t, run.e), true);
        snapshotControl_->data()->set(minMaxDecimated(run.t, run.u), true);
        snapshotOutput_->setName(tr("snapshot «%1» (y, e, u)").arg(name));
        if (!legend_->hasItemWithPlottable(snapshotOutput_))
            legend_->addItem(new QCPPlottableLegendItem(legend_, snapshotOutput_));
    } else if (legend_->hasItemWithPlottable(snapshotOutput_)) {
        legend_->removeItem(legend_->itemWithPlottable(snapshotOutput_));
    }
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
