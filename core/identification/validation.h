// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/identification/arx.h"
#include "core/identification/io_data.h"
#include "core/identification/polynomial_model.h"

#include <complex>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * Fit % = 100 (1 - ||y - yhat||_2 / ||y - mean(y)||_2), MATLAB compare's NRMSE fit: 100 for a
 * perfect model, 0 for the mean, negative for worse. Over samples firstSample .. N-1.
 * NaN when y is constant there.
 * @throws InvalidInput "yhat" for a length different from y's, "first_sample" beyond the end.
 */
double fitPercent(const std::vector<double>& y, const std::vector<double>& yhat,
                  std::size_t firstSample = 0);

/// Simulated output yhat = B / (A F) u from rest. @throws InvalidInput from model.validate().
std::vector<double> simulateModel(const PolynomialModel& model, const std::vector<double>& u);

/**
 * The k-step-ahead prediction yhat(t | t-k) of y = G u + H e, G = B/(A F), H = C/(A D)
 * (Ljung Eq. 3.31): with H_k the first k impulse-response terms of H,
 *   yhat = (H_k D B / (C F)) u + ((C - H_k A D) / C) y,
 * whose y part only sees y(t-k) and older. horizon 1 is the one-step predictor; a horizon of
 * N or more is the simulation. From rest (zero initial conditions).
 * @throws InvalidInput from model.validate(), validateIoData, "horizon" unless >= 1.
 */
std::vector<double> predictModel(const PolynomialModel& model, const IoData& data, int horizon);

/// One-step prediction errors e = D/C (A y - B/F u) (the residuals), from rest, length N.
/// @throws InvalidInput as predictModel.
std::vector<double> predictionErrors(const PolynomialModel& model, const IoData& data);

/// A model's output next to the data: horizon 0 means simulation.
struct ModelFit {
    int horizon = 0;
    std::vector<double> yhat;
    double fitPercent = 0.0;
};
/// Simulation (horizon 0) and k-step-ahead fit of @p model on @p data, over samples
/// firstSample .. N-1 (firstSample skips a transient). @throws InvalidInput as predictModel.
ModelFit simulationFit(const PolynomialModel& model, const IoData& data,
                       std::size_t firstSample = 0);
ModelFit predictionFit(const PolynomialModel& model, const IoData& data, int horizon,
                       std::size_t firstSample = 0);

/// Simulation and prediction fits on the estimation data and, when given, on separate
/// validation data.
struct FitReport {
    ModelFit estimationSimulation;
    ModelFit estimationPrediction;
    std::optional<ModelFit> validationSimulation;
    std::optional<ModelFit> validationPrediction;
};
FitReport fitReport(const PolynomialModel& model, const IoData& estimation,
                    const IoData* validation, int horizon = 1);

/**
 * Akaike's criteria for a loss V = (1/N) sum e^2, N samples, d parameters:
 *   FPE = V (1 + d/N) / (1 - d/N)  (MATLAB's `fpe`, Ljung Eq. 16.34),
 *   AIC = N ln V + 2 d              (Akaike's original form; MATLAB's `aic` "raw" variant adds
 *                                    the constant N (ln 2 pi + 1), and its "nAIC" is AIC / N).
 * Smaller is better for both; compare only models fitted to the same samples.
 * @throws InvalidInput "loss" unless > 0 and finite, "samples" unless N > d.
 */
struct InformationCriteria {
    double loss = 0.0;
    std::size_t samples = 0;
    std::size_t parameters = 0;
    double fpe = 0.0;
    double aic = 0.0;
};
InformationCriteria informationCriteria(double loss, std::size_t samples, std::size_t parameters);

/// A range of orders, both ends included.
struct OrderRange {
    int min = 1;
    int max = 1;
};

/// One row of the ARX order-selection table.
struct ArxOrderRow {
    ArxOrders orders;
    EstimationStatus status = EstimationStatus::Failed;
    Diagnostic message; ///< the ARX estimate's (coded)
    double loss = 0.0;  ///< V on the common estimation rows
    double fpe = 0.0;   ///< informationCriteria(loss, rows, na + nb)
    double aic = 0.0;
    double validationLoss = 0.0; ///< one-step loss on the validation data (NaN without them)
};

/// The table of arxOrderTable.
struct ArxOrderTable {
    std::vector<ArxOrderRow> rows;             ///< nk outermost, then na, then nb, all ascending
    std::size_t commonFirstRow = 0;            ///< losses are over samples commonFirstRow .. N-1
    std::optional<std::size_t> bestAic;        ///< index of the smallest AIC
    std::optional<std::size_t> bestValidation; ///< index of the smallest validation loss
    bool cancelled = false;
};

/**
 * Every ARX(na, nb, nk) of the ranges (MATLAB's arxstruc/selstruc): each estimated on its own
 * rows, its loss V taken over the COMMON samples max(n0) .. N-1 (so that the AIC of different
 * orders compares like with like), FPE and AIC from it; with @p validation, the one-step
 * prediction loss on those data over the same first sample. Rank-deficient orders keep their
 * status and NaN figures. @p progress as SweepOptions::progress (false cancels; the rows so far
 * are kept and `cancelled` set).
 * @throws InvalidInput "na", "nb", "nk" for a range with min > max or out of ArxOrders' limits,
 *         "data" (estimateArx) when N is too few for the largest orders.
 */
ArxOrderTable arxOrderTable(const IoData& estimation, const IoData* validation, OrderRange na,
                            OrderRange nb, OrderRange nk,
                            const std::function<bool(double fraction)>& progress = {});

/// One whiteness or independence test: normalized correlations at lags against +-bound.
struct CorrelationTest {
    std::vector<int> lags;
    std::vector<double> values; ///< normalized correlation, |value| <= 1
    double bound = 0.0;         ///< z / sqrt(N)
    bool passed = true;         ///< every |value| <= bound
    int outsideCount = 0;       ///< lags with |value| > bound (expected: 1 % of the lags)
    int worstLag = 0;           ///< lag of the largest |value|
    double worstValue = 0.0;
};

/**
 * Residual tests (Ljung Sec. 16.6), with the residual and input means removed:
 *  - autocorrelation r_e(tau) / r_e(0), tau = 1..M: whiteness;
 *  - cross-correlation r_eu(tau) / sqrt(r_e(0) r_u(0)), tau = -M..M, with
 *    r_eu(tau) = (1/N) sum_t e(t) u(t - tau): tau > 0 looks at past inputs (an unmodelled
 *    dynamic), tau < 0 at future inputs (feedback).
 * The bound z/sqrt(N) (z = 2.576: 99 %) is the two-sided band of one lag for white residuals
 * independent of u. The verdict asks every lag to be inside, so even for perfect residuals a
 * test fails with probability 1 - 0.99^M (22 % for M = 25 independent lags, 40 % for the 51
 * cross lags): a failure at one lag just outside the band is weak evidence; look at worstValue
 * and outsideCount (0.25 lags of 25 expected outside for white residuals).
 */
struct ResidualAnalysis {
    CorrelationTest autocorrelation;
    CorrelationTest crossCorrelation;
    std::size_t samples = 0;
    bool passed() const { return autocorrelation.passed && crossCorrelation.passed; }
};
/// Over samples firstSample .. N-1 (skip the ARX start rows or a transient).
/// @throws InvalidInput "residuals" (empty, not finite, N - firstSample <= maxLag), "input"
///         (length), "max_lag" (< 1), "confidence_z" (<= 0).
ResidualAnalysis residualAnalysis(const std::vector<double>& residuals,
                                  const std::vector<double>& input, int maxLag = 25,
                                  double confidenceZ = 2.576, std::size_t firstSample = 0);

/**
 * Poles and zeros of a polynomial model in the z-plane (positive powers of z): poles of
 * B / (A F) and of the noise model C / (A D), zeros of B without its delay and of C.
 * A zero of B outside the unit circle makes the model non-minimum-phase: the inverse a
 * tracking controller needs is unstable, "this is what makes ZPETC necessary"
 * (core/design/zpetc.h, Patrick, Ishak and Adnan).
 */
struct ModelRoots {
    double tsSeconds = 0.0;
    std::vector<std::complex<double>> poles;      ///< of B/(A F), sorted (sortRoots)
    std::vector<std::complex<double>> zeros;      ///< of B (delay removed), sorted
    std::vector<std::complex<double>> noisePoles; ///< of C/(A D)
    std::vector<std::complex<double>> noiseZeros; ///< of C
    /// Continuous poles and zeros, for models that have them (thirdOrderPlantRoots), else empty.
    std::vector<std::complex<double>> continuousPoles;
    std::vector<std::complex<double>> continuousZeros;
    bool stable = true; ///< every pole strictly inside the unit circle
    /// Not stable only through poles at z = 1 (an integrator, as a position output of a motor
    /// axis has): every other pole strictly inside. A pole counts as at 1 within 1e-6, the
    /// accuracy of a double root there from the companion-matrix eigenvalues (sqrt(eps) ~ 1.5e-8)
    /// with margin; a pole at 1 and a pole just outside cannot be told apart better than that.
    bool integrating = false;
    bool nonMinimumPhase = false;  ///< a zero of B on or outside the unit circle
    std::vector<Diagnostic> notes; ///< e.g. the NMP zero and what it implies (coded)
};
/// @throws InvalidInput from model.validate(), "model.b" when B is all zeros.
ModelRoots modelRoots(const PolynomialModel& model);

/**
 * The continuous poles (0 and the roots of s^2 + a1 s + a2; no finite zeros) of Braga et al.'s
 * plant and the z-plane poles and zeros of its exact ZOH discretization at @p tsSeconds, whose
 * sampling zeros (relative degree 3: near -3.73 and -0.27 for fast sampling) make it
 * non-minimum-phase. @throws InvalidInput from ThirdOrderPlant::validate, "ts".
 */
ModelRoots thirdOrderPlantRoots(const ThirdOrderPlant& plant, double tsSeconds);

} // namespace xyt
