// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/plant_uncertainty.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/normal_draws.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <random>

namespace xyt {

void setRelativeRange(std::vector<UncertainParameter>& parameters, const std::string& name,
                      double relative) {
    for (UncertainParameter& p : parameters)
        if (p.name == name) {
            if (!std::isfinite(relative) || relative < 0.0 || relative >= 1.0)
                throw InvalidInput("range." + name, makeDiagnostic("study_range_percent"));
            p.relative = relative;
            return;
        }
    std::string known;
    for (const UncertainParameter& p : parameters)
        known += (known.empty() ? "" : ", ") + p.name;
    throw InvalidInput("range", makeDiagnostic("study_no_such_parameter", {name, known}));
}

std::vector<UncertainParameter> scaledRanges(std::vector<UncertainParameter> parameters,
                                             double scale) {
    if (!std::isfinite(scale) || scale < 0.0)
        throw InvalidInput("scale", makeDiagnostic("finite_not_negative"));
    for (UncertainParameter& p : parameters)
        setRelativeRange(parameters, p.name, p.relative * scale);
    return parameters;
}

std::vector<std::vector<double>> drawPlants(const std::vector<UncertainParameter>& parameters,
                                            int count, std::uint64_t seed) {
    if (count < 0 || count > 1'000'000)
        throw InvalidInput("samples", makeDiagnostic("study_from_to", {"0", "1000000"}));
    std::mt19937_64 rng(seed);
    std::vector<std::vector<double>> plants(static_cast<std::size_t>(count));
    for (auto& plant : plants) {
        plant.reserve(parameters.size());
        for (const UncertainParameter& p : parameters) {
            const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53; // [0, 1), 53 bits
            plant.push_back(p.nominal * (1.0 + p.relative * (2.0 * u - 1.0)));
        }
    }
    return plants;
}

std::vector<std::vector<double>> drawPlantsNormal(const std::vector<UncertainParameter>& parameters,
                                                  const Eigen::MatrixXd& covariance, int count,
                                                  std::uint64_t seed) {
    if (count < 0 || count > 1'000'000)
        throw InvalidInput("samples", makeDiagnostic("study_from_to", {"0", "1000000"}));
    const Eigen::Index d = static_cast<Eigen::Index>(parameters.size());
    if (covariance.rows() != d || covariance.cols() != d)
        throw InvalidInput("covariance", makeDiagnostic("study_covariance_size",
                                                        {std::to_string(d), std::to_string(d)}));
    if (!covariance.allFinite())
        throw InvalidInput("covariance", makeDiagnostic("study_covariance_not_finite"));
    const double scale = covariance.cwiseAbs().maxCoeff();
    if (!((covariance - covariance.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale))
        throw InvalidInput("covariance", makeDiagnostic("study_covariance_not_symmetric"));
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(covariance);
    if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() < -1e-12 * scale).any())
        throw InvalidInput("covariance", makeDiagnostic("study_covariance_not_psd"));
    const Eigen::MatrixXd lower = ldlt.matrixL();
    const Eigen::MatrixXd m = ldlt.transpositionsP().transpose() *
                              (lower * ldlt.vectorD().cwiseMax(0.0).cwiseSqrt().asDiagonal());
    std::mt19937_64 rng(seed);
    Eigen::VectorXd z(d);
    std::vector<std::vector<double>> plants(static_cast<std::size_t>(count));
    for (auto& plant : plants) {
        for (Eigen::Index i = 0; i < d; ++i)
            z(i) = standardNormal(rng);
        const Eigen::VectorXd delta = m * z;
        for (Eigen::Index i = 0; i < d; ++i)
            plant.push_back(parameters[static_cast<std::size_t>(i)].nominal + delta(i));
    }
    return plants;
}

std::vector<std::vector<double>> boxCorners(const std::vector<UncertainParameter>& parameters) {
    std::vector<std::size_t> uncertain;
    for (std::size_t i = 0; i < parameters.size(); ++i)
        if (parameters[i].relative > 0.0)
            uncertain.push_back(i);
    if (uncertain.size() > 16)
        throw InvalidInput("corners", makeDiagnostic("study_too_many_corners",
                                                     {std::to_string(uncertain.size())}));
    const std::size_t count = std::size_t{1} << uncertain.size();
    std::vector<std::vector<double>> corners(count);
    for (std::size_t c = 0; c < count; ++c) {
        for (const UncertainParameter& p : parameters)
            corners[c].push_back(p.nominal);
        for (std::size_t j = 0; j < uncertain.size(); ++j) {
            const UncertainParameter& p = parameters[uncertain[j]];
            corners[c][uncertain[j]] =
                p.nominal * (1.0 + ((c >> j) & 1U ? p.relative : -p.relative));
        }
    }
    return corners;
}

} // namespace xyt
