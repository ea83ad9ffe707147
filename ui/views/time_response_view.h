// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class TimeResponsePlot;

/// The time plot of the current axis: its run, the digital implementation when overlaid, and
/// a snapshot's run overlaid when one is chosen (its evaluation cached by the presenter).
class TimeResponseView : public PresenterView {
    Q_OBJECT
public:
    TimeResponseView(TuningSession* session, TimeResponsePlot* plot);
    /// The snapshot overlaid (its index in the session's snapshots), -1 for none.
    void setOverlaySnapshot(int index);
    int overlaySnapshot() const { return overlay_; }

protected:
    void draw() override;

private:
    TimeResponsePlot* plot_;
    int overlay_ = -1;
};

} // namespace xyt::ui
