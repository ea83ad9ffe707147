// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"
#include "core/simulation/simulation.h"

namespace xyt {

/// Figures of one tracking run (see trackingMetrics for the definitions).
struct TrackingMetrics {
    double rmse = 0.0;                 ///< sqrt(mean e_k^2)
    double maxAbsError = 0.0;          ///< max |e_k|
    double maxAbsErrorPct = 0.0;       ///< max |e_k| / travel * 100, travel = max r - min r
    double maxAbsU = 0.0;              ///< max |u_k| (after saturation)
    bool saturated = false;            ///< some sample was clipped at +-umax
    double saturatedTimeSeconds = 0.0; ///< clipped samples * dt
    double itae = 0.0; ///< integral of t |e(t)| dt, trapezoidal rule (Braga et al.'s AEMT)
    /// Some sample of y, e or u is not finite (the run diverged): every figure above is then NaN
    /// ("n/a"), `saturated` is false but means nothing, and the run fails every criterion.
    bool diverged = false;
};

/// A diverged run (a non-finite sample) gives NaN figures and `diverged`, never a partial
/// maximum over its finite samples.
/// @throws InvalidInput "result" when the run is empty or its signals differ in length.
TrackingMetrics trackingMetrics(const SimulationResult& run);

/// Root mean square of a signal (0 for an empty one).
double rootMeanSquare(const std::vector<double>& v);

/// Step response figures of a continuous closed loop.
struct StepCharacteristics {
    bool stable = false;     ///< all poles in the open left half plane; else the rest is unset
    double finalValue = 0.0; ///< dc gain
    double settlingTimeSeconds = 0.0; ///< last time |y - final| > band |final|
    double overshootPct = 0.0;        ///< (max y - final) / |final| * 100, at least 0
    double peakTimeSeconds = 0.0;
};

/**
 * Settling time (band 2 % by default) and overshoot of the unit step response, computed exactly
 * at the samples (zero-order-hold discretization is exact for a step) of a multi-scale time grid:
 * a first span of 50 / |p|max seconds (|p|max the largest pole modulus), then spans that each
 * quadruple the time reached, every span with @p samples steps (so dt <= 3 t / samples after
 * the first span), up to a horizon of 12 time constants of the slowest pole (extended, by
 * further spans, to at most 12 * 32, while the response is still outside the band). The settling
 * instant is interpolated inside its step by a cubic Hermite polynomial using the exact derivative
 * y' = C (A x + B); the overshoot and peak time are those of the largest sample.
 *
 * Why multi-scale: with the slow pole-zero pair of a PI design (Braga et al., zero at -psi1 with a
 * pole next to it) the slowest time constant is up to 1e7 times the settling time; a uniform
 * grid over 12 slow time constants would step over the whole transient.
 * @throws InvalidInput "system" unless continuous and proper, "band" unless in (0, 1),
 *         "samples" unless >= 100.
 */
StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop, double band = 0.02,
                                        int samples = 500);
/// The same with the closed loop's poles already at hand (closedLoop.poles(), as a design
/// computes them): the same result without finding them again.
StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop,
                                        const std::vector<std::complex<double>>& poles,
                                        double band = 0.02, int samples = 500);

} // namespace xyt
