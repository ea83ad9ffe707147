// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/tuning_session.h"

#include <QUndoCommand>

namespace xyt::ui {

/// One undo step: the whole session before and after (the session is a few hundred bytes).
class SessionCommand : public QUndoCommand {
public:
    SessionCommand(TuningSession* owner, Session before, Session after, const QString& text,
                   int mergeKey)
        : QUndoCommand(text), owner_(owner), before_(std::move(before)), after_(std::move(after)),
          mergeKey_(mergeKey) {}

    void undo() override { owner_->assign(before_); }
    void redo() override { owner_->assign(after_); }
    int id() const override { return mergeKey_; }
    bool mergeWith(const QUndoCommand* other) override {
        if (other->id() != id() || mergeKey_ < 0)
            return false;
        after_ = static_cast<const SessionCommand*>(other)->after_;
        return true;
    }

private:
    TuningSession* owner_;
    Session before_;
    Session after_;
    int mergeKey_;
};

TuningSession::TuningSession(QObject* parent) : QObject(parent) {
    session_ = Session::paperDefault();
    evaluation_ = evaluateSession(session_);
}

const AxisEvaluation& TuningSession::axisEvaluation(int axis) const {
    return evaluation_.axes.at(static_cast<std::size_t>(axis));
}

void TuningSession::assign(const Session& next) {
    session_ = next;
    evaluation_ = evaluateSession(session_);
    emit designChanged();
}

void TuningSession::apply(const Session& next, const QString& description, int mergeKey) {
    undo_.push(new SessionCommand(this, session_, next, description, mergeKey));
}

void TuningSession::reset(const Session& next) {
    undo_.clear();
    assign(next);
    undo_.setClean();
}

void TuningSession::setCurrentAxis(int axis) {
    if (axis == currentAxis_ || axis < 0 || axis > 1)
        return;
    currentAxis_ = axis;
    emit currentAxisChanged(axis);
}

namespace {
QString axisName(const Session& s, int axis) {
    return QString::fromStdString(s.axes.at(static_cast<std::size_t>(axis)).id).toUpper();
}
} // namespace

void TuningSession::setOmegaN(int axis, double omegaNRadPerSec) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.omegaNRadPerSec = omegaNRadPerSec;
    apply(next, tr("Set ωn of %1 to %2").arg(axisName(next, axis)).arg(omegaNRadPerSec),
          kMergeOmegaN + axis);
}

void TuningSession::setKp(int axis, double kp) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.kp = kp;
    apply(next, tr("Set kp of %1 to %2").arg(axisName(next, axis)).arg(kp), kMergeKp + axis);
}

void TuningSession::setPlant(int axis, const ThirdOrderPlant& plant) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.plant = plant;
    apply(next, tr("Change the plant of %1").arg(axisName(next, axis)));
}

void TuningSession::setModelUnitScale(int axis, double modelUnitsPerPositionUnit) {
    Session next = session_;
    next.axes.at(static_cast<std::size_t>(axis)).gt.modelUnitsPerPositionUnit =
        modelUnitsPerPositionUnit;
    apply(next, tr("Change the model unit of %1").arg(axisName(next, axis)));
}

void TuningSession::setTrajectory(const TrajectorySettings& trajectory) {
    Session next = session_;
    next.trajectory = trajectory;
    apply(next, tr("Change the trajectory"));
}

void TuningSession::setUmax(double umaxVolts) {
    Session next = session_;
    next.umaxVolts = umaxVolts;
    apply(next, tr("Set the actuator limit to %1 V").arg(umaxVolts));
}

} // namespace xyt::ui
