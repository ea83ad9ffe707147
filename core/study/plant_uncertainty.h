// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace xyt {

/**
 * One uncertain plant parameter: drawn uniformly from nominal (1 - relative) to
 * nominal (1 + relative). The names are those of the plant's coefficients: "k0", "a1", "a2" of
 * a Guillemin-Truxal plant k0 / (s^3 + a1 s^2 + a2 s); "a1".."an" and "b1".."bm" of an ARX
 * model A(z^-1) = 1 + a1 z^-1 + ..., B(z^-1) = b1 z^-1 + ... (ascending powers of z^-1).
 */
struct UncertainParameter {
    std::string name;
    double nominal = 0.0;
    double relative = 0.0; ///< half-range as a fraction of |nominal|, 0 <= relative < 1
};

/**
 * Sets the relative half-range of parameter @p name (10 % is 0.1).
 * @throws InvalidInput "range.<name>" unless 0 <= relative < 1 (a range of 100 % or more could
 *         reach a zero or sign-changed coefficient: another plant structure, not a tolerance);
 *         "range" naming the known parameters when @p name is not one of them.
 */
void setRelativeRange(std::vector<UncertainParameter>& parameters, const std::string& name,
                      double relative);

/// Every parameter's relative range multiplied by @p scale (>= 0; the result must stay < 1).
std::vector<UncertainParameter> scaledRanges(std::vector<UncertainParameter> parameters,
                                             double scale);

/**
 * @p count random plants: row i holds the parameter values of plant i, each value
 * nominal (1 + relative (2 U - 1)) with U uniform on [0, 1) from a 64-bit Mersenne Twister
 * seeded with @p seed, drawn plant by plant on the calling thread (53 random bits per U, not
 * std::uniform_real_distribution, whose algorithm the standard leaves to the library): the
 * same seed gives the same plants on every machine and for any number of threads. With the same
 * seed, widening the ranges moves every plant farther from the nominal along the same
 * direction (U is the same), which keeps envelopes nested.
 * @throws InvalidInput "samples" unless 0 <= count <= 1'000'000.
 */
std::vector<std::vector<double>> drawPlants(const std::vector<UncertainParameter>& parameters,
                                            int count, std::uint64_t seed);

/**
 * @p count random plants from the normal distribution N(nominal, @p covariance) of an identified
 * model (the uncertainty "from identification"): theta = nominal + M z with
 * M M^T = covariance (Eigen's LDLT, so a semi-definite covariance, e.g. a parameter known
 * exactly, is allowed: M = P^T L D^(1/2)) and z standard normal (standardNormal: Box-Muller on
 * 53-bit uniforms of std::mt19937_64 seeded with @p seed), drawn plant by plant on the calling
 * thread: the same plants on every machine and for any number of threads.
 * @throws InvalidInput "samples" as drawPlants; "covariance" unless it is square of the
 *         parameters' size, finite, symmetric (to 1e-12 relative) and positive semi-definite.
 */
std::vector<std::vector<double>> drawPlantsNormal(const std::vector<UncertainParameter>& parameters,
                                                  const Eigen::MatrixXd& covariance, int count,
                                                  std::uint64_t seed);

/**
 * The corners of the parameter box: every combination of nominal (1 +- relative) over the p
 * parameters whose range is not 0 (the others nominal), 2^p plants, in binary order (bit j set:
 * the j-th uncertain parameter at its upper end).
 * @throws InvalidInput "corners" when p > 16 (65,536 corners).
 */
std::vector<std::vector<double>> boxCorners(const std::vector<UncertainParameter>& parameters);

} // namespace xyt
