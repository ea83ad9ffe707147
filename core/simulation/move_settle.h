// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/simulation.h"

#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

namespace xyt {

/// A point-to-point move: the reference goes from startMm to targetMm and holds targetMm from
/// endSeconds (the cubic's tf) on. Positions in trajectory units (mm).
struct PointToPointMove {
    double startMm = 0.0;
    double targetMm = 0.0;
    double endSeconds = 0.0;
};

/**
 * The move-and-settle figures a motion engineer quotes for a point-to-point move, with the
 * in-position window w (mm):
 *  - settle time T_s: from the end of the move tf until |e| stays inside w for the rest of the
 *    run, i.e. T_s = t* - tf where t* is the instant |e| last comes down through w (linear
 *    interpolation of |e| between the last sample outside and the next one; 0 when no sample at
 *    t >= tf is outside). A run whose last sample is outside has not settled (`settled` false,
 *    settleTimeSeconds unset), as has a run that ends before tf;
 *  - final error e(t_end), the error at the last sample;
 *  - final-position overshoot max_k (y_k - x_f) d, d = sign(x_f - x_0) (+1 for x_f = x_0), at
 *    least 0: how far the table passes the target in the direction of travel.
 * A run with a non-finite sample of y or e is `diverged`: finalErrorMm and finalOvershootMm are
 * NaN and it has not settled.
 */
struct MoveSettleMetrics {
    double windowMm = 0.01;
    double moveEndSeconds = 0.0;             ///< tf
    double runEndSeconds = 0.0;              ///< time of the last sample
    bool reachedMoveEnd = false;             ///< the run has a sample at t >= tf
    bool settled = false;                    ///< |e| <= w from tf + settleTimeSeconds to the end
    std::optional<double> settleTimeSeconds; ///< T_s (s after tf), set exactly when settled
    double finalErrorMm = 0.0;               ///< e at the last sample
    double finalOvershootMm = 0.0; ///< mm beyond the target in the direction of travel, >= 0
    bool diverged = false;
};

/**
 * Accumulates MoveSettleMetrics one sample at a time, in time order, without storing the run
 * (the design sweep's fast evaluator uses it; moveSettleMetrics feeds it a stored run). It keeps
 * the last sample at t >= tf where |e| > w and the sample after it, which is all the settle time
 * needs.
 */
class MoveSettleAccumulator {
public:
    /// @throws InvalidInput "in_position_window_mm" unless windowMm is finite and > 0,
    ///         "move" unless its numbers are finite.
    MoveSettleAccumulator(const PointToPointMove& move, double windowMm);
    void add(double tSeconds, double y, double e);
    /// The figures of the samples added so far. @throws InvalidInput "run" when none was added.
    MoveSettleMetrics finish() const;

private:
    PointToPointMove move_;
    double window_;
    double direction_;
    std::size_t count_ = 0;
    bool diverged_ = false;
    bool reachedEnd_ = false;
    bool lastWasOutside_ = false; ///< the previous sample (at t >= tf) was outside the window
    bool outsideSeen_ = false;
    bool afterSeen_ = false; ///< a sample followed the last one outside
    double outsideT_ = 0.0, outsideAbsE_ = 0.0, afterT_ = 0.0, afterAbsE_ = 0.0;
    double lastT_ = 0.0, lastE_ = 0.0;
    double maxBeyond_ = 0.0;
};

/**
 * MoveSettleMetrics of a stored run (its t, y and e).
 * @throws InvalidInput "run" when it is empty or t, y and e differ in length, and as
 *         MoveSettleAccumulator.
 */
MoveSettleMetrics moveSettleMetrics(const SimulationResult& run, const PointToPointMove& move,
                                    double windowMm);

/**
 * How long after tf a response needs to settle, estimated from its slowest mode: the error
 * |e(tf)| decays like exp(-sigma t) with sigma = -max Re p over the closed-loop poles (for a
 * discrete loop sigma = -ln max |z| / Ts), so it enters the window after ln(|e(tf)| / w) / sigma.
 * 0 when |e(tf)| <= w; +infinity when sigma <= 0 (not asymptotically stable) or an input is not
 * finite.
 */
double settleTimeEstimateSeconds(double errorAtMoveEndMm, double windowMm,
                                 double slowestDecayPerSecond);

/// -max Re p over continuous poles (1/s): the decay rate of the slowest mode; <= 0 when not
/// asymptotically stable (0 for no poles).
double continuousDecayPerSecond(const std::vector<std::complex<double>>& poles);
/// -ln max |z| / Ts over discrete poles (1/s); +infinity when every pole is at 0 (deadbeat).
double discreteDecayPerSecond(const std::vector<std::complex<double>>& poles, double tsSeconds);

/**
 * An automatic point-to-point run ends at most this many move durations (tf - t0) after tf.
 * Three keeps the move at least a quarter of a time plot's width and the live view's samples
 * bounded (at 10 moves the default session ran 1430 s, 143k samples an axis, and the slider
 * took twice its 16 ms frame budget). A design whose slow pole needs longer is reported as not
 * settled in the run, with the estimate in the duration description.
 */
inline constexpr double kAutomaticSettleMoves = 3.0;

/**
 * An automatic run stops its settle extension at this many samples: the GUI's live-view limit.
 * So an automatic duration never makes a run too long to draw live, and the duration a view
 * bounds its samples with (TrajectorySettings::effectiveDurationSeconds) does not grow when the
 * view coarsens dt to fit (the cap is then tf itself, as before the settle was added).
 */
inline constexpr double kMaxAutomaticSamples = 1'000'000.0;

/**
 * The longest automatic run of a move from t0 to tf sampled at dt: tf + kAutomaticSettleMoves
 * (tf - t0), lowered to what min(kMaxAutomaticSamples, sampleLimit()) samples hold at dt, never
 * below tf (tf itself when an input is not usable: the caller's checks name it).
 */
double automaticMoveCapSeconds(double t0Seconds, double tfSeconds, double dtSeconds);

/**
 * The automatic run of a move: tf + 1.5 x the settle estimate (it is an estimate) + a tenth of
 * the move (so that the response is seen to stay in the window), cut to @p capSeconds.
 */
double automaticMoveDurationSeconds(double t0Seconds, double tfSeconds,
                                    double settleEstimateSeconds, double capSeconds);

} // namespace xyt
