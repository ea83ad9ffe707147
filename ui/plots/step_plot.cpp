// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/step_plot.h"
#include "ui/plots/number_text.h"

#include "ui/plots/plot_tools.h"

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {
const QColor kOther{0x7f, 0x7f, 0x7f};
const QColor kMarker{0x11, 0x11, 0x11};
const QColor kEnvelope{0xd6, 0x27, 0x28};
const QColor kForbidden{0xd6, 0x27, 0x28, 28};

QString curveName(StepCurveKind kind, bool runs) {
    switch (kind) {
    case StepCurveKind::ClosedLoop:
        return QObject::tr("closed-loop unit step");
    case StepCurveKind::LoopAlone:
        return runs ? QObject::tr("loop alone Kf B/T") : QObject::tr("loop alone (no ZPETC)");
    case StepCurveKind::WithZpetc:
        return runs ? QObject::tr("with ZPETC") : QObject::tr("with ZPETC (off)");
    }
    return {};
}

QCPGraph* makeGraph(QCustomPlot* plot, const QPen& pen, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setPen(pen);
    g->setName(name);
    return g;
}

QCPGraph* makeMarker(QCustomPlot* plot, QCPScatterStyle::ScatterShape shape, const QString& name) {
    QCPGraph* g = makeGraph(plot, QPen(kMarker), name);
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(shape, QPen(kMarker, 1.5), QBrush(Qt::white), 8));
    return g;
}

/// The curve's samples at t - stepAtSeconds.
QVector<QCPGraphData> shifted(const StepResponseCurve& c) {
    QVector<QCPGraphData> out;
    out.reserve(static_cast<qsizetype>(c.t.size()));
    for (std::size_t k = 0; k < c.t.size(); ++k)
        out.append(QCPGraphData(c.t[k] - c.stepAtSeconds, c.y[k]));
    return out;
}
} // namespace

StepEnvelope specificationEnvelope(const Specification& spec) {
    StepEnvelope limits;
    limits.maxOvershootPct = spec.maxOvershootPct;
    limits.overshootSlackPct = Specification::kOvershootRoundOffPct;
    limits.settlingTimeSeconds = spec.maxSettlingTimeSeconds;
    limits.band = 0.02; // the band of stepCharacteristics, which the panel quotes
    return limits;
}

StepPlot::StepPlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Unit step of the closed loop (not the trajectory): output against time (s), "
                  "with the rise, peak and settling (2 % band) markers and the specification's "
                  "overshoot and settling envelope; samples outside it are red."));
    setObjectName("step-response");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, tr("Step response"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("time after the step (s)"));
    yAxis->setLabel(tr("output (unit step)"));
    // Envelope first, so the curves are drawn over it.
    overshootLine_ = makeGraph(this, QPen(kEnvelope, 1.2, Qt::DashLine), tr("overshoot limit"));
    bandUpper_ = makeGraph(this, QPen(kEnvelope, 1.2, Qt::DashLine), tr("settling band"));
    bandLower_ = makeGraph(this, QPen(kEnvelope, 1.2, Qt::DashLine), QString());
    bandLower_->removeFromLegend();
    other_ = makeGraph(this, QPen(kOther, 1.4, Qt::DashLine), QString());
    main_ = makeGraph(this, QPen(colors::output, 1.8), QString());
    violation_ = makeGraph(this, QPen(colors::error, 3.0), tr("violates the spec"));
    rise_ = makeMarker(this, QCPScatterStyle::ssTriangle, tr("rise 10–90 %"));
    peak_ = makeMarker(this, QCPScatterStyle::ssDiamond, tr("peak"));
    settling_ = makeMarker(this, QCPScatterStyle::ssSquare, tr("settling (2 %)"));
    placeLegendBelow(this, 2, 4);
    readout_ = addTextRow(this, 3, readoutHint());
    notice_ = std::make_unique<PlotNotice>(this, axisRect(), Qt::AlignBottom | Qt::AlignRight);
    setupInteractivePlot(this);
    connect(this, &QCustomPlot::mouseMove, this, &StepPlot::onMouseMove);
}

StepPlot::~StepPlot() = default;

QString StepPlot::readoutHint() {
    return tr("hover the plot: t and y of the step the axis runs");
}

QCPGraph* StepPlot::curveGraph(StepCurveKind kind) const {
    if (!hasResult_)
        return nullptr;
    if (kind == mainKind_)
        return main_;
    if (kind == otherKind_ && !other_->data()->isEmpty())
        return other_;
    return nullptr;
}

double StepPlot::overshootBoundDrawn() const {
    return overshootLine_->data()->isEmpty() ? qQNaN() : overshootLine_->data()->begin()->value;
}

double StepPlot::bandStartDrawn() const {
    return bandUpper_->data()->isEmpty() ? qQNaN() : bandUpper_->data()->begin()->key;
}

QStringList StepPlot::markerTexts() const {
    QStringList texts;
    for (QCPAbstractItem* item : items_)
        if (auto* t = qobject_cast<QCPItemText*>(item))
            texts << t->text();
    return texts;
}

void StepPlot::clearView() {
    for (QCPAbstractItem* item : items_)
        removeItem(item);
    items_.clear();
    for (QCPGraph* g : {main_, other_, violation_, rise_, peak_, settling_, overshootLine_,
                        bandUpper_, bandLower_})
        g->data()->clear();
}

QCPItemText* StepPlot::addLabel(double t, double y, const QString& text, const QColor& color,
                                Qt::Alignment align) {
    const QCPRange x = xAxis->range();
    QCPItemText* label =
        addAnnotation(this, axisRect(), t, y, text, color, align, t > x.lower + 0.55 * x.size());
    items_ << label;
    return label;
}

QCPItemRect* StepPlot::addShade(double t0, double y0, bool toTop) {
    // From (t0, y0) to the right edge and the top (or bottom) of the axis rect, whatever the zoom.
    auto* rect = new QCPItemRect(this);
    rect->setClipToAxisRect(true);
    rect->topLeft->setTypeX(QCPItemPosition::ptPlotCoords);
    rect->bottomRight->setTypeX(QCPItemPosition::ptAxisRectRatio);
    rect->topLeft->setTypeY(toTop ? QCPItemPosition::ptAxisRectRatio
                                  : QCPItemPosition::ptPlotCoords);
    rect->bottomRight->setTypeY(toTop ? QCPItemPosition::ptPlotCoords
                                      : QCPItemPosition::ptAxisRectRatio);
    rect->topLeft->setCoords(t0, toTop ? 0.0 : y0);
    rect->bottomRight->setCoords(1.0, toTop ? y0 : 1.0);
    rect->setPen(Qt::NoPen);
    rect->setBrush(kForbidden);
    rect->setLayer(QStringLiteral("background"));
    items_ << rect;
    return rect;
}

void StepPlot::showView(const StepView& view, const QString& title) {
    clearView();
    title_->setText(title);
    if (!view.stable || view.curves.empty()) {
        showNoResult(title, tr("unstable: no step response (the closed loop has a pole outside "
                               "the stability region)"));
        return;
    }
    hasResult_ = true;
    title_->setTextColor(palette().color(QPalette::WindowText));
    legend->setVisible(true);
    readout_->setVisible(true);
    // A discrete loop is known at its samples only: drawn as the held samples it computes.
    const auto style = view.sampleTimeSeconds > 0.0 ? QCPGraph::lsStepLeft : QCPGraph::lsLine;
    for (QCPGraph* g : {main_, other_, violation_})
        g->setLineStyle(style);
    const StepResponseCurve& c = view.curves.front().curve;
    mainKind_ = view.curves.front().kind;
    main_->setName(curveName(mainKind_, true));
    main_->data()->set(shifted(c), true);
    if (view.curves.size() > 1) {
        otherKind_ = view.curves[1].kind;
        other_->setName(curveName(otherKind_, false));
        other_->data()->set(shifted(view.curves[1].curve), true);
        other_->addToLegend();
    } else {
        other_->removeFromLegend();
    }

    // The view: from the first sample (a previewed step moves before it) to the horizon.
    double tMin = 0.0, lo = 0.0, hi = view.step.finalValue;
    for (const StepViewCurve& vc : view.curves) {
        tMin = std::min(tMin, vc.curve.t.front() - vc.curve.stepAtSeconds);
        for (double y : vc.curve.y)
            if (std::isfinite(y)) {
                lo = std::min(lo, y);
                hi = std::max(hi, y);
            }
    }
    const double tMax = view.horizonSeconds;
    const StepEnvelope& env = view.envelope;
    const double bound = env.overshootBound();
    // A bound within reach of the data is kept in view; one far above it is stated instead.
    const bool boundInView = std::isfinite(bound) && bound <= hi + 0.5 * (hi - lo);
    if (boundInView)
        hi = std::max(hi, bound);
    const double pad = 0.08 * std::max(hi - lo, 1e-9);
    if (!viewHeld()) { // the view follows the responses unless the user zoomed or panned it
        xAxis->setRange(tMin, tMax);
        yAxis->setRange(lo - pad, hi + pad);
    }

    QStringList notes;
    // The envelope: the overshoot bound everywhere, the band from the settling limit on, the
    // forbidden side shaded.
    if (std::isfinite(bound)) {
        overshootLine_->setName(tr("overshoot ≤ %1 %").arg(significant(env.maxOvershootPct, 3)));
        overshootLine_->data()->set({QCPGraphData(tMin, bound), QCPGraphData(tMax, bound)}, true);
        addShade(tMin, bound, true);
        if (!boundInView)
            notes << tr("overshoot limit %1 (%2 %) is above the view")
                         .arg(significant(bound, 4), significant(env.maxOvershootPct, 3));
    }
    const double ts = env.settlingTimeSeconds;
    if (std::isfinite(ts)) {
        const double half = env.band * std::abs(env.finalValue);
        bandUpper_->setName(
            tr("±%1 % after %2 s").arg(significant(100.0 * env.band, 3)).arg(significant(ts, 3)));
        if (ts < tMax) {
            bandUpper_->data()->set({QCPGraphData(ts, env.finalValue + half),
                                     QCPGraphData(tMax, env.finalValue + half)},
                                    true);
            bandLower_->data()->set({QCPGraphData(ts, env.finalValue - half),
                                     QCPGraphData(tMax, env.finalValue - half)},
                                    true);
            addShade(ts, env.finalValue + half, true);
            addShade(ts, env.finalValue - half, false);
        } else {
            notes << tr("settling limit %1 s lies beyond the right edge (%2 s)")
                         .arg(significant(ts, 3), significant(tMax, 3));
        }
    }
    // Where the response leaves the envelope: its samples in red, gaps elsewhere.
    QVector<QCPGraphData> bad;
    bool anyBad = false;
    for (std::size_t k = 0; k < c.t.size() && k < view.violations.size(); ++k) {
        anyBad = anyBad || view.violations[k];
        bad.append(QCPGraphData(c.t[k] - c.stepAtSeconds, view.violations[k] ? c.y[k] : qQNaN()));
    }
    violation_->data()->set(bad, true);
    if (anyBad)
        violation_->addToLegend();
    else
        violation_->removeFromLegend();

    // Markers: the core's figures (the metrics panel's), the rise time from the drawn curve.
    const StepCharacteristics& st = view.step;
    const double fin = st.finalValue;
    if (view.rise.reached) {
        const double t10 = view.rise.lowCrossingSeconds - c.stepAtSeconds;
        const double t90 = view.rise.highCrossingSeconds - c.stepAtSeconds;
        rise_->data()->set({QCPGraphData(t10, 0.1 * fin), QCPGraphData(t90, 0.9 * fin)}, true);
        // The label right of where the curve first reaches half its final value: below a
        // rising curve, clear of the settling label above the band.
        double tHalf = t90;
        for (std::size_t k = 0; k < c.y.size(); ++k)
            if (std::abs(c.y[k]) >= 0.5 * std::abs(fin)) {
                tHalf = c.t[k] - c.stepAtSeconds;
                if (k > 0 && view.sampleTimeSeconds <= 0.0 &&
                    c.y[k] != c.y[k - 1]) // between samples
                    tHalf -= (c.t[k] - c.t[k - 1]) * (c.y[k] - 0.5 * fin) / (c.y[k] - c.y[k - 1]);
                break;
            }
        addLabel(tHalf, 0.5 * fin, tr("  rise %1 s").arg(significant(view.rise.seconds, 3)),
                 kMarker, Qt::AlignLeft | Qt::AlignVCenter);
    } else {
        notes << tr("the response never reaches 90 % of its final value in view");
    }
    // An overshoot within the specification's round-off slack (a ZPETC step's 1e-14 %) is no
    // peak worth a marker.
    if (st.overshootPct > env.overshootSlackPct) {
        const double peakValue = fin * (1.0 + st.overshootPct / 100.0);
        const QString text = tr("peak %1 at %2 s (%3 %)")
                                 .arg(significant(peakValue, 4), significant(st.peakTimeSeconds, 3),
                                      significant(st.overshootPct, 3));
        if (st.peakTimeSeconds <= tMax) {
            peak_->data()->set({QCPGraphData(st.peakTimeSeconds, peakValue)}, true);
            addLabel(st.peakTimeSeconds, peakValue, text, kMarker, Qt::AlignLeft | Qt::AlignBottom);
        } else {
            notes << text + tr(": beyond the right edge");
        }
    }
    if (std::isfinite(st.settlingTimeSeconds) && st.settlingTimeSeconds > 0.0) {
        // The band edge the response last left: the side its last sample before the settling
        // time lies on.
        double side = 1.0;
        for (std::size_t k = 0; k < c.t.size() && c.t[k] - c.stepAtSeconds < st.settlingTimeSeconds;
             ++k)
            side = c.y[k] >= fin ? 1.0 : -1.0;
        const double y = fin + side * 0.02 * std::abs(fin);
        settling_->data()->set({QCPGraphData(st.settlingTimeSeconds, y)}, true);
        addLabel(st.settlingTimeSeconds, y,
                 tr("settles %1 s").arg(significant(st.settlingTimeSeconds, 3)), kMarker,
                 Qt::AlignLeft | (side > 0 ? Qt::AlignBottom : Qt::AlignTop));
    }
    if (anyBad)
        notes << tr("red: the response leaves the specification's envelope");
    notice_->setSevere(false);
    notice_->setLines(notes);
    replot(QCustomPlot::rpQueuedReplot);
}

void StepPlot::showNoResult(const QString& title, const QString& reason) {
    clearView();
    hasResult_ = false;
    title_->setText(title);
    title_->setTextColor(colors::error);
    legend->setVisible(false);
    readout_->setVisible(false);
    notice_->setSevere(true);
    notice_->setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

void StepPlot::leaveEvent(QEvent* event) {
    QCustomPlot::leaveEvent(event);
    setReadoutText(this, readout_, readoutHint());
}

void StepPlot::onMouseMove(QMouseEvent* event) {
    if (event->buttons() != Qt::NoButton || main_->data()->isEmpty())
        return;
    QString text = readoutHint();
    if (axisRect()->rect().contains(event->pos())) {
        const double t = xAxis->pixelToCoord(event->position().x());
        auto it = main_->data()->findBegin(t, false);
        if (it != main_->data()->constEnd() && it != main_->data()->constBegin() && it->key >= t) {
            const auto before = it - 1;
            const double s =
                it->key > before->key ? (t - before->key) / (it->key - before->key) : 0.0;
            const double y = before->value + s * (it->value - before->value);
            text = tr("t = %1 s   y = %2   (%3)")
                       .arg(significant(t, 4), significant(y, 5), main_->name());
        }
    }
    setReadoutText(this, readout_, text);
}

} // namespace xyt::ui
