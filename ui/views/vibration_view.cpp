// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/vibration_view.h"

#include "core/design/shaper_sensitivity.h"
#include "core/session/axis_vibration.h"
#include "ui/plots/number_text.h"
#include "ui/plots/vibration_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

VibrationView::VibrationView(TuningSession* session, VibrationPlot* plot)
    : PresenterView(session, plot), plot_(plot) {
    connect(session, &TuningSession::measurementsChanged, this, &PresenterView::requestRedraw);
}

void VibrationView::draw() {
    const int axis = session()->currentAxis();
    const QString title = tr("Vibration of %1").arg(axisTitle());
    const AxisVibration v = analyzeAxisVibration(session()->session(), axis);
    if (!v.ok) {
        plot_->showNoResult(title, diagnosticText(v.error));
        return;
    }
    QString summary;
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    if (e.ok && e.shaping) {
        const ShapingComparison& c = *e.shaping;
        // Round-off of a cancelled mode (1e-19 mm) reads as 0.
        const double shaped =
            c.residualShapedMm < 1e-9 * c.residualUnshapedMm ? 0.0 : c.residualShapedMm;
        summary = tr("%1 shaper: %2 impulses over %3 ms, a delay of %4 ms")
                      .arg(QString(shaperName(c.shaper.type)).toUpper())
                      .arg(c.shaper.amplitudes.size())
                      .arg(significant(1000.0 * c.shaper.duration(), 3),
                           significant(1000.0 * shaperDelaySeconds(c.shaper), 3));

        summary += tr("; the %1 Hz mode%2 rings %3 with an amplitude of %4 mm shaped, %5 mm "
                      "unshaped")
                       .arg(significant(c.modeHz, 4),
                            c.fromAxisMode ? QString() : tr(" it is designed for"),
                            c.afterMove ? tr("after the move") : tr("along the path"),
                            significant(shaped, 3), significant(c.residualUnshapedMm, 3));
    }
    VibrationMeasurements measured;
    if (const auto& r = session()->measuredResponse(axis)) {
        measured.response = &r->estimate;
        measured.responseSource = r->source;
        const GtAxisSettings& gt = session()->session().axes.at(static_cast<std::size_t>(axis)).gt;
        if (const auto pick = measuredModePick(r->estimate, gt, VibrationPlot::kMinCoherence)) {
            measured.measuredModeHz = pick->frequencyHz;
            measured.measuredModeDamping = pick->dampingRatio;
        }
    }
    if (const auto& a = session()->measuredAcceleration()) {
        measured.acceleration = &a->spectra;
        measured.accelerationSource = a->source;
    }
    plot_->showVibration(v, title, summary, measured);
}

} // namespace xyt::ui
