// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/flexible_mode.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <cmath>

namespace xyt {

void requireDampingRatio(double zeta, const std::string& field) {
    if (!std::isfinite(zeta) || zeta < 0.0 || zeta >= 1.0)
        throw InvalidInput(field, makeDiagnostic("model_damping_ratio"));
}

void validateFlexibleMode(const FlexibleMode& mode, const std::string& prefix) {
    if (!std::isfinite(mode.frequencyHz) || mode.frequencyHz < 0.0)
        throw InvalidInput(prefix + "frequency", makeDiagnostic("model_mode_frequency"));
    requireDampingRatio(mode.dampingRatio, prefix + "damping");
    if (!std::isfinite(mode.antiResonanceHz) || mode.antiResonanceHz < 0.0)
        throw InvalidInput(prefix + "anti_resonance",
                           makeDiagnostic("model_anti_resonance_frequency"));
    if (mode.present() && mode.twoMass() && mode.antiResonanceHz >= mode.frequencyHz)
        throw InvalidInput(prefix + "anti_resonance", makeDiagnostic("model_anti_resonance_below"));
    requireDampingRatio(mode.antiResonanceDamping, prefix + "anti_resonance_damping");
}

TransferFunction FlexibleMode::transferFunction() const {
    validateFlexibleMode(*this);
    if (!present())
        return TransferFunction::gain(1.0);
    const double wr = 2.0 * kPi * frequencyHz;
    const std::vector<double> den{1.0, 2.0 * dampingRatio * wr, wr * wr};
    if (!twoMass())
        return TransferFunction::fromDescending({wr * wr}, den);
    const double wa = 2.0 * kPi * antiResonanceHz;
    const double g = (wr * wr) / (wa * wa);
    return TransferFunction::fromDescending({g, g * 2.0 * antiResonanceDamping * wa, g * wa * wa},
                                            den);
}

} // namespace xyt
