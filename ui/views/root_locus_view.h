// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class RootLocusPlot;

/// The root locus of the current axis' loop (whatever its method) with the specification's region
/// and the design's closed-loop poles, or why there is none.
class RootLocusView : public PresenterView {
    Q_OBJECT
public:
    RootLocusView(TuningSession* session, RootLocusPlot* plot);

protected:
    void draw() override;

private:
    RootLocusPlot* plot_;
};

} // namespace xyt::ui
