// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/gcode_reader.h"
#include "core/contour/path.h"

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/**
 * The range of the planner's rates: feeds (mm/s), accelerations (mm/s^2) and jerks (mm/s^3)
 * outside [kMinProfileRate, kMaxProfileRate] are refused (a jerk may also be 0: none). Why:
 * one intermediate of the S-curve combines up to three rates (the speed A^2/J at which the
 * acceleration limit is reached, the distance v (dv/A + A/J)); for it to stay a normal double
 * (2.2e-308 .. 1.8e308) each rate must lie within the cube root of that range, 1.6e-103 ..
 * 5.6e102, rounded inwards to a power of ten. Products with a length (A L, L / v; G-code lengths
 * lie within 1e-40 .. 2e16 mm) then stay within 1e-140 .. 1e117. No machine comes near either end:
 * these bound what a file may ask for, not what is sensible.
 */
inline constexpr double kMinProfileRate = 1e-100;
inline constexpr double kMaxProfileRate = 1e100;

struct FeedProfileOptions {
    /// Multiplies every programmed feed (G1/G2/G3; the feed override of a control). Rapids
    /// keep their rate.
    double feedScale = 1.0;
    /// Largest tangential acceleration and deceleration along the path (mm/s^2), and the
    /// limit of the centripetal acceleration on arcs: v^2 / R <= maxAccel.
    double maxAccelMmPerS2 = 500.0;
    /// Largest tangential jerk (mm/s^3) for an S-curve; 0: none (a trapezoidal profile).
    double maxJerkMmPerS3 = 0.0;
    /**
     * A join turning by more than this is a sharp corner, where the profile stops (degrees).
     * Joins turning less keep their speed (the lower of the two segments' limits). 1 degree:
     * a tangent join written with 3 decimals turns by well under 0.2 degree on a 0.5 mm arc,
     * and a 1-degree kink at 20 mm/s steps the velocity by 0.35 mm/s, which a servo loop
     * absorbs as a small transient.
     */
    double cornerAngleDeg = 1.0;
    /// The sample step of x(t), y(t) (s).
    double dtSeconds = 0.001;
    /// The most samples the profile may hold (the caller passes the machine's sample limit).
    std::size_t maxSamples = 20'000'000;
    /// false: plan the pieces and the run time only, without the sample vectors (a summary);
    /// the bound on the samples at dt is checked all the same.
    bool withSamples = true;
};

/**
 * One piece of the profile: over t in [t0, t0 + duration] the path position is the cubic
 * s(t) = s0 + v0 tau + a0 tau^2 / 2 + jerk tau^3 / 6, tau = t - t0, on one segment (jerk = 0
 * for the constant-acceleration pieces of a trapezoid).
 */
struct FeedPiece {
    double t0 = 0.0;
    double duration = 0.0;
    double s0 = 0.0;
    double v0 = 0.0;
    double a0 = 0.0;
    double jerk = 0.0;
    std::size_t segment = 0;
};

/**
 * A feed-rate profile along a path and its samples at dt.
 *
 * Planning (the look-ahead of a CNC control, as GRBL's planner): each segment's speed limit is
 * its feed, and on an arc also sqrt(maxAccel R) (centripetal limit). A sharp corner
 * (cornerAngleDeg) and both ends of the path are junctions of speed 0; any other join passes at
 * the lower of its two segments' limits. A backward then a forward pass lower each junction
 * speed to what the deceleration to the next junction, and the acceleration from the previous
 * one, allow over the segment between. Each segment then accelerates from its entry speed to
 * a peak (its limit, or what its length allows), cruises, and decelerates to its exit speed:
 * constant-acceleration phases (trapezoid), or with maxJerk three-phase S-curves (jerk up,
 * constant acceleration, jerk down) whose acceleration is zero at every segment join, which is
 * conservative on programs of many short segments. The jerk bound is tangential: the normal
 * acceleration v^2/R steps where the curvature does (a line meeting an arc).
 *
 * The samples are t_k = k dt up to the first k dt >= totalTime (the last sample holds the end).
 */
struct FeedProfile {
    std::vector<FeedPiece> pieces;
    std::vector<double> junctionSpeed; ///< mm/s at each segment start, size() + 1 with the end
    std::vector<std::size_t> corners;  ///< joins where the profile stops (sharpCorners)
    double totalTimeSeconds = 0.0;
    double dtSeconds = 0.0;
    /// The samples: time, path position, speed, tangential acceleration, the reference point,
    /// and the segment each sample lies on.
    std::vector<double> t, s, v, a, x, y;
    std::vector<std::size_t> segment;
};

/**
 * The profile along @p path with @p feedMmPerSec per segment (feedScale is not applied here).
 *
 * What can be planned: the profile is sampled at dt, at most maxSamples samples, so its run
 * time T may be at most (maxSamples - 1) dt (the session's and the CLI's runs hold no more).
 * Each option alone sets a lower bound on T over a path of length L, whatever the others:
 * the feeds sum(L_i / f_i) (every segment at its feed); the acceleration 2 sqrt(L / A) (from
 * rest to rest, as every profile runs); the jerk 4 (L / 2J)^(1/3) (rest to rest with the
 * acceleration zero at both ends: jerk +J, -J, -J, +J for a quarter of the time each). An option
 * whose bound alone passes the limit is refused by its name, with both times; options that only
 * together pass it are refused by "dt" once planned. A jerk of 1e-200 mm/s^3 over 10 mm thus
 * needs 3.2e67 s. Every result has at least one piece per segment and one sample.
 *
 * @throws InvalidInput "feed" when the sizes differ, a feed is not finite or outside
 *         [kMinProfileRate, kMaxProfileRate] (naming the segment), or the feeds alone need more
 *         time than the samples hold; "max_accel" unless finite and within that range, or when
 *         it alone needs more time; "max_jerk" likewise (0 allowed); "corner_angle" unless in
 *         [0, 180); "dt" unless finite and > 0, or when the samples would be more than
 *         maxSamples.
 */
FeedProfile planFeedProfile(const Path& path, const std::vector<double>& feedMmPerSec,
                            const FeedProfileOptions& options);

/// The feed of each segment of a read program (mm/s): feed moves at @p feedScale times their F,
/// rapids at their rate. @throws InvalidInput "feed_scale" unless finite and > 0, or when it
/// takes a feed outside [kMinProfileRate, kMaxProfileRate] (naming the line); "rapid_feed" when
/// a rapid's rate is outside that range.
std::vector<double> programFeeds(const GcodeProgram& program, double feedScale);

/**
 * planFeedProfile(program.path, programFeeds(program, options.feedScale), options), with the
 * feeds' time bound (see above) named by its cause: "dt" when the feed moves at their own F
 * words need more time than the samples hold (the step is too fine for the program),
 * "rapid_feed" when the rapids alone do, "feed_scale" when the program fits at scale 1 but not
 * at the scale given, else "feed" (the two together).
 */
FeedProfile planFeedProfile(const GcodeProgram& program, const FeedProfileOptions& options);

/**
 * @throws InvalidInput @p field unless @p rate is finite and within [kMinProfileRate,
 *         kMaxProfileRate] (or 0 when @p zeroAllowed: a jerk of 0 is none); @p unit names it.
 */
void requireProfileRate(double rate, const std::string& field, const Diagnostic& unit,
                        bool zeroAllowed = false);

/**
 * Distance to change speed from @p v0 to @p v1 (either order, mm/s) with acceleration limit
 * @p accel and jerk limit @p jerk (0: none): (v0 + v1)/2 times the time, which is
 * |dv|/A + A/J when |dv| >= A^2/J and 2 sqrt(|dv|/J) otherwise (|dv|/A without jerk).
 */
double speedChangeDistance(double v0, double v1, double accel, double jerk);
/// The time of that change (s).
double speedChangeTime(double v0, double v1, double accel, double jerk);

} // namespace xyt
