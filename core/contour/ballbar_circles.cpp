// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/ballbar_circles.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace xyt {

namespace {

/**
 * How far the sweeps of a run of arcs may add up from one turn and still close it: 1e-9 of a
 * turn (6.3e-9 rad). Round-off stays below it: each sweep is the difference of two atan2 values
 * (a few ulp of 2 pi, about 1e-15 rad, and they telescope around a closed run), and the running
 * sum below adds and drops each arc of a run at most once, each step rounding by at most half
 * an ulp of a value below 4 pi (8.9e-16 rad), so over the 10^6 lines a program may have
 * (kMaxGcodeLines) it drifts by less than 2e-9 rad. A run that a program leaves open is open by
 * at least one unit of its last digit (0.001 mm, 0.0001 in), which on any circle up to 1 m in
 * radius is at least 1e-6 rad: far above it.
 */
constexpr double kTurnTolerance = 1e-9 * kTwoPi;

Diagnostic linesOf(const GcodeProgram& program, const CircleSegments& circle) {
    const std::size_t first = program.segments[circle.begin].line,
                      last = program.segments[circle.end - 1].line;
    return first == last ? makeDiagnostic("contour_gcode_line", {std::to_string(first)})
                         : makeDiagnostic("contour_gcode_lines",
                                          {std::to_string(first), std::to_string(last)});
}

/// The same programmed circle: the reader turns the same I, J and end point into the same
/// centre and radius up to round-off, so 1e-9 of the radius separates distinct circles.
bool sameCircle(const PathSegment& a, const PathSegment& b) {
    const double tolerance = 1e-9 * std::max(a.radius(), b.radius());
    return std::abs(a.radius() - b.radius()) <= tolerance &&
           std::abs(a.centre().x - b.centre().x) <= tolerance &&
           std::abs(a.centre().y - b.centre().y) <= tolerance;
}

/**
 * The full circles of @p program in path order. A run is a maximal sequence of consecutive
 * feed arcs on the circle of its first arc turning the same way (consecutive segments are
 * contiguous: the reader starts each move where the previous one ended). In a run, a circle is
 * the first window of whole arcs whose sweeps add up to one turn: the window grows by the next
 * arc while short of a turn and drops its first arc while beyond one, so a single full-circle
 * arc is a circle of one segment, five quadrants give the first four, and a quarter followed by
 * a full-circle arc gives the full-circle arc. After a circle the next window starts afresh.
 */
std::vector<CircleSegments> fullCircles(const GcodeProgram& program) {
    const std::vector<PathSegment>& path = program.path.segments();
    const std::size_t n = std::min(program.segments.size(), path.size());
    const auto feedArc = [&](std::size_t i) {
        return !program.segments[i].rapid && path[i].isArc();
    };
    std::vector<CircleSegments> out;
    for (std::size_t runBegin = 0; runBegin < n;) {
        if (!feedArc(runBegin)) {
            ++runBegin;
            continue;
        }
        const PathSegment& head = path[runBegin];
        std::size_t runEnd = runBegin + 1;
        while (runEnd < n && feedArc(runEnd) && sameCircle(head, path[runEnd]) &&
               (path[runEnd].sweep() < 0.0) == (head.sweep() < 0.0))
            ++runEnd;
        std::size_t begin = runBegin, end = runBegin;
        double turned = 0.0; // |sweep| summed over [begin, end)
        for (;;) {
            if (end > begin && std::abs(turned - kTwoPi) <= kTurnTolerance) {
                out.push_back({begin, end});
                begin = end;
                turned = 0.0;
            } else if (turned > kTwoPi + kTurnTolerance) {
                // A single arc turns at most once, so the window keeps at least one arc.
                turned -= std::abs(path[begin++].sweep());
            } else if (end < runEnd) {
                turned += std::abs(path[end++].sweep());
            } else {
                break;
            }
        }
        runBegin = runEnd;
    }
    return out;
}

} // namespace

BallbarCircles findBallbarCircles(const GcodeProgram& program) {
    const std::vector<CircleSegments> circles = fullCircles(program);
    BallbarCircles out;
    out.fullCircles = circles.size();
    if (circles.empty())
        return out;
    out.first = circles.front();
    const PathSegment& first = program.path.segments()[circles.front().begin];
    for (std::size_t k = 1; k < circles.size() && !out.opposite; ++k) {
        const PathSegment& s = program.path.segments()[circles[k].begin];
        if (sameCircle(first, s) && (s.sweep() < 0.0) != (first.sweep() < 0.0))
            out.opposite = circles[k];
    }
    const Diagnostic firstLines = linesOf(program, circles.front());
    if (!out.opposite) {
        out.note = circles.size() == 1
                       ? makeDiagnostic("contour_ballbar_one_way", {firstLines})
                       : makeDiagnostic("contour_ballbar_no_opposite",
                                        {std::to_string(circles.size()), firstLines});
    } else if (circles.size() > 2) {
        out.note =
            makeDiagnostic("contour_ballbar_many", {std::to_string(circles.size()), firstLines,
                                                    linesOf(program, *out.opposite)});
    }
    return out;
}

} // namespace xyt
