// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/metrics.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>
#include <vector>

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
        throw InvalidInput("result", makeDiagnostic("sim_run_has_no_samples"));
    if (run.r.size() != n || run.y.size() != n || run.e.size() != n || run.u.size() != n ||
        run.clipped.size() != n)
        throw InvalidInput("result", makeDiagnostic("sim_signals_different_lengths"));
    TrackingMetrics m;
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(run.y[k]) || !std::isfinite(run.e[k]) || !std::isfinite(run.u[k])) {
            // std::max ignores NaN, so a maximum over a diverged run would read as a small, finite
            // figure; a diverged run has no figures at all.
            const double nan = std::numeric_limits<double>::quiet_NaN();
            m.rmse = m.maxAbsError = m.maxAbsErrorPct = m.maxAbsU = m.itae = nan;
            m.saturatedTimeSeconds = nan;
            m.diverged = true;
            return m;
        }
    }
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

namespace {

/// Where the step response leaves the band for the last time, and its largest sample.
struct StepScan {
    double peak = 0.0, peakTime = 0.0;
    double tOutside = -1.0; ///< < 0: never outside the band
    double yOutside = 0.0, yAfter = 0.0, slopeOutside = 0.0, slopeAfter = 0.0, dtOutside = 0.0;
    double tEnd = 0.0;
    bool outsideAtEnd = false;
};

/// The largest value of the cubic Hermite interpolant on [0, 1] with end values y0, y1 and
/// end slopes m0, m1 (already multiplied by the interval length), and where it occurs.
std::pair<double, double> hermiteMaximum(double y0, double m0, double y1, double m1) {
    auto h = [&](double s) {
        const double s2 = s * s, s3 = s2 * s;
        return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 +
               (s3 - s2) * m1;
    };
    // h'(s) = a s^2 + b s + c
    const double a = 6 * y0 + 3 * m0 - 6 * y1 + 3 * m1;
    const double b = -6 * y0 - 4 * m0 + 6 * y1 - 2 * m1;
    const double c = m0;
    std::pair<double, double> best = y0 >= y1 ? std::pair{y0, 0.0} : std::pair{y1, 1.0};
    auto consider = [&](double s) {
        if (s > 0.0 && s < 1.0 && h(s) > best.first)
            best = {h(s), s};
    };
    if (std::abs(a) < 1e-300) {
        if (b != 0.0)
            consider(-c / b);
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc >= 0.0) {
            const double r = std::sqrt(disc);
            consider((-b + r) / (2 * a));
            consider((-b - r) / (2 * a));
        }
    }
    return best;
}

/**
 * The sampled step response on the multi-scale grid of stepCharacteristics, with fixed-size
 * matrices when the order is known at compile time (N = 4: every Guillemin-Truxal closed loop,
 * which a design sweep evaluates thousands of times) and dynamic ones otherwise; no allocation
 * inside the recursion either way.
 */
template <int N>
StepScan scanStep(const StateSpace& ss, double finalValue, double bandAbs, double firstSpan,
                  double horizon, double longestHorizon, int samples) {
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;
    const Eigen::Index n = ss.states();
    const Matrix a = ss.a;
    const Vector b = ss.b.col(0);
    const Vector c = ss.c.row(0).transpose();
    const double direct = ss.d(0, 0);
    Matrix phi(n, n);
    Vector gamma(n), x = Vector::Zero(n), next(n), xOutside(n), xPrev = Vector::Zero(n),
                     xPeak = Vector::Zero(n), xPeakPrev = Vector::Zero(n);
    double dtPrev = 0.0, dtPeak = 0.0, dtPeakPrev = 0.0;
    // The step matrices of every span, kept for the interpolation at the peak and at the last
    // exit from the band (which used to discretize again).
    std::vector<Matrix> spanPhi;
    std::vector<Vector> spanGamma;
    std::vector<double> spanDt;
    spanPhi.reserve(64);
    spanGamma.reserve(64);
    spanDt.reserve(64);
    auto discretize = [&](double dt) {
        const StateSpace d = discretizeZoh(ss, dt);
        phi = d.a;
        gamma = d.b.col(0);
    };
    // From the third span on, each step is 4 times the last: Phi(4h) = Phi(h)^4 and, with
    // Gamma(2h) = Gamma(h) + Phi(h) Gamma(h), Gamma(4h) by the same doubling once more. Two
    // squarings instead of a matrix exponential per span (exp itself scales and squares, so
    // the round-off is of the same kind: a few ulps per span).
    auto quadruple = [&] {
        for (int twice = 0; twice < 2; ++twice) {
            next.noalias() = phi * gamma;
            gamma += next;
            phi = (phi * phi).eval();
        }
    };
    // The second span's step is 3 times the first: Phi(3h) = Phi(h)^3 and Gamma(3h) = Gamma(h)
    // + Phi(h) Gamma(2h). So one matrix exponential serves the whole scan.
    auto triple = [&] {
        const Vector g1 = gamma;
        const Matrix p1 = phi;
        next.noalias() = p1 * g1;
        gamma = g1 + next; // Gamma(2h)
        next.noalias() = p1 * gamma;
        gamma = g1 + next; // Gamma(3h) = Gamma(h) + Phi(h) Gamma(2h)
        phi = (p1 * p1 * p1).eval();
    };
    auto keepSpan = [&](double dt) {
        spanPhi.push_back(phi);
        spanGamma.push_back(gamma);
        spanDt.push_back(dt);
    };
    auto restore = [&](double dt) { // the matrices of the span stepped with dt
        for (std::size_t i = 0; i < spanDt.size(); ++i)
            if (spanDt[i] == dt) {
                phi = spanPhi[i];
                gamma = spanGamma[i];
                return;
            }
        discretize(dt); // not reached: every dt recorded is a span's
    };
    auto output = [&](const Vector& state) { return direct + c.dot(state); };
    auto slope = [&](const Vector& state) { return c.dot(a * state + b); }; // y' = C (A x + B)

    StepScan scan;
    scan.peak = direct;
    double spanEnd = firstSpan;
    double dt = firstSpan / samples;
    double t = 0.0;
    discretize(dt);
    keepSpan(dt);
    for (int span = 1;; ++span) {
        for (int k = 0; k < samples; ++k) {
            const double yk = output(x);
            if (yk > scan.peak) {
                scan.peak = yk;
                scan.peakTime = t;
                xPeak = x;
                xPeakPrev = xPrev;
                dtPeak = dt;
                dtPeakPrev = dtPrev;
            }
            if (std::abs(yk - finalValue) > bandAbs) {
                scan.tOutside = t;
                scan.yOutside = yk;
                scan.dtOutside = dt;
                xOutside = x;
            }
            xPrev = x;
            dtPrev = dt;
            next.noalias() = phi * x;
            x = next + gamma;
            t = spanEnd - (samples - 1 - k) * dt; // exact at the span end, no drift
        }
        scan.outsideAtEnd = std::abs(output(x) - finalValue) > bandAbs;
        if (spanEnd >= longestHorizon || (spanEnd >= horizon && !scan.outsideAtEnd))
            break;
        // The next span quadruples the time reached: its step is 3 times the first span's,
        // then 4 times the previous one's.
        const double nextDt = 3.0 * spanEnd / samples;
        spanEnd *= 4.0;
        if (span == 1)
            triple();
        else
            quadruple();
        dt = nextDt;
        keepSpan(dt);
    }
    const double yEnd = output(x);
    if (yEnd > scan.peak) {
        scan.peak = yEnd;
        scan.peakTime = t;
    }
    scan.tEnd = spanEnd;
    if (dtPeak > 0.0 && scan.peakTime > 0.0 && scan.peakTime < spanEnd) {
        // The true peak lies within a step of the largest sample: maximize the cubic Hermite
        // interpolants on both neighbouring steps (exact values and slopes at their ends, so
        // the error is O(dt^4) instead of the O(dt^2) of taking the sample).
        restore(dtPeak);
        next.noalias() = phi * xPeak;
        next += gamma;
        const double yp = output(xPeak), sp = slope(xPeak);
        const auto after = hermiteMaximum(yp, sp * dtPeak, output(next), slope(next) * dtPeak);
        const auto before =
            hermiteMaximum(output(xPeakPrev), slope(xPeakPrev) * dtPeakPrev, yp, sp * dtPeakPrev);
        if (after.first > scan.peak) {
            scan.peak = after.first;
            scan.peakTime += after.second * dtPeak;
        }
        if (before.first > scan.peak) {
            scan.peak = before.first;
            scan.peakTime -= (1.0 - before.second) * dtPeakPrev;
        }
    }
    if (scan.tOutside >= 0.0 && !scan.outsideAtEnd) {
        restore(scan.dtOutside);
        next.noalias() = phi * xOutside;
        next += gamma;
        scan.yAfter = output(next);
        scan.slopeOutside = slope(xOutside);
        scan.slopeAfter = slope(next);
    }
    return scan;
}

} // namespace

StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop, double band,
                                        int samples) {
    if (closedLoop.isDiscrete() || !closedLoop.isProper())
        throw InvalidInput("system", makeDiagnostic("not_continuous_proper"));
    return stepCharacteristics(closedLoop, closedLoop.poles(), band, samples);
}

StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop,
                                        const std::vector<std::complex<double>>& poles, double band,
                                        int samples) {
    if (closedLoop.isDiscrete() || !closedLoop.isProper())
        throw InvalidInput("system", makeDiagnostic("not_continuous_proper"));
    if (!(band > 0.0 && band < 1.0))
        throw InvalidInput("band", makeDiagnostic("sim_between_zero_one"));
    if (samples < 100)
        throw InvalidInput("samples", makeDiagnostic("at_least", {"100"}));
    StepCharacteristics out;
    // Same test as TransferFunction::isStable (real part < 0), on the poles already at hand.
    out.stable = std::all_of(poles.begin(), poles.end(),
                             [](const std::complex<double>& p) { return p.real() < 0.0; });
    if (!out.stable)
        return out;
    out.finalValue = closedLoop.dcGain();
    double slowest = std::numeric_limits<double>::infinity();
    double fastest = 0.0;
    for (const auto& p : poles) {
        slowest = std::min(slowest, -p.real());
        fastest = std::max(fastest, std::abs(p));
    }
    const StateSpace ss = realize(closedLoop);
    const double scale = std::max(std::abs(out.finalValue), 1e-300);
    const double bandAbs = band * scale;
    const double horizon = poles.empty() ? 1.0 : 12.0 / slowest;
    // Never inside the band within 12 * 32 time constants: then the horizon reached is reported.
    const double longestHorizon = horizon * 32.0;
    // Multi-scale time grid: a closed loop with a slow pole-zero pair (the PI zero of Braga et al.
    // with its nearby pole) settles on the time scale of its fast poles but needs a horizon set
    // by the slow one, up to 1e7 times longer. The first span [0, T0] has T0 = 50 / |p|max
    // (>= 125 samples per period of the fastest oscillation with the default 500); each later
    // span quadruples the time reached, with @p samples steps (dt = 3 t / samples).
    const double firstSpan = fastest > 0.0 ? std::min(horizon, 50.0 / fastest) : horizon;
    const StepScan scan =
        ss.states() == 4
            ? scanStep<4>(ss, out.finalValue, bandAbs, firstSpan, horizon, longestHorizon, samples)
            : scanStep<Eigen::Dynamic>(ss, out.finalValue, bandAbs, firstSpan, horizon,
                                       longestHorizon, samples);
    out.overshootPct = std::max(0.0, (scan.peak - out.finalValue) / scale * 100.0);
    out.peakTimeSeconds = scan.peakTime;
    if (scan.outsideAtEnd) {
        out.settlingTimeSeconds = scan.tEnd; // the horizon reached
        return out;
    }
    if (scan.tOutside < 0.0) {
        out.settlingTimeSeconds = 0.0;
        return out;
    }
    // Hermite interpolation on [t_k, t_k + dt] of y - final crossing +-band*scale, with the
    // exact derivative at both ends.
    const double dt = scan.dtOutside;
    const double y0 = scan.yOutside, y1 = scan.yAfter;
    const double m0 = scan.slopeOutside * dt, m1 = scan.slopeAfter * dt;
    const double target = out.finalValue + std::copysign(bandAbs, y0 - out.finalValue);
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
    out.settlingTimeSeconds = scan.tOutside + 0.5 * (lo + hi) * dt;
    return out;
}

} // namespace xyt
