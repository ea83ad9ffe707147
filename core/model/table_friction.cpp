// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/table_friction.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>

namespace xyt {

bool TableFriction::active() const {
    return coulombVolts != 0.0 || staticVolts != 0.0 || viscousVoltsPerMmPerS != 0.0 ||
           backlashMm != 0.0 || amplifierDeadbandVolts != 0.0;
}

double frictionCompensationVolts(const TableFriction& friction,
                                 const FrictionCompensation& compensation, double velocityMmPerS) {
    if (compensation.percent == 0.0)
        return 0.0;
    const double ramp = std::clamp(velocityMmPerS / compensation.bandMmPerS, -1.0, 1.0);
    return compensation.percent / 100.0 *
           (friction.coulombVolts * ramp + friction.viscousVoltsPerMmPerS * velocityMmPerS);
}

namespace {

void requireNonNegative(double value, const std::string& field) {
    if (!std::isfinite(value) || value < 0.0)
        throw InvalidInput(field, makeDiagnostic("finite_not_negative"));
}

} // namespace

void validateTableFriction(const TableFriction& f, const std::string& prefix) {
    requireNonNegative(f.coulombVolts, prefix + "coulomb");
    requireNonNegative(f.staticVolts, prefix + "static");
    requireNonNegative(f.stribeckVelocityMmPerS, prefix + "stribeck_velocity");
    requireNonNegative(f.viscousVoltsPerMmPerS, prefix + "viscous");
    requireNonNegative(f.backlashMm, prefix + "backlash");
    requireNonNegative(f.amplifierDeadbandVolts, prefix + "amplifier_deadband");
    if (f.staticVolts != 0.0 && f.staticVolts < f.coulombVolts)
        throw InvalidInput(prefix + "static", makeDiagnostic("model_static_below_coulomb"));
    if (f.staticVolts > f.coulombVolts && !(f.stribeckVelocityMmPerS > 0.0))
        throw InvalidInput(prefix + "stribeck_velocity", makeDiagnostic("model_stribeck_velocity"));
}

void validateFrictionCompensation(const FrictionCompensation& c, const std::string& prefix) {
    if (!std::isfinite(c.percent) || c.percent < 0.0 || c.percent > 200.0)
        throw InvalidInput(prefix + "percent", makeDiagnostic("model_compensation_percent"));
    if (!std::isfinite(c.bandMmPerS) || !(c.bandMmPerS > 0.0))
        throw InvalidInput(prefix + "band", makeDiagnostic("model_compensation_band"));
}

} // namespace xyt
