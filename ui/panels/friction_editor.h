// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/table_friction.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QToolButton;

namespace xyt::ui {

class FieldForm;
class NumberField;

/**
 * The "Friction and backlash" fold of an axis: the table's Coulomb, static and viscous friction,
 * Stribeck velocity, backlash and amplifier deadband (TableFriction), which of the plant's two
 * poles is the electrical lag, and the firmware's friction compensation (FrictionCompensation).
 * Folded, its header says what is set. A value the core refuses (validateTableFriction) stays at
 * its field, red with the reason, and nothing is applied.
 */
class FrictionEditor : public QWidget {
    Q_OBJECT

public:
    explicit FrictionEditor(QWidget* parent = nullptr);
    ~FrictionEditor() override;
    /// Shows the axis' settings; @p massModel false (a pole-placement axis, whose ARX model takes
    /// the Coulomb level and the amplifier deadband only, as an input dead zone) disables the
    /// other fields with the reason.
    void setSettings(const TableFriction& friction, const FrictionCompensation& compensation,
                     bool massModel);
    /// The field of a TableFriction / FrictionCompensation field name ("coulomb", "static",
    /// "stribeck_velocity", "viscous", "backlash", "amplifier_deadband", "percent", "band").
    NumberField* field(const QString& name) const;
    QComboBox* electricalPoleBox() const { return pole_; }
    QToolButton* foldButton() const { return fold_; }
    bool isOpen() const;

signals:
    void frictionEdited(const TableFriction& friction, const FrictionCompensation& compensation);

private:
    void emitIfValid();
    void updateHeader();

    QToolButton* fold_;
    QWidget* body_;
    QComboBox* pole_;
    QLabel* note_;
    std::unique_ptr<FieldForm> form_;
    TableFriction friction_;
    FrictionCompensation compensation_;
};

} // namespace xyt::ui
