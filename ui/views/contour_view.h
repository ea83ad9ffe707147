// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class ContourPlot;

/// The XY contour of the session (both axes), its contour error and the program's corners.
class ContourView : public PresenterView {
    Q_OBJECT
public:
    ContourView(TuningSession* session, ContourPlot* plot);

protected:
    void draw() override;

private:
    ContourPlot* plot_;
};

} // namespace xyt::ui
