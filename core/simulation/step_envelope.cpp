// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/step_envelope.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>

namespace xyt {

double StepEnvelope::overshootBound() const {
    if (!std::isfinite(maxOvershootPct))
        return std::numeric_limits<double>::infinity();
    return finalValue * (1.0 + (maxOvershootPct + overshootSlackPct) / 100.0);
}

std::vector<bool> envelopeViolations(const StepResponseCurve& curve, const StepEnvelope& envelope) {
    if (curve.t.size() != curve.y.size())
        throw InvalidInput("curve", makeDiagnostic("sim_ty_same_length"));
    if (!std::isfinite(envelope.finalValue) || !(envelope.band > 0.0 && envelope.band < 1.0))
        throw InvalidInput("envelope", makeDiagnostic("sim_envelope_invalid"));
    const double bound = envelope.overshootBound();
    const double halfBand = envelope.band * std::abs(envelope.finalValue);
    std::vector<bool> out(curve.y.size(), false);
    for (std::size_t k = 0; k < curve.y.size(); ++k) {
        const double y = curve.y[k];
        const bool settled = curve.t[k] - curve.stepAtSeconds >= envelope.settlingTimeSeconds;
        out[k] = !std::isfinite(y) || y > bound ||
                 (settled && std::abs(y - envelope.finalValue) > halfBand);
    }
    return out;
}

double stepViewHorizonSeconds(const StepCharacteristics& step, double minimumSeconds,
                              double settlingLimitSeconds) {
    if (!(minimumSeconds >= 0.0) || !std::isfinite(minimumSeconds))
        throw InvalidInput("minimumSeconds", makeDiagnostic("finite_not_negative"));
    const double floor = minimumSeconds > 0.0 ? minimumSeconds : 1.0;
    if (!step.stable)
        return floor;
    double base =
        std::isfinite(step.settlingTimeSeconds) ? std::max(step.settlingTimeSeconds, 0.0) : 0.0;
    const double peak = step.peakTimeSeconds;
    if (std::isfinite(peak) && peak > 0.0 && step.overshootPct > 0.0 &&
        (base == 0.0 || peak <= 4.0 * base))
        base = std::max(base, peak);
    double horizon = std::max(1.5 * base, minimumSeconds);
    if (!(horizon > 0.0))
        horizon = floor;
    if (std::isfinite(settlingLimitSeconds) && settlingLimitSeconds >= horizon &&
        settlingLimitSeconds <= 3.0 * horizon)
        horizon = 1.15 * settlingLimitSeconds;
    return horizon;
}

} // namespace xyt
