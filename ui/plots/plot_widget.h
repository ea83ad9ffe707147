// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

namespace xyt::ui {

/**
 * The base of every plot of the workbench: a QCustomPlot whose size hints are constants. The
 * stock hints measure every title, legend and readout text of the plot's layout; Qt asks for
 * them on every layout pass of the window (a changed number in the metrics table or the status
 * bar starts one), for every tab page, hidden or not, which cost about a seventh of a slider
 * step. A plot needs no more than the room given here to be readable; the splitters and tabs
 * give it the rest.
 */
class PlotWidget : public QCustomPlot {
    Q_OBJECT
public:
    explicit PlotWidget(QWidget* parent = nullptr) : QCustomPlot(parent) {}
    QSize minimumSizeHint() const override { return {kMinimumWidth, kMinimumHeight}; }
    QSize sizeHint() const override { return {2 * kMinimumWidth, 2 * kMinimumHeight}; }

    /**
     * True once the user has zoomed (wheel) or panned (drag) the view since it was last reset:
     * the plot's automatic fit then leaves the view alone while the design changes, until
     * releaseView (View > Reset plot views, a double-click, "Reset view", or a change of plane).
     */
    bool viewHeld() const { return viewHeld_; }
    void releaseView() { viewHeld_ = false; }

    static constexpr int kMinimumWidth = 240;
    static constexpr int kMinimumHeight = 180;

protected:
    void wheelEvent(QWheelEvent* event) override {
        QCustomPlot::wheelEvent(event);
        if (interactions().testFlag(QCP::iRangeZoom))
            viewHeld_ = true;
    }
    void mouseMoveEvent(QMouseEvent* event) override {
        QCustomPlot::mouseMoveEvent(event);
        if ((event->buttons() & Qt::LeftButton) && interactions().testFlag(QCP::iRangeDrag))
            viewHeld_ = true;
    }

private:
    bool viewHeld_ = false;
};

} // namespace xyt::ui
