// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/zpetc_step.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/discrete_simulation.h"

#include <algorithm>
#include <cmath>

namespace xyt {

StepCharacteristics zpetcStepCharacteristics(const PolePlacementDesign& loop,
                                             const ZpetcDesign& zpetc, double band) {
    if (!(band > 0.0 && band < 1.0))
        throw InvalidInput("band", makeDiagnostic("sim_lie_in_zero_one"));
    StepCharacteristics out;
    const TransferFunction cl = loop.closedLoop();
    out.stable = cl.isStable();
    if (!out.stable)
        return out;
    // Room before the step for the preview to act, and after it for 12 time constants of the
    // slowest pole of T (which the feedforward cancels, so its mode only carries round-off).
    double slowest = 0.0;
    for (const auto& p : cl.poles())
        slowest = std::max(slowest, std::abs(p));
    const double decay = slowest > 0.0 ? -std::log(slowest) : 10.0;
    const std::size_t after =
        static_cast<std::size_t>(std::clamp(12.0 / std::max(decay, 1e-3), 50.0, 1e6));
    const std::size_t preview = static_cast<std::size_t>(std::max(zpetc.previewSteps, 0));
    const std::size_t stepAt =
        preview + static_cast<std::size_t>(std::max(zpetc.bMinus.degree(), 0)) + 2;
    const std::size_t samples = stepAt + after;
    std::vector<double> r(samples + preview, 0.0);
    std::fill(r.begin() + static_cast<std::ptrdiff_t>(stepAt), r.end(), 1.0);
    const std::vector<double> y = simulateZpetcLoop(loop, zpetc, r, samples).y;

    out.finalValue = y.back();
    const double scale = std::max(std::abs(out.finalValue), 1e-300);
    std::size_t peakAt = stepAt;
    std::size_t lastOutside = 0;
    bool everOutside = false;
    for (std::size_t k = 0; k < y.size(); ++k) {
        if (y[k] > y[peakAt])
            peakAt = k;
        if (std::abs(y[k] - out.finalValue) > band * scale) {
            lastOutside = k;
            everOutside = true;
        }
    }
    const double ts = loop.tsSeconds;
    out.overshootPct = std::max(0.0, (y[peakAt] - out.finalValue) / scale * 100.0);
    out.peakTimeSeconds = (static_cast<double>(peakAt) - static_cast<double>(stepAt)) * ts;
    // Settled at the first sample inside the band for good, counted from the step instant.
    out.settlingTimeSeconds = everOutside && lastOutside + 1 > stepAt
                                  ? static_cast<double>(lastOutside + 1 - stepAt) * ts
                                  : 0.0;
    return out;
}

StepCharacteristics loopStepCharacteristics(const PolePlacementDesign& loop) {
    StepCharacteristics out;
    const TransferFunction cl = loop.closedLoop();
    out.stable = cl.isStable();
    if (!out.stable)
        return out;
    out.finalValue = cl.dcGain();
    // The slowest pole decides how long the response takes: 12 time constants of it.
    double slowest = 0.0;
    for (const auto& p : cl.poles())
        slowest = std::max(slowest, std::abs(p));
    const double decay = slowest > 0.0 ? -std::log(slowest) : 10.0;
    const std::size_t n =
        static_cast<std::size_t>(std::clamp(12.0 / std::max(decay, 1e-3), 50.0, 1e6));
    const auto y =
        filterZInverse(loop.closedLoopNum, loop.closedLoopDen, std::vector<double>(n, 1.0));
    const double scale = std::max(std::abs(out.finalValue), 1e-300);
    double peak = y[0];
    std::size_t lastOutside = 0;
    bool everOutside = false;
    for (std::size_t k = 0; k < n; ++k) {
        if (y[k] > peak) {
            peak = y[k];
            out.peakTimeSeconds = static_cast<double>(k) * loop.tsSeconds;
        }
        if (std::abs(y[k] - out.finalValue) > 0.02 * scale) {
            lastOutside = k;
            everOutside = true;
        }
    }
    out.overshootPct = std::max(0.0, (peak - out.finalValue) / scale * 100.0);
    // A sampled response settles at the first sample inside the band for good.
    out.settlingTimeSeconds =
        everOutside ? static_cast<double>(lastOutside + 1) * loop.tsSeconds : 0.0;
    return out;
}

} // namespace xyt
