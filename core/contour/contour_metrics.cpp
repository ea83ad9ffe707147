// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/contour_metrics.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace xyt {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

void requirePoints(const std::vector<double>& x, const std::vector<double>& y, const char* field,
                   std::size_t minimum) {
    if (x.size() != y.size())
        throw InvalidInput(field, makeDiagnostic("contour_xy_different_lengths"));
    if (x.size() < minimum)
        throw InvalidInput(field,
                           makeDiagnostic("contour_needs_points", {std::to_string(minimum)}));
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
            throw InvalidInput(field, makeDiagnostic("point_not_finite", {std::to_string(i)}));
}

/// Radii of the points about @p c.
std::vector<double> radii(const std::vector<double>& x, const std::vector<double>& y, Point2 c) {
    std::vector<double> r(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        r[i] = std::hypot(x[i] - c.x, y[i] - c.y);
    return r;
}

double range(const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return *hi - *lo;
}

CircleFit fitCircle(const std::vector<double>& x, const std::vector<double>& y, bool geometric) {
    return geometric ? fitCircleGeometric(x, y) : fitCircleKasa(x, y);
}

/// A run's radius as a function of the angle about a centre, for interpolation.
struct PolarRun {
    std::vector<double> angle, radius; ///< sorted by angle in [-pi, pi]

    PolarRun(const std::vector<double>& x, const std::vector<double>& y, Point2 c) {
        std::vector<std::size_t> order(x.size());
        std::iota(order.begin(), order.end(), 0);
        std::vector<double> a(x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            a[i] = std::atan2(y[i] - c.y, x[i] - c.x);
        std::sort(order.begin(), order.end(),
                  [&](std::size_t p, std::size_t q) { return a[p] < a[q]; });
        for (const std::size_t i : order) {
            angle.push_back(a[i]);
            radius.push_back(std::hypot(x[i] - c.x, y[i] - c.y));
        }
    }
    /// Linear interpolation in angle, periodic over 2 pi (between the last and the first
    /// sample across the +-pi seam).
    double at(double theta) const {
        const std::size_t n = angle.size();
        const std::size_t hi = static_cast<std::size_t>(
            std::upper_bound(angle.begin(), angle.end(), theta) - angle.begin());
        double a0, a1, r0, r1;
        if (hi > 0 && hi < n) {
            a0 = angle[hi - 1], a1 = angle[hi], r0 = radius[hi - 1], r1 = radius[hi];
        } else {
            a0 = angle[n - 1], a1 = angle[0] + 2.0 * std::numbers::pi, r0 = radius[n - 1],
            r1 = radius[0];
            if (theta < a0)
                theta += 2.0 * std::numbers::pi;
        }
        const double span = a1 - a0;
        if (!(span > 0.0))
            return r0;
        const double f = std::clamp((theta - a0) / span, 0.0, 1.0);
        return r0 + f * (r1 - r0);
    }
};

/// max over the samples of one run of |r_run(theta) - r_other(theta)|.
double largestRadialDifference(const PolarRun& run, const PolarRun& other) {
    double h = 0.0;
    for (std::size_t i = 0; i < run.angle.size(); ++i)
        h = std::max(h, std::abs(run.radius[i] - other.at(run.angle[i])));
    return h;
}

std::vector<ReversalSpike> reversalSpikes(const std::vector<double>& x,
                                          const std::vector<double>& y,
                                          const NominalCircle& nominal, const CircleFit& ls,
                                          double windowDeg) {
    std::vector<ReversalSpike> out;
    for (int q = 0; q < 4; ++q) {
        ReversalSpike spike;
        spike.angleDeg = 90.0 * q;
        spike.axis = q % 2 == 0 ? 'x' : 'y';
        std::vector<std::size_t> in;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double a = std::atan2(y[i] - nominal.centre.y, x[i] - nominal.centre.x);
            const double d = std::remainder(a - spike.angleDeg * kDegree, 2.0 * std::numbers::pi);
            if (std::abs(d) <= windowDeg * kDegree)
                in.push_back(i);
        }
        spike.samples = in.size();
        if (in.size() >= 3) {
            std::vector<double> dr(in.size());
            for (std::size_t k = 0; k < in.size(); ++k)
                dr[k] = std::hypot(x[in[k]] - ls.centre.x, y[in[k]] - ls.centre.y) - ls.radius;
            std::vector<double> sorted = dr;
            std::nth_element(sorted.begin(),
                             sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                             sorted.end());
            const double median = sorted[sorted.size() / 2];
            std::size_t best = 0;
            for (std::size_t k = 1; k < dr.size(); ++k)
                if (std::abs(dr[k] - median) > std::abs(dr[best] - median))
                    best = k;
            spike.heightMm = dr[best] - median;
            spike.point = {x[in[best]], y[in[best]]};
        }
        out.push_back(spike);
    }
    return out;
}

void validateNominal(const NominalCircle& nominal, const Iso230Options& options) {
    if (!(nominal.radius > 0.0) || !std::isfinite(nominal.radius))
        throw InvalidInput("nominal_radius", makeDiagnostic("finite_positive"));
    if (!std::isfinite(nominal.centre.x) || !std::isfinite(nominal.centre.y))
        throw InvalidInput("nominal_centre", makeDiagnostic("sim_must_be_finite"));
    if (!(options.reversalWindowDeg > 0.0 && options.reversalWindowDeg <= 45.0))
        throw InvalidInput("reversal_window", makeDiagnostic("contour_reversal_window"));
}

} // namespace

ContourErrorResult contourError(const Path& path, const std::vector<double>& t,
                                const std::vector<double>& x, const std::vector<double>& y,
                                const ContourErrorOptions& options) {
    if (t.size() != x.size() || t.size() != y.size())
        throw InvalidInput("traced", makeDiagnostic("sim_txy_different_lengths"));
    if (t.empty())
        throw InvalidInput("traced", makeDiagnostic("contour_has_no_sample"));
    if (!options.measuredSegments.empty() && options.measuredSegments.size() != path.size())
        throw InvalidInput("measured_segments", makeDiagnostic("contour_one_flag_per_segment"));
    if (!(options.cornerWindowMm >= 0.0) || !std::isfinite(options.cornerWindowMm))
        throw InvalidInput("corner_window", makeDiagnostic("finite_not_negative"));
    const std::size_t n = t.size();
    ContourErrorResult out;
    out.error.resize(n);
    out.pathPosition.resize(n);
    out.segment.resize(n);
    out.measured.resize(n);

    const std::vector<std::size_t> joins = sharpCorners(path, options.cornerAngleDeg * kDegree);
    std::vector<double> cornerS(joins.size());
    for (std::size_t c = 0; c < joins.size(); ++c) {
        cornerS[c] = path.segmentStart(joins[c]);
        CornerOvershoot o;
        o.join = joins[c];
        o.pathPosition = cornerS[c];
        o.corner = path.segments()[joins[c]].start();
        out.corners.push_back(o);
    }

    double sumSquares = 0.0;
    std::size_t hint = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(t[k]) || !std::isfinite(x[k]) || !std::isfinite(y[k]))
            throw InvalidInput("traced", makeDiagnostic("sample_not_finite", {std::to_string(k)}));
        const PathProjection p = path.nearest({x[k], y[k]}, hint);
        hint = p.segment;
        out.error[k] = p.signedDistance;
        out.pathPosition[k] = p.pathPosition;
        out.segment[k] = p.segment;
        const bool measured =
            options.measuredSegments.empty() || options.measuredSegments[p.segment];
        out.measured[k] = measured;
        if (!measured)
            continue;
        ++out.measuredSamples;
        const double e = p.signedDistance;
        sumSquares += e * e;
        if (out.measuredSamples == 1 || std::abs(e) > out.maxAbs) {
            out.maxAbs = std::abs(e);
            out.maxIndex = k;
            out.maxTimeSeconds = t[k];
            out.maxSignedError = e;
            out.maxPathPosition = p.pathPosition;
            out.maxPoint = {x[k], y[k]};
        }
        // The corners within the window of this sample's path position.
        auto c = std::lower_bound(cornerS.begin(), cornerS.end(),
                                  p.pathPosition - options.cornerWindowMm);
        for (; c != cornerS.end() && *c <= p.pathPosition + options.cornerWindowMm; ++c) {
            CornerOvershoot& o = out.corners[static_cast<std::size_t>(c - cornerS.begin())];
            ++o.samples;
            if (o.samples == 1 || std::abs(e) > o.maxAbsError) {
                o.maxAbsError = std::abs(e);
                o.signedError = e;
                o.timeSeconds = t[k];
            }
        }
    }
    if (out.measuredSamples > 0)
        out.rms = std::sqrt(sumSquares / static_cast<double>(out.measuredSamples));
    return out;
}

CircleFit fitCircleKasa(const std::vector<double>& x, const std::vector<double>& y) {
    requirePoints(x, y, "points", 3);
    const auto n = static_cast<Eigen::Index>(x.size());
    // Relative to the mean, so that |p|^2 does not swamp the digits of a small circle far away.
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    // |p - c|^2 = R^2  <=>  2 cx u + 2 cy v + (R^2 - |c|^2) = u^2 + v^2, (u, v) = p - mean.
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double u = x[static_cast<std::size_t>(i)] - mx,
                     v = y[static_cast<std::size_t>(i)] - my;
        a(i, 0) = 2.0 * u;
        a(i, 1) = 2.0 * v;
        a(i, 2) = 1.0;
        b(i) = u * u + v * v;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 3)
        throw InvalidInput("points", makeDiagnostic("contour_points_collinear"));
    const Eigen::Vector3d s = qr.solve(b);
    const double r2 = s(2) + s(0) * s(0) + s(1) * s(1);
    if (!(r2 > 0.0) || !std::isfinite(r2))
        throw InvalidInput("points", makeDiagnostic("contour_fit_radius_not_real"));
    return {{s(0) + mx, s(1) + my}, std::sqrt(r2), false, 0};
}

CircleFit fitCircleGeometric(const std::vector<double>& x, const std::vector<double>& y) {
    const CircleFit start = fitCircleKasa(x, y);
    double cx = start.centre.x, cy = start.centre.y, r = start.radius;
    const std::size_t n = x.size();
    for (int iteration = 1; iteration <= 50; ++iteration) {
        // Residuals d_i - R with d_i = |p_i - c|, Jacobian rows [-(p_i - c)/d_i, -1]; the
        // normal equations J^T J step = -J^T res (3 x 3, LDLT).
        Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
        Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < n; ++i) {
            const double dx = x[i] - cx, dy = y[i] - cy;
            const double d = std::hypot(dx, dy);
            if (d == 0.0)
                continue; // a point at the centre has no direction; it does not steer the fit
            const Eigen::Vector3d row(-dx / d, -dy / d, -1.0);
            jtj += row * row.transpose();
            jtr += row * (d - r);
        }
        const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
        if (!step.allFinite())
            return start;
        cx += step(0);
        cy += step(1);
        r += step(2);
        if (!std::isfinite(cx) || !std::isfinite(cy) || !(r > 0.0) || !std::isfinite(r))
            return start;
        if (step.norm() <= 1e-13 * r)
            return {{cx, cy}, r, true, iteration};
    }
    return {{cx, cy}, r, true, 50};
}

Iso230Circular iso230Circular(const std::vector<double>& x, const std::vector<double>& y,
                              const NominalCircle& nominal, const Iso230Options& options) {
    validateNominal(nominal, options);
    Iso230Circular out;
    out.leastSquares = fitCircle(x, y, options.geometricFit);
    const std::vector<double> lsRadii = radii(x, y, out.leastSquares.centre);
    const auto [lsLo, lsHi] = std::minmax_element(lsRadii.begin(), lsRadii.end());
    out.minRadiusAboutLeastSquares = *lsLo;
    out.maxRadiusAboutLeastSquares = *lsHi;
    out.circularDeviationG = *lsHi - *lsLo;
    const std::vector<double> nominalRadii = radii(x, y, nominal.centre);
    const auto [lo, hi] = std::minmax_element(nominalRadii.begin(), nominalRadii.end());
    out.radialDeviationFMax = *hi - nominal.radius;
    out.radialDeviationFMin = *lo - nominal.radius;
    out.reversalSpikes = reversalSpikes(x, y, nominal, out.leastSquares, options.reversalWindowDeg);
    out.samples = x.size();
    return out;
}

Iso230Circular iso230Circular(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<double>& x2, const std::vector<double>& y2,
                              const NominalCircle& nominal, const Iso230Options& options) {
    Iso230Circular out = iso230Circular(x, y, nominal, options);
    requirePoints(x2, y2, "points", 3);
    std::vector<double> bothX = x, bothY = y;
    bothX.insert(bothX.end(), x2.begin(), x2.end());
    bothY.insert(bothY.end(), y2.begin(), y2.end());
    const CircleFit common = fitCircle(bothX, bothY, options.geometricFit);
    out.bidirectionalLeastSquares = common;
    out.bidirectionalG = range(radii(bothX, bothY, common.centre));
    const PolarRun first(x, y, common.centre), second(x2, y2, common.centre);
    out.hysteresisH =
        std::max(largestRadialDifference(first, second), largestRadialDifference(second, first));
    return out;
}

} // namespace xyt
