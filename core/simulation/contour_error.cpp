// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/contour_error.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>

namespace xyt {

ContourError circleContourError(const std::vector<double>& t, const std::vector<double>& x,
                                const std::vector<double>& y, const Circle& circle) {
    if (t.size() != x.size() || t.size() != y.size())
        throw InvalidInput("path", makeDiagnostic("sim_txy_different_lengths"));
    ContourError out;
    double sumSquares = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] < circle.rampInSeconds)
            continue;
        const double deviation =
            std::hypot(x[k] - circle.centreX, y[k] - circle.centreY) - circle.radius;
        out.maxAbs = std::max(out.maxAbs, std::abs(deviation));
        sumSquares += deviation * deviation;
        ++out.samples;
    }
    if (out.samples == 0)
        throw InvalidInput("path", makeDiagnostic("sim_no_sample_after_ramp_in"));
    out.rms = std::sqrt(sumSquares / static_cast<double>(out.samples));
    return out;
}

} // namespace xyt
