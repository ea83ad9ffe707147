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
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    if (!e.ok) {
        // An invalid or failed axis has no locus: never an earlier one.
        plot_->showNoResult(tr("Root locus of %1").arg(axisTitle()), noDesignReason(e));
        return;
    }
    LocusRequirements req;
    req.active = true;
    req.maxOvershootPct = s.spec.maxOvershootPct;
    req.maxSettlingTimeSeconds = s.spec.maxSettlingTimeSeconds;
    if (a.method == DesignMethod::GuilleminTruxal)
        req.designOmegaNRadPerSec = a.gt.omegaNRadPerSec;
    plot_->setRequirements(req);
    std::vector<std::complex<double>> poles;
    try {
        poles = e.closedLoop().poles();
    } catch (const std::exception&) {
        poles.clear();
    }
    plot_->showLocus(session()->rootLocus(axis), poles,
                     tr("Root locus of %1 (K = 1: the design)").arg(axisTitle()));
}

} // namespace xyt::ui
