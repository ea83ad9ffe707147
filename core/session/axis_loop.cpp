// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_loop.h"

#include "core/session/design_method_module.h"

namespace xyt {

std::optional<LoopTransferFunctions> axisLoop(const AxisEvaluation& axis) {
    return designMethodModule(axis.method).loop(axis);
}

std::vector<PoleZeroSet> axisPoleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& settings) {
    return designMethodModule(axis.method).poleZeroSets(axis, settings);
}

} // namespace xyt
