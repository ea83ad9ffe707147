// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Data for the identification tests, made by the core's own simulation
// (filterDifferenceEquation for z^-1 models) and std::mt19937_64 with fixed seeds. One random
// value per statement: the evaluation order of a call's arguments is unspecified.

#include "core/design/digital_controller.h"
#include "core/identification/io_data.h"

#include <QString>

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
inline IoData ioData(const std::vector<double>& u, const std::vector<double>& y, double tsSeconds) {
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

/**
 * The 200-seed check of the identification tests: for each parameter i, the sample SD of
 * est[i] must agree with the mean of the reported SDs sd[i] within 25 % (the sample SD of 200
 * draws has a relative standard error of 1/sqrt(398) = 5 %, so 25 % is 5 standard errors, with
 * room for the asymptotic covariance at a few hundred samples), and the mean must lie within
 * 4 standard errors plus 10 % of a spread (the O(1/N) bias of a nonlinear estimate) of
 * truth[i]. Returns an empty string when both hold, else what failed.
 */
inline QString spreadMismatch(const std::vector<std::vector<double>>& est,
                              const std::vector<std::vector<double>>& sd,
                              const std::vector<double>& truth) {
    for (std::size_t i = 0; i < truth.size(); ++i) {
        double mean = 0.0, spread = 0.0, meanSd = 0.0, unused = 0.0;
        meanAndSpread(est[i], mean, spread);
        meanAndSpread(sd[i], meanSd, unused);
        const double n = static_cast<double>(est[i].size());
        if (!std::isfinite(spread) || !std::isfinite(meanSd) || !(meanSd > 0.0) ||
            std::abs(spread - meanSd) > 0.25 * meanSd ||
            std::abs(mean - truth[i]) > 4.0 * spread / std::sqrt(n) + 0.1 * spread)
            return QStringLiteral(
                       "parameter %1: mean %2 (truth %3), spread %4, mean reported SD %5")
                .arg(i)
                .arg(mean, 0, 'g', 8)
                .arg(truth[i], 0, 'g', 8)
                .arg(spread, 0, 'g', 4)
                .arg(meanSd, 0, 'g', 4);
    }
    return {};
}

/// Runs @p fit for seeds 0 .. count-1 and collects its parameters and standard deviations.
template <typename Fit>
void collectOverSeeds(std::size_t count, std::size_t parameters, Fit fit,
                      std::vector<std::vector<double>>& est, std::vector<std::vector<double>>& sd) {
    est.assign(parameters, {});
    sd.assign(parameters, {});
    std::vector<double> p, s;
    for (std::size_t seed = 0; seed < count; ++seed) {
        fit(seed, p, s);
        for (std::size_t i = 0; i < parameters; ++i) {
            est[i].push_back(p[i]);
            sd[i].push_back(s[i]);
        }
    }
}

} // namespace xyt::test
