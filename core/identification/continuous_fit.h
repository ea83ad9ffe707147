// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/identification/io_data.h"
#include "core/identification/least_squares.h"
#include "core/identification/polynomial_model.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * Output of Braga et al.'s plant \f$ G(s) = \frac{k_0}{s^3 + a_1 s^2 + a_2 s} \f$ (Eq. 9) for a
 * zero-order-held input: the EXACT ZOH discretization (matrix exponential, discretizeZoh in
 * core/model/state_space.h) of the companion realization x = [y, y', y''], from rest at y = 0.
 * u[k] (V) is held over [k Ts, (k+1) Ts), y[k] is the position at k Ts (the model's output unit:
 * metres for the paper's k0). Length of the result = length of @p u.
 * @throws InvalidInput from ThirdOrderPlant::validate, "ts" unless > 0.
 */
std::vector<double> simulateThirdOrderPlant(const ThirdOrderPlant& plant,
                                            const std::vector<double>& u, double tsSeconds);

/// Settings of fitThirdOrderPlant.
struct ContinuousFitOptions {
    /// Start here instead of the converted discrete estimate (see fitThirdOrderPlant).
    std::optional<ThirdOrderPlant> initial;
    /// Iterations (>= 1), tolerances, and search.progress: the fraction done after each
    /// iteration and 1 at the end; false cancels (status Cancelled, best estimate so far), as
    /// SweepOptions::progress. May be empty.
    SearchOptions search;
    /// Central-difference Jacobian: parameter p is stepped by +-h, h = step * |p| (relative
    /// step 1e-6: truncation error ~ h^2, round-off ~ 1e-16 / h, both ~ 1e-10 of the output).
    double finiteDifferenceStep = 1e-6;
    /**
     * Also estimate the position y0 the table rests at when the record starts: yhat = y0 + the
     * response from rest. It is projected out of the search (for each k0, a1, a2 the best y0
     * is the mean of y minus the response), which gives the same estimate and the same
     * covariance of k0, a1, a2 as fitting y0 jointly. Without it the record must start at
     * exactly 0: subtracting a noisy first sample biases the fit by many standard deviations.
     */
    bool estimateInitialPosition = false;
};

/// The fit of Braga et al.'s plant structure to sampled data.
struct ContinuousFitResult {
    EstimationStatus status = EstimationStatus::Failed;
    Diagnostic message;    ///< how the search ended, or why it failed (coded)
    ThirdOrderPlant plant; ///< k0, a1, a2: fills the Guillemin-Truxal design directly
    /// Standard deviations of {k0, a1, a2}, from sigma^2 (J^T J)^-1 (NaN when J is singular).
    std::array<double, 3> standardDeviations{};
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero(); ///< order k0, a1, a2
    ThirdOrderPlant initialPlant;
    /// "ARX(3,3,1) converted", "pole grid" or "given".
    std::string initialization;
    double noiseVariance = 0.0; ///< ||e||^2 / (N - 3)
    double loss = 0.0;          ///< V = ||e||^2 / N
    std::size_t samples = 0;
    int iterations = 0;
    std::vector<double> lossHistory;
    /// The estimated initial position y0 (mm) with estimateInitialPosition, else 0.
    double initialPositionMm = 0.0;
    std::vector<double> simulated;    ///< model output at the estimate (with y0 when estimated)
    std::vector<double> residuals;    ///< y - simulated
    std::vector<Diagnostic> warnings; ///< coded
};

/**
 * Takes the record's first output sample y[0] off every output sample (y[k] - y[0]), in place:
 * the plant integrates, and the model fitThirdOrderPlant fits starts at rest at position 0, so a
 * record taken where the table stood elsewhere is moved to start at 0 first (the fit's
 * estimateInitialPosition then estimates where the table really stood, noise and all).
 * @return y[0], the position the outputs are now relative to (the caller says so to the user);
 *         unset, and the record untouched, when it has no output sample.
 */
std::optional<double> subtractInitialPosition(IoData& data);

/**
 * Output-error fit of G(s) = k0 / (s^3 + a1 s^2 + a2 s) to @p data: minimizes
 * V = (1/N) sum (y[k] - yhat[k])^2 with yhat = simulateThirdOrderPlant (so y must start at rest
 * at 0: subtract the initial position first), by Levenberg-Marquardt (least_squares.h) with a
 * central-difference Jacobian. Initial values: the ARX(3,3,1) estimate converted to continuous
 * time (the pole nearest z = 1 is the integrator, the others map by s = ln(z) / Ts, k0 =
 * a2 B(1) / (Ts prod(1 - z_i)) from the velocity gain), and the pole grid: real poles -p1, -p2
 * with p1 <= p2 from {0.003, 0.01, 0.03, 0.1, 0.3, 1} / Ts (21 pairs), each with its
 * least-squares k0 (the output is linear in k0). The ARX conversion is exact on noise-free data
 * but fails under measurement noise (ARX then puts a root on the negative real axis); the
 * candidate with the smaller loss starts the search.
 * @throws InvalidInput from validateIoData, "max_iterations" (< 1), "finite_difference_step"
 *         (not in (0, 0.1]), "data" when N < 10, "initial" from ThirdOrderPlant::validate.
 */
ContinuousFitResult fitThirdOrderPlant(const IoData& data,
                                       const ContinuousFitOptions& options = {});

/**
 * The discrete model (z^-1 polynomials, as PolynomialModel: A = denominator, B with its delay)
 * of the exact ZOH discretization of @p plant at @p tsSeconds (c2dZoh), e.g. to compare it with
 * an ARX(3,3,1) estimate or to see its sampling zeros.
 */
PolynomialModel discretizedThirdOrderPlant(const ThirdOrderPlant& plant, double tsSeconds);

} // namespace xyt
