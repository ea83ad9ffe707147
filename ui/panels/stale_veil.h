// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;

namespace xyt::ui {

/**
 * A translucent cover over a view's result that no longer describes the session, with a note
 * saying what it was computed for ("Computed for axis X, ωn = 2 rad/s, kp = 30 …"). The result
 * stays readable under it, but dimmed and out of reach of the mouse (no hover readout of a
 * stale map), so it is never taken for the current design's. It covers its parent whole and
 * follows its size.
 */
class StaleVeil : public QWidget {
    Q_OBJECT
public:
    explicit StaleVeil(QWidget* covered);

    /// Covers the parent with @p note on top.
    void veil(const QString& note);
    void lift();
    bool isVeiled() const { return !isHidden(); }
    QString note() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;

private:
    /// Sizes the note to its text at the cover's width (a wrapped label gets no height of its
    /// own from a layout).
    void fitNote();

    QLabel* note_;
};

} // namespace xyt::ui
