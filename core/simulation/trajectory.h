// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/// A reference and its first three time derivatives at one instant (mm, mm/s, mm/s^2, mm/s^3):
/// what a feedforward reads from the trajectory generator.
struct MotionSample {
    double position = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
    double jerk = 0.0;
};

/**
 * A position and its derivatives by central differences of step @p h from its values at
 * t - 2h, t - h, t, t + h, t + 2h: r' = (r(t+h) - r(t-h))/2h, r'' = (r(t+h) - 2 r(t) + r(t-h))/h^2,
 * r''' = (r(t+2h) - 2 r(t+h) + 2 r(t-h) - r(t-2h))/2h^3 (each second order in h).
 */
inline MotionSample centralDifferenceMotion(double m2, double m1, double p, double p1, double p2,
                                            double h) {
    return {p, (p1 - m1) / (2.0 * h), (p1 - 2.0 * p + m1) / (h * h),
            (p2 - 2.0 * p1 + 2.0 * m1 - m2) / (2.0 * h * h * h)};
}

/**
 * Cubic point-to-point trajectory, Braga et al. Eq. 4: P(t) = p0 + p1 t + p2 t^2 + p3 t^3 on
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
    /// @throws InvalidInput naming x0, v0, xf, vf, t0 or tf when not finite, or "tf" unless tf >
    /// t0.
    CubicTrajectory(double x0, double xf, double t0Seconds, double tfSeconds, double v0 = 0.0,
                    double vf = 0.0);

    double position(double tSeconds) const;
    double velocity(double tSeconds) const;
    /// The position and its derivatives: inside (t0, tf) those of the cubic (a constant jerk
    /// 6 p3), outside it the held position with zero derivatives. The acceleration steps at t0
    /// and tf (to 2 p2 and from 2 p2 + 6 p3 T): a model-inverse feedforward's jerk term cannot
    /// follow a step, which is why machine builders use the quintic.
    MotionSample motion(double tSeconds) const;
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
 * The quintic point-to-point move machine builders use: P(t) on [t0, tf] from x0 at velocity v0
 * to xf at velocity vf with zero acceleration at both ends, so that the acceleration is
 * continuous everywhere (the jerk steps, the acceleration does not). In local time tau = t - t0,
 * T = tf - t0, D = xf - x0, A = D - v0 T, B = vf - v0:
 *   P = x0 + v0 tau + c3 tau^3 + c4 tau^4 + c5 tau^5 with
 *   c3 T^3 = 10 A - 4 B T, c4 T^4 = -15 A + 7 B T, c5 T^5 = 6 A - 3 B T
 * (the three end conditions P(tf) = xf, P'(tf) = vf, P''(tf) = 0 solved in closed form; at rest,
 * v0 = vf = 0, the classical 10 s^3 - 15 s^4 + 6 s^5 of s = tau/T). Before t0 it holds x0, after
 * tf it holds xf.
 */
class QuinticTrajectory {
public:
    /// @throws InvalidInput as CubicTrajectory.
    QuinticTrajectory(double x0, double xf, double t0Seconds, double tfSeconds, double v0 = 0.0,
                      double vf = 0.0);
    double position(double tSeconds) const { return motion(tSeconds).position; }
    MotionSample motion(double tSeconds) const;
    /// Coefficients of the local-time quintic in tau = t - t0 (c0 .. c5).
    const std::array<double, 6>& localCoefficients() const { return local_; }

private:
    double x0_, xf_, t0_, tf_;
    std::array<double, 6> local_{};
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
    /// The value and its derivatives; during the ramp-in those of (A/Tr) t sin(omega t + phase).
    MotionSample motion(double tSeconds) const;
};

/**
 * The circle contour of Braga et al. Eq. 23-24: x = cx + R sin(omega t), y = cy + R cos(omega t)
 * (25 mm at 0.06 rad/s there; 30 mm at 0.1 rad/s in Patrick, Ishak and Adnan). Each axis follows
 * one sinusoid.
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

/**
 * The largest position, velocity (per second), amplitude or radius a trajectory may have:
 * 1e9 mm (1000 km). No XY table spans more than a few metres (1e3..1e4 mm), so this leaves five
 * decades for experiments in finer units (um, nm), yet keeps everything the simulation and the
 * metrics compute from it far from overflow: a squared error is at most ~1e18, an ITAE sum over
 * kMaxSamples samples of 1e9 mm for 1e9 s below 1e36, and a pole-placement command (gains are
 * bounded by 1e100 in pole_placement.cpp) below 1e109, where 1e308 is the double's limit.
 * A larger value (xf = 1e308) used to overflow the reference or give null metrics beside finite
 * ones; it is refused up front instead.
 */
inline constexpr double kMaxPositionMm = 1e9;

/// @throws InvalidInput naming @p field unless @p value is finite and |value| <= kMaxPositionMm.
void requirePosition(double value, const std::string& field);

/// Samples f(k dt) for k = 0 .. n-1 where n = floor(duration/dt + 1e-9) + 1.
/// @throws InvalidInput "dt" unless dt > 0, "duration" unless >= 0 and the sample count fits in
///         this machine's memory (at most sampleLimit(), see there).
std::vector<double> sampleTimes(double durationSeconds, double dtSeconds);
template <class F> std::vector<double> sampled(const F& f, const std::vector<double>& times) {
    std::vector<double> v(times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
        v[i] = f(times[i]);
    return v;
}

/// The most samples one simulation may hold on any machine: 20 million.
inline constexpr std::size_t kMaxSamples = 20'000'000;

/**
 * What one time sample costs the heaviest user, in bytes: peak resident memory of
 * `xytune-cli report` (and `export`, which holds the same evaluation) on a session of two
 * pole-placement + ZPETC axes was 200.5 B per sample above the program's own 10 MB (2 000 001
 * samples: 401 848 KB; two GT axes take 94 B, `contour` 144 B, `zpetc` 88 B, measured the same
 * way with GNU time). Rounded up to 256 B for the GUI's plot copies of the same run.
 */
inline constexpr double kBytesPerSample = 256.0;

/// The share of physical memory one run may take: a quarter, so that the GUI (which keeps a
/// snapshot beside the session), the desktop and a second program still fit.
inline constexpr double kSampleMemoryFraction = 0.25;

/// floor(kSampleMemoryFraction * memoryBytes / kBytesPerSample), never above kMaxSamples
/// (kMaxSamples when memoryBytes is not a positive number).
std::size_t sampleLimitForMemory(double memoryBytes);

/// Physical memory of this machine, sysconf(_SC_PHYS_PAGES) * sysconf(_SC_PAGESIZE) in bytes
/// (0 when unknown). The environment variable XYT_TEST_PHYSICAL_MEMORY_BYTES replaces it, so
/// that tests can play a smaller machine.
double physicalMemoryBytes();

/// The most samples a run may hold on this machine: sampleLimitForMemory(physicalMemoryBytes()),
/// read once per process.
std::size_t sampleLimit();

} // namespace xyt
