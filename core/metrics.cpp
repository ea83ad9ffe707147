// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/metrics.h"

#include "core/errors.h"
#include "core/state_space.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

double rootMeanSquare(const std::vector<double>& v) {
    if (v.empty())
        return 0.0;
    double acc = 0.0;
    for (double x : v)
        acc += x * x;
    return std::sqrt(acc / static_cast<double>(v.size()));
}

TrackingMetrics trackingMetrics(const SimulationResult& run) {
    const std::size_t n = run.t.size();
    if (n == 0)
        throw InvalidInput("result", "the run has no samples");
    if (run.r.size() != n || run.y.size() != n || run.e.size() != n || run.u.size() != n ||
        run.clipped.size() != n)
        throw InvalidInput("result", "signals of different lengths");
    TrackingMetrics m;
    m.rmse = rootMeanSquare(run.e);
    double rMin = run.r[0], rMax = run.r[0];
    std::size_t clippedCount = 0;
    for (std::size_t k = 0; k < n; ++k) {
        m.maxAbsError = std::max(m.maxAbsError, std::abs(run.e[k]));
        m.maxAbsU = std::max(m.maxAbsU, std::abs(run.u[k]));
        rMin = std::min(rMin, run.r[k]);
        rMax = std::max(rMax, run.r[k]);
        if (run.clipped[k])
            ++clippedCount;
        if (k > 0)
            m.itae += 0.5 * (run.t[k] - run.t[k - 1]) *
                      (run.t[k] * std::abs(run.e[k]) + run.t[k - 1] * std::abs(run.e[k - 1]));
    }
    const double travel = rMax - rMin;
    m.maxAbsErrorPct = travel > 0.0 ? 100.0 * m.maxAbsError / travel : 0.0;
    m.saturated = clippedCount > 0;
    m.saturatedTimeSeconds = static_cast<double>(clippedCount) * run.dtSeconds;
    return m;
}

StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop, double band,
                                        int samples) {
    if (closedLoop.isDiscrete() || !closedLoop.isProper())
        throw InvalidInput("system", "must be a continuous, proper transfer function");
    if (!(band > 0.0 && band < 1.0))
        throw InvalidInput("band", "must be between 0 and 1");
    if (samples < 100)
        throw InvalidInput("samples", "must be at least 100");
    StepCharacteristics out;
    const auto poles = closedLoop.poles();
    out.stable = closedLoop.isStable();
    if (!out.stable)
        return out;
    out.finalValue = closedLoop.dcGain();
    double slowest = std::numeric_limits<double>::infinity();
    for (const auto& p : poles)
        slowest = std::min(slowest, -p.real());
    const StateSpace ss = realize(closedLoop);
    const Eigen::Index n = ss.states();
    const double scale = std::max(std::abs(out.finalValue), 1e-300);
    double horizon = poles.empty() ? 1.0 : 12.0 / slowest;

    for (int attempt = 0; attempt < 6; ++attempt, horizon *= 2.0) {
        const double dt = horizon / samples;
        const StateSpace d = discretizeZoh(ss, dt);
        Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
        double peak = ss.d(0, 0);
        double peakTime = 0.0;
        // Last sample index outside the band, with the sample after it.
        int lastOutside = -1;
        std::vector<double> y(static_cast<std::size_t>(samples) + 1);
        std::vector<Eigen::VectorXd> states;
        states.reserve(y.size());
        for (int k = 0; k <= samples; ++k) {
            const double yk = (ss.c * x)(0) + ss.d(0, 0);
            y[static_cast<std::size_t>(k)] = yk;
            states.push_back(x);
            if (yk > peak) {
                peak = yk;
                peakTime = k * dt;
            }
            if (std::abs(yk - out.finalValue) > band * scale)
                lastOutside = k;
            x = d.a * x + d.b.col(0);
        }
        if (lastOutside == samples)
            continue; // still outside the band at the horizon: look further
        out.overshootPct = std::max(0.0, (peak - out.finalValue) / scale * 100.0);
        out.peakTimeSeconds = peakTime;
        if (lastOutside < 0) {
            out.settlingTimeSeconds = 0.0;
            return out;
        }
        // Hermite interpolation on [t_k, t_k+1] of y - final crossing +-band*scale.
        const int k = lastOutside;
        auto slope = [&](int i) {
            return (ss.c * (ss.a * states[static_cast<std::size_t>(i)] + ss.b.col(0)))(0);
        };
        const double y0 = y[static_cast<std::size_t>(k)], y1 = y[static_cast<std::size_t>(k + 1)];
        const double m0 = slope(k) * dt, m1 = slope(k + 1) * dt;
        const double target = out.finalValue + std::copysign(band * scale, y0 - out.finalValue);
        auto h = [&](double s) {
            const double s2 = s * s, s3 = s2 * s;
            return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 +
                   (s3 - s2) * m1 - target;
        };
        double lo = 0.0, hi = 1.0;
        const double sign0 = h(lo);
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            if ((h(mid) > 0) == (sign0 > 0))
                lo = mid;
            else
                hi = mid;
        }
        out.settlingTimeSeconds = (k + 0.5 * (lo + hi)) * dt;
        return out;
    }
    // Never inside the band within 12 * 2^5 time constants: report the horizon reached.
    out.settlingTimeSeconds = horizon;
    return out;
}

} // namespace xyt
