// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/trajectory.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include <unistd.h>

namespace xyt {

CubicTrajectory::CubicTrajectory(double x0, double xf, double t0Seconds, double tfSeconds,
                                 double v0, double vf)
    : x0_(x0), xf_(xf), t0_(t0Seconds), tf_(tfSeconds) {
    requireFinite(x0, "x0");
    requireFinite(xf, "xf");
    requireFinite(t0Seconds, "t0");
    requireFinite(tfSeconds, "tf");
    requireFinite(v0, "v0");
    requireFinite(vf, "vf");
    requirePosition(x0, "x0");
    requirePosition(xf, "xf");
    requirePosition(v0, "v0");
    requirePosition(vf, "vf");
    if (!(tfSeconds > t0Seconds))
        throw InvalidInput("tf", makeDiagnostic("sim_tf_after_t0"));
    const double T = tfSeconds - t0Seconds;
    const double D = xf - x0;
    local_ = {x0, v0, (3.0 * D - (2.0 * v0 + vf) * T) / (T * T),
              (-2.0 * D + (v0 + vf) * T) / (T * T * T)};
}

double CubicTrajectory::position(double t) const {
    if (t <= t0_)
        return x0_;
    if (t >= tf_)
        return xf_;
    const double tau = t - t0_;
    return local_[0] + tau * (local_[1] + tau * (local_[2] + tau * local_[3]));
}

double CubicTrajectory::velocity(double t) const {
    if (t < t0_ || t > tf_)
        return 0.0;
    const double tau = t - t0_;
    return local_[1] + tau * (2.0 * local_[2] + tau * 3.0 * local_[3]);
}

MotionSample CubicTrajectory::motion(double t) const {
    if (t <= t0_ || t >= tf_)
        return {position(t), 0.0, 0.0, 0.0};
    const double tau = t - t0_;
    const auto& l = local_;
    return {position(t), velocity(t), 2.0 * l[2] + 6.0 * l[3] * tau, 6.0 * l[3]};
}

QuinticTrajectory::QuinticTrajectory(double x0, double xf, double t0Seconds, double tfSeconds,
                                     double v0, double vf)
    : x0_(x0), xf_(xf), t0_(t0Seconds), tf_(tfSeconds) {
    // The cubic's checks, with the same fields and messages.
    const CubicTrajectory checked(x0, xf, t0Seconds, tfSeconds, v0, vf);
    const double T = tfSeconds - t0Seconds;
    const double A = xf - x0 - v0 * T;
    const double B = vf - v0;
    local_ = {x0,
              v0,
              0.0,
              (10.0 * A - 4.0 * B * T) / (T * T * T),
              (-15.0 * A + 7.0 * B * T) / (T * T * T * T),
              (6.0 * A - 3.0 * B * T) / (T * T * T * T * T)};
}

MotionSample QuinticTrajectory::motion(double t) const {
    if (t <= t0_)
        return {x0_, 0.0, 0.0, 0.0};
    if (t >= tf_)
        return {xf_, 0.0, 0.0, 0.0};
    const double tau = t - t0_;
    const auto& c = local_;
    MotionSample m;
    m.position = c[0] + tau * (c[1] + tau * (c[2] + tau * (c[3] + tau * (c[4] + tau * c[5]))));
    m.velocity =
        c[1] + tau * (2.0 * c[2] + tau * (3.0 * c[3] + tau * (4.0 * c[4] + tau * 5.0 * c[5])));
    m.acceleration = 2.0 * c[2] + tau * (6.0 * c[3] + tau * (12.0 * c[4] + tau * 20.0 * c[5]));
    m.jerk = 6.0 * c[3] + tau * (24.0 * c[4] + tau * 60.0 * c[5]);
    return m;
}

std::array<double, 4> CubicTrajectory::coefficients() const {
    // P(t) = sum_k l_k (t - t0)^k, expanded binomially.
    const double a = -t0_;
    const auto& l = local_;
    return {l[0] + l[1] * a + l[2] * a * a + l[3] * a * a * a,
            l[1] + 2.0 * l[2] * a + 3.0 * l[3] * a * a, l[2] + 3.0 * l[3] * a, l[3]};
}

void Sinusoid::validate() const {
    requireFinite(amplitude, "amplitude");
    requireFinite(omegaRadPerSec, "omega");
    requireFinite(phaseRad, "phase");
    requireFinite(offset, "offset");
    requireFinite(rampInSeconds, "ramp_in");
    requirePosition(amplitude, "amplitude");
    requirePosition(offset, "offset");
    if (rampInSeconds < 0.0)
        throw InvalidInput("ramp_in", makeDiagnostic("not_negative"));
}

double Sinusoid::value(double t) const {
    const double envelope =
        (rampInSeconds > 0.0 && t < rampInSeconds) ? std::max(t, 0.0) / rampInSeconds : 1.0;
    return offset + amplitude * envelope * std::sin(omegaRadPerSec * t + phaseRad);
}

MotionSample Sinusoid::motion(double t) const {
    const double w = omegaRadPerSec;
    const double th = w * t + phaseRad;
    const double sn = std::sin(th), cs = std::cos(th);
    if (rampInSeconds > 0.0 && t < rampInSeconds) {
        if (t <= 0.0)
            return {offset, 0.0, 0.0, 0.0};
        // d^n/dt^n of (A/Tr) t sin(th) by Leibniz: t f^(n) + n f^(n-1), f = sin(th).
        const double k = amplitude / rampInSeconds;
        return {offset + k * t * sn, k * (sn + w * t * cs), k * (2.0 * w * cs - w * w * t * sn),
                k * (-3.0 * w * w * sn - w * w * w * t * cs)};
    }
    const double a = amplitude;
    return {offset + a * sn, a * w * cs, -a * w * w * sn, -a * w * w * w * cs};
}

Sinusoid Circle::xAxis() const {
    return {radius, omegaRadPerSec, 0.0, centreX, rampInSeconds};
}

Sinusoid Circle::yAxis() const {
    return {radius, omegaRadPerSec, std::numbers::pi / 2.0, centreY, rampInSeconds};
}

double Circle::periodSeconds() const {
    requirePositive(std::abs(omegaRadPerSec), "omega");
    return 2.0 * std::numbers::pi / std::abs(omegaRadPerSec);
}

void requirePosition(double value, const std::string& field) {
    requireFinite(value, field);
    if (!(std::abs(value) <= kMaxPositionMm)) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.6g", value);
        throw InvalidInput(field,
                           makeDiagnostic("sim_position_beyond_limit", {std::string(shown)}));
    }
}

std::size_t sampleLimitForMemory(double memoryBytes) {
    if (!(memoryBytes > 0.0) || !std::isfinite(memoryBytes))
        return kMaxSamples;
    const double fits = std::floor(kSampleMemoryFraction * memoryBytes / kBytesPerSample);
    return fits < static_cast<double>(kMaxSamples) ? static_cast<std::size_t>(fits) : kMaxSamples;
}

double physicalMemoryBytes() {
    if (const char* injected = std::getenv("XYT_TEST_PHYSICAL_MEMORY_BYTES"))
        return std::strtod(injected, nullptr);
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGESIZE);
    return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize)
                                     : 0.0;
}

std::size_t sampleLimit() {
    static const std::size_t limit = sampleLimitForMemory(physicalMemoryBytes());
    return limit;
}

std::vector<double> sampleTimes(double durationSeconds, double dtSeconds) {
    requirePositive(dtSeconds, "dt");
    requireFinite(durationSeconds, "duration");
    if (durationSeconds < 0.0)
        throw InvalidInput("duration", makeDiagnostic("not_negative"));
    const double count = std::floor(durationSeconds / dtSeconds + 1e-9) + 1.0;
    const std::size_t limit = sampleLimit();
    if (!(count <= static_cast<double>(limit))) { // also inf (dt = 5e-324)
        char needs[32], memory[32];
        std::snprintf(needs, sizeof needs, "%.3g", count); // never cast an out-of-range count
        std::snprintf(memory, sizeof memory, "%.3g", physicalMemoryBytes() / 1e9);
        const Diagnostic needed =
            std::isfinite(count) ? Diagnostic(needs) : makeDiagnostic("sim_more_than", {"1e308"});
        throw InvalidInput(
            "duration",
            limit < kMaxSamples
                ? makeDiagnostic("sim_samples_beyond_memory",
                                 {needed, std::to_string(limit),
                                  std::to_string(static_cast<int>(kSampleMemoryFraction * 100)),
                                  memory, std::to_string(static_cast<int>(kBytesPerSample))})
                : makeDiagnostic("sim_samples_beyond_limit", {needed, std::to_string(limit)}));
    }
    std::vector<double> t(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < t.size(); ++k)
        t[k] = static_cast<double>(k) * dtSeconds;
    return t;
}

} // namespace xyt
