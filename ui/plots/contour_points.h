// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/contour_metrics.h"
#include "core/contour/path.h"

#include <QVector>

#include <vector>

namespace xyt::ui {

/// Points of one drawn XY curve (mm); NaN pairs break the line.
struct XyPoints {
    QVector<double> x, y;
};

/// The most degrees between two drawn points of an arc (a 30 mm circle then deviates from its
/// polygon by R (1 - cos 1 deg) = 0.005 mm, under a pixel at any zoom that shows the circle).
inline constexpr double kArcStepDeg = 2.0;

/**
 * The programmed path as a polyline, from the core's segments: a line by its two ends, an arc
 * by PathSegment::pointAt at steps of at most kArcStepDeg (at least 4 per arc). A segment that
 * does not start where the previous one ended is preceded by a NaN break (Path allows gaps).
 */
XyPoints programmedPathPoints(const Path& path);

/**
 * The contour error magnified along the path normal: for sample k, p + M e_k n with p the
 * nearest path point (Path::at at the sample's pathPosition on its segment), n the left normal
 * of the direction of travel there (e is positive to the left, contour_metrics.h), M the
 * magnification. M = 1 gives the traced point's projection back. Samples left out of the
 * statistics (G0 rapids) are NaN breaks.
 */
XyPoints magnifiedContourPoints(const Path& path, const ContourErrorResult& contour,
                                double magnification);

/**
 * A ballbar's polar plot of a traced circle: each point at its angle about the nominal centre
 * c0, at the radius R0 + M (|p - c0| - R0), so that the radial deviation is magnified M times
 * and the nominal circle is drawn at its own size.
 */
XyPoints polarDeviationPoints(const std::vector<double>& x, const std::vector<double>& y,
                              const NominalCircle& nominal, double magnification);

/// A circle as 361 points (the first repeated at the end).
XyPoints circlePoints(Point2 centre, double radius);

} // namespace xyt::ui
