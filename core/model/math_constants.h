// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <limits>
#include <numbers>

namespace xyt {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

} // namespace xyt
