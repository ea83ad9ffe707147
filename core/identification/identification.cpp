// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/identification.h"

#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>

namespace xyt {

std::string modelStructureName(ModelStructure structure) {
    switch (structure) {
    case ModelStructure::Arx:
        return "arx";
    case ModelStructure::Oe:
        return "oe";
    case ModelStructure::Bj:
        return "bj";
    case ModelStructure::ContinuousThirdOrder:
        return "gt3";
    }
    return "arx";
}

ModelStructure parseModelStructure(const std::string& name) {
    for (ModelStructure s : {ModelStructure::Arx, ModelStructure::Oe, ModelStructure::Bj,
                             ModelStructure::ContinuousThirdOrder})
        if (modelStructureName(s) == name)
            return s;
    throw InvalidInput("structure", makeDiagnostic("ident_structure_unknown", {name}));
}

std::string IdentificationSpec::describe() const {
    switch (structure) {
    case ModelStructure::Arx:
        return arx.toString();
    case ModelStructure::Oe:
        return oe.toString();
    case ModelStructure::Bj:
        return bj.toString();
    case ModelStructure::ContinuousThirdOrder:
        return "GT3 k0/(s^3+a1 s^2+a2 s)";
    }
    return {};
}

bool IdentifiedModel::hasEstimate() const {
    return status == EstimationStatus::Converged || status == EstimationStatus::IterationLimit ||
           (status == EstimationStatus::Cancelled && !parameters.empty());
}

namespace {

/// The fields every polynomial estimator's result shares (ArxResult, PemResult).
template <class Result> void takeEstimate(IdentifiedModel& out, const Result& r) {
    out.status = r.status;
    out.message = r.message;
    out.model = r.model;
    out.parameterNames = r.parameterNames;
    out.parameters = r.parameters;
    out.standardDeviations = r.standardDeviations;
    out.covariance = r.covariance;
    out.warnings = r.warnings;
    out.residuals = r.residuals;
}

/// The continuous fit as an output-error polynomial model (prediction = simulation).
PolynomialModel outputErrorForm(const ThirdOrderPlant& plant, double ts) {
    const PolynomialModel discrete = discretizedThirdOrderPlant(plant, ts);
    PolynomialModel m;
    m.b = discrete.b;
    m.f = discrete.a;
    m.tsSeconds = ts;
    return m;
}

} // namespace

IdentifiedModel identifyModel(const IoData& estimation, const IoData* validation,
                              const IdentificationSpec& spec) {
    if (spec.predictionHorizon < 1)
        throw InvalidInput("prediction_horizon", makeDiagnostic("at_least", {"1"}));
    if (spec.maxLag < 1)
        throw InvalidInput("max_lag", makeDiagnostic("at_least", {"1"}));
    if (validation &&
        !(std::abs(validation->tsSeconds - estimation.tsSeconds) <= 0.01 * estimation.tsSeconds))
        throw InvalidInput("validation", makeDiagnostic("ident_validation_sample_time",
                                                        {std::to_string(validation->tsSeconds),
                                                         std::to_string(estimation.tsSeconds)}));
    IdentifiedModel out;
    out.spec = spec;
    out.structure = spec.describe();
    std::size_t samples = estimation.size();
    double loss = 0.0;
    // The continuous fit estimates where the table stood (y0): the fits compare the model from
    // that position, on validation data from the position that fits them best.
    IoData estimationFrom = estimation;
    std::optional<IoData> validationFrom;
    if (validation)
        validationFrom = *validation;
    switch (spec.structure) {
    case ModelStructure::Arx: {
        const ArxResult r = estimateArx(estimation, spec.arx);
        takeEstimate(out, r);
        out.firstSample = r.firstRow;
        loss = r.loss;
        samples = r.rows;
        break;
    }
    case ModelStructure::Oe:
    case ModelStructure::Bj: {
        PemOptions o;
        o.search = spec.search;
        const PemResult r = spec.structure == ModelStructure::Oe
                                ? estimateOe(estimation, spec.oe, o)
                                : estimateBj(estimation, spec.bj, o);
        takeEstimate(out, r);
        loss = r.loss;
        samples = r.samples;
        break;
    }
    case ModelStructure::ContinuousThirdOrder: {
        ContinuousFitOptions o;
        o.search = spec.search;
        o.estimateInitialPosition = true; // a real record starts wherever the table stood
        const ContinuousFitResult r = fitThirdOrderPlant(estimation, o);
        out.status = r.status;
        out.message = r.message;
        out.plant = r.plant;
        out.model = outputErrorForm(r.plant, estimation.tsSeconds);
        out.parameterNames = {"k0", "a1", "a2"};
        out.parameters = {r.plant.k0, r.plant.a1, r.plant.a2};
        out.standardDeviations.assign(r.standardDeviations.begin(), r.standardDeviations.end());
        out.covariance = r.covariance;
        out.warnings = r.warnings;
        out.residuals = r.residuals;
        out.initialPositionMm = r.initialPositionMm;
        loss = r.loss;
        samples = r.samples;
        for (double& y : estimationFrom.y)
            y -= r.initialPositionMm;
        if (validationFrom && r.status != EstimationStatus::Failed) {
            const std::vector<double> fromRest =
                simulateThirdOrderPlant(r.plant, validationFrom->u, validationFrom->tsSeconds);
            double sum = 0.0;
            for (std::size_t k = 0; k < fromRest.size(); ++k)
                sum += validationFrom->y[k] - fromRest[k];
            const double y0 = sum / static_cast<double>(fromRest.size());
            for (double& y : validationFrom->y)
                y -= y0;
        }
        break;
    }
    }
    if (!out.hasEstimate())
        return out;
    if (loss > 0.0 && std::isfinite(loss) && samples > out.parameters.size())
        out.criteria = informationCriteria(loss, samples, out.parameters.size());
    else
        out.warnings.push_back(makeDiagnostic("ident_loss_zero"));
    out.fit = fitReport(out.model, estimationFrom, validationFrom ? &*validationFrom : nullptr,
                        spec.predictionHorizon);
    if (out.residuals.size() > out.firstSample + static_cast<std::size_t>(spec.maxLag) &&
        loss > 0.0)
        out.residualTests =
            residualAnalysis(out.residuals, estimation.u, spec.maxLag, 2.576, out.firstSample);
    out.roots =
        out.plant ? thirdOrderPlantRoots(*out.plant, estimation.tsSeconds) : modelRoots(out.model);
    out.warnings.insert(out.warnings.end(), out.roots.notes.begin(), out.roots.notes.end());
    return out;
}

} // namespace xyt
