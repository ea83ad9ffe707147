// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/step_response.h"

#include "core/model/errors.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>

namespace xyt {

StepResponseCurve stepResponseCurve(const TransferFunction& closedLoop, double horizonSeconds, int samples) {
    if (!(horizonSeconds > 0.0) || !std::isfinite(horizonSeconds))
        throw InvalidInput("horizon", "must be a finite number greater than zero");
    if (samples < 10 || samples > 1000000)
        throw InvalidInput("samples", "must lie in 10 .. 1000000");
    StepResponseCurve out;
    const double ts = closedLoop.tsSeconds();
    if (ts > 0.0) {
        const std::size_t n = static_cast<std::size_t>(
            std::clamp(std::ceil(horizonSeconds / ts), 2.0, 1e6)) + 1;
        // y(k) from N(z^-1)/D(z^-1) driven by u(k) = 1 for k >= 0.
        out.y = filterZInverse(closedLoop.numZInverse(), closedLoop.denZInverse(), std::vector<double>(n, 1.0));
        for (std::size_t k = 0; k < n; ++k)
            out.t.push_back(static_cast<double>(k) * ts);
        return out;
    }
    const double dt = horizonSeconds / samples;
    out.y = simulateLinear(closedLoop, std::vector<double>(static_cast<std::size_t>(samples) + 1, 1.0), dt);
    for (int k = 0; k <= samples; ++k)
        out.t.push_back(k * dt);
    return out;
}

StepResponseCurve zpetcStepResponseCurve(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                                         double horizonSeconds) {
    if (!(horizonSeconds > 0.0) || !std::isfinite(horizonSeconds))
        throw InvalidInput("horizon", "must be a finite number greater than zero");
    const double ts = loop.tsSeconds;
    const std::size_t preview = static_cast<std::size_t>(std::max(zpetc.previewSteps, 0));
    const std::size_t stepAt = preview + static_cast<std::size_t>(std::max(zpetc.bMinus.degree(), 0)) + 2;
    const std::size_t after = static_cast<std::size_t>(std::clamp(std::ceil(horizonSeconds / ts), 10.0, 1e6));
    const std::size_t samples = stepAt + after;
    std::vector<double> r(samples + preview, 0.0);
    std::fill(r.begin() + static_cast<std::ptrdiff_t>(stepAt), r.end(), 1.0);
    StepResponseCurve out;
    out.y = simulateZpetcLoop(loop, zpetc, r, samples).y;
    for (std::size_t k = 0; k < samples; ++k)
        out.t.push_back(static_cast<double>(k) * ts);
    out.stepAtSeconds = static_cast<double>(stepAt) * ts;
    return out;
}

} // namespace xyt
