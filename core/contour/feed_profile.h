// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/gcode_reader.h"
#include "core/contour/path.h"

#include <cstddef>
#include <vector>

namespace xyt {

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
 * @throws InvalidInput "feed" when the sizes differ or a feed is not finite and > 0 (naming the
 *         segment), "max_accel" unless finite and > 0, "max_jerk" unless finite and >= 0,
 *         "corner_angle" unless in [0, 180), "dt" unless finite and > 0, "dt" when the samples
 *         would be more than maxSamples.
 */
FeedProfile planFeedProfile(const Path& path, const std::vector<double>& feedMmPerSec,
                            const FeedProfileOptions& options);

/// The feed of each segment of a read program (mm/s): feed moves at @p feedScale times their F,
/// rapids at their rate. @throws InvalidInput "feed_scale" unless finite and > 0.
std::vector<double> programFeeds(const GcodeProgram& program, double feedScale);

/// planFeedProfile(program.path, programFeeds(program, options.feedScale), options).
FeedProfile planFeedProfile(const GcodeProgram& program, const FeedProfileOptions& options);

/**
 * Distance to change speed from @p v0 to @p v1 (either order, mm/s) with acceleration limit
 * @p accel and jerk limit @p jerk (0: none): (v0 + v1)/2 times the time, which is
 * |dv|/A + A/J when |dv| >= A^2/J and 2 sqrt(|dv|/J) otherwise (|dv|/A without jerk).
 */
double speedChangeDistance(double v0, double v1, double accel, double jerk);
/// The time of that change (s).
double speedChangeTime(double v0, double v1, double accel, double jerk);

} // namespace xyt
