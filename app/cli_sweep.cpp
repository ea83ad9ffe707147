// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli sweep: the design-space study of Braga et al. (wn x kp grid, feasibility, best
// design).
#include "app/cli_args.h"
#include "app/cli_commands.h"
#include "app/cli_design_args.h"
#include "app/cli_json.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"
#include "core/study/design_sweep.h"
#include "core/study/sweep_diagnosis.h"

#include <QTextStream>

#include <cmath>

namespace xyt::cli {

namespace {

const QStringList kSweepOptions = {"log",
                                   "points",
                                   "criterion",
                                   "threads",
                                   "max-settling",
                                   "max-overshoot",
                                   "max-error",
                                   "max-settle-time",
                                   "in-position-window",
                                   "min-phase-margin",
                                   "min-gain-margin"};

/// "MIN:MAX:N" of --wn or --kp.
SweepAxis parseAxis(const CliArgs& args, const QString& name, bool logarithmic) {
    const std::string field = CliArgs::field(name);
    const auto text = args.value(name);
    if (!text)
        throw InvalidInput(field, "is required (MIN:MAX:N)");
    const QStringList parts = text->split(':');
    if (parts.size() != 3)
        throw InvalidInput(field, "must be MIN:MAX:N, got '" + text->toStdString() + "'");
    SweepAxis axis;
    axis.logarithmic = logarithmic;
    axis.minValue = parseNumber(parts[0].toStdString(), field);
    axis.maxValue = parseNumber(parts[1].toStdString(), field);
    bool ok = false;
    axis.count = parts[2].toInt(&ok);
    if (!ok)
        throw InvalidInput(field, "N must be a whole number, got '" + parts[2].toStdString() + "'");
    if (logarithmic && !(axis.minValue > 0.0 && axis.maxValue > 0.0))
        throw InvalidInput(field, "a logarithmic axis needs MIN and MAX greater than zero");
    axis.validate(field);
    return axis;
}

QJsonObject pointJson(const DesignPoint& p) {
    return {{"wn", number(p.wn)},
            {"kp", number(p.kp)},
            {"ki", number(p.ki)},
            {"stable", p.stable},
            {"feasible", p.feasible},
            {"metrics", metricsJson(p.tracking, p.step)},
            {"move_and_settle", p.move ? QJsonValue(moveSettleJson(*p.move)) : QJsonValue()},
            {"phase_margin", number(p.phaseMarginDeg)},
            {"gain_margin", number(p.gainMarginDb)}};
}

QJsonObject checkJson(const SpecificationCheck& c) {
    return {{"stable", c.stable},
            {"settling_time", c.settlingTime},
            {"overshoot", c.overshoot},
            {"no_saturation", c.noSaturation},
            {"tracking_error", c.trackingError},
            {"settle", c.settleApplies ? QJsonValue(c.settle) : QJsonValue()},
            {"phase_margin", c.marginsApply ? QJsonValue(c.phaseMargin) : QJsonValue()},
            {"gain_margin", c.marginsApply ? QJsonValue(c.gainMargin) : QJsonValue()}};
}

/// One CSV field: the number, or empty when it is not finite or not defined.
QString field(double v, bool defined = true) {
    return defined && std::isfinite(v) ? QString::number(v, 'g', 12) : QString();
}

QString sweepCsv(const DesignSweepResult& r) {
    QString text;
    QTextStream out(&text);
    out << "i_wn,i_kp,wn,kp,ki,stable,feasible,rmse,max_abs_error,max_abs_error_pct,max_abs_u,"
           "saturated,saturated_time,settling_time,overshoot_pct,itae,settle_time,final_error,"
           "final_overshoot_mm,phase_margin,gain_margin\n";
    for (std::size_t i = 0; i < r.wnValues.size(); ++i)
        for (std::size_t j = 0; j < r.kpValues.size(); ++j) {
            const DesignPoint& p = r.at(i, j);
            const TrackingMetrics& m = p.tracking;
            out << i << ',' << j << ',' << field(p.wn) << ',' << field(p.kp) << ',' << field(p.ki)
                << ',' << int(p.stable) << ',' << int(p.feasible) << ',' << field(m.rmse) << ','
                << field(m.maxAbsError) << ',' << field(m.maxAbsErrorPct) << ',' << field(m.maxAbsU)
                << ',' << int(m.saturated) << ',' << field(m.saturatedTimeSeconds) << ','
                << field(p.step.settlingTimeSeconds, p.step.stable) << ','
                << field(p.step.overshootPct, p.step.stable) << ',' << field(m.itae) << ','
                << field(p.move && p.move->settleTimeSeconds ? *p.move->settleTimeSeconds : 0.0,
                         p.move && p.move->settleTimeSeconds)
                << ',' << field(p.move ? p.move->finalErrorMm : 0.0, p.move.has_value()) << ','
                << field(p.move ? p.move->finalOvershootMm : 0.0, p.move.has_value()) << ','
                << field(p.phaseMarginDeg) << ',' << field(p.gainMarginDb) << '\n';
        }
    out.flush();
    return text;
}

} // namespace

int runSweep(const QStringList& argv) {
    const CliArgs args = CliArgs::parse(argv, {"log", "points"});
    args.allowOnly(kPlantOptions + QStringList{"wn", "kp", kUnitOption} + kTrajectoryOptions +
                   kSweepOptions);
    const PlantInput plant = parsePlant(args);
    const bool logarithmic = args.flag("log");
    const SweepAxis wnAxis = parseAxis(args, "wn", logarithmic);
    const SweepAxis kpAxis = parseAxis(args, "kp", logarithmic);
    SimulationSetup setup = parseSimulationSetup(args, plant);

    DesignProblem problem;
    problem.plant = plant.plant;
    problem.modelUnitsPerPositionUnit = setup.options.modelUnitsPerPositionUnit;
    problem.dtSeconds = setup.options.dtSeconds;
    problem.spec.umaxVolts = setup.options.umaxVolts;
    problem.spec.maxSettlingTimeSeconds =
        positiveNumber(args, "max-settling", problem.spec.maxSettlingTimeSeconds);
    problem.spec.maxOvershootPct = args.number("max-overshoot", problem.spec.maxOvershootPct);
    if (problem.spec.maxOvershootPct < 0.0)
        throw InvalidInput("--max-overshoot", "must be zero or more");
    problem.spec.maxErrorPct = positiveNumber(args, "max-error", problem.spec.maxErrorPct);
    problem.spec.maxSettleTimeSeconds =
        positiveNumber(args, "max-settle-time", problem.spec.maxSettleTimeSeconds);
    problem.spec.inPositionWindowMm =
        positiveNumber(args, "in-position-window", problem.spec.inPositionWindowMm);
    problem.spec.minPhaseMarginDeg =
        args.number("min-phase-margin", problem.spec.minPhaseMarginDeg);
    if (!(problem.spec.minPhaseMarginDeg >= 0.0 && problem.spec.minPhaseMarginDeg <= 180.0))
        throw InvalidInput("--min-phase-margin", "must be 0 .. 180 degrees");
    problem.spec.minGainMarginDb = args.number("min-gain-margin", problem.spec.minGainMarginDb);
    if (!(problem.spec.minGainMarginDb >= 0.0))
        throw InvalidInput("--min-gain-margin", "must be zero or more (dB)");
    problem.move = setup.trajectory.move;
    // A move's automatic run covers the settle limit twice over (moveSweepDurationSeconds).
    if (problem.move && !args.has("duration"))
        resampleSetup(
            setup, args,
            moveSweepDurationSeconds(problem.move->endSeconds, problem.spec.maxSettleTimeSeconds));
    problem.reference = setup.reference;

    SweepOptions options;
    const QString criterion = args.text("criterion", "itae");
    const auto parsed = parseCriterion(criterion.toStdString());
    if (!parsed)
        throw InvalidInput("--criterion",
                           "must be itae, max_error, rmse, max_u, settle, phase_margin or "
                           "gain_margin, got '" +
                               criterion.toStdString() + "'");
    options.criterion = *parsed;
    options.threads = args.count("threads", 0, 1024);
    const DesignSweepResult r = [&] {
        try {
            return sweepDesignSpace(problem, wnAxis, kpAxis, options);
        } catch (const InvalidInput& e) { // a grid value the design cannot represent (wn 1e300)
            if (e.field() == "wn" || e.field() == "kp")
                throw InvalidInput("--" + e.field(), e.reason());
            throw;
        }
    }();
    if (const auto csv = args.value("csv"))
        writeTextFile("--csv", *csv, sweepCsv(r));

    QJsonObject out;
    out.insert("plant", plantJson(problem.plant));
    insertSetupJson(out, setup);
    out.insert("criterion", QString::fromStdString(criterionName(r.criterion)));
    out.insert("specification",
               QJsonObject{{"max_settling_time", problem.spec.maxSettlingTimeSeconds},
                           {"max_overshoot_pct", problem.spec.maxOvershootPct},
                           {"umax", problem.spec.umaxVolts},
                           {"max_error_pct", problem.spec.maxErrorPct},
                           {"max_settle_time", problem.spec.maxSettleTimeSeconds},
                           {"in_position_window_mm", problem.spec.inPositionWindowMm},
                           {"min_phase_margin", problem.spec.minPhaseMarginDeg},
                           {"min_gain_margin", problem.spec.minGainMarginDb}});
    out.insert("grid", QJsonObject{{"rows", "wn"},
                                   {"columns", "kp"},
                                   {"log", logarithmic},
                                   {"wn", numbers(r.wnValues)},
                                   {"kp", numbers(r.kpValues)}});
    out.insert("threads", r.threadsUsed);
    out.insert("stable_count", r.stableCount);
    out.insert("feasible_count", r.feasibleCount);
    if (r.bestIndex) {
        const DesignPoint& b = r.points[*r.bestIndex];
        QJsonObject best = pointJson(b);
        best.insert("index", QJsonArray{static_cast<qint64>(*r.bestIndex / r.kpValues.size()),
                                        static_cast<qint64>(*r.bestIndex % r.kpValues.size())});
        best.insert("checks", checkJson(b.check));
        out.insert("best", best);
    } else {
        out.insert("best", QJsonValue());
    }
    if (r.refined) {
        QJsonObject refined = pointJson(r.refined->point);
        refined.insert("checks", checkJson(r.refined->point.check));
        refined.insert("evaluations", r.refined->evaluations);
        refined.insert("improved", r.refined->improved);
        out.insert("refined", refined);
    } else {
        out.insert("refined", QJsonValue());
    }
    // Every point only when asked for: a 100 x 100 grid writes 13 MB of them, and the summary
    // (best, refined, counts, diagnosis) is what a reader of the study wants first.
    if (args.flag("points")) {
        QJsonArray rows;
        for (std::size_t i = 0; i < r.wnValues.size(); ++i) {
            QJsonArray row;
            for (std::size_t j = 0; j < r.kpValues.size(); ++j)
                row.append(pointJson(r.at(i, j)));
            rows.append(row);
        }
        out.insert("points", rows);
    }
    const SweepDiagnosis diagnosis = diagnoseSweep(r, problem.spec);
    QJsonArray warnings;
    for (const auto& w : r.warnings)
        warnings.append(QString::fromStdString(w));
    for (const auto& w : diagnosis.warnings)
        warnings.append(QString::fromStdString(w));
    out.insert("warnings", warnings);
    QJsonArray failing;
    for (const CriterionFailure& f : diagnosis.failingEverywhere) {
        QJsonObject o{
            {"criterion", QString::fromStdString(specCriterionName(f.criterion))},
            {"limit", number(f.limit)},
            {"best_value", f.bestIndex ? number(f.bestValue) : QJsonValue()},
            {"best_index", f.bestIndex ? QJsonValue(QJsonArray{
                                             static_cast<qint64>(*f.bestIndex / r.kpValues.size()),
                                             static_cast<qint64>(*f.bestIndex % r.kpValues.size())})
                                       : QJsonValue()}};
        if (f.bestIndex) {
            o.insert("wn", number(r.points[*f.bestIndex].wn));
            o.insert("kp", number(r.points[*f.bestIndex].kp));
        }
        failing.append(o);
    }
    QJsonObject relaxed;
    if (diagnosis.relaxed)
        relaxed = {{"max_settling_time", diagnosis.relaxed->maxSettlingTimeSeconds},
                   {"max_overshoot_pct", diagnosis.relaxed->maxOvershootPct},
                   {"max_error_pct", diagnosis.relaxed->maxErrorPct},
                   {"max_settle_time", diagnosis.relaxed->maxSettleTimeSeconds},
                   {"min_phase_margin", diagnosis.relaxed->minPhaseMarginDeg},
                   {"min_gain_margin", diagnosis.relaxed->minGainMarginDb}};
    out.insert(
        "diagnosis",
        QJsonObject{
            {"none_feasible", diagnosis.noneFeasible},
            {"failing_everywhere", failing},
            {"least_violating",
             diagnosis.leastViolating
                 ? QJsonValue(QJsonObject{
                       {"index",
                        QJsonArray{
                            static_cast<qint64>(*diagnosis.leastViolating / r.kpValues.size()),
                            static_cast<qint64>(*diagnosis.leastViolating % r.kpValues.size())}},
                       {"wn", number(r.points[*diagnosis.leastViolating].wn)},
                       {"kp", number(r.points[*diagnosis.leastViolating].kp)},
                       {"violation", number(diagnosis.leastViolation)}})
                 : QJsonValue()},
            {"relaxed_specification", diagnosis.relaxed ? QJsonValue(relaxed) : QJsonValue()},
            {"best_on_edge", diagnosis.onEdge()},
            {"edges", QJsonObject{{"wn_lower", diagnosis.wnAtLowerEdge},
                                  {"wn_upper", diagnosis.wnAtUpperEdge},
                                  {"kp_lower", diagnosis.kpAtLowerEdge},
                                  {"kp_upper", diagnosis.kpAtUpperEdge}}}});
    print(out);
    return 0;
}

} // namespace xyt::cli
