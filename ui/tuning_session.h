// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session.h"
#include "core/session_evaluation.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

namespace xyt::ui {

/**
 * The presenter of the workbench: owns the design (a core `Session`), its evaluation, and the
 * undo stack. Widgets call the setters and observe `designChanged()`; nothing is computed in a
 * widget. Every change goes through `apply()`, which pushes an undoable command holding the
 * session before and after; consecutive changes with the same merge key (one slider drag) merge
 * into one undo step.
 */
class TuningSession : public QObject {
    Q_OBJECT
public:
    explicit TuningSession(QObject* parent = nullptr);

    const Session& session() const { return session_; }
    const SessionEvaluation& evaluation() const { return evaluation_; }
    const AxisEvaluation& axisEvaluation(int axis) const;
    QUndoStack* undoStack() { return &undo_; }

    int currentAxis() const { return currentAxis_; }
    /// True when the session differs from the last saved or loaded state.
    bool isModified() const { return !undo_.isClean(); }

    /**
     * Replaces the whole session as one undoable step named @p description. A change whose
     * @p mergeKey equals the previous command's merges with it (slider drags); -1 never merges.
     */
    void apply(const Session& next, const QString& description, int mergeKey = -1);
    /// Replaces the session without an undo step (load, new) and marks it clean.
    void reset(const Session& next);
    /// Marks the current state as saved.
    void markSaved() { undo_.setClean(); }

    // Convenience setters (each one apply() step). Axis index 0 = x, 1 = y.
    void setOmegaN(int axis, double omegaNRadPerSec);
    void setKp(int axis, double kp);
    void setPlant(int axis, const ThirdOrderPlant& plant);
    void setModelUnitScale(int axis, double modelUnitsPerPositionUnit);
    void setTrajectory(const TrajectorySettings& trajectory);
    void setUmax(double umaxVolts);

public slots:
    void setCurrentAxis(int axis);

signals:
    /// The session or its evaluation changed: every view redraws from the getters.
    void designChanged();
    void currentAxisChanged(int axis);

private:
    friend class SessionCommand;
    /// Sets the session and re-evaluates it (used by the undo commands).
    void assign(const Session& next);

    Session session_;
    SessionEvaluation evaluation_;
    QUndoStack undo_;
    int currentAxis_ = 0;
};

/// Merge keys for slider drags: one per parameter and axis.
enum MergeKey { kMergeOmegaN = 100, kMergeKp = 200, kMergeT1 = 300 };

} // namespace xyt::ui
