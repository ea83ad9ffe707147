// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class NyquistPlot;

/// The Nyquist diagram of the current axis' open loop L with its margins and the criterion's
/// counts, or why there is none.
class NyquistView : public PresenterView {
    Q_OBJECT
public:
    NyquistView(TuningSession* session, NyquistPlot* plot);

protected:
    void draw() override;

private:
    NyquistPlot* plot_;
};

} // namespace xyt::ui
