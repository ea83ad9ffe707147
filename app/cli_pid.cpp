// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli simulate --method pid-ff | --ff-from-model, and tune: the PID with command
// feedforward that CNC drives run (LinuxCNC's pid, position in mm), simulated through a session
// as the workbench runs it, and PID gains from a target crossover and phase margin or from a
// relay experiment.
#include "app/cli_pid.h"

#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_friction.h"
#include "app/cli_json.h"

#include "core/analysis/nyquist.h"
#include "core/design/model_feedforward.h"
#include "core/design/pid_tuning.h"
#include "core/design/relay_experiment.h"
#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"

#include <QJsonArray>

#include <string>

namespace xyt::cli {

const QStringList kPidGainOptions = {"p",        "i",           "d",          "ff0",
                                     "ff1",      "ff2",         "ff3",        "bias",
                                     "deadband", "max-error-i", "max-output", "derivative-filter"};
const QStringList kPidFlags = {"derivative-on-measurement", "trajectory-derivatives"};

QSet<QString> simulateFlags() {
    return {"digital", "ff-from-model", "derivative-on-measurement", "trajectory-derivatives"};
}

namespace {

constexpr const char* kPidMethod = "pid-ff";
constexpr const char* kGtMethod = "guillemin-truxal";

/// The options of the Guillemin-Truxal digital PI that LinuxCNC's pid does not have.
const QStringList kPiOnlyOptions = {"discretization", "anti-windup", "tracking-time"};
/// The implementation options that apply to the PID's digital run too.
const QStringList kImplementationOptions = {"digital", "controller-ts", "delay-samples",
                                            "encoder-resolution", "dac-bits"};
/// The sine's options (the session has no sine trajectory).
const QStringList kSineOptions = {"amplitude", "omega", "phase-deg", "ramp-in"};

/// "max-error-i" -> "max_error_i": the parameter's name in AxisSettings::parameters.
std::string parameterName(const QString& option) {
    return QString(option).replace('-', '_').toStdString();
}

/**
 * The option of simulate that a field of its session stands for: "axes[0].parameters.ff1" ->
 * "--ff1", "axes[0].gt.plant.k0" -> "--k0", "controller_ts" -> "--controller-ts",
 * "trajectory.cubic.tf" -> "--tf"; a field with no option is returned as it is.
 */
std::string optionOfSessionField(const std::string& field) {
    std::string rest = field;
    if (rest.rfind("axes[", 0) == 0) {
        const std::size_t dot = rest.find("].");
        if (dot != std::string::npos)
            rest = rest.substr(dot + 2);
    }
    const auto option = [](std::string name) {
        return CliArgs::field(QString::fromStdString(name).replace('_', '-'));
    };
    const auto after = [&rest](const std::string& prefix) -> std::optional<std::string> {
        if (rest.rfind(prefix, 0) == 0 && rest.size() > prefix.size())
            return rest.substr(prefix.size());
        return std::nullopt;
    };
    if (rest == "parameters.command_derivatives")
        return "--trajectory-derivatives";
    for (const char* prefix :
         {"parameters.", "gt.plant.", "gt.", "implementation.", "trajectory.cubic.", "trajectory."})
        if (const auto name = after(prefix))
            return option(*name);
    if (rest == "controller_ts" || rest == "umax")
        return option(rest);
    if (after("specification."))
        return "--in-position-window";
    return field;
}

/// The first plant option the user typed of --k0, --a1, --a2, else --preset.
std::string plantOption(const CliArgs& args) {
    for (const char* name : {"k0", "a1", "a2"})
        if (args.has(name))
            return CliArgs::field(name);
    return "--preset";
}

/// Runs @p f, re-throwing a refusal of the core that names a session field as the option.
template <class F> auto namingOption(F&& f) {
    try {
        return f();
    } catch (const InvalidInput& e) {
        throw InvalidInput(optionOfSessionField(e.field()), e.reason());
    }
}

/// Refuses what the session path cannot take, naming the option and saying why.
void refuseOutsideSession(const CliArgs& args, bool pidMethod) {
    if (pidMethod) {
        for (const char* gt : {"wn", "kp"})
            if (args.has(gt))
                throw InvalidInput(CliArgs::field(gt),
                                   "applies to --method guillemin-truxal (the PID's gains are "
                                   "--p, --i, --d)");
    } else {
        for (const QString& name : kPidGainOptions + kPidFlags)
            if (args.has(name))
                throw InvalidInput(CliArgs::field(name),
                                   "needs --method pid-ff (--ff-from-model runs the "
                                   "Guillemin-Truxal PI as P = kp u, I = ki u)");
    }
    if (args.flag("ff-from-model"))
        for (const char* ff : {"ff0", "ff1", "ff2", "ff3"})
            if (args.has(ff))
                throw InvalidInput(CliArgs::field(ff),
                                   "cannot be combined with --ff-from-model, which sets FF0 to 0 "
                                   "and FF1..FF3 to the plant's exact inverse");
    if (!args.flag("digital"))
        for (const QString& name : kImplementationOptions + kPiOnlyOptions)
            if (name != "digital" && args.has(name))
                throw InvalidInput(CliArgs::field(name),
                                   "needs --digital (the run of the digital controller)");
    for (const QString& name : kPiOnlyOptions)
        if (args.has(name))
            throw InvalidInput(CliArgs::field(name),
                               "does not apply to the PID + feedforward: LinuxCNC's pid "
                               "integrates by the rectangle rule and stops integrating into the "
                               "output limit (--max-error-i limits the integrator)");
    const QString trajectory = args.text("trajectory", "");
    if (trajectory == "sine")
        throw InvalidInput("--trajectory",
                           "sine is not a trajectory of a session: --method pid-ff and "
                           "--ff-from-model run the cubic or quintic move");
    for (const QString& name : kSineOptions)
        if (args.has(name))
            throw InvalidInput(CliArgs::field(name), "applies to --trajectory sine only");
}

/// The axis the arguments describe (axis 0 of the session, the plant's fields set).
AxisSettings pidAxis(const CliArgs& args, const PlantInput& plant, double unit, bool pidMethod) {
    AxisSettings axis = Session::paperDefault().axes[0];
    axis.label =
        plant.preset ? plant.preset->description : std::string("plant from --k0 --a1 --a2");
    axis.gt.plant = plant.plant;
    axis.gt.modelUnitsPerPositionUnit = unit;
    if (!pidMethod) {
        // The Guillemin-Truxal design given, as its PI in mm units with the model's feedforward.
        const DesignInput design = parseDesign(args);
        axis.gt.omegaNRadPerSec = design.wn;
        axis.gt.kp = design.kp;
        return namingOption([&] { return withModelFeedforward(axis, 0); });
    }
    // Defaults: the preset's PI (Braga et al.) or the method's, and the plant's own inverse as
    // FF1..FF3 (the method's defaults are the lower base's).
    if (plant.preset) {
        axis.gt.omegaNRadPerSec = plant.preset->omegaNRadPerSec;
        axis.gt.kp = plant.preset->kp;
        axis = namingOption([&] { return withModelFeedforward(axis, 0); });
    } else {
        axis.method = DesignMethod::PidFeedforward;
        const ModelFeedforwardGains ff = namingOption([&] {
            try {
                return modelFeedforwardGains(axis.gt.plant, unit);
            } catch (const InvalidInput& e) {
                throw InvalidInput(e.field() == "model_unit_scale" ? "gt.model_unit_scale"
                                                                   : "gt.plant." + e.field(),
                                   e.reason());
            }
        });
        axis.parameters["ff1"] = ff.ff1;
        axis.parameters["ff2"] = ff.ff2;
        axis.parameters["ff3"] = ff.ff3;
    }
    for (const QString& name : kPidGainOptions)
        if (args.has(name))
            axis.parameters[parameterName(name)] = args.number(name);
    axis.parameters["derivative_on_measurement"] = args.flag("derivative-on-measurement") ? 1 : 0;
    axis.parameters["command_derivatives"] = args.flag("trajectory-derivatives") ? 1 : 0;
    if (args.flag("ff-from-model"))
        axis = namingOption([&] { return withModelFeedforward(axis, 0); });
    return axis;
}

QString derivativeSourceName(CommandDerivativeSource source) {
    return source == CommandDerivativeSource::TrajectoryGenerator ? "trajectory"
                                                                  : "backward-differences";
}

QJsonObject gainsJson(const PidFeedforwardDesign& d) {
    const ServoPidGains& g = d.gains;
    return {{"p", number(g.p)},
            {"i", number(g.i)},
            {"d", number(g.d)},
            {"ff0", number(g.ff0)},
            {"ff1", number(g.ff1)},
            {"ff2", number(g.ff2)},
            {"ff3", number(g.ff3)},
            {"bias", number(g.bias)},
            {"deadband", number(g.deadband)},
            {"max_error_i", number(g.maxErrorI)},
            {"max_output", number(g.maxOutput)},
            {"derivative_filter", number(g.derivativeFilterSeconds)},
            {"derivative_on_measurement", g.derivativeOnMeasurement},
            {"command_derivatives", derivativeSourceName(d.derivativeSource)}};
}

QJsonObject durationJson(const RunDuration& d) {
    return {{"automatic", d.automatic},
            {"includes_settle", d.includesSettle},
            {"settle_estimate", d.includesSettle ? number(d.settleEstimateSeconds) : QJsonValue()},
            {"cap", number(d.capSeconds)},
            {"capped", d.capped},
            {"description", QString::fromStdString(d.description)}};
}

QJsonObject digitalJson(const Session& session, const DigitalEvaluation& d) {
    QJsonValue limitCycle;
    if (d.limitCycle)
        limitCycle =
            QJsonObject{{"peak_to_peak", d.limitCycle->peakToPeak}, {"turns", d.limitCycle->turns}};
    return {{"controller_ts", number(d.tsSeconds)},
            {"delay_samples", session.implementation.delaySamples},
            {"encoder_resolution", session.implementation.encoderResolutionMm},
            {"dac_bits", session.implementation.dacBits},
            {"samples", static_cast<qint64>(d.run.result.t.size())},
            {"tracking", trackingJson(d.metrics)},
            {"move_and_settle",
             d.moveSettle ? QJsonValue(moveSettleJson(*d.moveSettle)) : QJsonValue()},
            {"poles", complexPairs(d.poles)},
            {"min_damping", number(d.minDamping)},
            {"design_min_damping", number(d.designMinDamping)},
            {"limit_cycle", limitCycle}};
}

/// The loop's margins, or null when the evaluation has none.
QJsonValue marginsValue(const AxisEvaluation& a) {
    const std::optional<LoopTransferFunctions> loop = axisLoop(a);
    if (!a.margins || !loop)
        return {};
    try {
        return marginsJson(*a.margins, nyquistCurve(loop->openLoop));
    } catch (const InvalidInput&) {
        return {}; // the evaluation's warnings say why the loop has no margins
    }
}

} // namespace

bool simulatesThroughSession(const CliArgs& args) {
    const QString method = args.text("method", kGtMethod);
    if (method != kGtMethod && method != kPidMethod)
        throw InvalidInput("--method", "must be guillemin-truxal or pid-ff, got '" +
                                           method.toStdString() +
                                           "' (pole placement and ZPETC: zpetc)");
    return method == kPidMethod || args.flag("ff-from-model");
}

int simulateThroughSession(const CliArgs& args) {
    const bool pidMethod = args.text("method", kGtMethod) == kPidMethod;
    refuseOutsideSession(args, pidMethod);
    QStringList allowed = kPlantOptions + kTrajectoryOptions + kImplementationOptions;
    allowed << kUnitOption << "in-position-window"
            << "method"
            << "ff-from-model";
    allowed += pidMethod ? kPidGainOptions + kPidFlags : QStringList{"wn", "kp"};
    allowed += kFrictionOptions;
    args.allowOnly(allowed);

    const PlantInput plant = parsePlant(args);
    // The trajectory, step, limit and duration as simulate checks them for every design.
    const SimulationSetup setup = parseSimulationSetup(args, plant);
    const double unit = setup.options.modelUnitsPerPositionUnit;

    Session session = Session::paperDefault();
    session.axes[0] = pidAxis(args, plant, unit, pidMethod);
    session.axes[0].friction = parseFriction(args);
    session.axes[0].frictionCompensation = parseFrictionCompensation(args);
    session.axes[1] = session.axes[0];
    session.axes[1].id = "y";
    TrajectorySettings& t = session.trajectory;
    t.kind = TrajectoryKind::Cubic;
    t.profile =
        setup.trajectory.description == "quintic" ? MoveProfile::Quintic : MoveProfile::Cubic;
    t.x0 = args.number("x0", 0.0);
    t.xf = args.number("xf");
    t.t0Seconds = args.number("t0", 0.0);
    t.tfSeconds = args.number("tf");
    t.v0 = args.number("v0", 0.0);
    t.vf = args.number("vf", 0.0);
    t.dtSeconds = setup.options.dtSeconds;
    t.durationSeconds = args.has("duration") ? setup.durationSeconds : 0.0; // 0: automatic
    session.umaxVolts = setup.options.umaxVolts;
    session.controllerTsSeconds = positiveNumber(args, "controller-ts", 0.01);
    const SampledDataOptions sampled = parseSampledDataOptions(args, session.umaxVolts);
    session.implementation.delaySamples = sampled.delaySamples;
    session.implementation.encoderResolutionMm = sampled.encoderResolution;
    session.implementation.dacBits = sampled.dacBits;
    session.spec.inPositionWindowMm =
        positiveNumber(args, "in-position-window", Specification{}.inPositionWindowMm);

    const AxisEvaluation a = evaluateAxis(session, 0);
    if (!a.ok) {
        const std::string option = optionOfSessionField(a.errorField);
        const QString name = QString::fromStdString(option).mid(2);
        // A gain not given is the plant's default (the preset's PI, the model's inverse): its
        // refusal is the plant's (a negative --k0 gives a negative I and FF1..FF3).
        if (a.errorField.find(".parameters.") != std::string::npos &&
            kPidGainOptions.contains(name) && !args.has(name))
            throw InvalidInput(plantOption(args), "gives " + option + " a default out of range (" +
                                                      a.error.text + "): give " + option);
        throw InvalidInput(option, a.error);
    }
    if (args.flag("digital") && !a.digital) {
        std::string why = "the digital run was not made";
        for (const std::string& w : a.warnings)
            if (w.rfind("no digital implementation", 0) == 0)
                why = w;
        throw InvalidInput(args.has("controller-ts") ? "--controller-ts" : "--digital", why);
    }
    const PidFeedforwardDesign& design = pidFeedforwardDesign(a);
    if (const auto csv = args.value("csv"))
        writeCsv(*csv, a.run, args.flag("digital") ? &a.digital->run.result : nullptr);

    QJsonArray warnings;
    for (const std::string& w : a.warnings)
        warnings.append(QString::fromStdString(w));
    QJsonObject out{{"method", kPidMethod},
                    {"converted_from", pidMethod ? QJsonValue() : QJsonValue(kGtMethod)},
                    {"feedforward_from_model", args.flag("ff-from-model")},
                    {"plant", plantJson(plant.plant)},
                    {"gains", gainsJson(design)},
                    {"model_feedforward", QJsonObject{{"ff1", number(design.model.ff1)},
                                                      {"ff2", number(design.model.ff2)},
                                                      {"ff3", number(design.model.ff3)}}},
                    {"controller", continuousTf(design.controller)},
                    {"continuous_derivative_filter", number(design.continuousFilterSeconds)},
                    {"closed_loop", QJsonObject{{"poles", complexPairs(design.closedLoopPoles)},
                                                {"stable", design.stable}}},
                    {"trajectory", setup.trajectory.description},
                    {"duration", number(a.duration.seconds)},
                    {"dt", number(t.dtSeconds)},
                    {"umax", number(session.umaxVolts)},
                    {"model_unit_scale", number(unit)},
                    {"samples", static_cast<qint64>(a.run.t.size())},
                    {"duration_choice", durationJson(a.duration)},
                    {"tracking", trackingJson(a.metrics)},
                    {"tracking_without_feedforward_rmse", number(a.rmseWithoutFf)},
                    {"improvement_pct", number(a.improvementPct)},
                    {"step_response", stepResponseJson(a.step)},
                    {"move_and_settle",
                     a.moveSettle ? QJsonValue(moveSettleJson(*a.moveSettle)) : QJsonValue()},
                    {"margins", marginsValue(a)},
                    {"warnings", warnings}};
    const AxisSettings& axis = session.axes[0];
    if (axis.friction.active() || axis.frictionCompensation.percent != 0.0) {
        out.insert("friction", frictionJson(axis.friction, axis.frictionCompensation));
        out.insert("stick_slip", stickSlipJson(a.run));
    }
    if (!pidMethod) {
        const GtDesign gt = sessionGtDesign(session.axes[0].gt, 0);
        out.insert("guillemin_truxal", QJsonObject{{"wn", number(gt.omegaNRadPerSec)},
                                                   {"kp", number(gt.kp)},
                                                   {"ki", number(gt.ki)}});
    }
    if (args.flag("digital"))
        out.insert("digital", digitalJson(session, *a.digital));
    print(out);
    return 0;
}

namespace {

/// Runs @p f, re-throwing a refusal of the tuning core as tune's option ("phase_margin" ->
/// --phase-margin, "relay_amplitude" -> --relay).
template <class F> auto asTuneOption(F&& f) {
    try {
        return f();
    } catch (const InvalidInput& e) {
        if (e.field() == "relay_amplitude")
            throw InvalidInput("--relay", e.reason());
        throw InvalidInput(CliArgs::field(QString::fromStdString(e.field()).replace('_', '-')),
                           e.reason());
    }
}

PidStructure parseStructure(const CliArgs& args) {
    const QString s = args.text("structure", "pid");
    if (s == "pi")
        return PidStructure::Pi;
    if (s == "pid")
        return PidStructure::Pid;
    throw InvalidInput("--structure", "must be pi or pid, got '" + s.toStdString() + "'");
}

QString structureName(PidStructure s) {
    return s == PidStructure::Pi ? "pi" : "pid";
}

QJsonArray textArray(const std::vector<Diagnostic>& lines) {
    QJsonArray out;
    for (const std::string& line : lines)
        out.append(QString::fromStdString(line));
    return out;
}

QJsonObject ruleJson(const UltimateCycleGains& g) {
    return {{"p", number(g.p)},
            {"i", number(g.i)},
            {"d", number(g.d)},
            {"ti", number(g.tiSeconds)},
            {"td", number(g.tdSeconds)}};
}

QJsonObject marginTuningJson(const CliArgs& args, const ThirdOrderPlant& plant, double unit,
                             PidStructure structure) {
    const double crossover = args.number("crossover");
    const double phaseMargin = args.number("phase-margin");
    const PidTuningResult r = asTuneOption(
        [&] { return tunePidForMargin(plant, unit, structure, crossover, phaseMargin); });
    return {{"target", QJsonObject{{"crossover", crossover}, {"phase_margin", phaseMargin}}},
            {"status", r.ok() ? "ok" : "unreachable"},
            {"reason", QString::fromStdString(r.reason)},
            {"gains", r.ok() ? QJsonValue(QJsonObject{{"p", number(r.p)},
                                                      {"i", number(r.i)},
                                                      {"d", number(r.d)},
                                                      {"ti", number(r.tiSeconds)},
                                                      {"td", number(r.tdSeconds)}})
                             : QJsonValue()},
            {"achieved", QJsonObject{{"crossover", number(r.achievedCrossoverRadPerSec)},
                                     {"phase_margin", number(r.achievedPhaseMarginDeg)}}},
            {"plant_phase", number(r.plantPhaseDeg)},
            {"required_controller_phase", number(r.requiredControllerPhaseDeg)},
            {"required_controller_gain", number(r.requiredControllerGainVoltsPerMm)},
            {"gain_crossover_count", r.gainCrossoverCount},
            {"closed_loop_stable", r.ok() ? QJsonValue(r.closedLoopStable) : QJsonValue()},
            {"warnings", textArray(r.warnings)}};
}

QJsonObject relayTuningJson(const CliArgs& args, const ThirdOrderPlant& plant, double unit,
                            PidStructure structure) {
    const double amplitude = args.number("relay");
    const RelayLimitCycle cycle =
        asTuneOption([&] { return relayLimitCycle(plant, unit, amplitude); });
    const RelayDescribingFunction df =
        asTuneOption([&] { return relayDescribingFunction(plant, unit, amplitude); });
    const auto rule = [&](UltimateCycleRule r) {
        return cycle.found ? QJsonValue(ruleJson(ultimateCycleGains(
                                 cycle.ultimateGainVoltsPerMm, cycle.periodSeconds, r, structure)))
                           : QJsonValue();
    };
    return {
        {"relay", QJsonObject{{"amplitude", amplitude},
                              {"found", cycle.found},
                              {"status", QString::fromStdString(cycle.status)},
                              {"period", number(cycle.periodSeconds)},
                              {"frequency", number(cycle.frequencyRadPerSec)},
                              {"limit_cycle_amplitude", number(cycle.amplitudeMm)},
                              {"ultimate_gain", number(cycle.ultimateGainVoltsPerMm)}}},
        {"describing_function", QJsonObject{{"omega180", number(df.omega180RadPerSec)},
                                            {"period", number(df.periodSeconds)},
                                            {"amplitude", number(df.amplitudeMm)},
                                            {"ultimate_gain", number(df.ultimateGainVoltsPerMm)}}},
        {"ziegler_nichols", rule(UltimateCycleRule::ZieglerNichols)},
        {"tyreus_luyben", rule(UltimateCycleRule::TyreusLuyben)}};
}

} // namespace

int runTune(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kPlantOptions +
                   QStringList{kUnitOption, "crossover", "phase-margin", "structure", "relay"});
    if (!args.positional().isEmpty())
        throw InvalidInput(args.positional().first().toStdString(), "unexpected argument");
    if (args.has("crossover") && args.has("relay"))
        throw InvalidInput("--relay", "and --crossover are exclusive: tune to a target crossover "
                                      "and phase margin, or from a relay experiment");
    if (!args.has("crossover") && !args.has("relay"))
        throw InvalidInput("--crossover",
                           "is required (with --phase-margin), or --relay AMPLITUDE for the relay "
                           "experiment");
    if (args.has("relay") && args.has("phase-margin"))
        throw InvalidInput("--phase-margin", "applies to --crossover, not to --relay");
    const PlantInput plant = parsePlant(args);
    const double unit = positiveNumber(args, kUnitOption, plant.modelUnitsPerPositionUnit);
    const PidStructure structure = parseStructure(args);
    QJsonObject out = args.has("relay") ? relayTuningJson(args, plant.plant, unit, structure)
                                        : marginTuningJson(args, plant.plant, unit, structure);
    out.insert("plant", plantJson(plant.plant));
    out.insert("model_unit_scale", number(unit));
    out.insert("structure", structureName(structure));
    print(out);
    return 0;
}

} // namespace xyt::cli
