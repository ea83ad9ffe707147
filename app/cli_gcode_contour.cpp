// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli contour --gcode FILE: a G-code program run by both axes, its contour error and,
// for a single full circle, the ISO 230-4 circular test.
#include "app/cli_gcode_contour.h"

#include "app/cli_cross_coupling.h"

#include "app/cli_friction.h"

#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_digital_run.h"
#include "core/session/design_method_module.h"
#include "core/session/session.h"
#include "core/simulation/metrics.h"
#include "core/simulation/trajectory.h"
#include "ui/files/session_file.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace xyt::cli {

const QStringList kGcodeContourOptions = {
    "gcode",         "feed-scale", "max-accel", "max-jerk", "dt",     "rapid-feed",  "corner-angle",
    "corner-window", "method",     "csv",       "ccc-kp",   "ccc-ki", "ccc-estimate"};

namespace {

/// A core option's field ("max_accel") as the argument the user typed ("--max-accel"); the
/// program's own feeds ("feed") as the program file (--gcode).
template <class F> auto namingOptions(const QString& file, F body) {
    try {
        return body();
    } catch (const InvalidInput& e) {
        for (const QString& name : kGcodeContourOptions)
            if (QString(name).replace('-', '_') == QString::fromStdString(e.field()))
                throw InvalidInput(CliArgs::field(name), e.reason());
        if (e.field() == "feed")
            throw InvalidInput("--gcode", file.toStdString() + ": " + e.what());
        throw;
    }
}

GcodeProgram readProgram(const QString& path, const GcodeReadOptions& options) {
    std::string text;
    try {
        text = readRegularFile(fileNameBytes(path), kMaxGcodeBytes);
    } catch (const FileError& e) {
        throw InvalidInput("--gcode", "cannot read " + std::string(e.what()));
    }
    try {
        return readGcode(text, options);
    } catch (const InvalidInput& e) {
        if (e.field() == "rapid_feed") // the option, not the file
            throw InvalidInput("--rapid-feed", e.reason());
        // "--gcode: part.nc: line 12: unknown word G5 at column 4"
        throw InvalidInput("--gcode", path.toStdString() + ": " + e.what());
    }
}

QJsonObject contourJson(const ContourErrorResult& c) {
    QJsonArray corners;
    for (const CornerOvershoot& o : c.corners)
        corners.append(QJsonObject{{"x", number(o.corner.x)},
                                   {"y", number(o.corner.y)},
                                   {"path_position", number(o.pathPosition)},
                                   {"max", o.samples ? number(o.maxAbsError) : QJsonValue()},
                                   {"signed", o.samples ? number(o.signedError) : QJsonValue()},
                                   {"time", o.samples ? number(o.timeSeconds) : QJsonValue()},
                                   {"samples", static_cast<qint64>(o.samples)}});
    const bool any = c.measuredSamples > 0;
    return {{"max", any ? number(c.maxAbs) : QJsonValue()},
            {"rms", any ? number(c.rms) : QJsonValue()},
            {"samples", static_cast<qint64>(c.measuredSamples)},
            {"max_at", any ? QJsonObject{{"time", number(c.maxTimeSeconds)},
                                         {"signed", number(c.maxSignedError)},
                                         {"path_position", number(c.maxPathPosition)},
                                         {"x", number(c.maxPoint.x)},
                                         {"y", number(c.maxPoint.y)}}
                           : QJsonValue()},
            {"corners", corners}};
}

QJsonObject circleFitJson(const CircleFit& f) {
    return {{"x", number(f.centre.x)},
            {"y", number(f.centre.y)},
            {"radius", number(f.radius)},
            {"fit", f.geometric ? "geometric" : "kasa"}};
}

QJsonObject isoJson(const ContourCircularTest& c) {
    const Iso230Circular& iso = c.iso;
    QJsonArray spikes;
    for (const ReversalSpike& s : iso.reversalSpikes)
        spikes.append(QJsonObject{{"angle_deg", number(s.angleDeg)},
                                  {"axis", QString(QChar(s.axis))},
                                  {"height", s.samples >= 3 ? number(s.heightMm) : QJsonValue()},
                                  {"x", number(s.point.x)},
                                  {"y", number(s.point.y)},
                                  {"samples", static_cast<qint64>(s.samples)}});
    return {
        {"nominal", QJsonObject{{"x", number(c.nominal.centre.x)},
                                {"y", number(c.nominal.centre.y)},
                                {"radius", number(c.nominal.radius)}}},
        {"direction", c.clockwise ? "clockwise" : "counter-clockwise"},
        {"least_squares", circleFitJson(iso.leastSquares)},
        {"G", number(iso.circularDeviationG)},
        {"F_max", number(iso.radialDeviationFMax)},
        {"F_min", number(iso.radialDeviationFMin)},
        {"H", iso.hysteresisH ? number(*iso.hysteresisH) : QJsonValue()},
        {"G_bidirectional", iso.bidirectionalG ? number(*iso.bidirectionalG) : QJsonValue()},
        {"G_reverse", c.reverseIso ? number(c.reverseIso->circularDeviationG) : QJsonValue()},
        {"F_max_reverse", c.reverseIso ? number(c.reverseIso->radialDeviationFMax) : QJsonValue()},
        {"F_min_reverse", c.reverseIso ? number(c.reverseIso->radialDeviationFMin) : QJsonValue()},
        {"runs", c.fromProgram ? "program" : "circle alone"},
        {"line", static_cast<qint64>(c.line)},
        {"reverse_line",
         c.reverseLine ? QJsonValue(static_cast<qint64>(c.reverseLine)) : QJsonValue()},
        {"reversal_spikes", spikes},
        {"samples", static_cast<qint64>(iso.samples)},
        {"reverse_samples", static_cast<qint64>(c.reverseX.size())}};
}

QJsonObject axisJson(const AxisSettings& axis, const SimulationResult& run) {
    QJsonObject o{{"label", QString::fromStdString(axis.label)},
                  {"tracking", trackingJson(trackingMetrics(run))}};
    if (axis.friction.active() || axis.frictionCompensation.percent != 0.0) {
        o.insert("friction", frictionJson(axis.friction, axis.frictionCompensation));
        o.insert("stick_slip", stickSlipJson(run));
    }
    o.insert("method", files::methodName(axis.method));
    if (axis.method == DesignMethod::GuilleminTruxal) {
        o.insert("wn", number(axis.gt.omegaNRadPerSec));
        o.insert("kp", number(axis.gt.kp));
    } else if (axis.method == DesignMethod::PolePlacementZpetc) {
        o.insert("ts", number(axis.pp.tsSeconds));
        o.insert("t1", number(axis.pp.t1));
    } else {
        for (const auto& [name, value] : axis.parameters)
            o.insert(QString::fromStdString(name), number(value));
    }
    return o;
}

/// The default session (as `xytune-cli new` writes it and the workbench starts: x the lower
/// base, y the upper base, +-2.5 V) with both axes on --method: Braga et al.'s Guillemin-Truxal
/// PI (wn 2 and 1 rad/s, kp 30) or Patrick, Ishak and Adnan's pole placement + ZPETC (x-axis and
/// y-axis models, T = 1 - 0.2 z^-1, Ts 70 ms).
Session sessionFor(const CliArgs& args) {
    Session session = Session::paperDefault();
    const QString method = args.text("method", "guillemin-truxal");
    const DesignMethodModule* module = findDesignMethodModule(method.toStdString());
    if (!module) {
        std::string names;
        for (const DesignMethodModule* m : designMethodModules())
            names += (names.empty() ? "" : ", ") + std::string(m->id());
        throw InvalidInput("--method",
                           "must be one of " + names + ", got '" + method.toStdString() + "'");
    }
    for (AxisSettings& axis : session.axes)
        axis.method = module->method();
    // The table: --coulomb etc. for both axes, --x.coulomb etc. for one (over the shared value).
    const TableFriction both = parseFriction(args);
    const FrictionCompensation bothCompensation = parseFrictionCompensation(args);
    for (AxisSettings& axis : session.axes) {
        const QString prefix = QString::fromStdString(axis.id) + ".";
        axis.friction = parseFriction(args, prefix, both);
        axis.frictionCompensation = parseFrictionCompensation(args, prefix, bothCompensation);
    }
    session.crossCoupling = parseCrossCoupling(args);
    return session;
}

} // namespace

QJsonValue programCouplingJson(const Session& session, const ContourRun& run,
                               const DigitalContourRun* digital) {
    const CrossCoupling& c = session.crossCoupling;
    if (!c.active())
        return QJsonValue();
    QJsonObject o{
        {"kp", number(c.kp)}, {"ki", number(c.ki)}, {"estimate", contourEstimateName(c.estimate)}};
    if (run.couplingStability)
        o.insert("line_loop", couplingStabilityJson(*run.couplingStability));
    if (run.trace.coupling && run.trace.coupling->estimate.size() == run.contour.error.size()) {
        // How good the estimate was: against the exact distance of each traced point from the
        // path (the contour error, positive left: the estimate is its negative), over the
        // samples the contour error measures.
        double worst = 0.0;
        for (std::size_t k = 0; k < run.contour.error.size(); ++k)
            if (run.contour.measured[k])
                worst = std::max(worst,
                                 std::abs(run.trace.coupling->estimate[k] + run.contour.error[k]));
        o.insert("estimate_error_max", number(worst));
    }
    if (digital) {
        // The axes' digital implementations (what the C export runs) coupled alike.
        o.insert("digital", QJsonObject{{"period", number(digital->periodSeconds)},
                                        {"contour_error", contourJson(digital->contour)}});
    }
    if (run.independent) {
        QJsonObject alone{{"contour_error", contourJson(run.independent->contour)}};
        if (run.independent->iso)
            alone.insert("circular_deviation_g", number(run.independent->iso->circularDeviationG));
        o.insert("independent_axes", alone);
    }
    if (run.feedbackOnly) {
        QJsonObject feedback{{"contour_error", contourJson(run.feedbackOnly->contour)}};
        if (run.feedbackOnly->iso)
            feedback.insert("circular_deviation_g",
                            number(run.feedbackOnly->iso->circularDeviationG));
        o.insert("feedback_only", feedback);
    }
    return o;
}

namespace {

/// t, s, v, the reference and traced points and the contour error, one row per sample.
void writeContourCsv(const QString& path, const ContourRun& run) {
    const FeedProfile& p = run.trace.profile;
    const std::vector<double>& e = run.contour.error;
    for (std::size_t k = 0; k < p.t.size(); ++k)
        if (!std::isfinite(run.trace.x[k]) || !std::isfinite(run.trace.y[k]) ||
            !std::isfinite(e[k]))
            throw InvalidInput("--csv",
                               "the traced path is not finite from t = " + std::to_string(p.t[k]) +
                                   " s (an unstable loop); no CSV was written");
    writeFile("--csv", path, [&](const ByteSink& sink) {
        sink("t,s,v,x_ref,y_ref,x,y,contour_error\n");
        char line[256];
        for (std::size_t k = 0; k < p.t.size(); ++k) {
            const int n = std::snprintf(
                line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", p.t[k],
                p.s[k], p.v[k], p.x[k], p.y[k], run.trace.x[k], run.trace.y[k], e[k]);
            sink(std::string_view(line, static_cast<std::size_t>(n)));
        }
    });
}

} // namespace

int runGcodeContour(const CliArgs& args) {
    args.allowOnly(kGcodeContourOptions + kCrossCouplingOptions + kCouplingSweepOptions +
                   frictionOptions() + frictionOptions("x.") + frictionOptions("y."));
    const std::optional<CouplingSweepGrid> sweepGrid = parseCouplingSweepGrid(args);
    const QString file = *args.value("gcode");
    GcodeReadOptions readOptions;
    readOptions.rapidFeedMmPerMin =
        positiveNumber(args, "rapid-feed", readOptions.rapidFeedMmPerMin);
    ContourRunOptions options;
    options.profile.feedScale = positiveNumber(args, "feed-scale", 1.0);
    options.profile.maxAccelMmPerS2 = positiveNumber(args, "max-accel", 100.0);
    options.profile.maxJerkMmPerS3 = args.number("max-jerk", 0.0);
    options.profile.dtSeconds = positiveNumber(args, "dt", 0.001);
    options.profile.cornerAngleDeg = args.number("corner-angle", options.profile.cornerAngleDeg);
    options.cornerWindowMm = args.number("corner-window", options.cornerWindowMm);
    const Session session = sessionFor(args);
    const GcodeProgram program = readProgram(file, readOptions);
    // Planned once without its samples first, as the run will plan it: what cannot be planned
    // (--max-jerk 1e-200 needs 3.2e67 s over 10 mm) is refused by its option before the axes run.
    namingOptions(file, [&] {
        FeedProfileOptions check = options.profile;
        check.withSamples = false;
        check.maxSamples = std::min(check.maxSamples, sampleLimit());
        return planFeedProfile(program, check);
    });
    const ContourRun run =
        namingOptions(file, [&] { return runProgramContour(session, program, options); });
    if (const auto csv = args.value("csv"))
        writeContourCsv(*csv, run);
    std::optional<DigitalContourRun> digital;
    if (session.crossCoupling.active())
        digital = namingOptions(
            file, [&] { return runDigitalProgramContour(session, program, options); });
    // The coupling's gains swept over the same program and profile (the session's estimate).
    std::optional<CouplingSweepResult> sweep;
    if (sweepGrid)
        sweep = namingOptions(file, [&] {
            return sweepProgramCoupling(session, program, options, *sweepGrid, {},
                                        &run.trace.profile);
        });

    const FeedProfile& p = run.trace.profile;
    QJsonArray warnings;
    for (const std::string& w : run.warnings)
        warnings.append(QString::fromStdString(w));
    QJsonObject out{
        {"gcode", file},
        {"lines", static_cast<qint64>(program.lines)},
        {"segments", static_cast<qint64>(program.path.size())},
        {"length", number(program.path.length())},
        {"profile", QJsonObject{{"duration", number(p.totalTimeSeconds)},
                                {"dt", number(p.dtSeconds)},
                                {"samples", static_cast<qint64>(p.t.size())},
                                {"feed_scale", number(options.profile.feedScale)},
                                {"max_accel", number(options.profile.maxAccelMmPerS2)},
                                {"max_jerk", number(options.profile.maxJerkMmPerS3)},
                                {"corner_angle", number(options.profile.cornerAngleDeg)},
                                {"sharp_corners", static_cast<qint64>(p.corners.size())}}},
        {"umax", number(session.umaxVolts)},
        {"x_axis", axisJson(session.axes[0], run.trace.axes[0])},
        {"y_axis", axisJson(session.axes[1], run.trace.axes[1])},
        {"contour_error", contourJson(run.contour)},
        {"iso230_4", run.circular ? QJsonValue(isoJson(*run.circular)) : QJsonValue()},
        {"cross_coupling", programCouplingJson(session, run, digital ? &*digital : nullptr)},
        {"warnings", warnings}};
    if (sweep)
        out.insert("cross_coupling_sweep", couplingSweepJson(*sweep));
    print(out);
    return 0;
}

} // namespace xyt::cli
