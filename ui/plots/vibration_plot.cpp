// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/vibration_plot.h"

#include "core/design/input_shaper.h"
#include "core/identification/accelerometer_log.h"
#include "core/identification/spectral_estimate.h"
#include "ui/plots/number_text.h"
#include "ui/plots/plot_tools.h"

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {
const QColor kRigid{0x7f, 0x7f, 0x7f};
const QColor kPlant{0x1f, 0x77, 0xb4};
const QColor kNotch{0x2c, 0xa0, 0x2c};
const QColor kShaper{0x94, 0x67, 0xbd};
const QColor kMode{0xc6, 0x28, 0x28};
const QColor kMeasured{0xd6, 0x27, 0x28};
const QColor kAcceleration{0x8c, 0x56, 0x4b};

/// 20 log10 of @p values (> 0) at @p x, where @p keep (when given) is at least @p threshold.
QVector<QCPGraphData> decibels(const std::vector<double>& x, const std::vector<double>& values,
                               double reference, const std::vector<double>* keep = nullptr,
                               double threshold = 0.0) {
    QVector<QCPGraphData> data;
    for (std::size_t i = 0; i < x.size() && i < values.size(); ++i)
        if (x[i] > 0.0 && values[i] > 0.0 && (!keep || (*keep)[i] >= threshold))
            data.append(QCPGraphData(x[i], 20.0 * std::log10(values[i] / reference)));
    return data;
}

QVector<QCPGraphData> curveData(const std::vector<double>& x, const std::vector<double>& y,
                                double scale = 1.0) {
    QVector<QCPGraphData> data;
    data.reserve(static_cast<qsizetype>(x.size()));
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
        if (std::isfinite(y[i]))
            data.append(QCPGraphData(x[i], scale * y[i]));
    return data;
}
} // namespace

VibrationPlot::VibrationPlot(QWidget* parent) : PlotWidget(parent) {
    description_ =
        tr("Vibration: the rigid plant, the plant with its flexible mode and the notch (mm/V "
           "against Hz), the input shaper's sensitivity curve with the 5 % tolerance, and the "
           "residual vibration of the run's move shaped and unshaped.");
    setToolTip(description_);
    setObjectName("vibration");
    setAutoAddPlottableToLegend(false);
    plotLayout()->clear();
    title_ = new QCPTextElement(this, tr("Vibration"), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    responseRect_ = new QCPAxisRect(this);
    shaperRect_ = new QCPAxisRect(this);
    plotLayout()->addElement(1, 0, responseRect_);
    plotLayout()->addElement(2, 0, shaperRect_);
    auto* margins = new QCPMarginGroup(this);
    for (QCPAxisRect* rect : {responseRect_, shaperRect_}) {
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        styleAxisRect(rect);
        rect->setRangeDrag(Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(Qt::Horizontal | Qt::Vertical);
    }
    QCPAxis* fx = responseRect_->axis(QCPAxis::atBottom);
    fx->setScaleType(QCPAxis::stLogarithmic);
    fx->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    fx->setNumberFormat("gb");
    fx->setNumberPrecision(0);
    fx->setLabel(tr("frequency (Hz)"));
    responseRect_->axis(QCPAxis::atLeft)->setLabel(tr("|G| (dB re mm/V)"));
    shaperRect_->axis(QCPAxis::atBottom)->setLabel(tr("frequency of the mode (Hz)"));
    shaperRect_->axis(QCPAxis::atLeft)->setLabel(tr("residual (%)"));
    const auto graph = [this](QCPAxisRect* rect, const QString& name, const QColor& color,
                              Qt::PenStyle style) {
        QCPGraph* g = addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        g->setName(name);
        g->setPen(QPen(color, style == Qt::SolidLine ? 1.8 : 1.3, style));
        return g;
    };
    rigid_ = graph(responseRect_, tr("rigid |G|"), kRigid, Qt::DashLine);
    plant_ = graph(responseRect_, tr("with the mode"), kPlant, Qt::SolidLine);
    notch_ = graph(responseRect_, tr("notch |N|"), kNotch, Qt::SolidLine);
    measured_ = graph(responseRect_, tr("measured |H|"), kMeasured, Qt::NoPen);
    measured_->setLineStyle(QCPGraph::lsNone);
    measured_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, kMeasured, 3.5));
    QCPAxis* psdAxis = responseRect_->axis(QCPAxis::atRight);
    psdAxis->setVisible(false);
    psdAxis->setLabel(tr("PSD (dB)"));
    acceleration_ = addGraph(responseRect_->axis(QCPAxis::atBottom), psdAxis);
    acceleration_->setPen(QPen(kAcceleration, 1.2));
    acceleration_->setName(tr("accel. PSD"));
    sensitivity_ = graph(shaperRect_, tr("input shaper"), kShaper, Qt::SolidLine);
    tolerance_ = graph(shaperRect_, tr("5 % tolerance"), kRigid, Qt::DotLine);
    legend_ = new QCPLegend;
    plotLayout()->addElement(3, 0, legend_);
    plotLayout()->setRowStretchFactor(3, 0.001);
    legend_->setLayer("legend");
    legend_->setFont(QFont(font().family(), 8));
    legend_->setBorderPen(Qt::NoPen);
    legend_->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend_->setWrap(3);
    compactLegend(legend_);
    summary_ = addTextRow(this, 4, QString());
    plotLayout()->setRowStretchFactor(1, 1.2);
    notice_ = std::make_unique<PlotNotice>(this, responseRect_, Qt::AlignTop | Qt::AlignRight);
    shaperNotice_ = std::make_unique<PlotNotice>(this, shaperRect_, Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(this);
}

VibrationPlot::~VibrationPlot() = default;

QString VibrationPlot::summaryText() const {
    return summary_->text();
}

QStringList VibrationPlot::markerTexts() const {
    QStringList out;
    for (QCPAbstractItem* item : markers_)
        if (auto* text = qobject_cast<QCPItemText*>(item))
            out << text->text();
    return out;
}

void VibrationPlot::placeLegend(bool shown) {
    // An empty legend, even hidden, caps the layout's column at its own (nil) width: it leaves
    // the layout while it has nothing to list.
    const bool placed = plotLayout()->hasElement(3, 0) && plotLayout()->element(3, 0) == legend_;
    if (shown && !placed)
        plotLayout()->addElement(3, 0, legend_);
    else if (!shown && placed)
        plotLayout()->take(legend_);
    legend_->setVisible(shown);
}

void VibrationPlot::clearMarkers() {
    for (QCPAbstractItem* item : std::as_const(markers_))
        removeItem(item);
    markers_.clear();
}

void VibrationPlot::showNoResult(const QString& title, const QString& reason) {
    title_->setText(title);
    clearMarkers();
    summary_->setText(QString());
    hasResult_ = false;
    legend_->clearItems();
    placeLegend(false);
    responseRect_->axis(QCPAxis::atRight)->setVisible(false);
    shaperNotice_->setLines({});
    clearWithNotice(this, *notice_,
                    {rigid_, plant_, notch_, sensitivity_, tolerance_, measured_, acceleration_},
                    reason);
}

void VibrationPlot::showVibration(const AxisVibration& v, const QString& title,
                                  const QString& summary, const VibrationMeasurements& measured) {
    title_->setText(title);
    clearMarkers();
    notice_->setSevere(false);
    hasResult_ = true;
    rigid_->data()->set(curveData(v.frequencyHz, v.rigidDb), true);
    plant_->data()->set(curveData(v.frequencyHz, v.plantDb), true);
    plant_->setVisible(v.modeHz > 0.0);
    notch_->data()->set(curveData(v.frequencyHz, v.notchDb), true);
    notch_->setVisible(!v.notchDb.empty());
    QCPAxis* fx = responseRect_->axis(QCPAxis::atBottom);
    QCPAxis* fy = responseRect_->axis(QCPAxis::atLeft);
    if (!v.frequencyHz.empty())
        fx->setRange(v.frequencyHz.front(), v.frequencyHz.back());
    // The measurements: |H| in mm/V on the model's scale, the PSD on its own (right) axis;
    // where they come from in the plot's tooltip.
    QStringList sources;
    if (measured.response) {
        const FrequencyResponseEstimate& h = *measured.response;
        measured_->data()->set(
            decibels(h.frequencyHz, h.magnitude, 1.0, &h.coherence, kMinCoherence), true);
        measured_->setName(tr("measured |H|"));
        sources << tr("|H| measured from %1, drawn where γ² ≥ %2")
                       .arg(measured.responseSource)
                       .arg(kMinCoherence);
    } else {
        measured_->data()->clear();
    }
    measured_->setVisible(measured.response != nullptr);
    QCPAxis* psdAxis = responseRect_->axis(QCPAxis::atRight);
    if (measured.acceleration) {
        const AccelerometerSpectra& a = *measured.acceleration;
        double peak = 0.0;
        for (double p : a.psdSum)
            peak = std::max(peak, p);
        // A power: 10 log10, i.e. 20 log10 of its square root.
        std::vector<double> root(a.psdSum.size());
        for (std::size_t i = 0; i < root.size(); ++i)
            root[i] = std::sqrt(a.psdSum[i]);
        acceleration_->data()->set(decibels(a.frequencyHz, root, std::sqrt(peak)), true);
        acceleration_->setName(tr("accel. PSD"));
        sources << tr("PSD of %1").arg(measured.accelerationSource);
        psdAxis->setRange(-60.0, 5.0);
    } else {
        acceleration_->data()->clear();
    }
    acceleration_->setVisible(measured.acceleration != nullptr);
    psdAxis->setVisible(measured.acceleration != nullptr);
    setToolTip(sources.isEmpty() ? description_ : description_ + '\n' + sources.join('\n'));
    // The magnitude range: what the curves reach within the grid, the deep low-frequency part
    // of an integrating plant cut at 60 dB below the top so the mode's peak stays readable.
    double top = -1e300;
    for (const auto* curve : {&v.rigidDb, &v.plantDb, &v.notchDb})
        for (double y : *curve)
            if (std::isfinite(y))
                top = std::max(top, y);
    double bottom = top;
    for (const auto* curve : {&v.rigidDb, &v.plantDb, &v.notchDb})
        for (std::size_t i = 0; i < curve->size(); ++i)
            if (std::isfinite((*curve)[i]) && v.frequencyHz[i] >= v.frequencyHz.back() / 30.0)
                bottom = std::min(bottom, (*curve)[i]);
    if (top > -1e300) {
        bottom = std::max(bottom, top - 160.0);
        fy->setRange(bottom - 5.0, top + 5.0);
    }
    // Whether a frequency lies in the right half of the logarithmic axis.
    const auto rightHalf = [&v](double hz) {
        return !v.frequencyHz.empty() &&
               std::log(hz / v.frequencyHz.front()) >
                   0.5 * std::log(v.frequencyHz.back() / v.frequencyHz.front());
    };
    const auto verticalLine = [this](QCPAxisRect* rect, double x, const QColor& color) {
        auto* line = new QCPItemStraightLine(this);
        line->setClipAxisRect(rect);
        line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        line->point1->setCoords(x, 0.0);
        line->point2->setCoords(x, 1.0);
        line->setPen(QPen(color, 1.0, Qt::DashLine));
        markers_ << line;
    };
    if (v.modeHz > 0.0) {
        verticalLine(responseRect_, v.modeHz, kMode);
        markers_ << addAnnotation(this, responseRect_, v.modeHz, fy->range().upper,
                                  tr("mode %1 Hz").arg(significant(v.modeHz, 4)), kMode,
                                  Qt::AlignLeft | Qt::AlignTop, rightHalf(v.modeHz));
    }
    if (v.notchHz > 0.0 && v.notchHz != v.modeHz) {
        verticalLine(responseRect_, v.notchHz, kNotch);
        markers_ << addAnnotation(this, responseRect_, v.notchHz, fy->range().lower,
                                  tr("notch %1 Hz").arg(significant(v.notchHz, 4)), kNotch,
                                  Qt::AlignLeft | Qt::AlignBottom, rightHalf(v.notchHz));
    }
    if (measured.measuredModeHz) {
        verticalLine(responseRect_, *measured.measuredModeHz, kMeasured);
        QString text = tr("measured %1 Hz").arg(significant(*measured.measuredModeHz, 4));
        if (measured.measuredModeDamping)
            text += tr(", ζ %1").arg(significant(*measured.measuredModeDamping, 2));
        markers_ << addAnnotation(this, responseRect_, *measured.measuredModeHz,
                                  fy->range().lower + 0.15 * fy->range().size(), text, kMeasured,
                                  Qt::AlignLeft | Qt::AlignBottom,
                                  rightHalf(*measured.measuredModeHz));
    }
    QCPAxis* sx = shaperRect_->axis(QCPAxis::atBottom);
    QCPAxis* sy = shaperRect_->axis(QCPAxis::atLeft);
    if (v.shaper && !v.sensitivity.frequencyHz.empty()) {
        sensitivity_->setName(tr("%1 %2 Hz, ζ %3")
                                  .arg(QString(shaperName(v.shaper->type)).toUpper(),
                                       significant(v.shaper->frequencyHz, 4),
                                       significant(v.shaper->dampingRatio, 3)));
        sensitivity_->data()->set(
            curveData(v.sensitivity.frequencyHz, v.sensitivity.vibration, 100.0), true);
        const double fMax = v.sensitivity.frequencyHz.back();
        tolerance_->data()->set({QCPGraphData(0.0, 5.0), QCPGraphData(fMax, 5.0)}, true);
        sensitivity_->setVisible(true);
        tolerance_->setVisible(true);
        shaperNotice_->setLines({});
        sx->setRange(0.0, fMax);
        sy->setRange(0.0, 105.0);
        const double at = v.modeHz > 0.0 ? v.modeHz : v.shaper->frequencyHz;
        verticalLine(shaperRect_, at, kMode);
        markers_ << addAnnotation(
            this, shaperRect_, at, v.residualAtModePercent,
            tr("%1 % left at %2 Hz")
                .arg(QString::number(v.residualAtModePercent, 'f', 1), significant(at, 4)),
            kMode, Qt::AlignLeft | Qt::AlignBottom, at > 0.5 * fMax);
    } else {
        sensitivity_->data()->clear();
        tolerance_->data()->clear();
        shaperNotice_->setLines({tr("No input shaper: the Mode fold's Input shaper sets one")});
        sensitivity_->setName(tr("no input shaper"));
        sx->setRange(0.0, std::max(1.0, 2.5 * v.modeHz));
        sy->setRange(0.0, 105.0);
    }
    // The legend lists what is drawn.
    legend_->clearItems();
    for (QCPGraph* g : {rigid_, plant_, notch_, measured_, acceleration_, sensitivity_})
        if (g->visible() && !g->data()->isEmpty())
            legend_->addItem(new QCPPlottableLegendItem(legend_, g));
    placeLegend(legend_->itemCount() > 0);
    QStringList notices;
    if (v.modeHz == 0.0)
        notices << tr("The table is rigid: set a flexible mode in the Design box's Mode fold");
    notice_->setLines(notices);
    summary_->setText(summary);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
