// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/design_method_module.h"

#include "core/model/errors.h"
#include "core/session/guillemin_truxal_method.h"
#include "core/session/pole_placement_method.h"

namespace xyt {

const std::vector<const DesignMethodModule*>& designMethodModules() {
    // The registry: one line per method.
    static const std::vector<const DesignMethodModule*> modules = {
        &guilleminTruxalMethod(),
        &polePlacementMethod(),
    };
    return modules;
}

const DesignMethodModule& designMethodModule(DesignMethod method) {
    for (const DesignMethodModule* m : designMethodModules())
        if (m->method() == method)
            return *m;
    throw InvalidInput("method", "no design method is registered for this value");
}

std::optional<LoopTransferFunctions> axisLoop(const AxisEvaluation& axis) {
    return designMethodModule(axis.method).loop(axis);
}

std::vector<PoleZeroSet> axisPoleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& settings) {
    return designMethodModule(axis.method).poleZeroSets(axis, settings);
}

} // namespace xyt
