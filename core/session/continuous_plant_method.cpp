// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/continuous_plant_method.h"

#include "core/session/axis_run.h"
#include "core/session/robustness_problem.h"

namespace xyt {

AxisTrace ContinuousPlantMethod::tracePath(const Session& session, int axisIndex,
                                           const std::vector<double>& /*t*/,
                                           const std::vector<double>& reference,
                                           double dtSeconds) const {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    AxisTrace out;
    out.run = traceContinuousAxis(axis, axisIndex, designedController(session, axisIndex),
                                  reference, dtSeconds, session.umaxVolts);
    out.outputOnPath = out.run.y;
    return out;
}

std::vector<UncertainParameter>
ContinuousPlantMethod::plantParameters(const AxisSettings& settings) const {
    return thirdOrderPlantParameters(settings.gt.plant);
}

RobustnessProblem ContinuousPlantMethod::robustnessProblem(const Session& session, int axisIndex,
                                                           const AxisEvaluation& nominal) const {
    return continuousRobustnessProblem(
        session, axisIndex, nominal, evaluatedController(nominal),
        session.axes.at(static_cast<std::size_t>(axisIndex)).gt.modelUnitsPerPositionUnit);
}

AxisSettings ContinuousPlantMethod::withPlantParameters(
    AxisSettings settings, const std::function<double(const std::string&, double)>& value) const {
    settings.gt.plant = withThirdOrderPlantParameters(settings.gt.plant, value);
    return settings;
}

} // namespace xyt
