// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Data for the identification tests, made by the core's own simulation
// (filterDifferenceEquation for z^-1 models) and std::mt19937_64 with fixed seeds. One random
// value per statement: the evaluation order of a call's arguments is unspecified.

#include "core/design/digital_controller.h"
#include "core/identification/io_data.h"

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace xyt::test {

/// n independent N(0, sigma^2) samples.
inline std::vector<double> gaussianNoise(std::size_t n, double sigma, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, sigma);
    std::vector<double> v(n);
    for (auto& x : v)
        x = g(rng);
    return v;
}

/// n independent +-amplitude samples (a random binary input, white, persistently exciting of
/// any order).
inline std::vector<double> randomBinary(std::size_t n, double amplitude, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution coin(0.5);
    std::vector<double> v(n);
    for (auto& x : v)
        x = coin(rng) ? amplitude : -amplitude;
    return v;
}

/// +-amplitude square wave starting high, halfPeriod samples per level.
inline std::vector<double> squareWave(std::size_t n, std::size_t halfPeriod, double amplitude) {
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k)
        v[k] = (k / halfPeriod) % 2 == 0 ? amplitude : -amplitude;
    return v;
}

inline std::vector<double> plus(std::vector<double> a, const std::vector<double>& b) {
    for (std::size_t k = 0; k < a.size(); ++k)
        a[k] += b[k];
    return a;
}

/// y = num/den u (+ the noise already filtered by the caller), as IoData at tsSeconds.
inline IoData ioData(const std::vector<double>& u, const std::vector<double>& y,
                     double tsSeconds) {
    IoData d;
    d.u = u;
    d.y = y;
    d.tsSeconds = tsSeconds;
    d.source = "simulated";
    return d;
}

/// Sample mean and standard deviation (n - 1) of a list.
inline void meanAndSpread(const std::vector<double>& v, double& mean, double& spread) {
    mean = 0.0;
    for (double x : v)
        mean += x;
    mean /= static_cast<double>(v.size());
    double s = 0.0;
    for (double x : v)
        s += (x - mean) * (x - mean);
    spread = std::sqrt(s / static_cast<double>(v.size() - 1));
}

} // namespace xyt::test
