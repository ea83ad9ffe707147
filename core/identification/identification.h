// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/identification/arx.h"
#include "core/identification/continuous_fit.h"
#include "core/identification/io_data.h"
#include "core/identification/polynomial_model.h"
#include "core/identification/prediction_error.h"
#include "core/identification/validation.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// The model structures XY Tune identifies.
enum class ModelStructure {
    Arx,                 ///< A y = B u + e (least squares)
    Oe,                  ///< y = B/F u + e (prediction error)
    Bj,                  ///< y = B/F u + C/D e (prediction error)
    ContinuousThirdOrder ///< Braga et al.: k0 / (s^3 + a1 s^2 + a2 s), output error, exact ZOH
};

/// "arx", "oe", "bj", "gt3" (the CLI's and the session file's names).
std::string modelStructureName(ModelStructure structure);
/// @throws InvalidInput "structure" for another name.
ModelStructure parseModelStructure(const std::string& name);

/// What to identify and how to judge it.
struct IdentificationSpec {
    ModelStructure structure = ModelStructure::Arx;
    ArxOrders arx;
    OeOrders oe;
    BjOrders bj;
    /// Horizon of the k-step-ahead prediction fit (>= 1; the simulation fit is always given).
    int predictionHorizon = 5;
    /// Lags of the residual tests (>= 1).
    int maxLag = 25;
    /// Iterations, tolerances, progress and cancel of the searches (OE, BJ, the continuous fit).
    SearchOptions search;

    /// "ARX(2,3,1)", "OE(3,2,1)", "BJ(3,1,1,2,1)", "GT3 k0/(s^3+a1 s^2+a2 s)".
    std::string describe() const;
};

/**
 * One identified model with everything the comparison of candidates shows: the estimate and
 * its uncertainty, its simulated and predicted output on the estimation (and validation) data,
 * FPE/AIC, the residual tests and its poles and zeros. The discrete `model` is the polynomial
 * form of every structure; for the continuous fit it is the exact ZOH discretization of `plant`
 * in output-error form (F = its denominator, A = C = D = 1), so that its prediction is its
 * simulation, as for any output-error model. Units: u in V, y in mm (IoData), so `plant`'s k0
 * is in mm / (V s^3); a session whose model unit is metres scales it (sessionAxisFromModel).
 */
struct IdentifiedModel {
    IdentificationSpec spec;
    std::string structure; ///< spec.describe()
    EstimationStatus status = EstimationStatus::Failed;
    Diagnostic message; ///< the estimator's (coded)
    PolynomialModel model;
    std::optional<ThirdOrderPlant> plant;
    std::vector<std::string> parameterNames; ///< "a1", "b1", "f1", ... or "k0", "a1", "a2"
    std::vector<double> parameters;
    std::vector<double> standardDeviations;
    Eigen::MatrixXd covariance;
    InformationCriteria criteria;
    FitReport fit;
    /// The continuous fit's estimated initial position (mm): its fits compare the model started
    /// there (on validation data, from the initial position that fits them best).
    double initialPositionMm = 0.0;
    std::vector<double> residuals; ///< the residual series the tests judge (from firstSample)
    std::size_t firstSample = 0;   ///< the first sample the fits and tests use (ARX start rows)
    ResidualAnalysis residualTests;
    ModelRoots roots;
    std::vector<Diagnostic> warnings; ///< coded

    /// An estimate exists (converged, or stopped at the iteration limit or by a cancel).
    bool hasEstimate() const;
};

/**
 * Identifies @p spec's structure on @p estimation and judges it there and, when given, on
 * @p validation (same sample time). An estimation that cannot give an estimate (input not
 * persistently exciting, a failed search) is a status with the message; the figures are then
 * left empty.
 * @throws InvalidInput from the estimators ("data", the orders), "validation" when its sample
 *         time differs from the estimation data's by more than 1 %, "prediction_horizon",
 *         "max_lag".
 */
IdentifiedModel identifyModel(const IoData& estimation, const IoData* validation,
                              const IdentificationSpec& spec);

} // namespace xyt
