// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <random>

namespace xyt {

/**
 * Random numbers that are the same on every machine and standard library (std::*_distribution
 * algorithms are left to the library): a uniform number in (0, 1) from the top 53 bits of one
 * std::mt19937_64 draw, never 0 or 1 ((k + 0.5) 2^-53).
 */
double uniformOpen53(std::mt19937_64& rng);

/// A standard normal number by Box-Muller (the cosine branch) on two uniformOpen53 draws.
double standardNormal(std::mt19937_64& rng);

} // namespace xyt
