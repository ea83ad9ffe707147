// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/contour_points.h"

#include <QtNumeric>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace xyt::ui {

namespace {

void append(XyPoints& out, Point2 p) {
    out.x.append(p.x);
    out.y.append(p.y);
}

void appendBreak(XyPoints& out) {
    out.x.append(qQNaN());
    out.y.append(qQNaN());
}

} // namespace

XyPoints programmedPathPoints(const Path& path) {
    XyPoints out;
    bool first = true;
    Point2 last;
    for (const PathSegment& s : path.segments()) {
        if (!first && !(s.start() == last))
            appendBreak(out);
        if (first || !(s.start() == last))
            append(out, s.start());
        if (s.isArc()) {
            const double stepRad = kArcStepDeg * std::numbers::pi / 180.0;
            const int steps =
                std::max(4, static_cast<int>(std::ceil(std::abs(s.sweep()) / stepRad)));
            for (int i = 1; i < steps; ++i)
                append(out, s.pointAt(s.length() * i / steps));
        }
        append(out, s.end());
        last = s.end();
        first = false;
    }
    return out;
}

XyPoints magnifiedContourPoints(const Path& path, const ContourErrorResult& contour,
                                double magnification) {
    XyPoints out;
    const std::size_t n = contour.error.size();
    out.x.reserve(static_cast<qsizetype>(n));
    out.y.reserve(static_cast<qsizetype>(n));
    for (std::size_t k = 0; k < n; ++k) {
        if (!contour.measured.empty() && !contour.measured[k]) {
            appendBreak(out);
            continue;
        }
        const PathPoint p = path.at(contour.pathPosition[k], contour.segment[k]);
        const Point2 normal{-p.tangent.y, p.tangent.x};
        append(out, p.point + (magnification * contour.error[k]) * normal);
    }
    return out;
}

XyPoints polarDeviationPoints(const std::vector<double>& x, const std::vector<double>& y,
                              const NominalCircle& nominal, double magnification) {
    XyPoints out;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        const double dx = x[i] - nominal.centre.x, dy = y[i] - nominal.centre.y;
        const double r = std::hypot(dx, dy);
        const double drawn = nominal.radius + magnification * (r - nominal.radius);
        const double angle = std::atan2(dy, dx);
        append(out, {nominal.centre.x + drawn * std::cos(angle),
                     nominal.centre.y + drawn * std::sin(angle)});
    }
    return out;
}

XyPoints circlePoints(Point2 centre, double radius) {
    XyPoints out;
    for (int i = 0; i <= 360; ++i) {
        const double a = i * std::numbers::pi / 180.0;
        append(out, {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    return out;
}

} // namespace xyt::ui
