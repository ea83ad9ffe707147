// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

namespace xyt {

/**
 * Patrick, Ishak and Adnan's discrete RST pole placement (the Diophantine equation) with the
 * ZPETC feedforward: the design, the loop with and without the feedforward (the improvement
 * figure), and its digital implementation.
 */
const DesignMethodModule& polePlacementMethod();

} // namespace xyt
