// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Random open loops for invariant tests (margins against the root locus, the Nyquist
// criterion): a fixed seed, so every run draws the same loops.

#include "core/model/polynomial.h"
#include "core/model/transfer_function.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace xyt::test {

struct RandomLoopOptions {
    bool discrete = false;
    int maxIntegrators = 2;           ///< poles at s = 0 (z = 1), 0..this
    double unstablePoleChance = 0.25; ///< chance of one open-loop pole in the unstable region
};

/// A random proper loop: 1-3 real poles, maybe a lightly to well damped pair, integrators,
/// maybe an unstable pole, fewer zeros than poles (some non-minimum-phase), a log-uniform gain.
inline TransferFunction randomLoop(std::mt19937& rng, const RandomLoopOptions& o) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto unif = [&](double a, double b) { return a + (b - a) * u(rng); };
    std::vector<std::complex<double>> poles, zeros;
    const int integrators = static_cast<int>(unif(0.0, o.maxIntegrators + 1.0 - 1e-9));
    for (int i = 0; i < integrators; ++i)
        poles.emplace_back(o.discrete ? 1.0 : 0.0, 0.0);
    const int real = 1 + static_cast<int>(unif(0.0, 3.0 - 1e-9));
    for (int i = 0; i < real; ++i)
        poles.emplace_back(o.discrete ? unif(-0.8, 0.97) : -std::pow(10.0, unif(-1.0, 1.0)), 0.0);
    if (u(rng) < 0.5) {
        std::complex<double> p;
        if (o.discrete) {
            p = std::polar(unif(0.3, 0.95), unif(0.1, 2.8));
        } else {
            const double wn = std::pow(10.0, unif(-0.5, 1.0)), zeta = unif(0.05, 0.9);
            p = {-zeta * wn, wn * std::sqrt(1.0 - zeta * zeta)};
        }
        poles.push_back(p);
        poles.push_back(std::conj(p));
    }
    if (u(rng) < o.unstablePoleChance)
        poles.emplace_back(
            o.discrete ? unif(1.05, 1.6) * (u(rng) < 0.8 ? 1.0 : -1.0) : unif(0.1, 2.0), 0.0);
    const int nz = static_cast<int>(unif(0.0, static_cast<double>(poles.size()) - 1e-9));
    for (int i = 0; i < nz; ++i)
        zeros.emplace_back(o.discrete ? unif(-2.0, 0.9) : unif(-10.0, 5.0), 0.0);
    const double gain = std::pow(10.0, unif(-1.5, 1.5)) * (o.discrete ? 0.2 : 1.0);
    return TransferFunction(Polynomial::fromRoots(zeros, gain), Polynomial::fromRoots(poles),
                            o.discrete ? unif(0.01, 0.5) : 0.0);
}

/// Closed-loop (roots of D + N) and open-loop (roots of D) pole counts in the unstable
/// region, and the smallest distance of a closed-loop pole to the boundary (relative).
struct PoleCounts {
    int openLoopUnstable = 0;
    int closedLoopUnstable = 0;
    double closedLoopBoundaryDistance = 0.0;
};

inline PoleCounts poleCounts(const TransferFunction& l) {
    PoleCounts c;
    const bool d = l.isDiscrete();
    for (const auto& r : l.den().roots())
        if (d ? std::abs(r) > 1.0 + 1e-6 : r.real() > 1e-6 * std::abs(r))
            ++c.openLoopUnstable;
    c.closedLoopBoundaryDistance = std::numeric_limits<double>::infinity();
    for (const auto& r : (l.den() + l.num()).roots()) {
        const double dist = d ? std::abs(std::abs(r) - 1.0) : std::abs(r.real()) / std::abs(r);
        c.closedLoopBoundaryDistance = std::min(c.closedLoopBoundaryDistance, dist);
        if (d ? std::abs(r) > 1.0 : r.real() > 0.0)
            ++c.closedLoopUnstable;
    }
    return c;
}

} // namespace xyt::test
