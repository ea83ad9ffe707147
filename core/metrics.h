// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation.h"
#include "core/transfer_function.h"

namespace xyt {

/// Figures of one tracking run (see trackingMetrics for the definitions).
struct TrackingMetrics {
    double rmse = 0.0;            ///< sqrt(mean e_k^2)
    double maxAbsError = 0.0;     ///< max |e_k|
    double maxAbsErrorPct = 0.0;  ///< max |e_k| / travel * 100, travel = max r - min r
    double maxAbsU = 0.0;         ///< max |u_k| (after saturation)
    bool saturated = false;       ///< some sample was clipped at +-umax
    double saturatedTimeSeconds = 0.0; ///< clipped samples * dt
    double itae = 0.0;            ///< integral of t |e(t)| dt, trapezoidal rule (paper 000's AEMT)
};

/// @throws InvalidInput "result" when the run is empty or its signals differ in length.
TrackingMetrics trackingMetrics(const SimulationResult& run);

/// Root mean square of a signal (0 for an empty one).
double rootMeanSquare(const std::vector<double>& v);

/// Step response figures of a continuous closed loop.
struct StepCharacteristics {
    bool stable = false;       ///< all poles in the open left half plane; else the rest is unset
    double finalValue = 0.0;   ///< dc gain
    double settlingTimeSeconds = 0.0; ///< last time |y - final| > band |final|
    double overshootPct = 0.0; ///< (max y - final) / |final| * 100, at least 0
    double peakTimeSeconds = 0.0;
};

/**
 * Settling time (band 2 % by default) and overshoot of the unit step response, computed exactly
 * at @p samples points (zero-order-hold discretization is exact for a step) over a horizon of
 * 12 time constants of the slowest pole (extended while the response is still outside the band),
 * with the settling instant interpolated between samples by a cubic Hermite polynomial using the
 * exact derivative y' = C (A x + B).
 * @throws InvalidInput "system" unless continuous and proper, "band" unless in (0, 1).
 */
StepCharacteristics stepCharacteristics(const TransferFunction& closedLoop, double band = 0.02,
                                        int samples = 4000);

} // namespace xyt
