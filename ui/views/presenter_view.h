// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QStringList>

class QWidget;

namespace xyt {
struct AxisEvaluation;
}

namespace xyt::ui {

class TuningSession;

/**
 * One view of the window, drawn from the presenter (TuningSession): it observes the presenter
 * and redraws its widget when the design or the current axis changes, or when one of its own
 * options changes (requestRedraw). It draws only while its widget is on screen: a view on a
 * hidden tab is marked stale and drawn when the tab is shown (its window calls drawIfStale on
 * a change of tab), so a slider drag pays for what the user sees. A window that is not shown at
 * all draws every view (tests, the screenshot).
 */
class PresenterView : public QObject {
    Q_OBJECT
public:
    PresenterView(TuningSession* session, QWidget* widget);
    /// Redraws now if the widget is on screen, else when it is shown.
    void requestRedraw();
    /// Draws a stale view whose widget is now on screen (a tab or the window was shown). A view
    /// drawn while its window was not shown counts as stale until it is drawn on screen.
    void drawIfStale();
    /// Whether the widget shows the presenter's current state (false while stale and hidden).
    bool isCurrent() const { return !stale_; }

protected:
    /// Draws the widget from the presenter's current state.
    virtual void draw() = 0;
    TuningSession* session() const { return session_; }
    /// "Axis X (label)": the current axis as the plots' titles name it.
    QString axisTitle() const;
    /// The presenter's notice about the live (preview) session, as plots list notices.
    QStringList liveNotices() const;
    /// "No design: <field>: <reason>": why an axis without a design has nothing to draw.
    static QString noDesignReason(const AxisEvaluation& axis);

private:
    bool onScreen() const;

    TuningSession* session_;
    QWidget* widget_;
    bool stale_ = true;
};

} // namespace xyt::ui
