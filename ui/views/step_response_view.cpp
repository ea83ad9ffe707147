// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/step_response_view.h"

#include "core/simulation/step_view.h"
#include "ui/plots/step_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

StepResponseView::StepResponseView(TuningSession* session, StepPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void StepResponseView::draw() {
    const int axis = session()->currentAxis();
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    const AxisSettings& a = session()->session().axes.at(static_cast<std::size_t>(axis));
    const QString title = tr("Unit step of %1").arg(axisTitle());
    if (!e.ok) {
        plot_->showNoResult(title, noDesignReason(e));
        return;
    }
    try {
        const bool pp = e.pp && e.zpetc;
        plot_->showView(
            stepView(e.closedLoop(), e.step, specificationEnvelope(session()->session().spec),
                     pp ? &*e.pp : nullptr, pp ? &*e.zpetc : nullptr, pp && a.pp.zpetcEnabled),
            title);
    } catch (const std::exception& ex) {
        plot_->showNoResult(title, tr("No step response: %1").arg(exceptionText(ex)));
    }
}

} // namespace xyt::ui
