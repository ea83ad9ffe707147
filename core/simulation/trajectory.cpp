// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/trajectory.h"

#include "core/model/errors.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

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
    if (!(tfSeconds > t0Seconds))
        throw InvalidInput("tf", "must be later than t0");
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
    if (rampInSeconds < 0.0)
        throw InvalidInput("ramp_in", "must be >= 0");
}

double Sinusoid::value(double t) const {
    const double envelope = (rampInSeconds > 0.0 && t < rampInSeconds) ? std::max(t, 0.0) / rampInSeconds : 1.0;
    return offset + amplitude * envelope * std::sin(omegaRadPerSec * t + phaseRad);
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

std::vector<double> sampleTimes(double durationSeconds, double dtSeconds) {
    requirePositive(dtSeconds, "dt");
    requireFinite(durationSeconds, "duration");
    if (durationSeconds < 0.0)
        throw InvalidInput("duration", "must be >= 0");
    const double count = std::floor(durationSeconds / dtSeconds + 1e-9) + 1.0;
    if (!(count <= static_cast<double>(kMaxSamples))) { // also inf (dt = 5e-324)
        char needs[32];
        std::snprintf(needs, sizeof needs, "%.3g", count); // never cast an out-of-range count
        throw InvalidInput("duration", std::string("needs ") +
                                           (std::isfinite(count) ? needs : "more than 1e308") +
                                           " samples at this dt; the limit is " +
                                           std::to_string(kMaxSamples));
    }
    std::vector<double> t(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < t.size(); ++k)
        t[k] = static_cast<double>(k) * dtSeconds;
    return t;
}

} // namespace xyt
