// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/metrics.h"

#include "core/errors.h"
#include "core/state_space.h"

#include <algorithm>
#include <cmath>
#include <complex>
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
    // Same test as TransferFunction::isStable (real part < 0), on the poles already at hand.
    out.stable = std::all_of(poles.begin(), poles.end(),
                             [](const std::complex<double>& p) { return p.real() < 0.0; });
    if (!out.stable)
        return out;
    out.finalValue = closedLoop.dcGain();
    double slowest = std::numeric_limits<double>::infinity();
    for (const auto& p : poles)
        slowest = std::min(slowest, -p.real());
    const StateSpace ss = realize(closedLoop);
    const Eigen::Index n = ss.states();
    const double scale = std::max(std::abs(out.finalValue), 1e-300);
    const double direct = ss.d(0, 0);
    double horizon = poles.empty() ? 1.0 : 12.0 / slowest;

    // The recursion runs on raw arrays: this is called for every point of a design sweep, and
    // Eigen's dynamic temporaries would allocate at every sample.
    const auto un = static_cast<std::size_t>(n);
    std::vector<double> c(un), x(un), next(un), xOutside(un), phi(un * un), gamma(un);
    for (std::size_t j = 0; j < un; ++j)
        c[j] = ss.c(0, static_cast<Eigen::Index>(j));
    auto output = [&](const std::vector<double>& state) {
        double acc = direct;
        for (std::size_t j = 0; j < un; ++j)
            acc += c[j] * state[j];
        return acc;
    };
    auto advance = [&](const std::vector<double>& from, std::vector<double>& to) {
        for (std::size_t i = 0; i < un; ++i) {
            double acc = gamma[i];
            for (std::size_t j = 0; j < un; ++j)
                acc += phi[i * un + j] * from[j];
            to[i] = acc;
        }
    };

    for (int attempt = 0; attempt < 6; ++attempt, horizon *= 2.0) {
        const double dt = horizon / samples;
        const StateSpace d = discretizeZoh(ss, dt);
        for (std::size_t i = 0; i < un; ++i) {
            gamma[i] = d.b(static_cast<Eigen::Index>(i), 0);
            for (std::size_t j = 0; j < un; ++j)
                phi[i * un + j] = d.a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        }
        std::fill(x.begin(), x.end(), 0.0);
        double peak = direct;
        double peakTime = 0.0;
        // Last sample index outside the band, with its state (the sample after it is recomputed).
        int lastOutside = -1;
        double yOutside = 0.0;
        for (int k = 0; k <= samples; ++k) {
            const double yk = output(x);
            if (yk > peak) {
                peak = yk;
                peakTime = k * dt;
            }
            if (std::abs(yk - out.finalValue) > band * scale) {
                lastOutside = k;
                yOutside = yk;
                xOutside = x;
            }
            advance(x, next);
            x.swap(next);
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
        std::vector<double>& xAfter = next;
        advance(xOutside, xAfter);
        auto slope = [&](const std::vector<double>& state) {
            double acc = 0.0; // y' = C (A x + B)
            for (std::size_t i = 0; i < un; ++i) {
                double dx = ss.b(static_cast<Eigen::Index>(i), 0);
                for (std::size_t j = 0; j < un; ++j)
                    dx += ss.a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) *
                          state[j];
                acc += c[i] * dx;
            }
            return acc;
        };
        const double y0 = yOutside, y1 = output(xAfter);
        const double m0 = slope(xOutside) * dt, m1 = slope(xAfter) * dt;
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
