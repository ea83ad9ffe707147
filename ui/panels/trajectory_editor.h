// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QWidget>

class QComboBox;
class QStackedWidget;

namespace xyt::ui {

class NumberField;

/// Editor of the commanded motion: cubic point-to-point (x0, xf, t0, tf, v0, vf) or circle
/// (radius, omega, ramp-in), plus the simulation step and duration.
class TrajectoryEditor : public QWidget {
    Q_OBJECT
public:
    explicit TrajectoryEditor(QWidget* parent = nullptr);

    void setTrajectory(const TrajectorySettings& trajectory);
    QComboBox* kindBox() const { return kind_; }
    NumberField* field(const QString& name) const;

signals:
    void trajectoryEdited(const TrajectorySettings& trajectory);

private:
    void emitIfValid();

    QComboBox* kind_;
    QStackedWidget* pages_;
    QMap<QString, NumberField*> fields_;
    TrajectorySettings current_;
};

} // namespace xyt::ui
