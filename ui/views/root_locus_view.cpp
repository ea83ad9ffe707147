// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/root_locus_view.h"

#include "ui/plots/root_locus_plot.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

RootLocusView::RootLocusView(TuningSession* session, RootLocusPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void RootLocusView::draw() {
    const int axis = session()->currentAxis();
    const Session& s = session()->session();
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    if (!e.ok) {
        // An invalid or failed axis has no locus: never an earlier one.
        plot_->showNoResult(tr("Root locus of %1").arg(axisTitle()), noDesignReason(e));
        return;
    }
    plot_->setRequirements(axisLocusRequirements(s, axis));
    plot_->showLocus(session()->rootLocus(axis), designClosedLoopPoles(e),
                     tr("Root locus of %1 (K = 1: the design)").arg(axisTitle()));
}

} // namespace xyt::ui
