// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli_args.h"
#include "core/model/table_friction.h"
#include "core/simulation/simulation.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>

namespace xyt::cli {

/// The table's options: --coulomb V --static V --stribeck-velocity MM_S --viscous V_PER_MM_S
/// --backlash MM --amp-deadband V --electrical-pole faster|slower --friction-compensation PERCENT
/// --compensation-band MM_S.
extern const QStringList kFrictionOptions;

/// kFrictionOptions with @p prefix ("x." for --x.coulomb).
QStringList frictionOptions(const QString& prefix = "");

/**
 * The friction of the options named with @p prefix, each unset one taken from @p base (the
 * paper's linear table by default).
 * @throws InvalidInput naming the option (--coulomb, --x.stribeck-velocity, ...).
 */
TableFriction parseFriction(const CliArgs& args, const QString& prefix = "",
                            const TableFriction& base = {});
/// The compensation of --friction-compensation and --compensation-band (with @p prefix).
FrictionCompensation parseFrictionCompensation(const CliArgs& args, const QString& prefix = "",
                                               const FrictionCompensation& base = {});

/// {"coulomb", ...} with the compensation: the table as the run used it.
QJsonObject frictionJson(const TableFriction& friction, const FrictionCompensation& compensation);

/// The stick-slip and hunting findings of @p run (stickSlipFindings), null without dry friction.
QJsonValue stickSlipJson(const SimulationResult& run);

/// identify --structure friction (app/cli_friction_identify.cpp).
int identifyFrictionCurve(const CliArgs& args);

} // namespace xyt::cli
