// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <limits>
#include <numbers>

namespace xyt {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace xyt
