// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/bode_plot.h"
#include "ui/plots/number_text.h"

#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace xyt::ui {

namespace {
const QColor kLoop{0x1f, 0x77, 0xb4};
const QColor kSensitivity{0xff, 0x7f, 0x0e};
const QColor kComplementary{0x2c, 0xa0, 0x2c};
const QColor kWithout{0x7f, 0x7f, 0x7f};
const QColor kWith{0x94, 0x67, 0xbd};
const QColor kMargin{0xc6, 0x28, 0x28}; ///< a margin that fails its minimum (or is negative)
const QColor kMet{0x1b, 0x7f, 0x2a};    ///< one that meets it: the metrics panel's check colours

/// " ✓ ≥ 30°" / " ✗ < 30°" after a margin label when the specification states a minimum.
QString requirementText(bool met, double minimum, const QString& unit) {
    if (!(minimum > 0.0))
        return met ? QString() : QStringLiteral(" ✗");
    return (met ? QStringLiteral(" ✓ ≥ ") : QStringLiteral(" ✗ < ")) + significant(minimum, 3) +
           unit;
}

/// Graph data of one response (non-finite values are left out: a pole on the axis).
void setResponse(QCPGraph* graph, const std::vector<double>& omega,
                 const std::vector<double>& values) {
    QVector<QCPGraphData> data;
    data.reserve(static_cast<qsizetype>(omega.size()));
    for (std::size_t i = 0; i < omega.size() && i < values.size(); ++i)
        if (omega[i] > 0.0 && std::isfinite(values[i]))
            data.append(QCPGraphData(omega[i], values[i]));
    graph->data()->set(data, true);
}

/// The phase curve's value at @p omega (linear in log omega between grid points).
double interpolate(const std::vector<double>& omega, const std::vector<double>& values, double at) {
    const auto it = std::lower_bound(omega.begin(), omega.end(), at);
    if (it == omega.begin())
        return values.front();
    if (it == omega.end())
        return values.back();
    const std::size_t i = static_cast<std::size_t>(it - omega.begin());
    const double t = std::log(at / omega[i - 1]) / std::log(omega[i] / omega[i - 1]);
    return values[i - 1] + t * (values[i] - values[i - 1]);
}
} // namespace

BodePlot::BodePlot(QWidget* parent) : PlotWidget(parent) {
    setToolTip(tr("Bode diagram of the loop L(jω) = C(jω) G(jω): magnitude (dB) and phase (°) "
                  "against ω (rad/s) on an adaptive grid, with the gain and phase margins drawn "
                  "where they are read (green when they meet the specification's minima, red when "
                  "not), and |S| = |1/(1 + L)| and |T| = |L/(1 + L)|."));
    setObjectName("bode");
    setAutoAddPlottableToLegend(
        false); // the legend lists each curve once (magnitude and phase share it)
    plotLayout()->clear();
    title_ = new QCPTextElement(this, tr("Bode diagram"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    magRect_ = new QCPAxisRect(this);
    phaseRect_ = new QCPAxisRect(this);
    plotLayout()->addElement(1, 0, magRect_);
    plotLayout()->addElement(2, 0, phaseRect_);
    auto* margins = new QCPMarginGroup(this);
    QSharedPointer<QCPAxisTickerLog> logTicker(new QCPAxisTickerLog);
    for (QCPAxisRect* rect : {magRect_, phaseRect_}) {
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        styleAxisRect(rect);
        QCPAxis* x = rect->axis(QCPAxis::atBottom);
        x->setScaleType(QCPAxis::stLogarithmic);
        x->setTicker(logTicker);
        x->setNumberFormat("gb");
        x->setNumberPrecision(0);
        x->setRange(0.01, 100.0);
        rect->setRangeDrag(Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(Qt::Horizontal | Qt::Vertical);
        // One frequency axis: panning or zooming one panel moves both.
        connect(x, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                [this, rect](const QCPRange& r) {
                    QCPAxisRect* other = rect == magRect_ ? phaseRect_ : magRect_;
                    if (other->axis(QCPAxis::atBottom)->range() != r)
                        other->axis(QCPAxis::atBottom)->setRange(r);
                });
    }
    magRect_->axis(QCPAxis::atLeft)->setLabel(tr("magnitude (dB)"));
    phaseRect_->axis(QCPAxis::atLeft)->setLabel(tr("phase (°)"));
    phaseRect_->axis(QCPAxis::atBottom)->setLabel(tr("frequency ω (rad/s)"));
    QSharedPointer<QCPAxisTickerFixed> degrees(new QCPAxisTickerFixed);
    degrees->setTickStep(45.0);
    degrees->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
    phaseRect_->axis(QCPAxis::atLeft)->setTicker(degrees);

    legend_ = new QCPLegend;
    plotLayout()->addElement(3, 0, legend_);
    plotLayout()->setRowStretchFactor(3, 0.001);
    legend_->setLayer("legend");
    legend_->setFont(QFont(font().family(), 8));
    legend_->setBorderPen(Qt::NoPen);
    legend_->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend_->setWrap(4);
    legend_->setSelectableParts(QCPLegend::spItems);
    readout_ = addTextRow(this, 4, readoutHint());
    plotLayout()->setRowStretchFactor(1, 1.2);
    notice_ = std::make_unique<PlotNotice>(this, magRect_, Qt::AlignTop | Qt::AlignRight);

    setupInteractivePlot(this);
    setInteraction(QCP::iSelectLegend, true);
    connect(this, &QCustomPlot::legendClick, this,
            [this](QCPLegend*, QCPAbstractLegendItem* item, QMouseEvent*) {
                auto* pi = qobject_cast<QCPPlottableLegendItem*>(item);
                if (!pi)
                    return;
                for (const Curve& c : std::as_const(curves_))
                    if (c.magnitude == pi->plottable()) {
                        const bool visible = !c.magnitude->visible();
                        c.magnitude->setVisible(visible);
                        if (c.phase)
                            c.phase->setVisible(visible);
                        item->setTextColor(visible ? Qt::black : QColor(0xaa, 0xaa, 0xaa));
                    }
                item->setSelected(false);
                replot(QCustomPlot::rpQueuedReplot);
            });
    connect(this, &QCustomPlot::mouseMove, this, &BodePlot::onMouseMove);
}

BodePlot::~BodePlot() = default;

void BodePlot::showMeasuredLoop(const MeasuredOpenLoop* loop, const QString& source) {
    const QColor measured{0xd6, 0x27, 0x28};
    if (!measuredMagnitude_) {
        measuredMagnitude_ =
            addGraph(magRect_->axis(QCPAxis::atBottom), magRect_->axis(QCPAxis::atLeft));
        measuredPhase_ =
            addGraph(phaseRect_->axis(QCPAxis::atBottom), phaseRect_->axis(QCPAxis::atLeft));
        for (QCPGraph* g : {measuredMagnitude_, measuredPhase_}) {
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, measured, 3.5));
            g->setPen(QPen(measured));
        }
        measuredMagnitude_->setName(tr("measured L = C H"));
    }
    const bool shown = loop && !loop->omegaRadPerSec.empty();
    if (shown) {
        setResponse(measuredMagnitude_, loop->omegaRadPerSec, loop->magnitudeDb);
        setResponse(measuredPhase_, loop->omegaRadPerSec, loop->phaseDeg);
        measuredMagnitude_->setName(tr("measured L = C H (%1)").arg(source));
        if (!legend_->hasItemWithPlottable(measuredMagnitude_))
            legend_->addItem(new QCPPlottableLegendItem(legend_, measuredMagnitude_));
    } else {
        measuredMagnitude_->data()->clear();
        measuredPhase_->data()->clear();
        if (legend_->hasItemWithPlottable(measuredMagnitude_))
            legend_->removeItem(legend_->itemWithPlottable(measuredMagnitude_));
    }
    measuredMagnitude_->setVisible(shown);
    measuredPhase_->setVisible(shown);
    replot(QCustomPlot::rpQueuedReplot);
}

QString BodePlot::readoutHint() {
    return tr("hover the plot: ω, |L| and ∠L of the open loop");
}

BodePlot::Curve& BodePlot::curve(const QString& name, const QColor& color, Qt::PenStyle style,
                                 bool withPhase) {
    auto it = curves_.find(name);
    if (it != curves_.end())
        return *it;
    Curve c;
    const QPen pen(color, style == Qt::SolidLine ? 1.8 : 1.3, style);
    c.magnitude = new QCPGraph(magRect_->axis(QCPAxis::atBottom), magRect_->axis(QCPAxis::atLeft));
    c.magnitude->setPen(pen);
    c.magnitude->setName(name);
    legend_->addItem(new QCPPlottableLegendItem(legend_, c.magnitude));
    if (withPhase) {
        c.phase =
            new QCPGraph(phaseRect_->axis(QCPAxis::atBottom), phaseRect_->axis(QCPAxis::atLeft));
        c.phase->setPen(pen);
        c.phase->setName(name);
    }
    return *curves_.insert(name, c);
}

QCPGraph* BodePlot::magnitudeGraph(const QString& name) const {
    return curves_.contains(name) ? curves_[name].magnitude : nullptr;
}

QCPGraph* BodePlot::phaseGraph(const QString& name) const {
    return curves_.contains(name) ? curves_[name].phase : nullptr;
}

QStringList BodePlot::markerTexts() const {
    QStringList texts;
    for (QCPAbstractItem* item : markers_)
        if (auto* t = qobject_cast<QCPItemText*>(item))
            texts << t->text();
    return texts;
}

void BodePlot::clearMarkers() {
    for (QCPAbstractItem* item : markers_)
        removeItem(item);
    markers_.clear();
}

void BodePlot::addVerticalMarker(QCPAxisRect* rect, double omega, double from, double to,
                                 const QPen& pen) {
    auto* line = new QCPItemLine(this);
    line->setClipAxisRect(rect);
    for (QCPItemPosition* p : {line->start, line->end})
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->start->setCoords(omega, from);
    line->end->setCoords(omega, to);
    line->setPen(pen);
    markers_ << line;
}

void BodePlot::addLabel(QCPAxisRect* rect, double omega, double value, const QString& text,
                        const QColor& color, Qt::Alignment align) {
    // Left of the line in the right half (on the logarithmic axis), where the text has room.
    const QCPRange x = rect->axis(QCPAxis::atBottom)->range();
    const bool rightHalf = std::log(omega / x.lower) > 0.5 * std::log(x.upper / x.lower);
    markers_ << addAnnotation(this, rect, omega, value, text, color, align, rightHalf);
}

void BodePlot::showAnalysis(const AxisFrequencyAnalysis& a, bool zpetcEnabled, const QString& title,
                            const BodeMarginRequirements& req) {
    hasResult_ = true;
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    legend_->setVisible(true);
    readout_->setVisible(true);
    openLoop_ = a.responses.openLoop;
    const std::vector<double>& w = a.responses.openLoop.omegaRadPerSec;
    Curve& l = curve(tr("open loop L"), kLoop, Qt::SolidLine, true);
    setResponse(l.magnitude, w, a.responses.openLoop.magnitudeDb);
    setResponse(l.phase, w, a.responses.openLoop.phaseDeg);
    setResponse(curve(tr("|S| sensitivity"), kSensitivity, Qt::DashLine, false).magnitude, w,
                a.responses.sensitivity.magnitudeDb);
    setResponse(curve(tr("|T| closed loop"), kComplementary, Qt::DashLine, false).magnitude, w,
                a.responses.complementarySensitivity.magnitudeDb);
    // A method with a feedforward (ZPETC, a PID's command feedforward): the tracking r -> y
    // without and with it.
    const QString without = tr("tracking, loop alone");
    const QString with = tr("tracking with %1").arg(coreText("xyt::CoreText", a.feedforwardName));
    for (const QString& name : curves_.keys())
        if ((name == without || name.startsWith(tr("tracking with "))) &&
            !(a.tracking && (name == without || (zpetcEnabled && name == with)))) {
            legend_->removeItem(legend_->itemWithPlottable(curves_[name].magnitude));
            removePlottable(curves_[name].magnitude);
            removePlottable(curves_[name].phase);
            curves_.remove(name);
        }
    if (a.tracking) {
        Curve& t0 = curve(without, kWithout, Qt::DashDotLine, true);
        setResponse(t0.magnitude, w, a.tracking->withoutFeedforward.magnitudeDb);
        setResponse(t0.phase, w, a.tracking->withoutFeedforward.phaseDeg);
        if (zpetcEnabled) {
            Curve& t1 = curve(with, kWith, Qt::SolidLine, true);
            setResponse(t1.magnitude, w, a.tracking->withZpetc.magnitudeDb);
            setResponse(t1.phase, w, a.tracking->withZpetc.phaseDeg);
        }
    }

    // A notch in the loop: L without it, dashed, named with the margins it had.
    const QString withoutNotch = tr("L without the notch");
    if (a.openLoopWithoutNotch) {
        Curve& n = curve(withoutNotch, kLoop, Qt::DashLine, true);
        setResponse(n.magnitude, w, a.openLoopWithoutNotch->magnitudeDb);
        setResponse(n.phase, w, a.openLoopWithoutNotch->phaseDeg);
        QString name = withoutNotch;
        if (a.marginsWithoutNotch && std::isfinite(a.marginsWithoutNotch->phaseMarginDeg))
            name += tr(" (PM %1°)").arg(significant(a.marginsWithoutNotch->phaseMarginDeg, 3));
        n.magnitude->setName(name);
    } else if (curves_.contains(withoutNotch)) {
        legend_->removeItem(legend_->itemWithPlottable(curves_[withoutNotch].magnitude));
        removePlottable(curves_[withoutNotch].magnitude);
        removePlottable(curves_[withoutNotch].phase);
        curves_.remove(withoutNotch);
    }

    // The view: the grid's frequencies, and magnitudes clipped to a readable band (an
    // integrator's +200 dB at low frequency would flatten everything else). The view follows
    // the curves as the design changes, unless the user zoomed or panned it (kept until it
    // is reset, or the plane or axis changes).
    if (!w.empty()) {
        const QCPRange span(w.front(), w.back());
        if (openLoop_.tsSeconds != lastTs_ || title != lastTitle_)
            releaseView();
        if (!viewHeld()) {
            lastTs_ = openLoop_.tsSeconds;
            lastTitle_ = title;
            magRect_->axis(QCPAxis::atBottom)->setRange(span);
            double lo = 1e300, hi = -1e300, plo = 1e300, phi = -1e300;
            for (const Curve& c : std::as_const(curves_)) {
                for (auto it = c.magnitude->data()->constBegin();
                     it != c.magnitude->data()->constEnd(); ++it) {
                    lo = std::min(lo, it->value);
                    hi = std::max(hi, it->value);
                }
                if (c.phase)
                    for (auto it = c.phase->data()->constBegin(); it != c.phase->data()->constEnd();
                         ++it) {
                        plo = std::min(plo, it->value);
                        phi = std::max(phi, it->value);
                    }
            }
            lo = std::max(lo, -120.0);
            hi = std::min(hi, 120.0);
            const double pad = 0.06 * std::max(hi - lo, 10.0);
            magRect_->axis(QCPAxis::atLeft)->setRange(lo - pad, hi + pad);
            const double ppad = 0.06 * std::max(phi - plo, 45.0);
            phaseRect_->axis(QCPAxis::atLeft)->setRange(plo - ppad, phi + ppad);
        }
    }
    // The margins where they are read: the gain margin as the gap from |L| to 0 dB at the phase
    // crossover, the phase margin as the gap from the phase to -180 (+ 360 k) at the gain
    // crossover; 0 dB and the -180 line as references.
    clearMarkers();
    const StabilityMargins& m = a.margins;
    const QPen guide(QColor(0x90, 0x90, 0x90), 1, Qt::DashLine);
    auto* zeroDb = new QCPItemStraightLine(this);
    zeroDb->setClipAxisRect(magRect_);
    for (QCPItemPosition* p : {zeroDb->point1, zeroDb->point2})
        p->setAxes(magRect_->axis(QCPAxis::atBottom), magRect_->axis(QCPAxis::atLeft));
    zeroDb->point1->setCoords(1.0, 0.0);
    zeroDb->point2->setCoords(10.0, 0.0);
    zeroDb->setPen(guide);
    markers_ << zeroDb;
    if (std::isfinite(m.gainMarginOmegaRadPerSec) && std::isfinite(m.gainMarginDb)) {
        const double wpc = m.gainMarginOmegaRadPerSec;
        const QColor color = req.gainMarginMet ? kMet : kMargin;
        addVerticalMarker(magRect_, wpc, -m.gainMarginDb, 0.0,
                          QPen(color, req.gainMarginMet ? 1.6 : 2.4));
        addLabel(magRect_, wpc, -0.5 * m.gainMarginDb,
                 tr("GM %1 dB at %2 rad/s")
                         .arg(significant(m.gainMarginDb, 3))
                         .arg(significant(wpc, 3)) +
                     requirementText(req.gainMarginMet, req.minGainMarginDb, tr(" dB")),
                 color, Qt::AlignLeft | Qt::AlignVCenter);
    }
    if (std::isfinite(m.phaseMarginOmegaRadPerSec) && std::isfinite(m.phaseMarginDeg)) {
        const double wgc = m.phaseMarginOmegaRadPerSec;
        const double phase = interpolate(w, a.responses.openLoop.phaseDeg, wgc);
        const double minus180 = phase - m.phaseMarginDeg; // -180 + 360 k on the unwrapped curve
        const QColor color = req.phaseMarginMet ? kMet : kMargin;
        addVerticalMarker(phaseRect_, wgc, minus180, phase,
                          QPen(color, req.phaseMarginMet ? 1.6 : 2.4));
        addLabel(
            phaseRect_, wgc, 0.5 * (phase + minus180),
            tr("PM %1° at %2 rad/s")
                    .arg(significant(m.phaseMarginDeg, 3))
                    .arg(significant(wgc, 3)) +
                requirementText(req.phaseMarginMet, req.minPhaseMarginDeg, QStringLiteral("°")),
            color, Qt::AlignLeft | Qt::AlignVCenter);
        auto* line = new QCPItemStraightLine(this);
        line->setClipAxisRect(phaseRect_);
        for (QCPItemPosition* p : {line->point1, line->point2})
            p->setAxes(phaseRect_->axis(QCPAxis::atBottom), phaseRect_->axis(QCPAxis::atLeft));
        line->point1->setCoords(1.0, minus180);
        line->point2->setCoords(10.0, minus180);
        line->setPen(guide);
        markers_ << line;
    }
    const auto frequencyLine = [this](double omega, const QString& text, const QColor& color) {
        for (QCPAxisRect* rect : {magRect_, phaseRect_}) {
            auto* line = new QCPItemStraightLine(this);
            line->setClipAxisRect(rect);
            for (QCPItemPosition* p : {line->point1, line->point2})
                p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            line->point1->setCoords(omega, 0.0);
            line->point2->setCoords(omega, 1.0);
            line->setPen(QPen(color, 1, Qt::DotLine));
            markers_ << line;
        }
        auto* label = new QCPItemText(this);
        label->setClipAxisRect(magRect_);
        label->position->setAxes(magRect_->axis(QCPAxis::atBottom), nullptr);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->position->setAxisRect(magRect_);
        label->position->setCoords(omega, 0.02);
        // Level, right of its line: a rotated label was taller than the magnitude plot at
        // 1366x768 (the guard moves a level one left of the line near the right edge).
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        label->setPadding(QMargins(3, 0, 2, 0));
        label->setText(text);
        label->setColor(color);
        label->setFont(QFont(font().family(), 7));
        markers_ << label;
    };
    if (std::isfinite(a.referenceOmegaRadPerSec) && a.referenceOmegaRadPerSec > 0.0)
        frequencyLine(a.referenceOmegaRadPerSec,
                      tr("reference ω = %1").arg(significant(a.referenceOmegaRadPerSec, 3)),
                      QColor(0x55, 0x55, 0x55));
    if (openLoop_.tsSeconds > 0.0)
        frequencyLine(std::numbers::pi / openLoop_.tsSeconds, tr("Nyquist π/Ts"),
                      QColor(0x55, 0x55, 0x55));

    QStringList notes;
    if (!m.closedLoopStable)
        notes << tr("the closed loop is unstable: the margins are not robustness measures");
    for (const auto& warning : m.warnings)
        notes << diagnosticText(warning);
    notice_->setSevere(!m.closedLoopStable);
    notice_->setLines(notes);

    replot(QCustomPlot::rpQueuedReplot);
}

void BodePlot::showNoResult(const QString& title, const QString& reason) {
    hasResult_ = false;
    if (measuredMagnitude_)
        showMeasuredLoop(nullptr, QString());
    title_->setText(title);
    title_->setTextColor(colors::error);
    for (const Curve& c : std::as_const(curves_)) {
        c.magnitude->data()->clear();
        if (c.phase)
            c.phase->data()->clear();
    }
    clearMarkers();
    openLoop_ = FrequencyResponse{};
    legend_->setVisible(false);
    readout_->setVisible(false);
    notice_->setSevere(true);
    notice_->setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

void BodePlot::leaveEvent(QEvent* event) {
    QCustomPlot::leaveEvent(event);
    setReadoutText(this, readout_, readoutHint());
}

void BodePlot::onMouseMove(QMouseEvent* event) {
    if (event->buttons() != Qt::NoButton || openLoop_.omegaRadPerSec.empty())
        return;
    QCPAxisRect* rect = magRect_->rect().contains(event->pos())     ? magRect_
                        : phaseRect_->rect().contains(event->pos()) ? phaseRect_
                                                                    : nullptr;
    QString text = readoutHint();
    if (rect) {
        const double omega = rect->axis(QCPAxis::atBottom)->pixelToCoord(event->position().x());
        const std::vector<double>& w = openLoop_.omegaRadPerSec;
        if (omega >= w.front() && omega <= w.back())
            text = tr("ω = %1 rad/s   |L| = %2 dB   ∠L = %3°")
                       .arg(significant(omega, 4))
                       .arg(significant(interpolate(w, openLoop_.magnitudeDb, omega), 4))
                       .arg(significant(interpolate(w, openLoop_.phaseDeg, omega), 4));
    }
    setReadoutText(this, readout_, text);
}

} // namespace xyt::ui
