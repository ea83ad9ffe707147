// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/polynomial_model.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/translatable_text.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

void requireFiniteCoefficients(const std::vector<double>& p, const std::string& field) {
    if (p.empty())
        throw InvalidInput(field, makeDiagnostic("is_empty"));
    for (double v : p)
        if (!std::isfinite(v))
            throw InvalidInput(field, makeDiagnostic("ident_coefficient_not_finite"));
}

void requireMonic(const std::vector<double>& p, const std::string& field) {
    requireFiniteCoefficients(p, field);
    if (p[0] != 1.0)
        throw InvalidInput(field, makeDiagnostic("ident_not_monic"));
}

} // namespace

std::vector<double> PolynomialModel::inputDenominator() const {
    return polynomialProduct(a, f);
}

std::vector<double> PolynomialModel::noiseDenominator() const {
    return polynomialProduct(a, d);
}

void PolynomialModel::validate() const {
    requireMonic(a, "model.a");
    requireFiniteCoefficients(b, "model.b");
    requireMonic(c, "model.c");
    requireMonic(d, "model.d");
    requireMonic(f, "model.f");
    requirePositive(tsSeconds, "model.ts");
}

std::string estimationStatusName(EstimationStatus status) {
    switch (status) {
    case EstimationStatus::Converged:
        return XYT_TRANSLATE_NOOP("xyt::EstimationStatus", "converged");
    case EstimationStatus::IterationLimit:
        return XYT_TRANSLATE_NOOP("xyt::EstimationStatus", "iteration-limit");
    case EstimationStatus::Cancelled:
        return XYT_TRANSLATE_NOOP("xyt::EstimationStatus", "cancelled");
    case EstimationStatus::NotPersistentlyExciting:
        return XYT_TRANSLATE_NOOP("xyt::EstimationStatus", "not-persistently-exciting");
    case EstimationStatus::Failed:
        return XYT_TRANSLATE_NOOP("xyt::EstimationStatus", "failed");
    }
    return "failed";
}

std::vector<double> polynomialProduct(const std::vector<double>& p, const std::vector<double>& q) {
    if (p.empty() || q.empty())
        return {};
    std::vector<double> r(p.size() + q.size() - 1, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < q.size(); ++j)
            r[i + j] += p[i] * q[j];
    return r;
}

void filterMonic(const std::vector<double>& num, const std::vector<double>& den, const double* x,
                 double* y, std::size_t n) {
    const std::size_t nn = num.size();
    const std::size_t nd = den.size();
    for (std::size_t k = 0; k < n; ++k) {
        double acc = 0.0;
        const std::size_t inum = std::min(nn, k + 1);
        for (std::size_t i = 0; i < inum; ++i)
            acc += num[i] * x[k - i];
        const std::size_t iden = std::min(nd, k + 1);
        for (std::size_t i = 1; i < iden; ++i)
            acc -= den[i] * y[k - i];
        y[k] = acc;
    }
}

} // namespace xyt
