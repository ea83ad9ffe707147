// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"

namespace xyt {

/**
 * The command feedforward that inverts Braga et al.'s plant G(s) = k0 / (s^3 + a1 s^2 + a2 s)
 * exactly: y = r needs u = (r''' + a1 r'' + a2 r') / k0 in model units, so with positions in mm
 * and u model units per mm (0.001 for the paper's metre models)
 *   FF1 = a2 u / k0  (V per mm/s),  FF2 = a1 u / k0  (V per mm/s^2),  FF3 = u / k0  (V per mm/s^3),
 * and FF0 = 0 (the plant has a free integrator, so a held position needs no voltage). For the
 * paper's lower base (k0 = 77.8, a1 = 125.3, a2 = 3665) FF1 = 0.0471 V/(mm/s).
 */
struct ModelFeedforwardGains {
    double ff1 = 0.0;
    double ff2 = 0.0;
    double ff3 = 0.0;
};

/// @throws InvalidInput as ThirdOrderPlant::validate, "model_unit_scale" unless > 0 and finite.
ModelFeedforwardGains modelFeedforwardGains(const ThirdOrderPlant& plant,
                                            double modelUnitsPerPositionUnit);

} // namespace xyt
