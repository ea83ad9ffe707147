// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli robustness SESSION.json: Monte Carlo and corner analysis of a session's axes under
// plant-model mismatch; with --contour also the XY contour both axes trace together.
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/model/errors.h"
#include "core/session/robustness_problem.h"
#include "core/study/contour_robustness.h"
#include "core/study/robustness.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace xyt::cli {

namespace {

struct Range {
    QString axis; ///< "x", "y" or empty (every analyzed axis that has the parameter)
    QString name;
    double relative = 0.0;
};

/// "k0=10%", "x.b1=0.05" (a fraction), "y.a2=2.5%".
Range parseRange(const QString& text) {
    static const QRegularExpression form(
        QStringLiteral("^(?:([xy])\\.)?([a-z][a-z0-9]*)=([^%]+)(%?)$"));
    const auto m = form.match(text.trimmed());
    if (!m.hasMatch())
        throw InvalidInput("--range",
                           "'" + text.toStdString() +
                               "' is not NAME=PERCENT% or NAME=FRACTION (e.g. k0=10%, x.b1=0.05)");
    bool ok = false;
    const double v = m.captured(3).toDouble(&ok);
    if (!ok || !std::isfinite(v))
        throw InvalidInput("--range", "'" + text.toStdString() + "': the range is not a number");
    return {m.captured(1), m.captured(2), m.captured(4).isEmpty() ? v : v / 100.0};
}

QJsonObject distributionJson(const Distribution& d) {
    return {{"count", d.count},
            {"min", number(d.count ? d.min : NAN)},
            {"p05", number(d.count ? d.p05 : NAN)},
            {"p50", number(d.count ? d.p50 : NAN)},
            {"p95", number(d.count ? d.p95 : NAN)},
            {"max", number(d.count ? d.max : NAN)},
            {"mean", number(d.count ? d.mean : NAN)}};
}

QJsonObject parametersJson(const std::vector<std::string>& names,
                           const std::vector<double>& values) {
    QJsonObject o;
    for (std::size_t i = 0; i < names.size(); ++i)
        o.insert(QString::fromStdString(names[i]), number(values[i]));
    return o;
}

QJsonObject runJson(const RobustnessResult& r, std::size_t i) {
    const PlantRun& p = r.runs[i];
    return {{"index", static_cast<qint64>(i)},
            {"kind", p.corner ? "corner" : "random"},
            {"parameters", parametersJson(r.parameterNames, p.values)},
            {"stable", p.stable},
            {"diverged", !p.finite},
            {"rmse", number(p.tracking.rmse)}};
}

QJsonObject axisJson(const QString& axisId, const RobustnessProblem& problem,
                     const RobustnessResult& r, const RobustnessOptions& o) {
    QJsonArray parameters;
    for (const UncertainParameter& p : problem.parameters)
        parameters.append(QJsonObject{{"name", QString::fromStdString(p.name)},
                                      {"nominal", number(p.nominal)},
                                      {"relative_range", number(p.relative)}});
    QJsonArray unstable;
    for (std::size_t i : r.unstable)
        unstable.append(runJson(r, i));
    QJsonObject statistics{{"rmse", distributionJson(r.rmse)},
                           {"max_abs_error", distributionJson(r.maxAbsError)},
                           {"max_abs_u", distributionJson(r.maxAbsU)},
                           {"phase_margin", distributionJson(r.phaseMarginDeg)},
                           {"gain_margin", distributionJson(r.gainMarginDb)}};
    if (problem.loop && problem.zpetcEnabled)
        statistics.insert("rmse_without_ff", distributionJson(r.rmseWithoutFf));
    QJsonArray warnings;
    for (const std::string& w : r.warnings)
        warnings.append(QString::fromStdString(w));
    return {{"axis", axisId},
            {"method", problem.loop ? "pole-placement-zpetc" : "guillemin-truxal"},
            {"uncertainty", problem.covariance
                                ? "identified covariance (normal draws; corners at 3 sigma)"
                                : "uniform ranges"},
            {"parameters", parameters},
            {"samples", o.samples},
            {"corners", static_cast<qint64>(r.runs.size()) - o.samples},
            {"nominal", QJsonObject{{"rmse", number(r.nominal.tracking.rmse)},
                                    {"max_abs_error", number(r.nominal.tracking.maxAbsError)},
                                    {"max_abs_u", number(r.nominal.tracking.maxAbsU)},
                                    {"meets_spec", r.nominal.meetsSpec}}},
            {"statistics", statistics},
            {"fraction_meeting_spec", number(r.fractionMeetingSpec)},
            {"unstable", unstable},
            {"worst", r.worst ? QJsonValue(runJson(r, *r.worst)) : QJsonValue()},
            {"warnings", warnings}};
}

QJsonObject pairJson(const ContourRobustnessResult& r, std::size_t i) {
    const JointPlantRun& p = r.runs[i];
    return {{"index", static_cast<qint64>(i)},
            {"kind", p.corner ? "corner" : "random"},
            {"parameters", parametersJson(r.parameterNames, p.values)},
            {"stable", p.stable},
            {"diverged", !p.finite},
            {"max_abs_contour_error", number(p.finite ? p.maxAbsContourError : NAN)}};
}

/// The joint XY analysis: the contour error of pairs of mismatched plants.
QJsonObject contourJson(const ContourRobustnessProblem& problem, const ContourRobustnessResult& r) {
    QJsonArray unstable;
    for (std::size_t i : r.unstable)
        unstable.append(pairJson(r, i));
    QJsonArray warnings;
    for (const std::string& w : r.warnings)
        warnings.append(QString::fromStdString(w));
    return {{"contour", problem.geometry.circle ? "circle" : "program"},
            {"pairs", static_cast<qint64>(r.runs.size())},
            {"nominal", QJsonObject{{"max_abs_contour_error", number(r.nominal.maxAbsContourError)},
                                    {"rms_contour_error", number(r.nominal.rmsContourError)}}},
            {"statistics",
             QJsonObject{{"max_abs_contour_error", distributionJson(r.maxAbsContourError)},
                         {"rms_contour_error", distributionJson(r.rmsContourError)}}},
            {"unstable", unstable},
            {"worst", r.worst ? QJsonValue(pairJson(r, *r.worst)) : QJsonValue()},
            {"warnings", warnings}};
}

/// One row per plant of every analyzed axis: axis, index, kind, one column per parameter of
/// every axis ("x.k0", "y.b1"; empty on the other axis' rows), then the figures; with the
/// joint analysis, one row "xy" per pair (both axes' parameters, the contour figures).
QString robustnessCsv(const std::vector<QString>& ids, const std::vector<RobustnessResult>& results,
                      const ContourRobustnessResult* contour) {
    QString csv;
    QTextStream out(&csv);
    out << "axis,index,kind";
    for (std::size_t a = 0; a < results.size(); ++a)
        for (const std::string& n : results[a].parameterNames)
            out << ',' << ids[a] << '.' << QString::fromStdString(n);
    out << ",stable,diverged,rmse,max_abs_error,max_abs_u,rmse_without_ff,meets_spec";
    if (contour)
        out << ",max_abs_contour_error,rms_contour_error";
    out << '\n';
    const auto cell = [](double v) {
        return std::isfinite(v) ? QString::number(v, 'g', 17) : QString();
    };
    for (std::size_t a = 0; a < results.size(); ++a)
        for (std::size_t i = 0; i < results[a].runs.size(); ++i) {
            const PlantRun& p = results[a].runs[i];
            out << ids[a] << ',' << i << ',' << (p.corner ? "corner" : "random");
            for (std::size_t b = 0; b < results.size(); ++b)
                for (std::size_t j = 0; j < results[b].parameterNames.size(); ++j)
                    out << ',' << (b == a ? cell(p.values[j]) : QString());
            out << ',' << (p.stable ? 1 : 0) << ',' << (p.finite ? 0 : 1) << ','
                << cell(p.tracking.rmse) << ',' << cell(p.tracking.maxAbsError) << ','
                << cell(p.tracking.maxAbsU) << ',' << cell(p.rmseWithoutFf) << ','
                << (p.meetsSpec ? 1 : 0) << (contour ? ",," : "") << '\n';
        }
    if (contour)
        for (std::size_t i = 0; i < contour->runs.size(); ++i) {
            const JointPlantRun& p = contour->runs[i];
            out << "xy," << i << ',' << (p.corner ? "corner" : "random");
            for (double v : p.values)
                out << ',' << cell(v);
            out << ',' << (p.stable ? 1 : 0) << ',' << (p.finite ? 0 : 1) << ",,,,,,"
                << cell(p.finite ? p.maxAbsContourError : NAN) << ','
                << cell(p.finite ? p.rmsContourError : NAN) << '\n';
        }
    return csv;
}

} // namespace

int runRobustness(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(
        argv, {"no-corners", "sensitivity", "contour", "from-identification"}, {"range"});
    args.allowOnly({"samples", "seed", "range", "axis", "no-corners", "threads", "csv",
                    "sensitivity", "contour", "from-identification"});
    const bool identified = args.flag("from-identification");
    if (identified && !args.values("range").isEmpty())
        throw InvalidInput("--range", "give either ranges or --from-identification, not both");
    if (args.positional().size() != 1)
        throw InvalidInput("SESSION",
                           "give one session file (xytune-cli robustness SESSION.json ...)");
    const Session session = loadSessionOrThrow(args.positional().first());
    RobustnessOptions o;
    o.samples = args.count("samples", 200, 1'000'000);
    const double seed = args.number("seed", 1.0);
    if (seed < 0.0 || seed > 9007199254740992.0 || seed != std::floor(seed))
        throw InvalidInput("--seed", "must be a whole number from 0 to 2^53");
    o.seed = static_cast<std::uint64_t>(seed);
    o.corners = !args.flag("no-corners");
    o.threads = args.has("threads") ? args.count("threads", 1, 1024) : 0;
    const QString axisChoice = args.text("axis", "both");
    if (axisChoice != "x" && axisChoice != "y" && axisChoice != "both")
        throw InvalidInput("--axis", "must be x, y or both");
    const bool contour = args.flag("contour");
    if (contour && axisChoice != "both")
        throw InvalidInput("--contour", "the contour is traced by both axes: leave out --axis");
    if (contour && session.trajectory.kind == TrajectoryKind::Cubic)
        throw InvalidInput("--contour",
                           "needs a circle or G-code trajectory (the session's is a cubic move)");
    std::vector<Range> ranges;
    for (const QString& text : args.values("range"))
        ranges.push_back(parseRange(text));

    // Every range is applied (and refused, naming it) before anything is computed.
    std::vector<QString> ids;
    std::vector<RobustnessProblem> problems;
    std::vector<bool> used(ranges.size(), false);
    for (int axis = 0; axis < 2; ++axis) {
        if (axisChoice != "both" && axisChoice != (axis == 0 ? "x" : "y"))
            continue;
        ids.push_back(QString::fromStdString(session.axes[static_cast<std::size_t>(axis)].id));
        RobustnessProblem problem = sessionRobustnessProblem(session, axis);
        if (identified)
            setIdentifiedUncertainty(problem, session,
                                     axis); // names axes[i].model_origin when it cannot
        for (std::size_t i = 0; i < ranges.size(); ++i) {
            const Range& range = ranges[i];
            if (!range.axis.isEmpty() && range.axis != (axis == 0 ? "x" : "y"))
                continue;
            const bool has = std::any_of(
                problem.parameters.begin(), problem.parameters.end(),
                [&](const UncertainParameter& p) { return p.name == range.name.toStdString(); });
            if (!has && range.axis.isEmpty())
                continue; // k0=10% applies to the axes that have a k0
            try {
                setRelativeRange(problem.parameters, range.name.toStdString(), range.relative);
            } catch (const InvalidInput& e) {
                throw InvalidInput(
                    "--range", (range.axis.isEmpty() ? QString() : range.axis + ".").toStdString() +
                                   range.name.toStdString() + ": " + e.reason());
            }
            used[i] = true;
        }
        problems.push_back(std::move(problem));
    }
    for (std::size_t i = 0; i < ranges.size(); ++i)
        if (!used[i])
            throw InvalidInput("--range",
                               "no analyzed axis has a parameter '" + ranges[i].name.toStdString() +
                                   "' (Guillemin-Truxal: k0, a1, a2; pole placement: a1.., b1..)");
    QJsonArray axes;
    std::vector<RobustnessResult> results;
    for (std::size_t a = 0; a < problems.size(); ++a) {
        results.push_back(analyzeRobustness(problems[a], o));
        QJsonObject axis = axisJson(ids[a], problems[a], results.back(), o);
        if (args.flag("sensitivity") && problems[a].loop && problems[a].zpetcEnabled) {
            QJsonArray curve;
            for (const ZpetcSensitivityPoint& p :
                 zpetcSensitivity(problems[a], {0.0, 0.25, 0.5, 0.75, 1.0}, o))
                curve.append(QJsonObject{{"scale", p.scale},
                                         {"rmse_with_ff", distributionJson(p.rmseWithFf)},
                                         {"rmse_without_ff", distributionJson(p.rmseWithoutFf)},
                                         {"median_improvement_pct", number(p.medianImprovementPct)},
                                         {"unstable", p.unstable}});
            axis.insert("zpetc_sensitivity", curve);
        }
        axes.append(axis);
    }
    QJsonObject out{{"seed", static_cast<qint64>(o.seed)}, {"axes", axes}};
    std::optional<ContourRobustnessResult> joint;
    if (contour) {
        ContourRobustnessProblem problem = sessionContourRobustnessProblem(session);
        problem.x.parameters = problems[0].parameters; // with the ranges applied above
        problem.y.parameters = problems[1].parameters;
        problem.x.covariance = problems[0].covariance; // (--from-identification)
        problem.y.covariance = problems[1].covariance;
        joint = analyzeContourRobustness(problem, o);
        out.insert("xy", contourJson(problem, *joint));
    }
    if (const auto path = args.value("csv"))
        writeTextFile("--csv", *path, robustnessCsv(ids, results, joint ? &*joint : nullptr));
    print(out);
    return 0;
}

} // namespace xyt::cli
