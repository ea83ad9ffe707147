// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/design_sweep.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/study/parallel_runs.h"

#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/state_space.h"
#include "core/simulation/simulation.h"
#include "core/simulation/tracking_batch.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

namespace xyt {

namespace {

bool stepFiguresFinite(const StepCharacteristics& s) {
    return !s.stable || (std::isfinite(s.finalValue) && std::isfinite(s.settlingTimeSeconds) &&
                         std::isfinite(s.overshootPct) && std::isfinite(s.peakTimeSeconds));
}

} // namespace

std::string criterionName(SweepCriterion criterion) {
    switch (criterion) {
    case SweepCriterion::Itae:
        return "itae";
    case SweepCriterion::MaxError:
        return "max_error";
    case SweepCriterion::Rmse:
        return "rmse";
    case SweepCriterion::MaxU:
        return "max_u";
    case SweepCriterion::Settle:
        return "settle";
    case SweepCriterion::PhaseMargin:
        return "phase_margin";
    case SweepCriterion::GainMargin:
        return "gain_margin";
    }
    return "itae";
}

std::optional<SweepCriterion> parseCriterion(const std::string& name) {
    for (SweepCriterion c : {SweepCriterion::Itae, SweepCriterion::MaxError, SweepCriterion::Rmse,
                             SweepCriterion::MaxU, SweepCriterion::Settle,
                             SweepCriterion::PhaseMargin, SweepCriterion::GainMargin})
        if (criterionName(c) == name)
            return c;
    return std::nullopt;
}

void SweepAxis::validate(const std::string& field) const {
    if (!std::isfinite(minValue) || !std::isfinite(maxValue))
        throw InvalidInput(field, makeDiagnostic("study_bounds_not_finite"));
    if (!(minValue > 0.0))
        throw InvalidInput(field, makeDiagnostic("study_minimum_not_positive"));
    if (minValue > maxValue)
        throw InvalidInput(field, makeDiagnostic("study_minimum_above_maximum"));
    if (count < 1 || count > kMaxCount)
        throw InvalidInput(field, makeDiagnostic("study_count_range", {std::to_string(kMaxCount)}));
}

std::vector<double> SweepAxis::values(const std::string& field) const {
    validate(field);
    std::vector<double> v(static_cast<std::size_t>(count));
    v[0] = minValue;
    if (count == 1)
        return v;
    const double last = count - 1;
    for (int i = 1; i + 1 < count; ++i) {
        const double f = i / last;
        v[static_cast<std::size_t>(i)] = logarithmic ? minValue * std::pow(maxValue / minValue, f)
                                                     : minValue + (maxValue - minValue) * f;
    }
    v.back() = maxValue;
    return v;
}

double criterionValue(const DesignPoint& point, SweepCriterion criterion) {
    if (!point.computed || !point.metricsFinite)
        return kInf;
    switch (criterion) {
    case SweepCriterion::Itae:
        return point.tracking.itae;
    case SweepCriterion::MaxError:
        return point.tracking.maxAbsError;
    case SweepCriterion::Rmse:
        return point.tracking.rmse;
    case SweepCriterion::MaxU:
        return point.tracking.maxAbsU;
    case SweepCriterion::Settle:
        return point.move && point.move->settleTimeSeconds ? *point.move->settleTimeSeconds : kInf;
    case SweepCriterion::PhaseMargin:
        return std::isnan(point.phaseMarginDeg) ? kInf : -point.phaseMarginDeg;
    case SweepCriterion::GainMargin:
        return std::isnan(point.gainMarginDb) ? kInf : -point.gainMarginDb;
    }
    return kInf;
}

bool criterionMaximizes(SweepCriterion criterion) {
    return criterion == SweepCriterion::PhaseMargin || criterion == SweepCriterion::GainMargin;
}

double criterionMetric(const DesignPoint& point, SweepCriterion criterion) {
    const double v = criterionValue(point, criterion);
    if (!criterionMaximizes(criterion))
        return v;
    return v == kInf ? std::numeric_limits<double>::quiet_NaN() : -v;
}

double moveSweepDurationSeconds(double tfSeconds, double maxSettleTimeSeconds) {
    return tfSeconds + 2.0 * maxSettleTimeSeconds;
}

DesignEvaluator::DesignEvaluator(DesignProblem problem) : problem_(std::move(problem)) {
    plantTf_ = problem_.plant.transferFunction(); // validates the plant
    if (problem_.plantFactor)
        plantTf_ = series(plantTf_, *problem_.plantFactor);
    requirePositive(problem_.modelUnitsPerPositionUnit, "model_unit_scale");
    requirePositive(problem_.dtSeconds, "dt");
    problem_.spec.validate();
    if (problem_.reference.empty())
        throw InvalidInput("reference", makeDiagnostic("has_no_samples"));
    for (double r : problem_.reference)
        requireFinite(r, "reference");
    const auto [lo, hi] = std::minmax_element(problem_.reference.begin(), problem_.reference.end());
    travel_ = *hi - *lo;
    if (problem_.stepSamples < 100 || problem_.stepSamples > 100000)
        throw InvalidInput("step_samples", makeDiagnostic("study_from_to", {"100", "100000"}));
    if (problem_.move) // validates the move
        (void)MoveSettleAccumulator(*problem_.move, problem_.spec.inPositionWindowMm);
}

DesignPoint DesignEvaluator::evaluate(double wn, double kp) const {
    DesignPoint p;
    evaluateBatch(std::span<const double>(&wn, 1), std::span<const double>(&kp, 1),
                  std::span<DesignPoint>(&p, 1), 1);
    return p;
}

void DesignEvaluator::evaluateBatch(std::span<const double> wn, std::span<const double> kp,
                                    std::span<DesignPoint> out, int batchWidth) const {
    if (kp.size() != wn.size() || out.size() != wn.size())
        throw InvalidInput("designs", makeDiagnostic("study_designs_same_length"));
    const std::size_t n = wn.size();
    std::vector<GtDesign> designs;
    std::vector<LoopModes> modes;
    designs.reserve(n);
    modes.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        designs.push_back(designGuilleminTruxal(problem_.plant, wn[i], kp[i]));
        if (problem_.plantFactor || problem_.controllerFilter)
            designs.back() =
                withLoopElements(std::move(designs.back()),
                                 problem_.plantFactor.value_or(TransferFunction::gain(1.0)),
                                 problem_.controllerFilter.value_or(TransferFunction::gain(1.0)));
        modes.push_back(loopModes(plantTf_, designs.back().controller));
    }
    std::vector<std::optional<MoveSettleAccumulator>> moves(problem_.move ? n : 0);
    std::vector<MoveSettleAccumulator*> movePointers;
    for (auto& m : moves)
        movePointers.push_back(&m.emplace(*problem_.move, problem_.spec.inPositionWindowMm));
    std::vector<std::optional<TrackingMetrics>> tracking(n);
    TrackingRun run;
    run.reference = &problem_.reference;
    run.dtSeconds = problem_.dtSeconds;
    run.umaxVolts = problem_.spec.umaxVolts;
    run.modelUnitsPerPositionUnit = problem_.modelUnitsPerPositionUnit;
    if (!problem_.feedforwardVolts.empty())
        run.feedforwardVolts = &problem_.feedforwardVolts;
    if (problem_.table && problem_.table->active()) {
        // The nonlinear table: simulateLoop per design, its samples fed to the same figures.
        LoopSimulationOptions o;
        o.dtSeconds = problem_.dtSeconds;
        o.umaxVolts = problem_.spec.umaxVolts;
        o.modelUnitsPerPositionUnit = problem_.modelUnitsPerPositionUnit;
        o.feedforwardVolts = run.feedforwardVolts;
        o.table = &*problem_.table;
        SimulationResult r;
        for (std::size_t i = 0; i < n; ++i) {
            simulateLoopInto(plantTf_, designs[i].controller, problem_.reference, o, r);
            const TrackingMetrics m = trackingMetrics(r);
            if (!m.diverged)
                tracking[i] = m;
            if (!moves.empty() && !m.diverged)
                for (std::size_t k = 0; k < r.t.size(); ++k)
                    movePointers[i]->add(r.t[k], r.y[k], r.e[k]);
        }
    } else {
        trackBatch(modes, run, movePointers, tracking, batchWidth);
    }
    for (std::size_t i = 0; i < n; ++i)
        out[i] = finishPoint(designs[i], tracking[i], moves.empty() ? nullptr : &*moves[i]);
}

DesignPoint DesignEvaluator::finishPoint(const GtDesign& design,
                                         const std::optional<TrackingMetrics>& tracking,
                                         MoveSettleAccumulator* move) const {
    DesignPoint p;
    p.wn = design.omegaNRadPerSec;
    p.kp = design.kp;
    p.ki = design.ki;
    p.stable = design.stable;
    p.step =
        stepCharacteristics(design.closedLoop, design.closedLoopPoles, 0.02, problem_.stepSamples);
    p.metricsFinite = tracking.has_value() && stepFiguresFinite(p.step);
    if (tracking) {
        p.tracking = *tracking;
    } else {
        // Diverged: say so with infinities (JSON null), never with NaN taken for a number.
        p.tracking.rmse = p.tracking.maxAbsError = p.tracking.maxAbsErrorPct = kInf;
        p.tracking.maxAbsU = p.tracking.itae = kInf;
        p.tracking.saturated = true;
        p.tracking.saturatedTimeSeconds = kInf;
    }
    if (move) {
        if (!tracking) // the kernel stopped feeding it at the first non-finite sample
            move->add(kInf, kInf, kInf);
        p.move = move->finish();
        if (p.move->diverged) // never NaN taken for a number (as the tracking figures above)
            p.move->finalErrorMm = p.move->finalOvershootMm = kInf;
    }
    try {
        const StabilityMargins m = stabilityMargins(gtLoopTransferFunctions(design).openLoop);
        p.phaseMarginDeg = m.phaseMarginDeg;
        p.gainMarginDb = m.gainMarginDb;
    } catch (const InvalidInput&) {
        // Left NaN: the margin criteria fail and the map shows no value (L is always proper
        // here; this guards the contract, not a known case).
    }
    p.check = checkSpecification(problem_.spec, p.tracking, p.step, p.move,
                                 LoopMarginFigures{p.phaseMarginDeg, p.gainMarginDb});
    p.computed = true;
    p.feasible = p.metricsFinite && p.check.allPassed();
    return p;
}

RefinementResult refineDesign(const DesignEvaluator& evaluator, const DesignPoint& start,
                              SweepCriterion criterion, double wnMin, double wnMax, double kpMin,
                              double kpMax, double wnStepLog, double kpStepLog, int maxEvaluations,
                              double toleranceLog) {
    if (!start.feasible)
        throw InvalidInput("start", makeDiagnostic("study_search_needs_feasible"));
    if (!(start.wn >= wnMin && start.wn <= wnMax && start.kp >= kpMin && start.kp <= kpMax))
        throw InvalidInput("start", makeDiagnostic("study_outside_search_box"));
    if (!(wnStepLog >= 0.0 && std::isfinite(wnStepLog) && kpStepLog >= 0.0 &&
          std::isfinite(kpStepLog)))
        throw InvalidInput("step", makeDiagnostic("study_steps_not_finite"));
    if (maxEvaluations < 0)
        throw InvalidInput("max_evaluations", makeDiagnostic("not_negative"));
    RefinementResult r;
    r.point = start;
    double best = criterionValue(start, criterion);
    const double startValue = best;
    double du = wnStepLog, dv = kpStepLog;
    // The 8 compass and diagonal directions: the optimum usually lies on the boundary of the
    // feasible set, which is rarely aligned with an axis; diagonals let the search slide along it.
    static constexpr std::array<std::array<int, 2>, 8> kDirections = {
        {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
    while ((du > toleranceLog || dv > toleranceLog) && r.evaluations < maxEvaluations) {
        std::optional<DesignPoint> bestPoll;
        double bestPollValue = best;
        for (const auto& dir : kDirections) {
            if (r.evaluations >= maxEvaluations)
                break;
            const double wn = std::clamp(r.point.wn * std::exp(dir[0] * du), wnMin, wnMax);
            const double kp = std::clamp(r.point.kp * std::exp(dir[1] * dv), kpMin, kpMax);
            if (wn == r.point.wn && kp == r.point.kp)
                continue;
            const DesignPoint candidate = evaluator.evaluate(wn, kp);
            ++r.evaluations;
            const double value = criterionValue(candidate, criterion);
            if (candidate.feasible && value < bestPollValue) {
                bestPollValue = value;
                bestPoll = candidate;
            }
        }
        if (bestPoll) {
            r.point = *bestPoll;
            best = bestPollValue;
        } else {
            du *= 0.5;
            dv *= 0.5;
        }
    }
    r.improved = best < startValue;
    return r;
}

namespace {

/// The grid spacing around index i of an axis, in log units (0 for a single value).
double logSpacing(const std::vector<double>& values, std::size_t i) {
    if (values.size() < 2)
        return 0.0;
    const std::size_t lo = i > 0 ? i - 1 : i;
    const std::size_t hi = i + 1 < values.size() ? i + 1 : i;
    return std::log(values[hi] / values[lo]) / static_cast<double>(hi - lo);
}

} // namespace

void tallyDesignSpace(DesignSweepResult& result) {
    const std::size_t total = result.points.size();
    result.feasibleMask.assign(total, 0);
    result.computedCount = result.feasibleCount = result.stableCount = 0;
    result.bestIndex.reset();
    double bestValue = kInf;
    for (std::size_t i = 0; i < total; ++i) {
        const DesignPoint& p = result.points[i];
        if (!p.computed)
            continue;
        ++result.computedCount;
        result.stableCount += p.stable ? 1 : 0;
        if (!p.feasible)
            continue;
        result.feasibleMask[i] = 1;
        ++result.feasibleCount;
        const double value = criterionValue(p, result.criterion);
        if (!result.bestIndex || value < bestValue) {
            bestValue = value;
            result.bestIndex = i;
        }
    }
}

void rejudgeDesignSpace(DesignSweepResult& result, const Specification& spec) {
    spec.validate();
    for (const DesignPoint& p : result.points)
        if (p.computed && p.move && p.move->windowMm != spec.inPositionWindowMm)
            throw InvalidInput("in_position_window_mm", makeDiagnostic("study_other_window"));
    for (DesignPoint& p : result.points) {
        if (!p.computed)
            continue;
        p.check = checkSpecification(spec, p.tracking, p.step, p.move,
                                     LoopMarginFigures{p.phaseMarginDeg, p.gainMarginDb});
        p.feasible = p.metricsFinite && p.check.allPassed();
    }
    tallyDesignSpace(result);
    result.refined.reset();
}

DesignSweepResult sweepDesignSpace(const DesignProblem& problem, const SweepAxis& wnAxis,
                                   const SweepAxis& kpAxis, const SweepOptions& options) {
    if (options.threads < 0 || options.threads > 1024)
        throw InvalidInput("threads", makeDiagnostic("study_threads_range"));
    if (options.maxRefineEvaluations < 0)
        throw InvalidInput("max_refine_evaluations", makeDiagnostic("not_negative"));
    if (options.batchWidth != 1 && options.batchWidth != 2 && options.batchWidth != 4 &&
        options.batchWidth != 8)
        throw InvalidInput("batch_width", makeDiagnostic("sim_batch_width"));
    DesignSweepResult result;
    result.criterion = options.criterion;
    result.wnValues = wnAxis.values("wn");
    result.kpValues = kpAxis.values("kp");
    const DesignEvaluator evaluator(problem);
    const std::size_t nKp = result.kpValues.size();
    const std::size_t total = result.wnValues.size() * nKp;
    result.points.resize(total);

    // Workers take batchWidth consecutive points at a time (one trackBatch call), so a point's
    // neighbours in a batch vary from run to run; each lane's arithmetic is its own, so that
    // does not change a bit either.
    ParallelRunOptions run;
    run.threads = options.threads;
    run.chunk = static_cast<std::size_t>(options.batchWidth);
    run.progress = options.progress;
    run.progressScale =
        static_cast<double>(total) / (static_cast<double>(total) + 1.0); // + 1: the refinement
    run.onWorkerStart = options.onWorkerStart;
    const ParallelRunOutcome outcome =
        parallelRuns(total, run, [&](std::size_t first, std::size_t count) {
            double wn[8], kp[8];
            for (std::size_t j = 0; j < count; ++j) {
                wn[j] = result.wnValues[(first + j) / nKp];
                kp[j] = result.kpValues[(first + j) % nKp];
            }
            evaluator.evaluateBatch(
                std::span<const double>(wn, count), std::span<const double>(kp, count),
                std::span<DesignPoint>(result.points.data() + first, count), options.batchWidth);
        });
    result.threadsUsed = outcome.threadsUsed;
    tallyDesignSpace(result);
    if (outcome.cancelled || result.computedCount < static_cast<int>(total)) {
        result.status = SweepStatus::Cancelled;
        result.warnings.push_back(
            makeDiagnostic("study_sweep_cancelled",
                           {std::to_string(result.computedCount), std::to_string(total)}));
        return result;
    }
    if (!result.bestIndex)
        result.warnings.push_back(makeDiagnostic("study_no_feasible_design"));
    if (options.refine && result.bestIndex) {
        const std::size_t b = *result.bestIndex;
        result.refined = refineDesign(
            evaluator, result.points[b], options.criterion, wnAxis.minValue, wnAxis.maxValue,
            kpAxis.minValue, kpAxis.maxValue, logSpacing(result.wnValues, b / nKp),
            logSpacing(result.kpValues, b % nKp), options.maxRefineEvaluations);
    }
    if (options.progress)
        options.progress(1.0);
    return result;
}

} // namespace xyt
