// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/damping_grid.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace xyt {

namespace {

using Complex = std::complex<double>;

void requireZetas(const std::vector<double>& zetas) {
    for (double z : zetas)
        if (!(z >= 0.0 && z <= 1.0))
            throw InvalidInput("zetas", makeDiagnostic("analysis_damping_ratios_range"));
}

void requirePointCount(int pointsPerLine) {
    if (pointsPerLine < 2)
        throw InvalidInput("pointsPerLine", makeDiagnostic("at_least", {"2"}));
}

/// Upper half then its mirror image: one polyline through the real axis. The upper half runs
/// from its far end to the real axis, so the result is continuous.
std::vector<Complex> mirrored(const std::vector<Complex>& upperFromFarEnd) {
    std::vector<Complex> line(upperFromFarEnd);
    for (auto it = upperFromFarEnd.rbegin() + 1; it != upperFromFarEnd.rend(); ++it)
        line.push_back(std::conj(*it));
    return line;
}

/// theta from pi/2 to pi: the upper left quarter of a circle of radius omega, far end first.
std::vector<Complex> upperQuarter(double omega, int points) {
    std::vector<Complex> q;
    q.reserve(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i) {
        const double theta = std::numbers::pi / 2.0 * (1.0 + static_cast<double>(i) / (points - 1));
        q.push_back(std::polar(omega, theta));
    }
    return q;
}

} // namespace

DampingAndFrequency dampingOf(std::complex<double> root, double tsSeconds) {
    requireFinite(root.real(), "root");
    requireFinite(root.imag(), "root");
    if (!(tsSeconds >= 0.0) || !std::isfinite(tsSeconds))
        throw InvalidInput("tsSeconds", makeDiagnostic("analysis_finite_and_not_negative"));
    if (tsSeconds > 0.0) {
        if (root == Complex(0.0))
            return {1.0, std::numeric_limits<double>::infinity()};
        root = std::log(root) / tsSeconds;
    }
    const double omega = std::abs(root);
    if (omega == 0.0)
        return {1.0, 0.0};
    return {std::clamp(-root.real() / omega, -1.0, 1.0), omega};
}

DampingGrid sPlaneDampingGrid(const std::vector<double>& zetas,
                              const std::vector<double>& omegasRadPerSec, double radius,
                              int pointsPerLine) {
    requireZetas(zetas);
    requirePositive(radius, "radius");
    requirePointCount(pointsPerLine);
    for (double w : omegasRadPerSec)
        requirePositive(w, "omegasRadPerSec");
    DampingGrid grid;
    for (double zeta : zetas) {
        // A ray is straight: its two ends and the origin describe it exactly.
        const Complex end = radius * Complex(-zeta, std::sqrt(1.0 - zeta * zeta));
        grid.dampingLines.push_back({zeta, {end, Complex(0.0), std::conj(end)}});
    }
    for (double w : omegasRadPerSec)
        grid.frequencyLines.push_back({w, mirrored(upperQuarter(w, pointsPerLine))});
    return grid;
}

DampingGrid zPlaneDampingGrid(const std::vector<double>& zetas,
                              const std::vector<double>& omegasRadPerSec, double tsSeconds,
                              int pointsPerLine) {
    requireZetas(zetas);
    requirePositive(tsSeconds, "tsSeconds");
    requirePointCount(pointsPerLine);
    const double nyquist = std::numbers::pi / tsSeconds;
    for (double w : omegasRadPerSec) {
        requirePositive(w, "omegasRadPerSec");
        if (w > nyquist * (1.0 + 1e-12))
            throw InvalidInput("omegasRadPerSec", makeDiagnostic("analysis_exceeds_nyquist"));
    }
    DampingGrid grid;
    grid.tsSeconds = tsSeconds;
    for (double zeta : zetas) {
        const double damped = std::sqrt(1.0 - zeta * zeta);
        // omega_n at which the damped frequency reaches Nyquist (zeta = 1: the real axis to
        // s = -pi/Ts, the same reach).
        const double omegaEnd = damped > 0.0 ? nyquist / damped : nyquist;
        std::vector<Complex> upper;
        for (int i = pointsPerLine - 1; i >= 0; --i) {
            const double omega = omegaEnd * static_cast<double>(i) / (pointsPerLine - 1);
            upper.push_back(std::exp(tsSeconds * omega * Complex(-zeta, damped)));
        }
        grid.dampingLines.push_back({zeta, mirrored(upper)});
    }
    for (double w : omegasRadPerSec) {
        std::vector<Complex> upper = upperQuarter(w, pointsPerLine);
        for (Complex& s : upper)
            s = std::exp(tsSeconds * s);
        grid.frequencyLines.push_back({w, mirrored(upper)});
    }
    return grid;
}

std::vector<double> defaultGridZetas() {
    std::vector<double> z;
    for (int i = 0; i <= 10; ++i)
        z.push_back(i / 10.0);
    return z;
}

std::vector<double> niceGridFrequencies(double maxRadPerSec, int count) {
    requirePositive(maxRadPerSec, "maxRadPerSec");
    if (count < 1)
        throw InvalidInput("count", makeDiagnostic("at_least", {"1"}));
    std::vector<double> values;
    double decade = std::pow(10.0, std::floor(std::log10(maxRadPerSec)));
    // Walk down the 1-2-5 sequence from the largest value not above the maximum.
    while (static_cast<int>(values.size()) < count) {
        for (double mantissa : {5.0, 2.0, 1.0}) {
            const double v = mantissa * decade;
            if (v <= maxRadPerSec * (1.0 + 1e-12) && static_cast<int>(values.size()) < count)
                values.push_back(v);
        }
        decade /= 10.0;
    }
    std::sort(values.begin(), values.end());
    return values;
}

std::vector<double> defaultZGridFrequencies(double tsSeconds) {
    requirePositive(tsSeconds, "tsSeconds");
    std::vector<double> w;
    for (int k = 1; k <= 10; ++k)
        w.push_back(k / 10.0 * std::numbers::pi / tsSeconds);
    return w;
}

} // namespace xyt
