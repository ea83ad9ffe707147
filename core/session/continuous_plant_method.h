// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

namespace xyt {

/**
 * What a method that puts a continuous controller ahead of the axis' continuous third-order plant
 * k0/(s^3 + a1 s^2 + a2 s) (AxisSettings::gt: the plant and its model unit) shares, given its
 * controller: the contour run (the loop with the actuator limit along the path), the plant's
 * uncertain parameters k0, a1, a2, a drawn plant loaded into the settings, and the robustness
 * problem (that controller on the drawn plants). Braga et al.'s PI is one such method.
 */
class ContinuousPlantMethod : public DesignMethodModule {
public:
    /// The controller of an evaluated design (volts per model unit of error).
    virtual TransferFunction evaluatedController(const AxisEvaluation& axis) const = 0;
    /// The controller that axis @p axisIndex's settings in @p session design, without a run.
    /// Throws InvalidInput naming the session field of a setting that allows no design.
    virtual TransferFunction designedController(const Session& session, int axisIndex) const = 0;

    AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& t,
                        const std::vector<double>& reference, double dtSeconds) const override;
    std::unique_ptr<SteppedLoop> steppedPath(const Session& session, int axisIndex,
                                             const std::vector<double>& t,
                                             const std::vector<double>& reference,
                                             double dtSeconds) const override;
    SampledAxisModel couplingModel(const Session& session, int axisIndex,
                                   double periodSeconds) const override;
    std::vector<UncertainParameter> plantParameters(const AxisSettings& settings) const override;
    RobustnessProblem robustnessProblem(const Session& session, int axisIndex,
                                        const AxisEvaluation& nominal) const override;
    AxisSettings withPlantParameters(
        AxisSettings settings,
        const std::function<double(const std::string&, double)>& value) const override;
};

} // namespace xyt
