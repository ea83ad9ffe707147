// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/parameter_locus.h"
#include "ui/views/presenter_view.h"

namespace xyt::ui {

class ParameterLocusPlot;

/// The closed-loop poles of a Guillemin-Truxal axis as ωn or kp sweeps a decade each way of
/// the design, or why an axis of another method or without a design has none.
class ParameterLocusView : public PresenterView {
    Q_OBJECT
public:
    ParameterLocusView(TuningSession* session, ParameterLocusPlot* plot);
    /// The swept parameter (the tab's corner box).
    void setSweptParameter(GtSweptParameter parameter);

protected:
    void draw() override;

private:
    ParameterLocusPlot* plot_;
    GtSweptParameter swept_ = GtSweptParameter::OmegaN;
};

} // namespace xyt::ui
