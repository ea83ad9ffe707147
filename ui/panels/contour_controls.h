// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QCheckBox;
class QToolButton;

namespace xyt::ui {

class ContourPlot;

/**
 * The controls of the XY contour view that only a G-code program has: the ballbar (polar) view
 * of a single-circle program and the stepping through the program's sharp corners (previous,
 * next; past the last one the whole path is shown again). They sit in the plot's top-right
 * corner, at the end of its title row (ContourPlot reserves the room), so the tab bar keeps
 * its width; the plot's title names the corner shown.
 */
class ContourControls : public QWidget {
    Q_OBJECT
public:
    /// A child of @p plot, kept in its top-right corner.
    explicit ContourControls(ContourPlot* plot);

    /// Enables what the plot's current data allows (call after ContourPlot::showSession).
    void sync();

    QCheckBox* polarView() const { return polar_; }
    QToolButton* previousCorner() const { return previous_; }
    QToolButton* nextCorner() const { return next_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void step(int direction);
    void place();

    ContourPlot* plot_;
    QCheckBox* polar_;
    QToolButton* previous_;
    QToolButton* next_;
};

} // namespace xyt::ui
