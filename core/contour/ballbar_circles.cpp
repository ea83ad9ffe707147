// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/ballbar_circles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace xyt {

namespace {

std::string lineOf(const GcodeProgram& program, std::size_t segment) {
    return "line " + std::to_string(program.segments[segment].line);
}

/// The same programmed circle: the reader turns the same I, J and end point into the same
/// centre and radius up to round-off, so 1e-9 of the radius separates distinct circles.
bool sameCircle(const PathSegment& a, const PathSegment& b) {
    const double tolerance = 1e-9 * std::max(a.radius(), b.radius());
    return std::abs(a.radius() - b.radius()) <= tolerance && std::abs(a.centre().x - b.centre().x) <= tolerance &&
           std::abs(a.centre().y - b.centre().y) <= tolerance;
}

} // namespace

BallbarCircles findBallbarCircles(const GcodeProgram& program) {
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    std::vector<std::size_t> circles;
    for (std::size_t i = 0; i < program.segments.size() && i < program.path.segments().size(); ++i) {
        const PathSegment& s = program.path.segments()[i];
        if (!program.segments[i].rapid && s.isArc() && std::abs(s.sweep()) == kTwoPi)
            circles.push_back(i);
    }
    BallbarCircles out;
    out.fullCircles = circles.size();
    if (circles.empty())
        return out;
    out.first = circles.front();
    const PathSegment& first = program.path.segments()[circles.front()];
    for (std::size_t k = 1; k < circles.size() && !out.opposite; ++k) {
        const PathSegment& s = program.path.segments()[circles[k]];
        if (sameCircle(first, s) && (s.sweep() < 0.0) != (first.sweep() < 0.0))
            out.opposite = circles[k];
    }
    const std::string firstLine = lineOf(program, circles.front());
    if (!out.opposite) {
        out.note = circles.size() == 1
                       ? "the program runs its full circle (" + firstLine +
                             ") one way only: no circular hysteresis H, which needs a clockwise and a "
                             "counter-clockwise run of the same circle"
                       : "none of the program's " + std::to_string(circles.size()) +
                             " full circles runs the circle of " + firstLine +
                             " the other way on the same centre and radius: G and F are that circle's, "
                             "no circular hysteresis H";
    } else if (circles.size() > 2) {
        out.note = "the program holds " + std::to_string(circles.size()) +
                   " full circles: the figures are those of " + firstLine + " and " +
                   lineOf(program, *out.opposite);
    }
    return out;
}

} // namespace xyt
