// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/nyquist_view.h"

#include "ui/plots/nyquist_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

NyquistView::NyquistView(TuningSession* session, NyquistPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void NyquistView::draw() {
    const int axis = session()->currentAxis();
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    if (!e.ok) {
        plot_->showNoResult(tr("Nyquist diagram of %1").arg(axisTitle()), noDesignReason(e));
        return;
    }
    const AxisFrequencyAnalysis& f = session()->frequencyAnalysis(axis);
    if (!f.ok) {
        plot_->showNoResult(tr("Nyquist diagram of %1").arg(axisTitle()),
                            tr("No frequency analysis: %1").arg(diagnosticText(f.error)));
        return;
    }
    plot_->showCurve(f.nyquist, f.margins,
                     tr("Nyquist diagram of %1 (open loop L)").arg(axisTitle()));
}

} // namespace xyt::ui
