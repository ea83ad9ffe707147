// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/model_feedforward.h"

#include "core/model/errors.h"

#include <cmath>

namespace xyt {

ModelFeedforwardGains modelFeedforwardGains(const ThirdOrderPlant& plant,
                                            double modelUnitsPerPositionUnit) {
    plant.validate();
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    requireFinite(modelUnitsPerPositionUnit, "model_unit_scale");
    const double scale = modelUnitsPerPositionUnit / plant.k0;
    return {plant.a2 * scale, plant.a1 * scale, scale};
}

} // namespace xyt
