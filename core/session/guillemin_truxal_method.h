// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

namespace xyt {

/**
 * Braga et al.'s continuous PI by the Guillemin-Truxal reference-model method: the design
 * (sessionGtDesign), the loop simulated with the actuator limit, and its digital implementation
 * as the sampled-data PI at the controller period.
 */
const DesignMethodModule& guilleminTruxalMethod();

} // namespace xyt
