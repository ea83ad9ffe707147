// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/validation.h"

#include "core/identification/continuous_fit.h"
#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"
#include "core/model/polynomial.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

std::vector<double> filtered(const std::vector<double>& num, const std::vector<double>& den,
                             const std::vector<double>& x) {
    std::vector<double> y(x.size());
    filterMonic(num, den, x.data(), y.data(), x.size());
    return y;
}

/// Roots in z of a polynomial in z^-1 given ascending, after dropping its leading zeros (a
/// delay) and trailing zeros (roots at z = 0 are kept as such by Polynomial).
std::vector<std::complex<double>> zRoots(const std::vector<double>& p) {
    std::size_t first = 0;
    while (first < p.size() && p[first] == 0.0)
        ++first;
    if (first + 1 >= p.size())
        return {};
    const std::vector<double> zAscending(p.rbegin(), p.rend() - static_cast<std::ptrdiff_t>(first));
    std::vector<std::complex<double>> r = Polynomial::fromAscending(zAscending).roots();
    sortRoots(r);
    return r;
}

std::string formatRoot(std::complex<double> r) {
    if (r.imag() == 0.0)
        return formatNumber(r.real());
    return formatNumber(r.real()) + (r.imag() < 0 ? " - " : " + ") +
           formatNumber(std::abs(r.imag())) + "i";
}

void flagRoots(ModelRoots& out) {
    constexpr double kAtOne = 1e-6; // see ModelRoots::integrating
    bool onlyAtOne = true;
    for (const auto& p : out.poles)
        if (std::abs(p) >= 1.0) {
            out.stable = false;
            onlyAtOne = onlyAtOne && std::abs(p - 1.0) <= kAtOne;
        }
    out.integrating = !out.stable && onlyAtOne;
    for (const auto& z : out.zeros)
        if (std::abs(z) >= 1.0) {
            out.nonMinimumPhase = true;
            out.notes.push_back(
                makeDiagnostic("ident_nmp_zero", {formatRoot(z), formatNumber(std::abs(z))}));
        }
}

CorrelationTest correlationTest(std::vector<int> lags, std::vector<double> values, double bound) {
    CorrelationTest t;
    t.bound = bound;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::abs(values[i]) > bound) {
            t.passed = false;
            ++t.outsideCount;
        }
        if (i == 0 || std::abs(values[i]) > std::abs(t.worstValue)) {
            t.worstValue = values[i];
            t.worstLag = lags[i];
        }
    }
    t.lags = std::move(lags);
    t.values = std::move(values);
    return t;
}

} // namespace

double fitPercent(const std::vector<double>& y, const std::vector<double>& yhat,
                  std::size_t firstSample) {
    if (yhat.size() != y.size())
        throw InvalidInput("yhat",
                           makeDiagnostic("ident_yhat_y_lengths",
                                          {std::to_string(yhat.size()), std::to_string(y.size())}));
    if (firstSample >= y.size())
        throw InvalidInput("first_sample", makeDiagnostic("ident_beyond_last_sample"));
    double mean = 0.0;
    for (std::size_t k = firstSample; k < y.size(); ++k)
        mean += y[k];
    mean /= static_cast<double>(y.size() - firstSample);
    double err = 0.0, spread = 0.0;
    for (std::size_t k = firstSample; k < y.size(); ++k) {
        err += (y[k] - yhat[k]) * (y[k] - yhat[k]);
        spread += (y[k] - mean) * (y[k] - mean);
    }
    if (spread == 0.0)
        return kNaN;
    return 100.0 * (1.0 - std::sqrt(err) / std::sqrt(spread));
}

std::vector<double> simulateModel(const PolynomialModel& model, const std::vector<double>& u) {
    model.validate();
    return filtered(model.b, model.inputDenominator(), u);
}

std::vector<double> predictModel(const PolynomialModel& model, const IoData& data, int horizon) {
    model.validate();
    validateIoData(data);
    if (horizon < 1)
        throw InvalidInput("horizon", makeDiagnostic("at_least", {"1"}));
    const std::size_t n = data.size();
    if (static_cast<std::size_t>(horizon) >= n)
        return simulateModel(model, data.u);
    const std::size_t k = static_cast<std::size_t>(horizon);
    // H_k: the first k impulse-response terms of H = C / (A D).
    std::vector<double> impulse(k, 0.0);
    impulse[0] = 1.0;
    const std::vector<double> hk = filtered(model.c, model.noiseDenominator(), impulse);
    const std::vector<double> uNum = polynomialProduct(polynomialProduct(hk, model.d), model.b);
    const std::vector<double> uDen = polynomialProduct(model.c, model.f);
    std::vector<double> yNum = polynomialProduct(polynomialProduct(hk, model.a), model.d);
    // C - H_k A D: its first k coefficients vanish by construction of H_k; set them exactly.
    yNum.resize(std::max(yNum.size(), model.c.size()), 0.0);
    for (std::size_t i = 0; i < yNum.size(); ++i)
        yNum[i] = (i < model.c.size() ? model.c[i] : 0.0) - yNum[i];
    for (std::size_t i = 0; i < std::min(k, yNum.size()); ++i)
        yNum[i] = 0.0;
    std::vector<double> yhat = filtered(uNum, uDen, data.u);
    const std::vector<double> fromY = filtered(yNum, model.c, data.y);
    for (std::size_t t = 0; t < n; ++t)
        yhat[t] += fromY[t];
    return yhat;
}

std::vector<double> predictionErrors(const PolynomialModel& model, const IoData& data) {
    const std::vector<double> yhat = predictModel(model, data, 1);
    std::vector<double> e(data.size());
    for (std::size_t t = 0; t < e.size(); ++t)
        e[t] = data.y[t] - yhat[t];
    return e;
}

ModelFit simulationFit(const PolynomialModel& model, const IoData& data, std::size_t firstSample) {
    validateIoData(data);
    ModelFit f;
    f.yhat = simulateModel(model, data.u);
    f.fitPercent = fitPercent(data.y, f.yhat, firstSample);
    return f;
}

ModelFit predictionFit(const PolynomialModel& model, const IoData& data, int horizon,
                       std::size_t firstSample) {
    ModelFit f;
    f.horizon = horizon;
    f.yhat = predictModel(model, data, horizon);
    f.fitPercent = fitPercent(data.y, f.yhat, firstSample);
    return f;
}

FitReport fitReport(const PolynomialModel& model, const IoData& estimation,
                    const IoData* validation, int horizon) {
    FitReport r;
    r.estimationSimulation = simulationFit(model, estimation);
    r.estimationPrediction = predictionFit(model, estimation, horizon);
    if (validation) {
        r.validationSimulation = simulationFit(model, *validation);
        r.validationPrediction = predictionFit(model, *validation, horizon);
    }
    return r;
}

InformationCriteria informationCriteria(double loss, std::size_t samples, std::size_t parameters) {
    if (!(loss > 0.0) || !std::isfinite(loss))
        throw InvalidInput("loss", makeDiagnostic("ident_finite_gt_zero"));
    if (samples <= parameters)
        throw InvalidInput("samples",
                           makeDiagnostic("ident_exceed_parameters", {std::to_string(parameters)}));
    InformationCriteria c;
    c.loss = loss;
    c.samples = samples;
    c.parameters = parameters;
    const double n = static_cast<double>(samples);
    const double d = static_cast<double>(parameters);
    c.fpe = loss * (1.0 + d / n) / (1.0 - d / n);
    c.aic = n * std::log(loss) + 2.0 * d;
    return c;
}

ArxOrderTable arxOrderTable(const IoData& estimation, const IoData* validation, OrderRange na,
                            OrderRange nb, OrderRange nk,
                            const std::function<bool(double fraction)>& progress) {
    validateIoData(estimation);
    if (validation)
        validateIoData(*validation);
    for (const auto& [range, field] :
         {std::pair{na, "na"}, std::pair{nb, "nb"}, std::pair{nk, "nk"}})
        if (range.min > range.max)
            throw InvalidInput(field, makeDiagnostic("ident_range_min_max"));
    ArxOrders{na.min, nb.min, nk.min}.validate();
    ArxOrders{na.max, nb.max, nk.max}.validate();
    ArxOrderTable table;
    table.commonFirstRow = static_cast<std::size_t>(std::max(na.max, nk.max + nb.max - 1));
    const std::size_t total = static_cast<std::size_t>(nk.max - nk.min + 1) *
                              static_cast<std::size_t>(na.max - na.min + 1) *
                              static_cast<std::size_t>(nb.max - nb.min + 1);
    const std::size_t n = estimation.size();
    for (int k = nk.min; k <= nk.max; ++k)
        for (int a = na.min; a <= na.max; ++a)
            for (int b = nb.min; b <= nb.max; ++b) {
                if (progress && !progress(static_cast<double>(table.rows.size()) /
                                          static_cast<double>(total))) {
                    table.cancelled = true;
                    return table;
                }
                ArxOrderRow row;
                row.orders = ArxOrders{a, b, k};
                const ArxResult r = estimateArx(estimation, row.orders);
                row.status = r.status;
                row.message = r.message;
                row.loss = row.fpe = row.aic = row.validationLoss = kNaN;
                if (r.status == EstimationStatus::Converged) {
                    double sse = 0.0;
                    for (std::size_t t = table.commonFirstRow; t < n; ++t)
                        sse += r.residuals[t] * r.residuals[t];
                    const std::size_t rows = n - table.commonFirstRow;
                    row.loss = sse / static_cast<double>(rows);
                    const std::size_t d = static_cast<std::size_t>(a + b);
                    if (row.loss > 0.0 && rows > d) {
                        const InformationCriteria c = informationCriteria(row.loss, rows, d);
                        row.fpe = c.fpe;
                        row.aic = c.aic;
                    }
                    if (validation && validation->size() > table.commonFirstRow) {
                        const std::vector<double> e = predictionErrors(r.model, *validation);
                        double v = 0.0;
                        for (std::size_t t = table.commonFirstRow; t < e.size(); ++t)
                            v += e[t] * e[t];
                        row.validationLoss =
                            v / static_cast<double>(e.size() - table.commonFirstRow);
                    }
                }
                table.rows.push_back(row);
                const std::size_t i = table.rows.size() - 1;
                if (std::isfinite(row.aic) &&
                    (!table.bestAic || row.aic < table.rows[*table.bestAic].aic))
                    table.bestAic = i;
                if (std::isfinite(row.validationLoss) &&
                    (!table.bestValidation ||
                     row.validationLoss < table.rows[*table.bestValidation].validationLoss))
                    table.bestValidation = i;
            }
    if (progress)
        progress(1.0);
    return table;
}

ResidualAnalysis residualAnalysis(const std::vector<double>& residuals,
                                  const std::vector<double>& input, int maxLag, double confidenceZ,
                                  std::size_t firstSample) {
    if (maxLag < 1)
        throw InvalidInput("max_lag", makeDiagnostic("at_least", {"1"}));
    if (!(confidenceZ > 0.0) || !std::isfinite(confidenceZ))
        throw InvalidInput("confidence_z", makeDiagnostic("ident_finite_gt_zero"));
    if (input.size() != residuals.size())
        throw InvalidInput("input", makeDiagnostic("ident_input_residuals_lengths",
                                                   {std::to_string(input.size()),
                                                    std::to_string(residuals.size())}));
    if (residuals.size() <= firstSample + static_cast<std::size_t>(maxLag))
        throw InvalidInput("residuals", makeDiagnostic("ident_residuals_need_more"));
    const std::size_t n = residuals.size() - firstSample;
    std::vector<double> e(residuals.begin() + static_cast<std::ptrdiff_t>(firstSample),
                          residuals.end());
    std::vector<double> u(input.begin() + static_cast<std::ptrdiff_t>(firstSample), input.end());
    for (const auto* v : {&e, &u}) {
        for (double x : *v)
            if (!std::isfinite(x))
                throw InvalidInput(v == &e ? "residuals" : "input",
                                   makeDiagnostic("ident_has_value_not_finite"));
    }
    const auto demean = [](std::vector<double>& v) {
        double m = 0.0;
        for (double x : v)
            m += x;
        m /= static_cast<double>(v.size());
        for (double& x : v)
            x -= m;
    };
    demean(e);
    demean(u);
    // r_xy(tau) = (1/N) sum_t x(t) y(t - tau), the biased estimate (Ljung Eq. 16.62).
    const auto corr = [n](const std::vector<double>& x, const std::vector<double>& y, int tau) {
        double s = 0.0;
        for (std::size_t t = 0; t < n; ++t) {
            const long long j = static_cast<long long>(t) - tau;
            if (j >= 0 && j < static_cast<long long>(n))
                s += x[t] * y[static_cast<std::size_t>(j)];
        }
        return s / static_cast<double>(n);
    };
    ResidualAnalysis out;
    out.samples = n;
    const double bound = confidenceZ / std::sqrt(static_cast<double>(n));
    const double re0 = corr(e, e, 0);
    const double ru0 = corr(u, u, 0);
    std::vector<int> lags;
    std::vector<double> values;
    for (int tau = 1; tau <= maxLag; ++tau) {
        lags.push_back(tau);
        values.push_back(re0 > 0.0 ? corr(e, e, tau) / re0 : 0.0);
    }
    out.autocorrelation = correlationTest(lags, values, bound);
    lags.clear();
    values.clear();
    const double norm = std::sqrt(re0 * ru0);
    for (int tau = -maxLag; tau <= maxLag; ++tau) {
        lags.push_back(tau);
        values.push_back(norm > 0.0 ? corr(e, u, tau) / norm : 0.0);
    }
    out.crossCorrelation = correlationTest(lags, values, bound);
    return out;
}

ModelRoots modelRoots(const PolynomialModel& model) {
    model.validate();
    if (std::all_of(model.b.begin(), model.b.end(), [](double c) { return c == 0.0; }))
        throw InvalidInput("model.b", makeDiagnostic("ident_b_all_zeros"));
    ModelRoots out;
    out.tsSeconds = model.tsSeconds;
    out.poles = zRoots(model.inputDenominator());
    out.zeros = zRoots(model.b);
    out.noisePoles = zRoots(model.noiseDenominator());
    out.noiseZeros = zRoots(model.c);
    flagRoots(out);
    return out;
}

ModelRoots thirdOrderPlantRoots(const ThirdOrderPlant& plant, double tsSeconds) {
    plant.validate();
    requirePositive(tsSeconds, "ts");
    ModelRoots out = modelRoots(discretizedThirdOrderPlant(plant, tsSeconds));
    out.continuousPoles = plant.transferFunction().poles();
    sortRoots(out.continuousPoles);
    if (out.nonMinimumPhase)
        out.notes.push_back(makeDiagnostic("ident_sampling_zero"));
    return out;
}

} // namespace xyt
