// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/bode_view.h"

#include "core/model/errors.h"
#include "core/session/continuous_plant_method.h"
#include "core/session/design_method_module.h"
#include "ui/plots/bode_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

BodeView::BodeView(TuningSession* session, BodePlot* plot)
    : PresenterView(session, plot), plot_(plot) {
    connect(session, &TuningSession::measurementsChanged, this, &PresenterView::requestRedraw);
}

void BodeView::draw() {
    const int axis = session()->currentAxis();
    const Session& s = session()->session();
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    const QString title = tr("Bode diagram of %1").arg(axisTitle());
    if (!e.ok) {
        plot_->showNoResult(title, noDesignReason(e));
        return;
    }
    const AxisFrequencyAnalysis& f = session()->frequencyAnalysis(axis);
    if (!f.ok) {
        plot_->showNoResult(title, tr("No frequency analysis: %1").arg(diagnosticText(f.error)));
        return;
    }
    // The feedforward's curve unless the axis has it switched off (pole placement's ZPETC).
    plot_->showAnalysis(f, a.method != DesignMethod::PolePlacementZpetc || a.pp.zpetcEnabled, title,
                        {s.spec.minPhaseMarginDeg, s.spec.minGainMarginDb, e.check.phaseMargin,
                         e.check.gainMargin});
    // A measured plant response: the loop it makes with the axis' controller, over the model's.
    const auto& measured = session()->measuredResponse(axis);
    const auto* continuous =
        dynamic_cast<const ContinuousPlantMethod*>(&designMethodModule(e.method));
    if (measured && continuous) {
        try {
            const MeasuredOpenLoop loop =
                measuredOpenLoop(measured->estimate, continuous->evaluatedController(e),
                                 a.gt.modelUnitsPerPositionUnit, f.responses.openLoop);
            plot_->showMeasuredLoop(&loop, measured->source);
            return;
        } catch (const InvalidInput&) {
            // a discrete controller: no measured loop to draw
        }
    }
    plot_->showMeasuredLoop(nullptr, QString());
}

} // namespace xyt::ui
