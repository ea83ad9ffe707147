// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class BodePlot;

/// The Bode diagram of the current axis' loop with its margins against the specification's, or why
/// there is none.
class BodeView : public PresenterView {
    Q_OBJECT
public:
    BodeView(TuningSession* session, BodePlot* plot);

protected:
    void draw() override;

private:
    BodePlot* plot_;
};

} // namespace xyt::ui
