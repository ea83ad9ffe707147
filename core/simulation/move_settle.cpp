// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/move_settle.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

MoveSettleAccumulator::MoveSettleAccumulator(const PointToPointMove& move, double windowMm)
    : move_(move), window_(windowMm), direction_(move.targetMm >= move.startMm ? 1.0 : -1.0) {
    requirePositive(windowMm, "in_position_window_mm");
    if (!std::isfinite(move.startMm) || !std::isfinite(move.targetMm) ||
        !std::isfinite(move.endSeconds))
        throw InvalidInput("move", makeDiagnostic("sim_move_not_finite"));
}

void MoveSettleAccumulator::add(double t, double y, double e) {
    ++count_;
    lastT_ = t;
    lastE_ = e;
    if (!std::isfinite(y) || !std::isfinite(e)) {
        diverged_ = true;
        return;
    }
    maxBeyond_ = std::max(maxBeyond_, (y - move_.targetMm) * direction_);
    if (t < move_.endSeconds)
        return;
    reachedEnd_ = true;
    const double absE = std::abs(e);
    if (absE > window_) {
        outsideSeen_ = true;
        outsideT_ = t;
        outsideAbsE_ = absE;
        afterSeen_ = false;
        lastWasOutside_ = true;
    } else {
        if (lastWasOutside_) {
            afterSeen_ = true;
            afterT_ = t;
            afterAbsE_ = absE;
        }
        lastWasOutside_ = false;
    }
}

MoveSettleMetrics MoveSettleAccumulator::finish() const {
    if (count_ == 0)
        throw InvalidInput("run", makeDiagnostic("has_no_samples"));
    MoveSettleMetrics m;
    m.windowMm = window_;
    m.moveEndSeconds = move_.endSeconds;
    m.runEndSeconds = lastT_;
    m.reachedMoveEnd = reachedEnd_;
    if (diverged_) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        m.diverged = true;
        m.finalErrorMm = m.finalOvershootMm = nan;
        return m;
    }
    m.finalErrorMm = lastE_;
    m.finalOvershootMm = maxBeyond_;
    if (!reachedEnd_ || lastWasOutside_)
        return m; // ended before tf, or still outside at the last sample
    m.settled = true;
    if (!outsideSeen_) {
        m.settleTimeSeconds = 0.0;
        return m;
    }
    // |e| comes down through w between the last sample outside and the next one: linear
    // interpolation of |e| (the step is short against the decay it samples).
    const double drop = outsideAbsE_ - afterAbsE_;
    const double fraction =
        drop > 0.0 ? std::clamp((outsideAbsE_ - window_) / drop, 0.0, 1.0) : 1.0;
    const double crossing = outsideT_ + fraction * (afterT_ - outsideT_);
    m.settleTimeSeconds = std::max(0.0, crossing - move_.endSeconds);
    return m;
}

MoveSettleMetrics moveSettleMetrics(const SimulationResult& run, const PointToPointMove& move,
                                    double windowMm) {
    const std::size_t n = run.t.size();
    if (n == 0)
        throw InvalidInput("run", makeDiagnostic("has_no_samples"));
    if (run.y.size() != n || run.e.size() != n)
        throw InvalidInput("run", makeDiagnostic("sim_signals_different_lengths"));
    MoveSettleAccumulator acc(move, windowMm);
    for (std::size_t k = 0; k < n; ++k)
        acc.add(run.t[k], run.y[k], run.e[k]);
    return acc.finish();
}

double settleTimeEstimateSeconds(double errorAtMoveEndMm, double windowMm,
                                 double slowestDecayPerSecond) {
    const double inf = std::numeric_limits<double>::infinity();
    if (!std::isfinite(errorAtMoveEndMm) || !(windowMm > 0.0) || !std::isfinite(windowMm) ||
        !(slowestDecayPerSecond > 0.0))
        return inf;
    const double e = std::abs(errorAtMoveEndMm);
    return e <= windowMm ? 0.0 : std::log(e / windowMm) / slowestDecayPerSecond;
}

double continuousDecayPerSecond(const std::vector<std::complex<double>>& poles) {
    if (poles.empty())
        return 0.0;
    double slowest = -std::numeric_limits<double>::infinity();
    for (const auto& p : poles)
        slowest = std::max(slowest, p.real());
    return -slowest;
}

double discreteDecayPerSecond(const std::vector<std::complex<double>>& poles, double tsSeconds) {
    double largest = 0.0;
    for (const auto& p : poles)
        largest = std::max(largest, std::abs(p));
    return largest > 0.0 ? -std::log(largest) / tsSeconds : std::numeric_limits<double>::infinity();
}

double automaticMoveCapSeconds(double t0Seconds, double tfSeconds, double dtSeconds) {
    const double cap = tfSeconds + kAutomaticSettleMoves * (tfSeconds - t0Seconds);
    if (!std::isfinite(cap) || !(dtSeconds > 0.0) || !(cap > tfSeconds))
        return tfSeconds;
    // Two samples below the limit: sampleTimes rounds duration / dt up by 1e-9.
    const double fits =
        (std::min(kMaxAutomaticSamples, static_cast<double>(sampleLimit())) - 2.0) * dtSeconds;
    return std::max(tfSeconds, std::min(cap, fits));
}

double automaticMoveDurationSeconds(double t0Seconds, double tfSeconds,
                                    double settleEstimateSeconds, double capSeconds) {
    const double wanted = tfSeconds + 1.5 * settleEstimateSeconds + 0.1 * (tfSeconds - t0Seconds);
    return wanted <= capSeconds ? wanted : capSeconds;
}

} // namespace xyt
