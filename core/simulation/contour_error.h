// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/trajectory.h"

#include <vector>

namespace xyt {

/// Radial deviation of a traced XY path from a commanded circle.
struct ContourError {
    double maxAbs = 0.0; ///< max |rho_k - R|, rho_k the traced distance from the centre
    double rms = 0.0;    ///< sqrt(mean (rho_k - R)^2)
    std::size_t samples = 0;
};

/**
 * Contour error of the path (x_k, y_k) sampled at t_k against @p circle: the radial deviation
 * rho_k - R with rho_k = |(x_k - cx, y_k - cy)|, as a ballbar measures it. Samples during the
 * ramp-in (t < rampInSeconds), where the command is not yet the circle, are left out.
 * @throws InvalidInput "path" when the sizes differ or no sample is past the ramp-in.
 */
ContourError circleContourError(const std::vector<double>& t, const std::vector<double>& x,
                                const std::vector<double>& y, const Circle& circle);

} // namespace xyt
