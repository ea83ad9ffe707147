// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/continuous_plant_method.h"

#include "core/session/axis_run.h"
#include "core/session/robustness_problem.h"

#include <algorithm>
#include <utility>

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

std::unique_ptr<SteppedLoop>
ContinuousPlantMethod::steppedPath(const Session& session, int axisIndex,
                                   const std::vector<double>& /*t*/,
                                   const std::vector<double>& reference, double dtSeconds) const {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    return steppedContinuousAxis(axis, axisIndex, designedController(session, axisIndex), reference,
                                 dtSeconds, session.umaxVolts);
}

SampledAxisModel ContinuousPlantMethod::couplingModel(const Session& session, int axisIndex,
                                                      double periodSeconds) const {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    return continuousAxisModel(axisPlantTransferFunction(axis.gt, axisIndex),
                               designedController(session, axisIndex),
                               axis.gt.modelUnitsPerPositionUnit, periodSeconds);
}

std::vector<UncertainParameter>
ContinuousPlantMethod::plantParameters(const AxisSettings& settings) const {
    std::vector<UncertainParameter> out = thirdOrderPlantParameters(settings.gt.plant);
    // The table's friction levels that are set (a zero level has no relative range).
    const TableFriction& f = settings.friction;
    for (const auto& [name, value] : {std::pair<const char*, double>{"coulomb", f.coulombVolts},
                                      {"static", f.staticVolts},
                                      {"viscous", f.viscousVoltsPerMmPerS},
                                      {"backlash", f.backlashMm}})
        if (value > 0.0)
            out.push_back({name, value, 0.0});
    // The flexible mode's frequency and damping, the least certain numbers of a table's model.
    const FlexibleMode& m = settings.gt.flexibleMode;
    if (m.present()) {
        out.push_back({"mode_frequency", m.frequencyHz, 0.0});
        if (m.dampingRatio > 0.0)
            out.push_back({"mode_damping", m.dampingRatio, 0.0});
    }
    return out;
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
    TableFriction& f = settings.friction;
    if (f.coulombVolts > 0.0)
        f.coulombVolts = value("coulomb", f.coulombVolts);
    if (f.staticVolts > 0.0)
        f.staticVolts = std::max(value("static", f.staticVolts), f.coulombVolts);
    if (f.viscousVoltsPerMmPerS > 0.0)
        f.viscousVoltsPerMmPerS = value("viscous", f.viscousVoltsPerMmPerS);
    if (f.backlashMm > 0.0)
        f.backlashMm = value("backlash", f.backlashMm);
    FlexibleMode& m = settings.gt.flexibleMode;
    if (m.present()) {
        m.frequencyHz = value("mode_frequency", m.frequencyHz);
        if (m.dampingRatio > 0.0)
            m.dampingRatio = std::clamp(value("mode_damping", m.dampingRatio), 0.0, 0.999);
        if (m.twoMass())
            m.antiResonanceHz = std::min(m.antiResonanceHz, 0.999 * m.frequencyHz);
    }
    return settings;
}

} // namespace xyt
