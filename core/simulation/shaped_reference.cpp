// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/shaped_reference.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>

namespace xyt {

namespace {

std::string shapedSeconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", s);
    return buf;
}

void requireShapedShaper(const InputShaper& s) {
    if (s.amplitudes.empty() || s.amplitudes.size() != s.times.size())
        throw InvalidInput("shaper", makeDiagnostic("sim_shaper_sizes"));
    for (std::size_t i = 0; i < s.times.size(); ++i) {
        if (!std::isfinite(s.amplitudes[i]) || !std::isfinite(s.times[i]))
            throw InvalidInput("shaper", makeDiagnostic("sim_shaper_not_number"));
        if (i == 0 ? s.times[0] != 0.0 : !(s.times[i] > s.times[i - 1]))
            throw InvalidInput("shaper", makeDiagnostic("sim_shaper_times_order"));
    }
}

/// One impulse as whole samples plus a fraction: r(t_k - t_i) = (1 - f) r[k - m] + f r[k - m - 1].
struct ShapedImpulse {
    double amplitude;
    std::ptrdiff_t samples;
    double fraction;
};

std::vector<ShapedImpulse> shapedImpulses(const InputShaper& s, double dt) {
    std::vector<ShapedImpulse> out;
    for (std::size_t i = 0; i < s.times.size(); ++i) {
        const double x = s.times[i] / dt;
        const double whole = std::round(x);
        // A time on the grid (to 1e-9 of a sample) reads its sample: exact, not 1e-16 off.
        if (std::abs(x - whole) <= 1e-9)
            out.push_back({s.amplitudes[i], static_cast<std::ptrdiff_t>(whole), 0.0});
        else
            out.push_back(
                {s.amplitudes[i], static_cast<std::ptrdiff_t>(std::floor(x)), x - std::floor(x)});
    }
    return out;
}

std::size_t shapedAddedSamples(const InputShaper& s, double dt) {
    const double x = s.duration() / dt;
    const double whole = std::round(x);
    return static_cast<std::size_t>(std::abs(x - whole) <= 1e-9 ? whole : std::ceil(x));
}

/// Distance from (px, py) to the segment (ax, ay)-(bx, by).
double shapedSegmentDistance(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double u = len2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    return std::hypot(px - (ax + u * dx), py - (ay + u * dy));
}

} // namespace

ShapedReference shapeReference(const InputShaper& shaper, const std::vector<double>& r,
                               double dtSeconds, double moveSeconds) {
    requirePositive(dtSeconds, "dt");
    requirePositive(moveSeconds, "move");
    requireShapedShaper(shaper);
    if (r.empty())
        throw InvalidInput("reference", makeDiagnostic("is_empty"));
    for (double v : r)
        requireFinite(v, "reference");
    if (shaper.duration() > moveSeconds)
        throw InvalidInput("shaper.frequency", makeDiagnostic("sim_shaper_longer_than_move",
                                                              {shapedSeconds(shaper.duration()),
                                                               shapedSeconds(moveSeconds)}));
    const std::vector<ShapedImpulse> impulses = shapedImpulses(shaper, dtSeconds);
    ShapedReference out;
    out.addedSamples = shapedAddedSamples(shaper, dtSeconds);
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(r.size());
    const std::ptrdiff_t total = n + static_cast<std::ptrdiff_t>(out.addedSamples);
    // r held before the first sample and after the last.
    const auto at = [&](std::ptrdiff_t k) { return r[std::clamp<std::ptrdiff_t>(k, 0, n - 1)]; };
    out.values.resize(static_cast<std::size_t>(total));
    for (std::ptrdiff_t k = 0; k < total; ++k) {
        double sum = 0.0;
        for (const ShapedImpulse& p : impulses) {
            const std::ptrdiff_t j = k - p.samples;
            sum +=
                p.amplitude *
                (p.fraction == 0.0 ? at(j) : (1.0 - p.fraction) * at(j) + p.fraction * at(j - 1));
        }
        out.values[static_cast<std::size_t>(k)] = sum;
    }
    return out;
}

ShapedPath shapePath(const InputShaper& shaper, const std::vector<double>& x,
                     const std::vector<double>& y, double dtSeconds, double moveSeconds) {
    if (x.size() != y.size())
        throw InvalidInput("y", makeDiagnostic("sim_y_x_sizes", {std::to_string(y.size()),
                                                                 std::to_string(x.size())}));
    ShapedReference sx = shapeReference(shaper, x, dtSeconds, moveSeconds);
    ShapedReference sy = shapeReference(shaper, y, dtSeconds, moveSeconds);
    return {std::move(sx.values), std::move(sy.values), sx.addedSamples};
}

PathDeviation shapedPathDeviation(const ShapedPath& shaped, const std::vector<double>& x,
                                  const std::vector<double>& y, const InputShaper& shaper,
                                  double dtSeconds) {
    requirePositive(dtSeconds, "dt");
    requireShapedShaper(shaper);
    if (x.empty())
        throw InvalidInput("x", makeDiagnostic("is_empty"));
    if (x.size() != y.size())
        throw InvalidInput("y", makeDiagnostic("sim_y_x_sizes", {std::to_string(y.size()),
                                                                 std::to_string(x.size())}));
    if (shaped.x.size() != shaped.y.size())
        throw InvalidInput("shaped.y", makeDiagnostic("sim_shaped_sizes_differ"));
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(shapedAddedSamples(shaper, dtSeconds));
    PathDeviation out;
    for (std::size_t k = 0; k < shaped.x.size(); ++k) {
        const std::ptrdiff_t hi = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(k), n - 1);
        const std::ptrdiff_t lo =
            std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(k) - m - 1, 0, hi);
        double d = std::hypot(shaped.x[k] - x[static_cast<std::size_t>(lo)],
                              shaped.y[k] - y[static_cast<std::size_t>(lo)]);
        for (std::ptrdiff_t j = lo; j < hi; ++j) {
            const auto a = static_cast<std::size_t>(j);
            d = std::min(
                d, shapedSegmentDistance(shaped.x[k], shaped.y[k], x[a], y[a], x[a + 1], y[a + 1]));
        }
        if (d > out.maxMm) {
            out.maxMm = d;
            out.index = k;
        }
    }
    return out;
}

double shapedCircleRadiusRatio(const InputShaper& shaper, double omegaRadPerSec) {
    requireFinite(omegaRadPerSec, "omega");
    std::complex<double> h = 0.0;
    for (std::size_t i = 0; i < shaper.amplitudes.size(); ++i)
        h += shaper.amplitudes[i] * std::polar(1.0, -omegaRadPerSec * shaper.times[i]);
    return std::abs(h);
}

} // namespace xyt
