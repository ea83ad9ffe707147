// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/arx.h"

#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <Eigen/QR>

#include <algorithm>
#include <utility>

namespace xyt {

std::string ArxOrders::toString() const {
    return "ARX(" + std::to_string(na) + "," + std::to_string(nb) + "," + std::to_string(nk) + ")";
}

void ArxOrders::validate() const {
    if (na < 0 || na > 100)
        throw InvalidInput("na", makeDiagnostic("ident_between_n_100", {"0"}));
    if (nb < 1 || nb > 100)
        throw InvalidInput("nb", makeDiagnostic("ident_between_n_100", {"1"}));
    if (nk < 0 || nk > 100)
        throw InvalidInput("nk", makeDiagnostic("ident_between_n_100", {"0"}));
}

ArxResult estimateArx(const IoData& data, const ArxOrders& orders, double rankThreshold) {
    validateIoData(data);
    orders.validate();
    const std::size_t n = data.size();
    const std::size_t na = static_cast<std::size_t>(orders.na);
    const std::size_t nb = static_cast<std::size_t>(orders.nb);
    const std::size_t nk = static_cast<std::size_t>(orders.nk);
    const std::size_t n0 = std::max(na, nk + nb - 1);
    const std::size_t d = na + nb;
    // One more row than parameters, so that the noise variance has a degree of freedom.
    if (n < n0 + d + 1)
        throw InvalidInput("data", makeDiagnostic("ident_too_few_samples_for",
                                                  {std::to_string(n), orders.toString(),
                                                   std::to_string(n0 + d + 1)}));
    ArxResult out;
    out.orders = orders;
    out.rankThreshold = rankThreshold;
    out.firstRow = n0;
    out.rows = n - n0;
    const Eigen::Index rows = static_cast<Eigen::Index>(out.rows);
    Eigen::MatrixXd phi(rows, static_cast<Eigen::Index>(d));
    Eigen::VectorXd target(rows);
    for (std::size_t t = n0; t < n; ++t) {
        const Eigen::Index r = static_cast<Eigen::Index>(t - n0);
        for (std::size_t i = 1; i <= na; ++i)
            phi(r, static_cast<Eigen::Index>(i - 1)) = -data.y[t - i];
        for (std::size_t j = 0; j < nb; ++j)
            phi(r, static_cast<Eigen::Index>(na + j)) = data.u[t - nk - j];
        target(r) = data.y[t];
    }
    for (std::size_t i = 1; i <= na; ++i)
        out.parameterNames.push_back("a" + std::to_string(i));
    for (std::size_t j = 0; j < nb; ++j)
        out.parameterNames.push_back("b" + std::to_string(nk + j));

    const LinearLeastSquares ls = linearLeastSquares(std::move(phi), target, rankThreshold);
    out.rank = ls.rank;
    if (!ls.fullRank()) {
        out.status = EstimationStatus::NotPersistentlyExciting;
        // Which order is to blame: the input block alone, or y and u together.
        Eigen::MatrixXd uBlock(rows, static_cast<Eigen::Index>(nb));
        for (std::size_t t = n0; t < n; ++t)
            for (std::size_t j = 0; j < nb; ++j)
                uBlock(static_cast<Eigen::Index>(t - n0), static_cast<Eigen::Index>(j)) =
                    data.u[t - nk - j];
        const LinearLeastSquares uOnly =
            linearLeastSquares(uBlock, Eigen::VectorXd::Zero(rows), rankThreshold);
        if (!uOnly.fullRank())
            out.message = makeDiagnostic("ident_arx_input_not_exciting",
                                         {std::to_string(nb), std::to_string(uOnly.rank)});
        else
            out.message = makeDiagnostic(
                "ident_arx_regressor_rank",
                {orders.toString(), std::to_string(ls.rank), std::to_string(d), std::to_string(d)});
        return out;
    }
    out.status = EstimationStatus::Converged;
    out.parameters.assign(ls.theta.data(), ls.theta.data() + ls.theta.size());
    // Equation errors e(t) = y(t) + sum a_i y(t-i) - sum b_j u(t-nk-j).
    out.residuals.assign(n, 0.0);
    double sse = 0.0;
    for (std::size_t t = n0; t < n; ++t) {
        double e = data.y[t];
        for (std::size_t i = 1; i <= na; ++i)
            e += out.parameters[i - 1] * data.y[t - i];
        for (std::size_t j = 0; j < nb; ++j)
            e -= out.parameters[na + j] * data.u[t - nk - j];
        out.residuals[t] = e;
        sse += e * e;
    }
    out.loss = sse / static_cast<double>(out.rows);
    out.noiseVariance = sse / static_cast<double>(out.rows - d);
    out.covariance = out.noiseVariance * ls.inverseGram;
    out.standardDeviations.resize(d);
    for (std::size_t j = 0; j < d; ++j)
        out.standardDeviations[j] =
            std::sqrt(out.covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)));

    out.model.tsSeconds = data.tsSeconds;
    out.model.a.assign(1, 1.0);
    out.model.a.insert(out.model.a.end(), out.parameters.begin(),
                       out.parameters.begin() + static_cast<std::ptrdiff_t>(na));
    out.model.b.assign(nk, 0.0);
    out.model.b.insert(out.model.b.end(), out.parameters.begin() + static_cast<std::ptrdiff_t>(na),
                       out.parameters.end());
    if (maxRootMagnitude(out.model.a) > 1.0)
        out.warnings.push_back(makeDiagnostic("ident_arx_unstable"));
    return out;
}

} // namespace xyt
