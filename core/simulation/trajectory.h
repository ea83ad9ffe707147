// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <vector>

namespace xyt {

/**
 * Cubic point-to-point trajectory, paper 000 Eq. 4: P(t) = p0 + p1 t + p2 t^2 + p3 t^3 on
 * [t0, tf], with P(t0) = x0, P'(t0) = v0, P(tf) = xf, P'(tf) = vf. Before t0 the reference holds
 * x0, after tf it holds xf.
 *
 * The conditions give the linear system (paper Eq. 5, corrected; the paper prints t0 for the 1 in
 * row 2 and 3 tf for 3 tf^2 in row 4):
 *   [1 t0 t0^2 t0^3; 0 1 2t0 3t0^2; 1 tf tf^2 tf^3; 0 1 2tf 3tf^2] p = [x0; v0; xf; vf].
 * It is solved in local time tau = t - t0 (closed form, well conditioned for any t0):
 *   P = x0 + v0 tau + (3 D - (2 v0 + vf) T) tau^2 / T^2 + (-2 D + (v0 + vf) T) tau^3 / T^3,
 * D = xf - x0, T = tf - t0; `coefficients()` expands that into the paper's absolute-time p.
 */
class CubicTrajectory {
public:
    /// @throws InvalidInput naming x0, v0, xf, vf, t0 or tf when not finite, or "tf" unless tf > t0.
    CubicTrajectory(double x0, double xf, double t0Seconds, double tfSeconds, double v0 = 0.0,
                    double vf = 0.0);

    double position(double tSeconds) const;
    double velocity(double tSeconds) const;
    /// p0..p3 of Eq. 4 in absolute time t.
    std::array<double, 4> coefficients() const;
    /// Coefficients of the local-time cubic in tau = t - t0.
    const std::array<double, 4>& localCoefficients() const { return local_; }
    double t0() const { return t0_; }
    double tf() const { return tf_; }
    double x0() const { return x0_; }
    double xf() const { return xf_; }

private:
    double x0_, xf_, t0_, tf_;
    std::array<double, 4> local_{};
};

/**
 * offset + A s(t) sin(omega t + phase), with an optional linear ramp-in envelope s(t) = t/Tr for
 * t < Tr (s = 1 afterwards, and always when Tr = 0). The ramp-in is the paper's remedy (000,
 * Sec. 3.4) for starting a cosine far from the table's rest position at the origin.
 */
struct Sinusoid {
    double amplitude = 1.0;
    double omegaRadPerSec = 1.0;
    double phaseRad = 0.0;
    double offset = 0.0;
    double rampInSeconds = 0.0;

    /// @throws InvalidInput naming the field when not finite, or rampInSeconds < 0.
    void validate() const;
    double value(double tSeconds) const;
};

/**
 * The circle contour of paper 000 Eq. 23-24: x = cx + R sin(omega t), y = cy + R cos(omega t)
 * (25 mm at 0.06 rad/s there; 30 mm at 0.1 rad/s in paper 001). Each axis follows one sinusoid.
 */
struct Circle {
    double radius = 25.0;
    double omegaRadPerSec = 0.06;
    double centreX = 0.0;
    double centreY = 0.0;
    double rampInSeconds = 0.0;

    Sinusoid xAxis() const;
    Sinusoid yAxis() const;
    /// One revolution, 2 pi / omega.
    double periodSeconds() const;
};

/// Samples f(k dt) for k = 0 .. n-1 where n = floor(duration/dt + 1e-9) + 1.
/// @throws InvalidInput "dt" unless dt > 0, "duration" unless >= 0 and the sample count fits in
///         memory (at most kMaxSamples).
std::vector<double> sampleTimes(double durationSeconds, double dtSeconds);
template <class F> std::vector<double> sampled(const F& f, const std::vector<double>& times) {
    std::vector<double> v(times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
        v[i] = f(times[i]);
    return v;
}

/// The most samples one simulation may hold (each sample stores a few doubles): 20 million.
inline constexpr std::size_t kMaxSamples = 20'000'000;

} // namespace xyt
