// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/tracking_batch.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace xyt {

namespace {

constexpr int kStates = 4; // a third-order plant and a PI controller

/// The exact FOH step of one mode (discretizeFoh), errors named "dt" as in simulateLoop.
FohDiscretization modeStep(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double dt) {
    try {
        return discretizeFoh(a, b, dt);
    } catch (const InvalidInput& e) {
        throw InvalidInput("dt", e.reasonDiagnostic());
    }
}

/**
 * W loops in structure-of-arrays form: element [i][l] is coefficient i of lane l. The
 * clipped-mode arrays of a lane are filled when it first clips (clippedReady).
 */
template <int W> struct Lanes {
    double phiL[kStates * kStates][W], g0L[kStates][W], g1L[kStates][W];
    double g0F[kStates][W], g1F[kStates][W]; ///< the feedforward's input column, when there is one
    double phiC[kStates * kStates][W], g0C[kStates][2][W], g1C[kStates][2][W];
    double cp[3][W], cc[W], dc[W];
    bool clippedReady[W];
    const LoopModes* modes[W];

    void load(int l, const LoopModes& m, double dt, bool feedforward) {
        if (m.plantStates != 3 || m.controllerStates != 1)
            throw std::logic_error("trackBatch: expected a third-order plant and a PI controller");
        // With a feedforward the linear mode has the plant input as its second input, as in
        // simulateLoop (the same two-column discretization, so the same bits).
        Eigen::MatrixXd b = m.bLinear;
        if (feedforward) {
            b.conservativeResize(Eigen::NoChange, 2);
            b.col(1) = m.bClipped.col(1);
        }
        const FohDiscretization s = modeStep(m.aLinear, b, dt);
        for (int i = 0; i < kStates; ++i) {
            for (int j = 0; j < kStates; ++j) {
                phiL[i * kStates + j][l] = s.phi(i, j);
                phiC[i * kStates + j][l] = 0.0;
            }
            g0L[i][l] = s.gamma0(i, 0);
            g1L[i][l] = s.gamma1(i, 0);
            g0F[i][l] = feedforward ? s.gamma0(i, 1) : 0.0;
            g1F[i][l] = feedforward ? s.gamma1(i, 1) : 0.0;
            for (int j = 0; j < 2; ++j)
                g0C[i][j][l] = g1C[i][j][l] = 0.0;
        }
        for (int j = 0; j < 3; ++j)
            cp[j][l] = m.plantC(j);
        cc[l] = m.controllerC(0);
        dc[l] = m.controllerD;
        clippedReady[l] = false;
        modes[l] = &m;
    }

    void loadClipped(int l, double dt) {
        const FohDiscretization s = modeStep(modes[l]->aClipped, modes[l]->bClipped, dt);
        for (int i = 0; i < kStates; ++i) {
            for (int j = 0; j < kStates; ++j)
                phiC[i * kStates + j][l] = s.phi(i, j);
            for (int j = 0; j < 2; ++j) {
                g0C[i][j][l] = s.gamma0(i, j);
                g1C[i][j][l] = s.gamma1(i, j);
            }
        }
        clippedReady[l] = true;
    }
};

/// How often (in steps) a batch looks whether all its lanes have diverged.
constexpr std::size_t kDivergenceCheckSteps = 64;

/**
 * One batch of `used` <= W loops (the remaining lanes repeat lane 0 and are discarded). Per lane
 * the operations and their order are those of simulateLoop's runLoop and of trackingMetrics.
 */
template <int W>
void runBatch(const LoopModes* const* loops, int used, const TrackingRun& run, double travel,
              MoveSettleAccumulator* const* moves, std::optional<TrackingMetrics>* results) {
    Lanes<W> lanes;
    for (int l = 0; l < W; ++l)
        lanes.load(l, *loops[l < used ? l : 0], run.dtSeconds, run.feedforwardVolts != nullptr);
    const double* ff = run.feedforwardVolts ? run.feedforwardVolts->data() : nullptr;
    const std::vector<double>& ref = *run.reference;
    const std::size_t count = ref.size();
    const double dt = run.dtSeconds;
    const double unit = run.modelUnitsPerPositionUnit;
    const double umax = run.umaxVolts;
    const bool limited = std::isfinite(umax);

    double x[kStates][W] = {};
    double sumSquares[W] = {}, maxAbsE[W] = {}, maxAbsU[W] = {}, itae[W] = {};
    double previousTimeAbsE[W] = {}; // t_{k-1} |e_{k-1}|
    double clippedCount[W] = {};
    // Flags as 0/1 doubles, not bools: the lane loops below then have no control flow and
    // the compiler vectorizes them.
    double clip[W];
    double bad[W] = {}; // 1 once some sample of y, e or u was not finite
    bool alive[W];      // not yet bad: still fed to its move accumulator
    for (int l = 0; l < W; ++l)
        alive[l] = l < used;
    double y[W], u[W], e[W], next[kStates][W], clippedNext[kStates][W];
    double previousTime = 0.0;
    constexpr double kHuge = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < count; ++k) {
        const double rk = ref[k] * unit;
        const double ffk = ff ? ff[k] : 0.0;
        const double t = static_cast<double>(k) * dt;
        // 0 at k = 0, where trackingMetrics adds nothing: adding 0.5 * 0 * (finite) = +0.0 to
        // itae = +0.0 leaves the same bits (a lane with a non-finite sample is discarded).
        const double halfStep = 0.5 * (t - previousTime);
        double anyClip = 0.0;
        for (int l = 0; l < W; ++l) {
            double yl = 0.0;
            yl += lanes.cp[0][l] * x[0][l];
            yl += lanes.cp[1][l] * x[1][l];
            yl += lanes.cp[2][l] * x[2][l];
            double v = lanes.dc[l] * (rk - yl) + ffk; // simulateLoop's order
            v += lanes.cc[l] * x[3][l];
            const bool c = limited && std::abs(v) > umax;
            u[l] = c ? std::copysign(umax, v) : v;
            clip[l] = c ? 1.0 : 0.0;
            anyClip += clip[l];
            y[l] = yl / unit;
            e[l] = ref[k] - y[l];
        }
        for (int l = 0; l < W; ++l) {
            const double absE = std::abs(e[l]);
            // |y| + |e| + |u| is not finite exactly when one of them is not (or, beyond 1e308,
            // when their sum overflows: a run that large has diverged for any purpose).
            const double size = std::abs(y[l]) + absE + std::abs(u[l]);
            bad[l] = size <= kHuge ? bad[l] : 1.0;
            sumSquares[l] += e[l] * e[l];
            maxAbsE[l] = std::max(maxAbsE[l], absE);
            maxAbsU[l] = std::max(maxAbsU[l], std::abs(u[l]));
            clippedCount[l] += clip[l];
            itae[l] += halfStep * (t * absE + previousTimeAbsE[l]);
            previousTimeAbsE[l] = t * absE;
        }
        previousTime = t;
        if (moves)
            for (int l = 0; l < used; ++l) {
                alive[l] = alive[l] && bad[l] == 0.0;
                if (alive[l] && moves[l])
                    moves[l]->add(t, y[l], e[l]);
            }
        if (k + 1 == count)
            break;
        if (k % kDivergenceCheckSteps == 0 &&
            std::all_of(bad, bad + used, [](double b) { return b != 0.0; }))
            break; // every result is nullopt; the rest of the run cannot change that
        const double slope = (ref[k + 1] - ref[k]) * unit / dt;
        const double ffSlope = ff ? (ff[k + 1] - ff[k]) / dt : 0.0;
        for (int i = 0; i < kStates; ++i)
            for (int l = 0; l < W; ++l) {
                double acc = 0.0;
                for (int j = 0; j < kStates; ++j)
                    acc += lanes.phiL[i * kStates + j][l] * x[j][l];
                acc += lanes.g0L[i][l] * rk + lanes.g1L[i][l] * slope;
                if (ff)
                    acc += lanes.g0F[i][l] * ffk + lanes.g1F[i][l] * ffSlope;
                next[i][l] = acc;
            }
        if (anyClip != 0.0) {
            for (int l = 0; l < W; ++l)
                if (clip[l] != 0.0 && !lanes.clippedReady[l])
                    lanes.loadClipped(l, dt);
            for (int i = 0; i < kStates; ++i)
                for (int l = 0; l < W; ++l) {
                    double acc = 0.0;
                    for (int j = 0; j < kStates; ++j)
                        acc += lanes.phiC[i * kStates + j][l] * x[j][l];
                    acc += lanes.g0C[i][0][l] * rk + lanes.g1C[i][0][l] * slope;
                    acc += lanes.g0C[i][1][l] * u[l] + lanes.g1C[i][1][l] * 0.0;
                    clippedNext[i][l] = acc;
                }
            for (int i = 0; i < kStates; ++i)
                for (int l = 0; l < W; ++l)
                    x[i][l] = clip[l] != 0.0 ? clippedNext[i][l] : next[i][l];
        } else {
            for (int i = 0; i < kStates; ++i)
                for (int l = 0; l < W; ++l)
                    x[i][l] = next[i][l];
        }
    }
    for (int l = 0; l < used; ++l) {
        if (bad[l] != 0.0) {
            results[l].reset();
            continue;
        }
        TrackingMetrics m;
        m.rmse = std::sqrt(sumSquares[l] / static_cast<double>(count));
        m.maxAbsError = maxAbsE[l];
        m.maxAbsErrorPct = travel > 0.0 ? 100.0 * m.maxAbsError / travel : 0.0;
        m.maxAbsU = maxAbsU[l];
        m.saturated = clippedCount[l] > 0.0;
        m.saturatedTimeSeconds = clippedCount[l] * dt;
        m.itae = itae[l];
        if (std::isfinite(m.rmse) && std::isfinite(m.itae) && std::isfinite(m.maxAbsErrorPct))
            results[l] = m;
        else
            results[l].reset(); // finite samples whose sums overflowed
    }
}

template <int W>
void runAll(std::span<const LoopModes> lanes, const TrackingRun& run, double travel,
            std::span<MoveSettleAccumulator* const> moves,
            std::span<std::optional<TrackingMetrics>> results) {
    const LoopModes* group[W];
    for (std::size_t first = 0; first < lanes.size(); first += W) {
        const int used = static_cast<int>(std::min<std::size_t>(W, lanes.size() - first));
        for (int l = 0; l < used; ++l)
            group[l] = &lanes[first + static_cast<std::size_t>(l)];
        runBatch<W>(group, used, run, travel, moves.empty() ? nullptr : moves.data() + first,
                    results.data() + first);
    }
}

} // namespace

void trackBatch(std::span<const LoopModes> lanes, const TrackingRun& run,
                std::span<MoveSettleAccumulator* const> moves,
                std::span<std::optional<TrackingMetrics>> results, int width) {
    if (results.size() != lanes.size() || (!moves.empty() && moves.size() != lanes.size()))
        throw InvalidInput("lanes", makeDiagnostic("sim_batch_lanes"));
    if (!run.reference || run.reference->empty())
        throw InvalidInput("reference", makeDiagnostic("has_no_samples"));
    requirePositive(run.dtSeconds, "dt");
    if (std::isnan(run.umaxVolts) || !(run.umaxVolts > 0.0))
        throw InvalidInput("umax", makeDiagnostic("sim_umax_positive"));
    requirePositive(run.modelUnitsPerPositionUnit, "model_unit_scale");
    if (run.feedforwardVolts && run.feedforwardVolts->size() != run.reference->size())
        throw InvalidInput("feedforward", makeDiagnostic("sim_one_sample_per_reference"));
    const auto [lo, hi] = std::minmax_element(run.reference->begin(), run.reference->end());
    const double travel = *hi - *lo; // as trackingMetrics: max r - min r
    switch (width) {
    case 1:
        return runAll<1>(lanes, run, travel, moves, results);
    case 2:
        return runAll<2>(lanes, run, travel, moves, results);
    case 4:
        return runAll<4>(lanes, run, travel, moves, results);
    case 8:
        return runAll<8>(lanes, run, travel, moves, results);
    default:
        throw InvalidInput("batch_width", makeDiagnostic("sim_batch_width"));
    }
}

} // namespace xyt
