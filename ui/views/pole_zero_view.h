// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class PoleZeroPlot;

/// The pole-zero map of the current axis (its module's sets), or, when asked and the axis has
/// one, the z-plane map of its digital implementation; why there is none for an axis without a
/// design.
class PoleZeroView : public PresenterView {
    Q_OBJECT
public:
    PoleZeroView(TuningSession* session, PoleZeroPlot* plot);
    /// Whether the map shows the digital loop in the z-plane (View menu).
    void setDigitalPlane(bool digital);

protected:
    void draw() override;

private:
    PoleZeroPlot* plot_;
    bool digital_ = false;
};

} // namespace xyt::ui
