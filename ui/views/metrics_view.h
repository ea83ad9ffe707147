// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class MetricsPanel;

/// The figures of both axes with their verdicts and margins (the metrics panel).
class MetricsView : public PresenterView {
    Q_OBJECT
public:
    MetricsView(TuningSession* session, MetricsPanel* panel);

protected:
    void draw() override;

private:
    MetricsPanel* panel_;
};

} // namespace xyt::ui
