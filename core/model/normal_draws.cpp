// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/normal_draws.h"

#include <cmath>
#include <numbers>

namespace xyt {

double uniformOpen53(std::mt19937_64& rng) {
    return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}

double standardNormal(std::mt19937_64& rng) {
    const double r = uniformOpen53(rng); // drawn in this order, as two statements
    const double theta = uniformOpen53(rng);
    return std::sqrt(-2.0 * std::log(r)) * std::cos(2.0 * std::numbers::pi * theta);
}

} // namespace xyt
