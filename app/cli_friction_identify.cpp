// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli identify --structure friction: the Stribeck curve from a jog log (excite --signal
// jog, or a machine's log with time, reference, position and command columns).
#include "app/cli_args.h"
#include "app/cli_design_args.h"
#include "app/cli_friction.h"
#include "app/cli_json.h"

#include "core/identification/experiment_file.h"
#include "core/identification/experiment_table.h"
#include "core/identification/friction_identification.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/session/session.h"

#include <QJsonArray>

#include <cmath>

namespace xyt::cli {

namespace {

/// The column @p option names (default @p fallback) of @p table, every cell a number.
std::vector<double> numericColumn(const ExperimentTable& table, const CliArgs& args,
                                  const QString& option, const QString& fallback) {
    const std::string name = args.text(option, fallback).toStdString();
    std::size_t c = 0;
    try {
        c = table.column(name);
    } catch (const InvalidInput& e) {
        throw InvalidInput(CliArgs::field(option), e.what());
    }
    if (const auto& problem = table.firstProblem[c])
        throw InvalidInput(table.cellField(c, problem->row),
                           "'" + problem->text + "' " + problem->reason.text);
    return table.columns[c];
}

} // namespace

int identifyFrictionCurve(const CliArgs& args) {
    args.allowOnly({"data", "structure", "time-col", "reference-col", "output-col", "input-col",
                    "settle-fraction", "no-stribeck", "session", "axis"});
    if (!args.has("data"))
        throw InvalidInput("--data", "give the jog log (CSV/TSV, .lvm or .mat)");
    const QString path = *args.value("data");
    const std::vector<std::string> columns{
        args.text("time-col", "t").toStdString(), args.text("reference-col", "r").toStdString(),
        args.text("output-col", "y").toStdString(), args.text("input-col", "u").toStdString()};
    ExperimentTable table;
    try {
        table = readExperimentTable(fileNameBytes(path), 1, columns);
    } catch (const FileError& e) {
        throw InvalidInput("--data", e.what());
    } catch (const InvalidInput& e) {
        // A column the file lacks: named by the option that asked for it.
        const QString what = QString::fromStdString(e.what());
        const std::pair<const char*, std::size_t> options[] = {
            {"time-col", 0}, {"reference-col", 1}, {"output-col", 2}, {"input-col", 3}};
        for (const auto& [option, index] : options)
            if (what.contains("'" + QString::fromStdString(columns[index]) + "'"))
                throw InvalidInput(CliArgs::field(option), e.what());
        throw;
    }
    const auto t = numericColumn(table, args, "time-col", "t");
    const auto r = numericColumn(table, args, "reference-col", "r");
    const auto y = numericColumn(table, args, "output-col", "y");
    const auto u = numericColumn(table, args, "input-col", "u");
    FrictionIdentificationOptions options;
    options.settleFraction = args.number("settle-fraction", options.settleFraction);
    if (!(options.settleFraction >= 0.0 && options.settleFraction < 1.0))
        throw InvalidInput("--settle-fraction", "must be in [0, 1)");
    options.allowStribeck = !args.flag("no-stribeck");
    FrictionEstimate e;
    try {
        e = identifyFriction(t, r, y, u, options);
    } catch (const InvalidInput& error) {
        const QString field = QString::fromStdString(error.field());
        const QString option = field == "t"           ? "--time-col"
                               : field == "reference" ? "--reference-col"
                               : field == "position"  ? "--output-col"
                               : field == "command"   ? "--input-col"
                                                      : "--data";
        throw InvalidInput(option.toStdString(), path.toStdString() + ": " + error.reason());
    }
    QJsonArray points;
    for (const FrictionPoint& p : e.points)
        points.append(QJsonObject{{"velocity", number(p.velocityMmPerS)},
                                  {"volts", number(p.volts)},
                                  {"volts_std", number(p.voltsStd)},
                                  {"samples", static_cast<qint64>(p.samples)}});
    QJsonObject out{
        {"structure", "friction"},
        {"data", path},
        {"coulomb", number(e.coulombVolts)},
        {"coulomb_std", number(e.coulombStd)},
        {"viscous", number(e.viscousVoltsPerMmPerS)},
        {"viscous_std", number(e.viscousStd)},
        {"stribeck", e.hasStribeck},
        {"static", e.hasStribeck ? number(e.staticVolts) : QJsonValue()},
        {"static_std", e.hasStribeck ? number(e.staticStd) : QJsonValue()},
        {"stribeck_velocity", e.hasStribeck ? number(e.stribeckVelocityMmPerS) : QJsonValue()},
        {"stribeck_velocity_std", e.hasStribeck ? number(e.stribeckStd) : QJsonValue()},
        {"residual_std", number(e.residualStdVolts)},
        {"degrees_of_freedom", static_cast<qint64>(e.degreesOfFreedom)},
        {"points", points}};
    // The slope against the model's own: a2 / k0 per mm of travel is the viscous term the linear
    // model already holds; the excess is the table's viscous friction.
    if (args.has("session")) {
        const Session session = loadSessionOrThrow(*args.value("session"));
        const QString axisName = args.text("axis", "x");
        if (axisName != "x" && axisName != "y")
            throw InvalidInput("--axis", "must be x or y");
        const AxisSettings& axis = session.axes[axisName == "x" ? 0 : 1];
        const double model =
            axis.gt.plant.a2 / axis.gt.plant.k0 * axis.gt.modelUnitsPerPositionUnit;
        out.insert("model_slope", number(model));
        out.insert("viscous_beyond_model", number(e.viscousVoltsPerMmPerS - model));
    } else if (args.has("axis")) {
        throw InvalidInput("--axis", "only with --session SESSION.json");
    }
    print(out);
    return 0;
}

} // namespace xyt::cli
