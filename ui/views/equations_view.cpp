// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/equations_view.h"

#include "ui/panels/equations_panel.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

EquationsView::EquationsView(TuningSession* session, EquationsPanel* panel)
    : PresenterView(session, panel), panel_(panel) {}

void EquationsView::draw() {
    const int axis = session()->currentAxis();
    panel_->showAxis(session()->session().axes.at(static_cast<std::size_t>(axis)),
                     session()->axisEvaluation(axis));
}

} // namespace xyt::ui
