// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli pp | zpetc | contour: discrete pole placement and ZPETC of Patrick, Ishak and Adnan.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_cross_coupling.h"
#include "app/cli_gcode_contour.h"
#include "app/cli_json.h"

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"
#include "core/simulation/zpetc_tracking.h"

#include <QJsonArray>

#include <cmath>
#include <numbers>

namespace xyt::cli {

namespace {

const QStringList kPpOptions = {"preset", "a", "b", "t", "ts"};
const QStringList kZpetcOptions = {"margin", "start", "duration", "frequency-points"};
const QStringList kSineOptions = {"amplitude", "omega", "phase-deg"};

/// Runs @p body, turning a core InvalidInput about a design input ("a", "ts", ...) into one
/// about the CLI argument ("--a", "--ts") so the message names what the user typed.
template <class F> auto namingArguments(F body) {
    try {
        return body();
    } catch (const InvalidInput& e) {
        for (const char* name : {"a", "b", "t", "ts", "margin"})
            if (e.field() == name)
                throw InvalidInput(std::string("--") + name, e.reason());
        throw;
    }
}

Polynomial coefficients(const CliArgs& args, const QString& name) {
    const std::string field = CliArgs::field(name);
    return Polynomial::fromAscending(parseCoefficientList(args.value(name)->toStdString(), field),
                                     field);
}

/// The axis model from --preset and/or --a --b --t --ts (explicit values override the preset's).
PolePlacementDesign parseDesign(const CliArgs& args) {
    std::optional<PolePlacementPreset> preset;
    if (const auto name = args.value("preset")) {
        preset = findPolePlacementPreset(name->toStdString());
        if (!preset)
            throw InvalidInput("--preset",
                               "unknown preset '" + name->toStdString() + "' (x-axis or y-axis)");
    } else {
        for (const char* name : {"a", "b", "t"})
            if (!args.has(name))
                throw InvalidInput(std::string("--") + name, "is required without --preset");
    }
    const Polynomial a = args.has("a") ? coefficients(args, "a") : preset->a;
    const Polynomial b = args.has("b") ? coefficients(args, "b") : preset->b;
    const Polynomial t = args.has("t") ? coefficients(args, "t") : preset->t;
    const double ts = args.number("ts", preset ? preset->tsSeconds : 0.07);
    return namingArguments([&] { return designPolePlacement(a, b, t, ts); });
}

QJsonArray strings(const std::vector<Diagnostic>& v) {
    QJsonArray a;
    for (const auto& s : v)
        a.append(QString::fromStdString(s));
    return a;
}

QJsonObject designJson(const PolePlacementDesign& d) {
    return {{"A", ascending(d.a)},
            {"B", ascending(d.b)},
            {"T", ascending(d.t)},
            {"ts", number(d.tsSeconds)},
            {"delay", d.delay},
            {"F", ascending(d.f)},
            {"G", ascending(d.g)},
            {"Kf", number(d.kf)},
            {"residual", number(d.residual)},
            {"sylvester_condition", number(d.conditionNumber)},
            {"closed_loop",
             QJsonObject{{"num", ascending(d.closedLoopNum)}, {"den", ascending(d.closedLoopDen)}}},
            {"plant_poles", complexPairs(d.plantPoles)},
            {"plant_zeros", complexPairs(d.plantZeros)},
            {"warnings", strings(d.warnings)}};
}

double parseMargin(const CliArgs& args) {
    return args.number("margin", kDefaultZpetcMargin);
}

StartCondition parseStart(const CliArgs& args) {
    const QString s = args.text("start", "reference");
    if (s == "reference")
        return StartCondition::AtReference;
    if (s == "origin")
        return StartCondition::AtOrigin;
    throw InvalidInput("--start", "must be reference or origin, got '" + s.toStdString() + "'");
}

/// The argument to blame when the run would need too many samples or hold a single one:
/// --duration when typed, else --omega, whose period set the duration.
std::string durationField(const CliArgs& args) {
    return args.has("duration") ? "--duration" : "--omega";
}

/// Runs a tracking run, naming the argument the user typed for a refusal about the run's
/// length ("duration") or its reference ("amplitude", "omega"; contour: @p amplitudeArgument).
template <class F>
auto namingRunArguments(const CliArgs& args, const std::string& amplitudeArgument, F run) {
    try {
        return run();
    } catch (const InvalidInput& e) {
        if (e.field() == "duration")
            throw InvalidInput(durationField(args), e.reason());
        if (e.field() == "amplitude")
            throw InvalidInput(amplitudeArgument, e.reason());
        if (e.field() == "omega")
            throw InvalidInput("--omega", e.reason());
        throw;
    }
}

double parseDuration(const CliArgs& args, double omega) {
    const double duration = args.number("duration", 2.0 * std::numbers::pi / std::abs(omega));
    if (!(duration > 0.0))
        throw InvalidInput("--duration", "must be greater than zero");
    return duration;
}

double parseOmega(const CliArgs& args, double fallback) {
    const double omega = args.number("omega", fallback);
    if (omega == 0.0)
        throw InvalidInput("--omega", "must be nonzero");
    return omega;
}

QJsonObject zpetcJson(const ZpetcDesign& z) {
    QJsonArray zeros, nmp;
    for (const auto& zero : z.zeros) {
        zeros.append(QJsonObject{{"re", number(zero.z.real())},
                                 {"im", number(zero.z.imag())},
                                 {"cancelled", zero.cancelled}});
        if (!zero.cancelled)
            nmp.append(QJsonArray{number(zero.z.real()), number(zero.z.imag())});
    }
    return {{"zeros", zeros},
            {"nmp_zeros", nmp},
            {"margin", number(z.margin)},
            {"b_plus", ascending(z.bPlus)},
            {"b_minus", ascending(z.bMinus)},
            {"preview_steps", z.previewSteps},
            {"feedforward", QJsonObject{{"num", ascending(z.feedforwardNum)},
                                        {"den", ascending(z.feedforwardDen)},
                                        {"input", "r(k + preview_steps)"}}},
            {"overall_fir", ascending(z.overallFir)},
            {"gain_factor", number(z.gainFactor)}};
}

QJsonObject trackingJson(const ZpetcTrackingRun& run) {
    return {{"rmse_without_ff", number(run.rmseWithoutFf)},
            {"rmse_with_ff", number(run.rmseWithFf)},
            {"improvement_pct", number(run.improvementPct)},
            {"max_abs_error_without_ff", number(run.maxAbsErrorWithoutFf)},
            {"max_abs_error_with_ff", number(run.maxAbsErrorWithFf)},
            {"samples", static_cast<qint64>(run.t.size())}};
}

QJsonObject frequencyJson(const ZpetcFrequencyResponse& f) {
    return {{"omega", numbers(f.omegaRadPerSec)},
            {"gain_without_ff", numbers(f.gainWithoutFf)},
            {"gain_with_ff", numbers(f.gainWithFf)},
            {"phase_without_ff_rad", numbers(f.phaseWithoutFfRad)},
            {"phase_with_ff_rad", numbers(f.phaseWithFfRad)},
            {"omitted_omega", numbers(f.omittedOmegaRadPerSec)}};
}

QString startName(StartCondition s) {
    return s == StartCondition::AtReference ? "reference" : "origin";
}

QJsonObject contourJson(const ContourError& e) {
    return {{"max", number(e.maxAbs)}, {"rms", number(e.rms)}};
}

} // namespace

int runPp(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kPpOptions);
    print(designJson(parseDesign(args)));
    return 0;
}

int runZpetc(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv);
    args.allowOnly(kPpOptions + kZpetcOptions + kSineOptions);
    const PolePlacementDesign loop = parseDesign(args);
    const ZpetcDesign z = namingArguments([&] { return designZpetc(loop, parseMargin(args)); });
    Sinusoid reference;
    reference.amplitude = args.number("amplitude", 30.0);
    requirePosition(reference.amplitude, "--amplitude");
    reference.omegaRadPerSec = parseOmega(args, 0.1);
    reference.phaseRad = args.number("phase-deg", 0.0) * std::numbers::pi / 180.0;
    const double duration = parseDuration(args, reference.omegaRadPerSec);
    const StartCondition start = parseStart(args);
    const ZpetcTrackingRun run = namingArguments([&] {
        return namingRunArguments(args, "--amplitude", [&] {
            return runZpetcTracking(loop, z, reference, duration, start);
        });
    });
    QJsonObject out = designJson(loop);
    const QJsonObject zpetcKeys = zpetcJson(z);
    for (auto it = zpetcKeys.begin(); it != zpetcKeys.end(); ++it)
        out.insert(it.key(), it.value());
    out.insert("start", startName(start));
    out.insert("duration", number(duration));
    out.insert("metrics", trackingJson(run));
    if (args.has("frequency-points")) {
        const int points = args.count("frequency-points", 50, 100000);
        out.insert("frequency_response",
                   frequencyJson(zpetcFrequencyResponse(
                       loop, z, nyquistLogGrid(loop.tsSeconds, std::max(points, 2)))));
    }
    print(out);
    return 0;
}

int runContour(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, {"ccc-sweep"}); // the one flag (--gcode only)
    if (args.has("gcode"))
        return runGcodeContour(args);
    args.allowOnly(QStringList{"preset", "radius", "omega", "duration", "start", "margin"} +
                   kCrossCouplingOptions);
    const CrossCoupling coupling = parseCrossCoupling(args);
    const QString preset = args.text("preset", "paper-zpetc");
    if (preset != "paper-zpetc")
        throw InvalidInput("--preset",
                           "unknown preset pair '" + preset.toStdString() + "' (paper-zpetc)");
    Circle circle;
    circle.radius = args.number("radius", 30.0);
    if (!(circle.radius > 0.0))
        throw InvalidInput("--radius", "must be greater than zero");
    requirePosition(circle.radius, "--radius");
    circle.omegaRadPerSec = parseOmega(args, 0.1);
    const double duration = parseDuration(args, circle.omegaRadPerSec);
    const StartCondition start = parseStart(args);
    const double margin = parseMargin(args);
    const auto design = [&](const char* name) {
        const PolePlacementPreset p = *findPolePlacementPreset(name);
        return designPolePlacement(p.a, p.b, p.t, p.tsSeconds);
    };
    const PolePlacementDesign xLoop = design("x-axis");
    const PolePlacementDesign yLoop = design("y-axis");
    const ZpetcDesign xZ = namingArguments([&] { return designZpetc(xLoop, margin); });
    const ZpetcDesign yZ = namingArguments([&] { return designZpetc(yLoop, margin); });
    const ZpetcCircleRun run = namingRunArguments(args, "--radius", [&] {
        return runZpetcCircle(xLoop, xZ, yLoop, yZ, circle, duration, start);
    });
    // The cross-coupled run: the session's two pole-placement axes (these presets, ZPETC with
    // its default margin) on the circle, coupled and independent, both from rest at r(0).
    QJsonValue couplingJson;
    if (coupling.active()) {
        if (args.has("margin"))
            throw InvalidInput("--margin", "cannot go with --ccc-kp/--ccc-ki: the coupled run "
                                           "uses the session's ZPETC (its default margin)");
        if (start != StartCondition::AtReference)
            throw InvalidInput("--start", "must be reference with --ccc-kp/--ccc-ki: the coupled "
                                          "run starts at rest at the reference");
        Session session = Session::paperDefault();
        for (int i = 0; i < 2; ++i) {
            const PolePlacementPreset p = *findPolePlacementPreset(i == 0 ? "x-axis" : "y-axis");
            AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
            axis.method = DesignMethod::PolePlacementZpetc;
            axis.pp.a = p.a.ascending();
            axis.pp.b = p.b.ascending();
            axis.pp.t1 = p.t.coefficient(1);
            axis.pp.tsSeconds = p.tsSeconds;
        }
        session.trajectory.kind = TrajectoryKind::Circle;
        session.trajectory.radius = circle.radius;
        session.trajectory.omegaRadPerSec = circle.omegaRadPerSec;
        session.trajectory.rampInSeconds = 0.0;
        session.trajectory.durationSeconds = duration;
        session.crossCoupling = coupling;
        const SessionEvaluation evaluation = evaluateSession(session);
        if (!evaluation.couplingError.text.empty())
            throw InvalidInput("--ccc-kp", evaluation.couplingError);
        if (!evaluation.coupledTrajectory)
            throw InvalidInput(
                "--ccc-kp", "the coupled run could not be made: " + evaluation.axes[0].error.text +
                                evaluation.axes[1].error.text);
        couplingJson = trajectoryCouplingJson(session, *evaluation.coupledTrajectory);
    }
    print({{"preset", preset},
           {"radius", number(circle.radius)},
           {"omega", number(circle.omegaRadPerSec)},
           {"duration", number(duration)},
           {"start", startName(start)},
           {"x_axis",
            QJsonObject{{"metrics", trackingJson(run.x)}, {"preview_steps", xZ.previewSteps}}},
           {"y_axis",
            QJsonObject{{"metrics", trackingJson(run.y)}, {"preview_steps", yZ.previewSteps}}},
           {"contour_error", QJsonObject{{"without_ff", contourJson(run.contourWithoutFf)},
                                         {"with_ff", contourJson(run.contourWithFf)}}},
           {"cross_coupling", couplingJson}});
    return 0;
}

} // namespace xyt::cli
