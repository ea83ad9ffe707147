// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <vector>

namespace xyt {

/**
 * The friction experiment's program: closed-loop jogs of one axis back and forth at each speed,
 * whose constant-velocity parts give one point each of the Stribeck curve
 * (friction_identification.h). Lengths in mm, times in s.
 */
struct JogProgram {
    /// Cruise speeds (mm/s, each > 0), jogged in this order; at most kMaxJogSpeeds.
    std::vector<double> speedsMmPerS;
    /// Length of each move (mm, > 0): from 0 to +travel and back.
    double travelMm = 20;
    /// Acceleration of the ramps (mm/s^2, > 0).
    double accelMmPerS2 = 100;
    /// Rest before the first move and after every move (s, >= 0).
    double dwellSeconds = 1;
    /// Sampling period of the reference (s, > 0).
    double tsSeconds = 0.01;
};

/// The constant-velocity (cruise) part of one move: from startSeconds to endSeconds the
/// reference moves at velocityMmPerS (signed: + for the move out, - for the move back).
struct JogSegment {
    double startSeconds = 0;
    double endSeconds = 0;
    double velocityMmPerS = 0;
};

/// The sampled reference: position[k] (mm) at t[k] = k Ts, and the cruise of every move in time
/// order (two per speed: out, then back).
struct JogReference {
    std::vector<double> t;
    std::vector<double> position;
    std::vector<JogSegment> segments;
};

/// The most speeds a jog program may hold.
inline constexpr std::size_t kMaxJogSpeeds = 64;

/// The most samples a jog reference may have: 10^7 (over 27 hours at 10 ms).
inline constexpr std::size_t kMaxJogSamples = 10'000'000;

/**
 * The jog program's position reference. The axis rests at 0 for one dwell; then for each speed
 * V in the given order: a move of D = travel in the + direction, a dwell, the same move in the
 * - direction back to 0, a dwell. Each move is a trapezoid in velocity with A = accel: a ramp of
 * t_a = V / A (covering V^2 / (2 A)), a cruise at V of t_c = D / V - V / A, a ramp down of t_a;
 * the move lasts T = D / V + V / A. With tau the time since the move began and sigma = +-1 its
 * direction, the position is (closed form, evaluated at each sample)
 * \f[ p(\tau) = p_0 + \sigma \begin{cases} A \tau^2 / 2 & \tau < t_a \\
 *     V^2 / (2 A) + V (\tau - t_a) & \tau < t_a + t_c \\
 *     D - A (T - \tau)^2 / 2 & \tau < T \\ D & \text{after.} \end{cases} \f]
 * The samples are t[k] = k Ts for k = 0 .. n-1, n - 1 = ceil(duration / Ts) (a quotient within
 * 1e-9 of a whole number counts as that number), so the last sample is at or after the end of
 * the last dwell, at rest at 0.
 * The cruise must last at least half of each move (t_c >= T / 2, i.e. D >= 3 V^2 / A), so that
 * a steady part remains after the loop's transient.
 * @throws InvalidInput naming the field: "speeds" (empty, more than kMaxJogSpeeds, a speed not
 *         finite or <= 0), "travel" (not finite or <= 0, or shorter than 3 V^2 / A for some
 *         speed), "accel" (not finite or <= 0), "dwell" (not finite or < 0), "ts" (not finite or
 *         <= 0, or more than kMaxJogSamples samples over the program's duration).
 */
JogReference jogReference(const JogProgram& program);

} // namespace xyt
