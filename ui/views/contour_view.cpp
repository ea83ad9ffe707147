// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/contour_view.h"

#include "ui/plots/contour_plot.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

ContourView::ContourView(TuningSession* session, ContourPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void ContourView::draw() {
    plot_->showSession(session()->liveSession(), session()->evaluation(), liveNotices());
}

} // namespace xyt::ui
