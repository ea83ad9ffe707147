// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class VibrationPlot;

/// The current axis' flexible mode, notch and input shaper (analyzeAxisVibration), with what
/// the shaper does to the run (AxisEvaluation::shaping), or why there is nothing to draw.
class VibrationView : public PresenterView {
    Q_OBJECT
public:
    VibrationView(TuningSession* session, VibrationPlot* plot);

protected:
    void draw() override;

private:
    VibrationPlot* plot_;
};

} // namespace xyt::ui
