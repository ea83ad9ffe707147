// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ui/views/presenter_view.h"

namespace xyt::ui {

class EquationsPanel;

/// The current axis' design equations (the teaching panel).
class EquationsView : public PresenterView {
    Q_OBJECT
public:
    EquationsView(TuningSession* session, EquationsPanel* panel);

protected:
    void draw() override;

private:
    EquationsPanel* panel_;
};

} // namespace xyt::ui
