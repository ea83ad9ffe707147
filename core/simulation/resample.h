// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

namespace xyt {

/**
 * y sampled at the times @p t by linear interpolation in (ts, ys) (held at the ends), so that
 * axes with different sample times can be paired for the XY contour. @p ts must be increasing;
 * a time of @p t equal to a sample time of @p ts gives that sample exactly.
 */
std::vector<double> resampleLinear(const std::vector<double>& ts, const std::vector<double>& ys,
                                   const std::vector<double>& t);

} // namespace xyt
