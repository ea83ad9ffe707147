// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/// A point or a vector of the XY plane, in mm.
struct Point2 {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const Point2&, const Point2&) = default;
};

/**
 * One segment of a programmed XY path: a straight line from start to end, or a circular arc
 * about centre of radius R from the angle startAngle, turning by sweep (radians, signed:
 * sweep > 0 counter-clockwise as G3, sweep < 0 clockwise as G2, |sweep| <= 2 pi; a full
 * circle has |sweep| = 2 pi and end = start). Angles are measured from the +x axis. The length
 * is |end - start| for a line and R |sweep| for an arc. Regular value type, built by the two
 * named constructors, which validate.
 */
class PathSegment {
public:
    enum class Kind { Line, Arc };

    /// @throws InvalidInput "segment" when a coordinate is not finite or start == end.
    static PathSegment line(Point2 start, Point2 end);
    /// @throws InvalidInput "segment" unless centre and angles are finite, radius > 0 and
    ///         0 < |sweep| <= 2 pi (a rounding excess up to 1e-12 rad is clamped).
    static PathSegment arc(Point2 centre, double radius, double startAngleRad, double sweepRad);

    Kind kind() const { return kind_; }
    bool isArc() const { return kind_ == Kind::Arc; }
    Point2 start() const { return start_; }
    Point2 end() const { return end_; }
    double length() const { return length_; }
    /// Arcs only (0 and the start point for lines): centre, radius, start angle, signed sweep.
    Point2 centre() const { return centre_; }
    double radius() const { return radius_; }
    double startAngle() const { return startAngle_; }
    double sweep() const { return sweep_; }
    /// Signed curvature: +1/R counter-clockwise, -1/R clockwise, 0 for a line (1/mm).
    double curvature() const;

    /// The point at arc length @p u from the segment's start (clamped to [0, length]).
    Point2 pointAt(double u) const;
    /// The unit tangent (direction of travel) at arc length @p u.
    Point2 tangentAt(double u) const;

    /**
     * The point of this segment nearest to @p q: its arc length u from the segment's start,
     * and the distance |q - p|. When q is the centre of an arc every point is nearest; the
     * start is returned.
     */
    struct Nearest {
        double u = 0.0;
        double distance = 0.0;
    };
    Nearest nearest(Point2 q) const;

    /// Bounding box [minX, maxX] x [minY, maxY] (exact for arcs: the axis extremes they pass).
    void bounds(double& minX, double& minY, double& maxX, double& maxY) const;

    friend bool operator==(const PathSegment&, const PathSegment&) = default;

private:
    Kind kind_ = Kind::Line;
    Point2 start_, end_, centre_;
    double radius_ = 0.0, startAngle_ = 0.0, sweep_ = 0.0, length_ = 0.0;
};

/// Where a query point lies relative to a path (Path::nearest).
struct PathProjection {
    std::size_t segment = 0;   ///< index of the segment holding the nearest point
    double pathPosition = 0.0; ///< arc length s of the nearest point from the path's start (mm)
    Point2 point;              ///< the nearest point of the path
    Point2 tangent;            ///< unit direction of travel there
    /**
     * Signed perpendicular distance from the path to the query point q (mm): positive when q is
     * LEFT of the direction of travel (for a counter-clockwise circle: inside; for a clockwise
     * one: outside), |signedDistance| = |q - point|. When the nearest point is a join of two
     * segments the side is taken against the sum of the incoming and outgoing tangents (the
     * corner's bisector), so that a point beyond a corner gets the side of the corner's outside
     * or inside whichever segment's end is reported.
     */
    double signedDistance = 0.0;
};

/// A point of a path at a given arc length (Path::at).
struct PathPoint {
    std::size_t segment = 0;
    Point2 point;
    Point2 tangent;
};

/**
 * A programmed XY path: segments traversed in order (mm). Consecutive segments are meant to
 * join (the G-code reader's arcs end within its arc tolerance of the next start); a gap is
 * allowed, is not traversed, and adds nothing to the length.
 *
 * Nearest-point queries use a bounding-box hierarchy over runs of consecutive segments (a
 * balanced binary tree, built once in O(n)), searched branch and bound: a hint segment (the
 * previous answer, or the segment the reference was on) is measured first, its distance prunes
 * every box that lies farther away, and the result is the exact global nearest point. A traced
 * point near its hint visits O(log n) boxes; 100 000 queries on a 10 000-segment path take
 * tens of milliseconds (tst_path). Ties (equal distances) keep the first one found, the hint
 * first, so results do not jump between equally near segments from one query to the next.
 */
class Path {
public:
    Path() = default;
    /// @throws InvalidInput "path" when @p segments is empty.
    explicit Path(std::vector<PathSegment> segments);

    const std::vector<PathSegment>& segments() const { return segments_; }
    std::size_t size() const { return segments_.size(); }
    double length() const { return starts_.empty() ? 0.0 : starts_.back(); }
    /// Arc length at the start of segment i (i = size() gives the total length).
    double segmentStart(std::size_t i) const { return starts_[i]; }

    /// The point and tangent at arc length @p s (clamped to [0, length()]).
    PathPoint at(double s) const;
    /// The same, knowing the segment (no search): s is clamped to that segment.
    PathPoint at(double s, std::size_t segment) const;
    /// The segment holding arc length @p s (the later one at a join), by binary search.
    std::size_t segmentAt(double s) const;

    /// The nearest point of the path to @p q (see the class comment); @p hintSegment is only a
    /// starting guess (any value is valid; out of range is clamped).
    PathProjection nearest(Point2 q, std::size_t hintSegment = 0) const;

    /**
     * Turning angle at the join before segment i (1 <= i < size()): the angle between the
     * tangent at the end of segment i-1 and the tangent at the start of segment i, in [0, pi]
     * radians. 0 for a tangent join; pi for a reversal.
     */
    double joinAngle(std::size_t i) const;

private:
    struct Box {
        double minX, minY, maxX, maxY;
    };
    double boxDistanceSquared(const Box& b, Point2 q) const;
    void build(std::size_t node, std::size_t first, std::size_t last);
    double sideAtJoin(std::size_t segment, double u, Point2 q, Point2 point) const;

    std::vector<PathSegment> segments_;
    std::vector<double> starts_; ///< size() + 1 cumulative lengths
    /// The hierarchy: node 1 is the root covering every segment, node k has children 2k, 2k+1;
    /// nodeFirst_/nodeLast_ give its segment range [first, last].
    std::vector<Box> boxes_;
    std::vector<std::size_t> nodeFirst_, nodeLast_;
};

/// The joins (indices i of the segment after the join, 1 <= i < size()) where the path turns by
/// more than @p thresholdRad (Path::joinAngle): the sharp corners, where a feed profile stops.
std::vector<std::size_t> sharpCorners(const Path& path, double thresholdRad);

/// a + b, a - b, k a, dot and cross products (z of the 3-D cross), length.
inline Point2 operator+(Point2 a, Point2 b) {
    return {a.x + b.x, a.y + b.y};
}
inline Point2 operator-(Point2 a, Point2 b) {
    return {a.x - b.x, a.y - b.y};
}
inline Point2 operator*(double k, Point2 a) {
    return {k * a.x, k * a.y};
}
inline double dot(Point2 a, Point2 b) {
    return a.x * b.x + a.y * b.y;
}
inline double cross(Point2 a, Point2 b) {
    return a.x * b.y - a.y * b.x;
}
double norm(Point2 a);

} // namespace xyt
