// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/identified_axis.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

namespace xyt {

AxisSettings axisWithIdentifiedModel(const AxisSettings& axis, const IdentifiedModel& model,
                                     const IoData& data) {
    if (!model.hasEstimate())
        throw InvalidInput(
            "model", model.message.text.empty()
                         ? makeDiagnostic("session_model_no_estimate",
                                          {model.structure, estimationStatusName(model.status)})
                         : makeDiagnostic("session_model_no_estimate_because",
                                          {model.structure, estimationStatusName(model.status),
                                           model.message}));
    AxisSettings out = axis;
    if (model.plant) {
        out.method = DesignMethod::GuilleminTruxal;
        out.gt.plant = *model.plant;
        out.gt.plant.k0 *= axis.gt.modelUnitsPerPositionUnit;
    } else {
        out.method = DesignMethod::PolePlacementZpetc;
        out.pp.a = model.model.inputDenominator();
        out.pp.b = model.model.b;
        out.pp.tsSeconds = model.model.tsSeconds;
    }
    ModelOrigin origin;
    origin.source = data.source;
    origin.structure = model.structure;
    origin.tsSeconds = data.tsSeconds;
    origin.samples = data.size();
    origin.fitPercent = model.fit.estimationSimulation.fitPercent;
    if (model.fit.validationSimulation)
        origin.validationFitPercent = model.fit.validationSimulation->fitPercent;
    origin.parameterNames = model.parameterNames;
    origin.standardDeviations = model.standardDeviations;
    const Eigen::Index d = static_cast<Eigen::Index>(model.parameters.size());
    if (model.covariance.rows() == d && model.covariance.cols() == d &&
        model.covariance.allFinite())
        for (Eigen::Index i = 0; i < d; ++i)
            for (Eigen::Index j = 0; j < d; ++j)
                origin.covariance.push_back(model.covariance(i, j));
    out.origin = origin;
    return out;
}

} // namespace xyt
