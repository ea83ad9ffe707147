// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class StepPlot;

/// The unit step of the current axis' closed loop against the specification's envelope (with
/// the ZPETC preview of a pole-placement axis), or why there is none.
class StepResponseView : public PresenterView {
    Q_OBJECT
public:
    StepResponseView(TuningSession* session, StepPlot* plot);

protected:
    void draw() override;

private:
    StepPlot* plot_;
};

} // namespace xyt::ui
