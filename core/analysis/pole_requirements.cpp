// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/pole_requirements.h"

#include "core/analysis/damping_grid.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>
#include <numbers>

namespace xyt {

double dampingForOvershoot(double overshootPct) {
    if (!(overshootPct >= 0.0))
        throw InvalidInput("overshootPct", makeDiagnostic("analysis_number_not_negative"));
    const double mp = overshootPct / 100.0;
    if (mp == 0.0)
        return 1.0;
    if (mp >= 1.0)
        return 0.0;
    const double l = std::log(mp);
    return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

PoleRequirements poleRequirements(double maxOvershootPct, double maxSettlingTimeSeconds) {
    if (!(maxOvershootPct >= 0.0))
        throw InvalidInput("maxOvershootPct", makeDiagnostic("analysis_number_not_negative"));
    if (!(maxSettlingTimeSeconds > 0.0))
        throw InvalidInput("maxSettlingTimeSeconds", makeDiagnostic("not_positive"));
    PoleRequirements out;
    out.minDamping = dampingForOvershoot(maxOvershootPct);
    if (std::isfinite(maxSettlingTimeSeconds))
        out.maxRealPartPerSec = -4.0 / maxSettlingTimeSeconds;
    return out;
}

double settlingRadius(const PoleRequirements& requirements, double tsSeconds) {
    if (!(tsSeconds > 0.0) || !std::isfinite(tsSeconds))
        throw InvalidInput("tsSeconds", makeDiagnostic("finite_positive"));
    return std::exp(requirements.maxRealPartPerSec * tsSeconds);
}

PoleViolation checkPole(std::complex<double> pole, const PoleRequirements& requirements,
                        double tsSeconds) {
    const DampingAndFrequency d = dampingOf(pole, tsSeconds);
    PoleViolation out;
    out.damping = d.zeta < requirements.minDamping - 1e-9;
    // Re s = -zeta omega_n (for z = 0, s = -infinity: never too slow).
    const double re = std::isfinite(d.omegaNRadPerSec) ? -d.zeta * d.omegaNRadPerSec : -INFINITY;
    const double sigma = requirements.maxRealPartPerSec;
    out.settling = std::isfinite(sigma) && re > sigma + 1e-9 * std::abs(sigma);
    return out;
}

} // namespace xyt
