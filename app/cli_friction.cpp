// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_friction.h"

#include "app/cli_json.h"
#include "core/model/errors.h"
#include "core/simulation/stick_slip.h"

namespace xyt::cli {

const QStringList kFrictionOptions{
    "coulomb",      "static",          "stribeck-velocity",     "viscous",          "backlash",
    "amp-deadband", "electrical-pole", "friction-compensation", "compensation-band"};

QStringList frictionOptions(const QString& prefix) {
    QStringList out;
    for (const QString& name : kFrictionOptions)
        out << prefix + name;
    return out;
}

namespace {

/// The option that sets a core field of TableFriction / FrictionCompensation.
QString optionOfField(const std::string& field) {
    if (field == "amplifier_deadband")
        return "amp-deadband";
    if (field == "percent")
        return "friction-compensation";
    if (field == "band")
        return "compensation-band";
    return QString::fromStdString(field).replace('_', '-');
}

template <class F> void namingFrictionOptions(const QString& prefix, F body) {
    try {
        body();
    } catch (const InvalidInput& e) {
        throw InvalidInput(CliArgs::field(prefix + optionOfField(e.field())), e.reason());
    }
}

} // namespace

TableFriction parseFriction(const CliArgs& args, const QString& prefix, const TableFriction& base) {
    TableFriction f = base;
    f.coulombVolts = args.number(prefix + "coulomb", base.coulombVolts);
    f.staticVolts = args.number(prefix + "static", base.staticVolts);
    f.stribeckVelocityMmPerS =
        args.number(prefix + "stribeck-velocity", base.stribeckVelocityMmPerS);
    f.viscousVoltsPerMmPerS = args.number(prefix + "viscous", base.viscousVoltsPerMmPerS);
    f.backlashMm = args.number(prefix + "backlash", base.backlashMm);
    f.amplifierDeadbandVolts = args.number(prefix + "amp-deadband", base.amplifierDeadbandVolts);
    if (args.has(prefix + "electrical-pole")) {
        const QString pole = args.text(prefix + "electrical-pole", "faster");
        if (pole != "faster" && pole != "slower")
            throw InvalidInput(CliArgs::field(prefix + "electrical-pole"),
                               "must be faster or slower, got '" + pole.toStdString() + "'");
        f.electricalPole = pole == "faster" ? ElectricalPole::Faster : ElectricalPole::Slower;
    }
    namingFrictionOptions(prefix, [&] { validateTableFriction(f); });
    return f;
}

FrictionCompensation parseFrictionCompensation(const CliArgs& args, const QString& prefix,
                                               const FrictionCompensation& base) {
    FrictionCompensation c = base;
    c.percent = args.number(prefix + "friction-compensation", base.percent);
    c.bandMmPerS = args.number(prefix + "compensation-band", base.bandMmPerS);
    namingFrictionOptions(prefix, [&] { validateFrictionCompensation(c); });
    return c;
}

QJsonObject frictionJson(const TableFriction& f, const FrictionCompensation& c) {
    return {{"coulomb", number(f.coulombVolts)},
            {"static", number(f.breakawayVolts())},
            {"stribeck_velocity", number(f.stribeckVelocityMmPerS)},
            {"viscous", number(f.viscousVoltsPerMmPerS)},
            {"backlash", number(f.backlashMm)},
            {"amp_deadband", number(f.amplifierDeadbandVolts)},
            {"electrical_pole", f.electricalPole == ElectricalPole::Faster
                                    ? QStringLiteral("faster")
                                    : QStringLiteral("slower")},
            {"compensation_percent", number(c.percent)},
            {"compensation_band", number(c.bandMmPerS)}};
}

QJsonValue stickSlipJson(const SimulationResult& run) {
    const auto f = stickSlipFindings(run);
    if (!f)
        return QJsonValue();
    return QJsonObject{
        {"stops_during_move", f->stopsDuringMove},
        {"first_stop", f->stopsDuringMove > 0 ? number(f->firstStopSeconds) : QJsonValue()},
        {"breakaways_at_rest", f->breakawaysAtRest},
        {"hunting", f->breakawaysAtRest >= 2},
        {"rest_peak_to_peak", number(f->restPeakToPeakMm)}};
}

} // namespace xyt::cli
