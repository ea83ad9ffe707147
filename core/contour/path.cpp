// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/path.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace xyt {

namespace {

/// Segments per leaf of the bounding-box hierarchy: small enough that a leaf is cheap to scan,
/// large enough to quarter the tree's memory (16 bytes of boxes per segment instead of 64).
constexpr std::size_t kLeafSegments = 4;

bool finite(Point2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

/// @p angle - @p from, in [0, 2 pi).
double angleFrom(double angle, double from) {
    double d = std::fmod(angle - from, kTwoPi);
    if (d < 0.0)
        d += kTwoPi;
    return d >= kTwoPi ? 0.0 : d;
}

} // namespace

double norm(Point2 a) {
    return std::hypot(a.x, a.y);
}

PathSegment PathSegment::line(Point2 start, Point2 end) {
    if (!finite(start) || !finite(end))
        throw InvalidInput("segment", makeDiagnostic("contour_line_not_finite"));
    if (start == end)
        throw InvalidInput("segment", makeDiagnostic("contour_line_zero_length"));
    PathSegment s;
    s.kind_ = Kind::Line;
    s.start_ = start;
    s.end_ = end;
    s.centre_ = start;
    s.length_ = norm(end - start);
    if (!std::isfinite(s.length_))
        throw InvalidInput("segment", makeDiagnostic("contour_line_length_overflows"));
    return s;
}

PathSegment PathSegment::arc(Point2 centre, double radius, double startAngleRad, double sweepRad) {
    if (!finite(centre) || !std::isfinite(radius) || !std::isfinite(startAngleRad) ||
        !std::isfinite(sweepRad))
        throw InvalidInput("segment", makeDiagnostic("contour_arc_not_finite"));
    if (!(radius > 0.0))
        throw InvalidInput("segment", makeDiagnostic("contour_arc_radius_not_positive"));
    if (std::abs(sweepRad) > kTwoPi + 1e-12 || sweepRad == 0.0)
        throw InvalidInput("segment", makeDiagnostic("contour_arc_sweep"));
    PathSegment s;
    s.kind_ = Kind::Arc;
    s.centre_ = centre;
    s.radius_ = radius;
    s.startAngle_ = startAngleRad;
    s.sweep_ = std::clamp(sweepRad, -kTwoPi, kTwoPi);
    s.length_ = radius * std::abs(s.sweep_);
    if (!std::isfinite(s.length_))
        throw InvalidInput("segment", makeDiagnostic("contour_arc_length_overflows"));
    s.start_ = centre + radius * Point2{std::cos(startAngleRad), std::sin(startAngleRad)};
    const double endAngle = startAngleRad + s.sweep_;
    s.end_ = std::abs(s.sweep_) == kTwoPi
                 ? s.start_
                 : centre + radius * Point2{std::cos(endAngle), std::sin(endAngle)};
    return s;
}

double PathSegment::curvature() const {
    if (kind_ == Kind::Line)
        return 0.0;
    return (sweep_ > 0.0 ? 1.0 : -1.0) / radius_;
}

Point2 PathSegment::pointAt(double u) const {
    u = std::clamp(u, 0.0, length_);
    if (kind_ == Kind::Line) {
        if (u == length_)
            return end_;
        return start_ + (u / length_) * (end_ - start_);
    }
    const double angle = startAngle_ + (sweep_ > 0.0 ? u : -u) / radius_;
    return centre_ + radius_ * Point2{std::cos(angle), std::sin(angle)};
}

Point2 PathSegment::tangentAt(double u) const {
    if (kind_ == Kind::Line)
        return (1.0 / length_) * (end_ - start_);
    u = std::clamp(u, 0.0, length_);
    const double direction = sweep_ > 0.0 ? 1.0 : -1.0;
    const double angle = startAngle_ + direction * u / radius_;
    return direction * Point2{-std::sin(angle), std::cos(angle)};
}

PathSegment::Nearest PathSegment::nearest(Point2 q) const {
    if (kind_ == Kind::Line) {
        const Point2 d = end_ - start_;
        const double u = std::clamp(dot(q - start_, d) / length_, 0.0, length_);
        return {u, norm(q - pointAt(u))};
    }
    const Point2 v = q - centre_;
    const double rho = norm(v);
    if (rho == 0.0)
        return {0.0, radius_};
    const double phi = std::atan2(v.y, v.x);
    // The angle travelled from the start to the direction of q.
    const double travelled =
        sweep_ > 0.0 ? angleFrom(phi, startAngle_) : angleFrom(startAngle_, phi);
    if (travelled <= std::abs(sweep_))
        return {radius_ * travelled, std::abs(rho - radius_)};
    const double toStart = norm(q - start_), toEnd = norm(q - end_);
    return toStart <= toEnd ? Nearest{0.0, toStart} : Nearest{length_, toEnd};
}

void PathSegment::bounds(double& minX, double& minY, double& maxX, double& maxY) const {
    minX = std::min(start_.x, end_.x);
    maxX = std::max(start_.x, end_.x);
    minY = std::min(start_.y, end_.y);
    maxY = std::max(start_.y, end_.y);
    if (kind_ == Kind::Line)
        return;
    // The axis directions 0, pi/2, pi, 3 pi/2 that the arc passes add their extreme points.
    const double sweep = std::abs(sweep_);
    const double from = sweep_ > 0.0 ? startAngle_ : startAngle_ + sweep_;
    for (int k = 0; k < 4; ++k) {
        const double axis = k * std::numbers::pi / 2.0;
        if (angleFrom(axis, from) <= sweep) {
            const Point2 p = centre_ + radius_ * Point2{std::cos(axis), std::sin(axis)};
            minX = std::min(minX, k == 2 ? centre_.x - radius_ : p.x);
            maxX = std::max(maxX, k == 0 ? centre_.x + radius_ : p.x);
            minY = std::min(minY, k == 3 ? centre_.y - radius_ : p.y);
            maxY = std::max(maxY, k == 1 ? centre_.y + radius_ : p.y);
        }
    }
}

Path::Path(std::vector<PathSegment> segments) : segments_(std::move(segments)) {
    if (segments_.empty())
        throw InvalidInput("path", makeDiagnostic("contour_has_no_segment"));
    starts_.resize(segments_.size() + 1);
    starts_[0] = 0.0;
    for (std::size_t i = 0; i < segments_.size(); ++i)
        starts_[i + 1] = starts_[i] + segments_[i].length();
    if (!std::isfinite(starts_.back()))
        throw InvalidInput("path", makeDiagnostic("contour_path_length_overflows"));
    std::size_t leaves = (segments_.size() + kLeafSegments - 1) / kLeafSegments;
    std::size_t nodes = 1;
    while (nodes < leaves)
        nodes *= 2;
    boxes_.resize(2 * nodes);
    nodeFirst_.assign(2 * nodes, 0);
    nodeLast_.assign(2 * nodes, 0);
    build(1, 0, segments_.size() - 1);
}

void Path::build(std::size_t node, std::size_t first, std::size_t last) {
    nodeFirst_[node] = first;
    nodeLast_[node] = last;
    Box& b = boxes_[node];
    if (last - first + 1 <= kLeafSegments) {
        b = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
        for (std::size_t i = first; i <= last; ++i) {
            double x0, y0, x1, y1;
            segments_[i].bounds(x0, y0, x1, y1);
            b = {std::min(b.minX, x0), std::min(b.minY, y0), std::max(b.maxX, x1),
                 std::max(b.maxY, y1)};
        }
        return;
    }
    const std::size_t middle = first + (last - first) / 2;
    build(2 * node, first, middle);
    build(2 * node + 1, middle + 1, last);
    const Box& l = boxes_[2 * node];
    const Box& r = boxes_[2 * node + 1];
    b = {std::min(l.minX, r.minX), std::min(l.minY, r.minY), std::max(l.maxX, r.maxX),
         std::max(l.maxY, r.maxY)};
}

double Path::boxDistanceSquared(const Box& b, Point2 q) const {
    const double dx = std::max({b.minX - q.x, 0.0, q.x - b.maxX});
    const double dy = std::max({b.minY - q.y, 0.0, q.y - b.maxY});
    return dx * dx + dy * dy;
}

std::size_t Path::segmentAt(double s) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
    const std::size_t i =
        it == starts_.begin() ? 0 : static_cast<std::size_t>(it - starts_.begin()) - 1;
    return std::min(i, segments_.size() - 1);
}

PathPoint Path::at(double s) const {
    return at(s, segmentAt(std::clamp(s, 0.0, length())));
}

PathPoint Path::at(double s, std::size_t segment) const {
    const PathSegment& seg = segments_[segment];
    const double u = std::clamp(s - starts_[segment], 0.0, seg.length());
    return {segment, seg.pointAt(u), seg.tangentAt(u)};
}

double Path::joinAngle(std::size_t i) const {
    const Point2 in = segments_[i - 1].tangentAt(segments_[i - 1].length());
    const Point2 out = segments_[i].tangentAt(0.0);
    return std::atan2(std::abs(cross(in, out)), dot(in, out));
}

std::vector<std::size_t> sharpCorners(const Path& path, double thresholdRad) {
    std::vector<std::size_t> out;
    for (std::size_t i = 1; i < path.size(); ++i)
        if (path.joinAngle(i) > thresholdRad)
            out.push_back(i);
    return out;
}

double Path::sideAtJoin(std::size_t segment, double u, Point2 q, Point2 point) const {
    const PathSegment& seg = segments_[segment];
    Point2 direction = seg.tangentAt(u);
    // At a join the bisector of the two tangents decides the side (see PathProjection).
    if (u == 0.0 && segment > 0)
        direction = segments_[segment - 1].tangentAt(segments_[segment - 1].length()) + direction;
    else if (u == seg.length() && segment + 1 < segments_.size())
        direction = direction + segments_[segment + 1].tangentAt(0.0);
    if (norm(direction) < 1e-12) // a reversal: no bisector, keep the segment's own tangent
        direction = seg.tangentAt(u);
    return cross(direction, q - point) < 0.0 ? -1.0 : 1.0;
}

PathProjection Path::nearest(Point2 q, std::size_t hintSegment) const {
    if (segments_.empty())
        throw InvalidInput("path", makeDiagnostic("contour_has_no_segment"));
    std::size_t bestSegment = 0;
    PathSegment::Nearest best{0.0, std::numeric_limits<double>::infinity()};
    const auto consider = [&](std::size_t i) {
        const PathSegment::Nearest n = segments_[i].nearest(q);
        if (n.distance < best.distance) {
            best = n;
            bestSegment = i;
        }
    };
    // The hint and its neighbours first: their distance prunes nearly the whole hierarchy.
    const std::size_t hint = std::min(hintSegment, segments_.size() - 1);
    consider(hint);
    if (hint > 0)
        consider(hint - 1);
    if (hint + 1 < segments_.size())
        consider(hint + 1);
    // Branch and bound; the depth is at most log2(size / kLeafSegments) + 1 < 64, and each
    // level leaves at most one pushed sibling, so 128 entries always suffice.
    std::array<std::size_t, 128> stack{};
    std::size_t top = 0;
    stack[top++] = 1;
    while (top > 0) {
        const std::size_t node = stack[--top];
        if (boxDistanceSquared(boxes_[node], q) >= best.distance * best.distance)
            continue;
        const std::size_t first = nodeFirst_[node], last = nodeLast_[node];
        if (last - first + 1 <= kLeafSegments) {
            for (std::size_t i = first; i <= last; ++i)
                consider(i);
            continue;
        }
        const std::size_t left = 2 * node, right = 2 * node + 1;
        // The nearer child is searched first (pushed last).
        if (boxDistanceSquared(boxes_[left], q) <= boxDistanceSquared(boxes_[right], q)) {
            stack[top++] = right;
            stack[top++] = left;
        } else {
            stack[top++] = left;
            stack[top++] = right;
        }
    }
    const PathSegment& seg = segments_[bestSegment];
    PathProjection out;
    out.segment = bestSegment;
    out.pathPosition = starts_[bestSegment] + best.u;
    out.point = seg.pointAt(best.u);
    out.tangent = seg.tangentAt(best.u);
    const bool interior = best.u > 0.0 && best.u < seg.length();
    if (interior && seg.isArc()) {
        // Exact form on an arc: left of travel is the centre's side for counter-clockwise arcs.
        const double rho = norm(q - seg.centre());
        out.signedDistance = seg.sweep() > 0.0 ? seg.radius() - rho : rho - seg.radius();
    } else if (interior) {
        out.signedDistance = cross(out.tangent, q - seg.start());
    } else {
        out.signedDistance = best.distance * sideAtJoin(bestSegment, best.u, q, out.point);
    }
    return out;
}

} // namespace xyt
