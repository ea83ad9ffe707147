// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/metrics_view.h"

#include "ui/panels/metrics_panel.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

MetricsView::MetricsView(TuningSession* session, MetricsPanel* panel)
    : PresenterView(session, panel), panel_(panel) {}

void MetricsView::draw() {
    panel_->showEvaluation(session()->session(), session()->evaluation(), session()->liveNotice());
    for (int i = 0; i < 2; ++i)
        panel_->showMargins(i, session()->axisEvaluation(i));
}

} // namespace xyt::ui
