// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/pole_zero_view.h"

#include "ui/plots/pole_zero_plot.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

PoleZeroView::PoleZeroView(TuningSession* session, PoleZeroPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void PoleZeroView::setDigitalPlane(bool digital) {
    digital_ = digital;
    requestRedraw();
}

void PoleZeroView::draw() {
    const int axis = session()->currentAxis();
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    if (!e.ok)
        plot_->showNoResult(tr("Pole-zero map of %1").arg(axisTitle()), noDesignReason(e));
    else if (digital_ && e.digital)
        plot_->showSets(digitalPoleZeroSets(e), tr("Digital loop of %1 in the z-plane (Ts = %2 s)")
                                                    .arg(axisTitle())
                                                    .arg(e.digital->tsSeconds));
    else
        plot_->showSets(session()->poleZeroSets(axis), tr("Pole-zero map of %1").arg(axisTitle()));
}

} // namespace xyt::ui
