// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/model/diagnostic.h"
#include "core/model/table_friction.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/study/specification.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace xyt {

/**
 * The design-space study of Braga et al. (Sec. 3, script steps 1-7): vary wn and kp, compute the
 * Guillemin-Truxal reference model G_R and PI controller for each pair, simulate the loop with
 * the actuator limit on the trajectory, and keep the design that best meets the specification,
 * with the ITAE (the paper's "AEMT") as the default guide.
 */

/// What "best" means among the feasible designs: the smallest value of this metric.
enum class SweepCriterion {
    Itae,     ///< integral of t |e| dt (TrackingMetrics::itae)
    MaxError, ///< max |e| (TrackingMetrics::maxAbsError)
    Rmse,     ///< TrackingMetrics::rmse
    MaxU,     ///< max |u| (TrackingMetrics::maxAbsU): the gentlest feasible design
    /// Settle time after a point-to-point move (MoveSettleMetrics::settleTimeSeconds); +infinity
    /// for a point that did not settle or a problem without a move.
    Settle,
    /// The loop's phase margin (deg) and gain margin (dB): larger is better, so these two are
    /// maximized (criterionValue is their negative; criterionMetric the margin itself).
    PhaseMargin,
    GainMargin,
};
/// "itae", "max_error", "rmse", "max_u", "settle", "phase_margin", "gain_margin".
std::string criterionName(SweepCriterion criterion);
/// The inverse of criterionName; nullopt for an unknown name.
std::optional<SweepCriterion> parseCriterion(const std::string& name);

/**
 * One axis of the grid: @p count values from minValue to maxValue, both included, evenly spaced
 * (linear) or evenly spaced in log (logarithmic: v_i = min (max/min)^(i/(count-1))). count = 1
 * gives minValue alone. Values must be > 0 on both kinds of axis: wn and kp of the design are.
 */
struct SweepAxis {
    double minValue = 1.0;
    double maxValue = 1.0;
    int count = 1;
    bool logarithmic = false;

    static constexpr int kMaxCount = 500;

    /// @throws InvalidInput @p field when a bound is not finite or not > 0, min > max, or count
    ///         is outside [1, kMaxCount].
    void validate(const std::string& field) const;
    /// The values, first exactly minValue and (count > 1) last exactly maxValue.
    /// @throws InvalidInput as validate.
    std::vector<double> values(const std::string& field = "axis") const;
};

/// What is studied: one plant, one sampled trajectory, one specification.
struct DesignProblem {
    ThirdOrderPlant plant;
    /// What each design is closed around besides the plant it is made on (withLoopElements): a
    /// flexible mode of the table and a notch after the PI; absent (no factor) by default.
    std::optional<TransferFunction> plantFactor, controllerFilter;
    /// Plant output units per trajectory unit (0.001 for the paper's presets: m per mm), as
    /// LoopSimulationOptions::modelUnitsPerPositionUnit.
    double modelUnitsPerPositionUnit = 1.0;
    std::vector<double> reference; ///< r(k dt), trajectory units, the loop starts at rest at 0
    double dtSeconds = 0.01;
    /// spec.umaxVolts is also the actuator limit of every simulation.
    Specification spec;
    /// A point-to-point move (the reference holds its target from move->endSeconds on): every
    /// point then gets move-and-settle figures with spec.inPositionWindowMm and is judged on
    /// spec.maxSettleTimeSeconds. The reference must run past the move's end for the settle to
    /// be measured (moveSweepDurationSeconds).
    std::optional<PointToPointMove> move;
    /// Samples per span of the step-figure scan (stepCharacteristics' `samples`, at least 100):
    /// the default 500 for a study; a live preview may take 100 (about 25 samples per period
    /// of the fastest closed-loop oscillation instead of 125: the sampled peak is then within
    /// 1 - cos(pi / 25) = 0.8 % of that oscillation's amplitude).
    int stepSamples = 500;
    /// A command feedforward every design runs with (V at the reference's samples; empty:
    /// none): a PID + feedforward axis' feedforward, fixed while its PI gains are varied.
    std::vector<double> feedforwardVolts;
    /// The axis' table with friction (core/simulation/table_dynamics.h): every design then runs
    /// simulateLoop's nonlinear integration instead of the batched linear kernel, one design at
    /// a time (a few times the kernel's cost per design: xytune-bench design_space_friction).
    std::optional<TableFriction> table;
};

/**
 * How long the reference of a sweep over a point-to-point move should run: tf + 2 x the
 * settle limit, so that a design settling within the limit is seen to stay in the window for
 * at least as long again. (A sweep cannot use the per-design automatic duration of a session:
 * all its designs share one reference.)
 */
double moveSweepDurationSeconds(double tfSeconds, double maxSettleTimeSeconds);

/// Everything known about one design (wn, kp).
struct DesignPoint {
    double wn = 0.0;       ///< rad/s
    double kp = 0.0;       ///< V per model unit
    double ki = 0.0;       ///< kp psi1 = wn^4 / k0 (Braga et al. Eq. 11, 16)
    bool computed = false; ///< false for points a cancelled sweep never reached
    bool stable = false;   ///< closed loop (= G_R) asymptotically stable
    /// Every tracking figure is finite and, for a stable loop, the step figures too. When false
    /// the run diverged: the tracking figures are set to +infinity (never NaN) and the point is
    /// infeasible.
    bool metricsFinite = false;
    TrackingMetrics tracking; ///< on the problem's trajectory, with the actuator limit
    StepCharacteristics step; ///< of the closed loop (unset when unstable, see its doc)
    /// Move-and-settle figures, for a problem with a move (see DesignProblem::move).
    std::optional<MoveSettleMetrics> move;
    /// The loop's margins (stabilityMargins of L = G_c G): the phase margin of smallest
    /// magnitude (deg) and the gain margin nearest 0 dB; +infinity without such a crossing, NaN
    /// when not computed. Judged against spec.minPhaseMarginDeg / minGainMarginDb.
    double phaseMarginDeg = std::numeric_limits<double>::quiet_NaN();
    double gainMarginDb = std::numeric_limits<double>::quiet_NaN();
    SpecificationCheck check;
    bool feasible = false; ///< computed && metricsFinite && check.allPassed()
};

/**
 * The value minimized by @p criterion: the metric itself, or its negative for the maximized
 * margins; +infinity for a point not computed or not finite (a margin of +infinity, no
 * crossing, is the best there is: -infinity).
 */
double criterionValue(const DesignPoint& point, SweepCriterion criterion);
/// The metric @p criterion looks at, in its own unit (what a map or a table shows): equal to
/// criterionValue except that margins are given as they are. Not finite when it has none.
double criterionMetric(const DesignPoint& point, SweepCriterion criterion);
/// True for the criteria whose metric is maximized (the margins).
bool criterionMaximizes(SweepCriterion criterion);

/**
 * Evaluates designs of one DesignProblem. Equal, bit for bit, to
 *   d = designGuilleminTruxal(plant, wn, kp);
 *   run = simulateLoop(plant.transferFunction(), d.controller, reference, {dt, spec.umaxVolts, 0,
 * unit}); trackingMetrics(run), stepCharacteristics(d.closedLoop, 0.02, stepSamples),
 * checkSpecification(...) but faster: the tracking runs of several designs are stepped together by
 * trackBatch (one vector lane per design, the metrics accumulated on the fly instead of storing the
 * signals, the clipped-mode matrices computed only when a design's command first reaches the
 * limit).
 *
 * evaluate() and evaluateBatch() are const and keep no state: they may be called from several
 * threads at once.
 */
class DesignEvaluator {
public:
    /// @throws InvalidInput "plant" fields (ThirdOrderPlant::validate), "model_unit_scale",
    ///         "dt", "reference" (empty or not finite), the spec's fields.
    explicit DesignEvaluator(DesignProblem problem);

    /// @throws InvalidInput "wn" or "kp" unless finite and > 0.
    DesignPoint evaluate(double wn, double kp) const;
    /// out[i] = evaluate(wn[i], kp[i]) bit for bit, the tracking runs stepped @p batchWidth at a
    /// time (trackBatch: 1, 2, 4 or 8). @throws InvalidInput "designs" when the sizes differ,
    /// "batch_width", and as evaluate.
    void evaluateBatch(std::span<const double> wn, std::span<const double> kp,
                       std::span<DesignPoint> out, int batchWidth = 8) const;

    const DesignProblem& problem() const { return problem_; }

private:
    DesignPoint finishPoint(const GtDesign& design, const std::optional<TrackingMetrics>& tracking,
                            MoveSettleAccumulator* move) const;

    DesignProblem problem_;
    TransferFunction plantTf_;
    double travel_ = 0.0; ///< max r - min r, for maxAbsErrorPct
};

/// Result of the local search around the best grid point.
struct RefinementResult {
    DesignPoint point;     ///< the refined design (the start point when nothing better was found)
    int evaluations = 0;   ///< designs evaluated by the search
    bool improved = false; ///< the criterion is strictly lower than at the start
};

/**
 * Compass (pattern) search in (ln wn, ln kp) from @p start, which must be feasible: polls the
 * 8 neighbours at the current steps, moves to the best feasible one that lowers the criterion,
 * halves the steps when none does, and stops when both steps are below @p toleranceLog (a
 * relative change of about that much in wn and kp) or after @p maxEvaluations designs. Never
 * leaves [wnMin, wnMax] x [kpMin, kpMax] nor the feasible set, and never returns a point worse
 * than @p start. Deterministic.
 * @throws InvalidInput "start" unless it is feasible and inside the box, "step" unless the steps
 *         are >= 0 and finite, "max_evaluations" unless >= 0.
 */
RefinementResult refineDesign(const DesignEvaluator& evaluator, const DesignPoint& start,
                              SweepCriterion criterion, double wnMin, double wnMax, double kpMin,
                              double kpMax, double wnStepLog, double kpStepLog,
                              int maxEvaluations = 400, double toleranceLog = 1e-4);

struct SweepOptions {
    SweepCriterion criterion = SweepCriterion::Itae;
    /// Worker threads; 0 means std::thread::hardware_concurrency() (at least 1). Never more
    /// than the number of grid points. The result does not depend on it, bit for bit.
    int threads = 0;
    bool refine = true;
    int maxRefineEvaluations = 400;
    /// Designs whose tracking runs are stepped together (trackBatch): 1, 2, 4 or 8. The result
    /// does not depend on it, bit for bit.
    int batchWidth = 8;
    /// Called first on each worker thread (a GUI lowers the workers' priority with it, so that
    /// a live study never delays a repaint). May be empty.
    std::function<void()> onWorkerStart;
    /**
     * Called with the fraction done, in [0, 1], non-decreasing, ALWAYS ON THE THREAD THAT CALLED
     * sweepDesignSpace (never on a worker), about every 20 ms while the grid is computed, and
     * once with exactly 1 when everything, refinement included, is finished. Return false to
     * cancel: the workers stop after the point each is computing, the result says Cancelled.
     * The grid counts as N points and the refinement as one more, so grid progress stays < 1.
     */
    std::function<bool(double fraction)> progress;
};

enum class SweepStatus { Completed, Cancelled };

/**
 * The grid: points[index(iWn, iKp)] with index = iWn * kpValues.size() + iKp (row-major, one row
 * per wn value, columns over kp), so a heat map is rows = wn, columns = kp.
 */
struct DesignSweepResult {
    SweepStatus status = SweepStatus::Completed;
    SweepCriterion criterion = SweepCriterion::Itae;
    std::vector<double> wnValues;
    std::vector<double> kpValues;
    std::vector<DesignPoint> points;
    std::vector<std::uint8_t> feasibleMask; ///< 1 where points[i].feasible, same indexing
    int computedCount = 0;
    int feasibleCount = 0;
    int stableCount = 0;
    /// argmin of criterionValue over the feasible computed points (ties: the lowest index);
    /// nullopt when no point is feasible.
    std::optional<std::size_t> bestIndex;
    /// The refined best (Completed sweeps with a best point and options.refine only).
    std::optional<RefinementResult> refined;
    int threadsUsed = 0;
    std::vector<Diagnostic> warnings;

    std::size_t index(std::size_t iWn, std::size_t iKp) const {
        return iWn * kpValues.size() + iKp;
    }
    const DesignPoint& at(std::size_t iWn, std::size_t iKp) const {
        return points[index(iWn, iKp)];
    }
};

/// Recounts computedCount, stableCount, feasibleMask, feasibleCount and bestIndex (for
/// result.criterion) from the points' `computed`, `stable` and `feasible`.
void tallyDesignSpace(DesignSweepResult& result);

/**
 * Judges every computed point of @p result again against @p spec, which must have the study's
 * actuator limit (the runs depend on it; on the other limits they do not, so this is exact):
 * check, feasible and the tally (tallyDesignSpace) are recomputed. The refinement searched
 * under the old limits and is dropped. The settle figures depend on the in-position window,
 * so a point-to-point study must keep its window; a larger maxSettleTimeSeconds than the run
 * covers after tf judges a design that had not settled by the end of the run as failing.
 * @throws InvalidInput from Specification::validate; "in_position_window_mm" when a point has
 *         move-and-settle figures for another window (run the study again).
 */
void rejudgeDesignSpace(DesignSweepResult& result, const Specification& spec);

/**
 * Evaluates every (wn, kp) of the grid (DesignEvaluator::evaluate), on all cores, then picks
 * the best feasible design and refines it inside the grid's box (refineDesign, starting with
 * the grid spacing at the best point as steps).
 * @throws InvalidInput from DesignEvaluator, "wn" / "kp" for a bad axis, "threads" unless
 *         0 <= threads <= 1024, "max_refine_evaluations" unless >= 0.
 */
DesignSweepResult sweepDesignSpace(const DesignProblem& problem, const SweepAxis& wnAxis,
                                   const SweepAxis& kpAxis, const SweepOptions& options = {});

} // namespace xyt
