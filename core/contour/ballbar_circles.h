// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/gcode_reader.h"

#include <cstddef>
#include <optional>
#include <string>

namespace xyt {

/// The consecutive segments [begin, end) of path.segments() that run one full circle.
struct CircleSegments {
    std::size_t begin = 0;
    std::size_t end = 0; ///< one past the last
    bool contains(std::size_t segment) const { return segment >= begin && segment < end; }
};

/**
 * The circles of a circular (ballbar) test in a program as machine shops write it: a clockwise
 * and a counter-clockwise full circle on the same centre and radius, often with feed-in and
 * feed-out arcs (or lines) around them. A full circle is written as one feed arc (G2/G3) whose
 * end is its start (|sweep| = 2 pi), or as consecutive feed arcs (semicircles, quadrants) on the
 * same centre and radius (within 1e-9 of the radius), turning the same way, whose sweeps add up
 * to one turn. Within a longer run of such arcs the circle is the first whole turn that starts
 * on an arc's start (five quadrants: the first four; a quarter then a full-circle arc: the
 * full-circle arc), and the runs after it may hold further circles. The feed-in and feed-out
 * moves are not part of the measured runs.
 */
struct BallbarCircles {
    /// Segments of the first full circle: the run G and F are given for.
    std::optional<CircleSegments> first;
    /// The first later full circle on the same centre and radius (within 1e-9 of the radius)
    /// run the other way: with it, the hysteresis H of ISO 230-4.
    std::optional<CircleSegments> opposite;
    std::size_t fullCircles = 0; ///< full circles the program holds
    /// Why the figures are fewer than G, F and H of a clockwise and counter-clockwise pair, or
    /// which circles they are of when the program holds more than two; empty otherwise (and
    /// when the program holds no full circle: it is no circular test).
    Diagnostic note;
};

/// Finds the full circles of @p program and pairs the first with one run the other way.
BallbarCircles findBallbarCircles(const GcodeProgram& program);

} // namespace xyt
