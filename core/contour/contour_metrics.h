// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/path.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace xyt {

struct ContourErrorOptions {
    /// Joins turning by more than this are the sharp corners whose overshoot is reported
    /// (degrees; the feed profile's cornerAngleDeg).
    double cornerAngleDeg = 1.0;
    /// A sample belongs to a corner when its nearest path position is within this distance of
    /// the corner along the path (mm).
    double cornerWindowMm = 1.0;
    /// Per path segment: false to leave samples nearest to it out of the statistics (G0
    /// rapids, whose accuracy nobody judges). Empty: every segment counts.
    std::vector<bool> measuredSegments;
};

/// The largest contour error near one sharp corner.
struct CornerOvershoot {
    std::size_t join = 0;      ///< the corner is the start of this segment
    double pathPosition = 0.0; ///< s of the corner (mm)
    Point2 corner;             ///< the corner's point
    double maxAbsError = 0.0;  ///< max |e| of the samples near it (mm); 0 when none is
    double signedError = 0.0;  ///< e there (mm, + left of travel)
    double timeSeconds = 0.0;  ///< when
    std::size_t samples = 0;   ///< samples within the window
};

/**
 * The contour error of a traced path: per sample, the signed perpendicular distance e from the
 * programmed path to the traced point (PathProjection::signedDistance: positive LEFT of the
 * direction of travel, so on a counter-clockwise circle positive inside), the arc-length
 * position and segment of the nearest path point; statistics over the measured samples.
 */
struct ContourErrorResult {
    std::vector<double> error;        ///< e_k (mm)
    std::vector<double> pathPosition; ///< s_k of the nearest point (mm)
    std::vector<std::size_t> segment; ///< its segment
    std::vector<bool> measured;       ///< whether sample k enters the statistics
    std::size_t measuredSamples = 0;
    double maxAbs = 0.0; ///< max |e_k| over the measured samples
    double rms = 0.0;    ///< sqrt(mean e_k^2) over them
    /// Where the maximum is: sample index, time, e with its sign, path position, traced point.
    std::size_t maxIndex = 0;
    double maxTimeSeconds = 0.0;
    double maxSignedError = 0.0;
    double maxPathPosition = 0.0;
    Point2 maxPoint;
    std::vector<CornerOvershoot> corners; ///< one per sharp corner, in path order
};

/**
 * Contour error of the traced points (x_k, y_k) at times t_k against @p path. Each query starts
 * from the previous sample's segment (Path::nearest), so a run costs O(n log segments).
 * @throws InvalidInput "traced" when t, x, y differ in size, are empty or hold a non-finite
 *         value; "measured_segments" when its size is neither 0 nor path.size();
 *         "corner_window" unless finite and >= 0.
 */
ContourErrorResult contourError(const Path& path, const std::vector<double>& t,
                                const std::vector<double>& x, const std::vector<double>& y,
                                const ContourErrorOptions& options = {});

/// A least-squares circle.
struct CircleFit {
    Point2 centre;
    double radius = 0.0;
    bool geometric = false; ///< refined by Gauss-Newton (else the algebraic fit alone)
    int iterations = 0;     ///< Gauss-Newton iterations taken
};

/**
 * The algebraic (Kasa) circle: the c, R minimizing sum (|p_i - c|^2 - R^2)^2, a linear least
 * squares problem in (c, R^2 - |c|^2) solved by QR (Eigen) on coordinates taken relative to
 * the points' mean. Exact for points on a circle; biased towards smaller radii for points
 * on part of one.
 * @throws InvalidInput "points" for sizes that differ, fewer than 3 points, non-finite values
 *         or collinear points.
 */
CircleFit fitCircleKasa(const std::vector<double>& x, const std::vector<double>& y);
/**
 * The geometric least-squares circle, minimizing sum (|p_i - c| - R)^2 (the least-squares
 * circle of ISO 230-4): Gauss-Newton from the Kasa circle, at most 50 iterations, until the
 * step is below 1e-13 of the radius. If an iteration fails (not finite) the Kasa circle is
 * returned with geometric = false.
 * @throws InvalidInput as fitCircleKasa.
 */
CircleFit fitCircleGeometric(const std::vector<double>& x, const std::vector<double>& y);

/// The nominal circle of a circular test (the programmed one).
struct NominalCircle {
    Point2 centre;
    double radius = 0.0;
};

struct Iso230Options {
    /// Half-width of the window around each axis reversal (degrees about the nominal centre).
    double reversalWindowDeg = 10.0;
    /// Use the geometric least-squares circle (ISO 230-4) rather than the Kasa circle alone.
    bool geometricFit = true;
};

/// The radial excursion around one quadrant change (an axis reversal).
struct ReversalSpike {
    double angleDeg = 0.0;   ///< 0, 90, 180 or 270 about the nominal centre
    char axis = 'x';         ///< the axis whose velocity reverses there ('x' at 0 and 180)
    double heightMm = 0.0;   ///< largest |dr - median dr| in the window, with its sign
    Point2 point;            ///< the traced point where it is
    std::size_t samples = 0; ///< samples within the window
};

/**
 * The circular test of ISO 230-4 on a traced circle (the conventions of ISO 230-4:2005, Sec. 3):
 *   - circular deviation G: the range of the radial distances r_i = |p_i - c_LS| about the
 *     least-squares circle's centre, max r_i - min r_i (the radial separation of the two
 *     circles about c_LS that enclose the path);
 *   - radial deviation F: against the nominal circle, F max = max (|p_i - c0| - R0) and
 *     F min = min (|p_i - c0| - R0);
 *   - circular hysteresis H (two runs, one clockwise and one counter-clockwise): the largest
 *     difference of the two runs' radii at the same angle about the least-squares centre of
 *     both runs together, each run's radius interpolated linearly in angle at the other's
 *     sample angles; and the bidirectional circular deviation G(b), the range of both runs'
 *     radii about that common centre. Each run should cover the whole circle;
 *   - reversal spikes: around each quadrant change (0, 90, 180, 270 degrees about the nominal
 *     centre, where one axis reverses), the radial deviation about the least-squares circle
 *     whose distance from the window's median is largest, with its sign (+ outward).
 * A ballbar's radius, as the table's, is in mm; so is everything here.
 */
struct Iso230Circular {
    CircleFit leastSquares;          ///< of the (first) run
    double circularDeviationG = 0.0; ///< of the first run (mm)
    /// The radii of the two circles about leastSquares.centre that enclose the first run (mm):
    /// G = maxRadiusAboutLeastSquares - minRadiusAboutLeastSquares (what a polar plot draws).
    double minRadiusAboutLeastSquares = 0.0;
    double maxRadiusAboutLeastSquares = 0.0;
    double radialDeviationFMax = 0.0;
    double radialDeviationFMin = 0.0;
    std::optional<double> hysteresisH;    ///< two runs only
    std::optional<double> bidirectionalG; ///< two runs only
    std::optional<CircleFit> bidirectionalLeastSquares;
    std::vector<ReversalSpike> reversalSpikes; ///< of the first run, in angle order
    std::size_t samples = 0;
};

/// @throws InvalidInput "points" as fitCircleKasa, "nominal_radius" unless > 0, "nominal_centre"
///         unless finite, "reversal_window" unless in (0, 45].
Iso230Circular iso230Circular(const std::vector<double>& x, const std::vector<double>& y,
                              const NominalCircle& nominal, const Iso230Options& options = {});
/// Both directions: @p x, @p y one run, @p x2, @p y2 the other (either may be the clockwise
/// one). G, F and the spikes are those of the first run.
Iso230Circular iso230Circular(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<double>& x2, const std::vector<double>& y2,
                              const NominalCircle& nominal, const Iso230Options& options = {});

} // namespace xyt
