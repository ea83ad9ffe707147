// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/time_response_view.h"

#include "ui/plots/time_response_plot.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

TimeResponseView::TimeResponseView(TuningSession* session, TimeResponsePlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void TimeResponseView::setOverlaySnapshot(int index) {
    overlay_ = index;
    requestRedraw();
}

void TimeResponseView::draw() {
    const int axis = session()->currentAxis();
    const Session& s = session()->session();
    plot_->showAxis(session()->axisEvaluation(axis), axisTitle(), s.umaxVolts, liveNotices());
    if (overlay_ >= static_cast<int>(s.snapshots.size()))
        overlay_ = -1; // its snapshot was removed (undo, load)
    if (overlay_ < 0) {
        plot_->showSnapshot(SimulationResult{}, QString());
        return;
    }
    const AxisEvaluation& overlay =
        session()->snapshotEvaluation(static_cast<std::size_t>(overlay_), axis);
    plot_->showSnapshot(
        overlay.ok ? overlay.run : SimulationResult{},
        QString::fromStdString(s.snapshots.at(static_cast<std::size_t>(overlay_)).name));
}

} // namespace xyt::ui
