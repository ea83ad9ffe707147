// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/step_response.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

StepResponseCurve stepResponseCurve(const TransferFunction& closedLoop, double horizonSeconds,
                                    int samples) {
    if (!(horizonSeconds > 0.0) || !std::isfinite(horizonSeconds))
        throw InvalidInput("horizon", makeDiagnostic("finite_positive"));
    if (samples < 10 || samples > 1000000)
        throw InvalidInput("samples", makeDiagnostic("sim_samples_range"));
    StepResponseCurve out;
    const double ts = closedLoop.tsSeconds();
    if (ts > 0.0) {
        const std::size_t n =
            static_cast<std::size_t>(std::clamp(std::ceil(horizonSeconds / ts), 2.0, 1e6)) + 1;
        // y(k) from N(z^-1)/D(z^-1) driven by u(k) = 1 for k >= 0.
        out.y = filterZInverse(closedLoop.numZInverse(), closedLoop.denZInverse(),
                               std::vector<double>(n, 1.0));
        for (std::size_t k = 0; k < n; ++k)
            out.t.push_back(static_cast<double>(k) * ts);
        return out;
    }
    const double dt = horizonSeconds / samples;
    out.y = simulateLinear(closedLoop,
                           std::vector<double>(static_cast<std::size_t>(samples) + 1, 1.0), dt);
    for (int k = 0; k <= samples; ++k)
        out.t.push_back(k * dt);
    return out;
}

StepResponseCurve zpetcStepResponseCurve(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                                         double horizonSeconds) {
    if (!(horizonSeconds > 0.0) || !std::isfinite(horizonSeconds))
        throw InvalidInput("horizon", makeDiagnostic("finite_positive"));
    const double ts = loop.tsSeconds;
    const std::size_t preview = static_cast<std::size_t>(std::max(zpetc.previewSteps, 0));
    const std::size_t stepAt =
        preview + static_cast<std::size_t>(std::max(zpetc.bMinus.degree(), 0)) + 2;
    const std::size_t after =
        static_cast<std::size_t>(std::clamp(std::ceil(horizonSeconds / ts), 10.0, 1e6));
    // Samples 0 .. stepAt + after: the last one `after` steps (>= the horizon) past the step.
    const std::size_t samples = stepAt + after + 1;
    std::vector<double> r(samples + preview, 0.0);
    std::fill(r.begin() + static_cast<std::ptrdiff_t>(stepAt), r.end(), 1.0);
    StepResponseCurve out;
    out.y = simulateZpetcLoop(loop, zpetc, r, samples).y;
    for (std::size_t k = 0; k < samples; ++k)
        out.t.push_back(static_cast<double>(k) * ts);
    out.stepAtSeconds = static_cast<double>(stepAt) * ts;
    return out;
}

RiseTime riseTime(const StepResponseCurve& curve, double finalValue, double lowFraction,
                  double highFraction) {
    if (curve.t.size() != curve.y.size() || curve.t.size() < 2)
        throw InvalidInput("curve", makeDiagnostic("sim_ty_same_length_two"));
    if (!std::isfinite(finalValue) || finalValue == 0.0)
        throw InvalidInput("finalValue", makeDiagnostic("sim_finite_nonzero"));
    if (!(lowFraction >= 0.0 && lowFraction < highFraction && highFraction <= 1.0))
        throw InvalidInput("fractions", makeDiagnostic("sim_fractions_order"));
    // The first instant at which y / final reaches the level (dividing by the final value lets
    // a response to a negative final value rise "up" as well).
    const auto crossing = [&](double level) {
        for (std::size_t k = 0; k < curve.y.size(); ++k) {
            const double v = curve.y[k] / finalValue;
            if (!(v >= level))
                continue;
            if (k == 0)
                return curve.t[0];
            const double before = curve.y[k - 1] / finalValue;
            const double s = (level - before) / (v - before); // in (0, 1]: before < level <= v
            return curve.t[k - 1] + s * (curve.t[k] - curve.t[k - 1]);
        }
        return std::numeric_limits<double>::quiet_NaN();
    };
    RiseTime out;
    const double low = crossing(lowFraction), high = crossing(highFraction);
    if (std::isnan(low) || std::isnan(high))
        return out;
    out.reached = true;
    out.lowCrossingSeconds = low;
    out.highCrossingSeconds = high;
    out.seconds = high - low;
    return out;
}

} // namespace xyt
