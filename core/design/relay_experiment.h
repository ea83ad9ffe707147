// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/design/pid_tuning.h"
#include "core/model/diagnostic.h"

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace xyt {

// The relay experiment of Åström and Hägglund (Automatica 20(5), 1984) on the motor base
// G(s) = k0/(s^3 + a1 s^2 + a2 s) (Braga et al. Eq. 9, model units per volt), simulated.
//
// Conventions of this header:
// - The relay closes the loop around the axis at the reference r = 0: e = r - y = -y and
//   u = d sign(e) = -d sign(y), d the relay amplitude in volts. The relay is ideal: zero
//   hysteresis (the only case supported). It switches when e, i.e. y, changes sign.
// - The realization is x = [y, y', y''] in model units:
//   x' = A x + B u, y = C x with A = [[0, 1, 0], [0, 0, 1], [0, -a2, -a1]],
//   B = [0, 0, k0]^T, C = [1, 0, 0] (realize()'s companion form with the state scaled by k0).
// - Positions reported in mm: model units divided by u = modelUnitsPerPositionUnit (0.001 for
//   a model in metres).

/**
 * The exact symmetric limit cycle of the relay loop (Tsypkin's periodic-solution method):
 * with \f$ \Phi(h) = e^{A h} \f$ and \f$ \Gamma(h) = \int_0^h e^{A\tau} B\,d\tau \f$ (exact
 * ZOH, discretizeZoh), a symmetric oscillation of half period h that switches to u = +d at
 * t = 0 with state x0 has \f$ x(h) = \Phi(h) x_0 + \Gamma(h) d = -x_0 \f$, so
 *   \f$ x_0(h) = -(I + \Phi(h))^{-1} \Gamma(h)\, d \f$
 * (Phi's eigenvalues are 1, from the integrator, and e^{lambda h} with Re lambda < 0, never -1:
 * I + Phi is invertible), and the switching condition \f$ y(0) = C x_0(h) = 0 \f$ with
 * \f$ y'(0) < 0 \f$ (e turns positive, so the relay goes to +d) and \f$ y < 0 \f$ on (0, h).
 *
 * C x0(h) is h^3 k0 d / 24 + O(h^5) > 0 for small h and tends to -infinity (the integrator's
 * triangle wave) for large h; the root is searched by bisection, to adjacent doubles, in a
 * bracket grown from [h_DF/2, 2 h_DF] (h_DF = pi/sqrt(a2), the describing function's half
 * period) by factors of 2 until C x0 changes sign (at most 60 times each way). Then y < 0 is
 * checked on 2000 equal sub-steps of (0, h) and the peak is where y' = 0, found by bisection
 * to adjacent doubles between the grid points around the grid's minimum (y is stationary there,
 * so the amplitude is exact to round-off).
 *
 * A failure of the search or of the checks is a status (found == false), not a throw.
 */
struct RelayLimitCycle {
    bool found = false;
    Diagnostic status; ///< empty (uncoded) when found, else why not (coded)
    double halfPeriodSeconds = std::numeric_limits<double>::quiet_NaN();  ///< h
    double periodSeconds = std::numeric_limits<double>::quiet_NaN();      ///< Tu = 2 h
    double frequencyRadPerSec = std::numeric_limits<double>::quiet_NaN(); ///< 2 pi / Tu
    double amplitudeMm = std::numeric_limits<double>::quiet_NaN();        ///< a = max |y|, mm
    double peakTimeSeconds = std::numeric_limits<double>::quiet_NaN(); ///< of max |y| after t = 0
    /// Ku = 4 d / (pi a), V/mm: the describing-function gain of the relay at the exact amplitude.
    double ultimateGainVoltsPerMm = std::numeric_limits<double>::quiet_NaN();
    /// x0 = [y, y', y''] at the switch to +d, model units (y = 0 up to round-off).
    std::array<double, 3> switchState{};
};

/// @throws InvalidInput "k0", "a1", "a2" (requirePositivePlant), "model_unit_scale",
///         "relay_amplitude" unless finite and > 0.
RelayLimitCycle relayLimitCycle(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit,
                                double relayAmplitudeVolts);

/**
 * The describing-function estimate (first harmonic only): the relay's N(a) = 4 d / (pi a) and
 * the condition N(a) G(j w) = -1. For this plant G(j w) = k0 / (j w (a2 - w^2 + j a1 w)) is
 * real and negative at \f$ \omega_{180} = \sqrt{a_2} \f$, where
 * \f$ G(j\omega_{180}) = -k_0/(a_1 a_2) \f$, so
 *   \f$ a = 4 d k_0 / (\pi a_1 a_2) \f$ (model units, divided by u for mm),
 *   \f$ T_u = 2\pi/\omega_{180} \f$, \f$ K_u = 4 d/(\pi a) = u\, a_1 a_2 / k_0 \f$ (V/mm),
 * the gain at which a proportional loop would sit on the stability boundary (Routh: the same
 * a1 a2 / k0 in model units).
 */
struct RelayDescribingFunction {
    double omega180RadPerSec = 0.0;
    double periodSeconds = 0.0;
    double amplitudeMm = 0.0;
    double ultimateGainVoltsPerMm = 0.0;
};

/// @throws InvalidInput as relayLimitCycle.
RelayDescribingFunction relayDescribingFunction(const ThirdOrderPlant& plant,
                                                double modelUnitsPerPositionUnit,
                                                double relayAmplitudeVolts);

/// Settings of simulateRelayFeedback.
struct RelaySimulationOptions {
    double initialOffsetMm = 0.01; ///< y(0), the axis at rest there; nonzero
    double durationSeconds = 2.0;
    /// Output sample spacing; it must be small against the period (a step that spans two
    /// sign changes of y misses both; a warning says when it exceeds Tu_DF / 50).
    double stepSeconds = 1e-4;
    int cyclesToMeasure = 3; ///< the last this many full cycles give the measured period
};

/**
 * A time simulation of the relay loop from rest at y(0) = initialOffsetMm: exact between
 * switches (u is constant there, so x advances by the exact ZOH step Phi, Gamma of
 * discretizeZoh; only round-off accumulates). When y changes sign within a step the switch
 * instant is found by bisection on the sub-step length to adjacent doubles, the state is taken
 * there and the step finishes with the new u; likewise each extremum of y (y' = 0) is located
 * by bisection and recorded, so the measured amplitude is exact for the simulated trajectory.
 *
 * Samples: t = 0, every step end, and each switch twice (with the old u, then the new one) so
 * that a plot draws u's edges vertically. The measured period is the mean spacing of the last
 * cyclesToMeasure + 1 switches to +d (fewer if fewer happened), the measured amplitude the
 * largest |y| at the extrema between the first and last of those switches; both NaN with a
 * warning when fewer than two switches to +d happened.
 */
struct RelaySimulation {
    std::vector<double> tSeconds;
    std::vector<double> yMm;
    std::vector<double> uVolts;
    std::vector<double> switchTimesSeconds; ///< every switch, alternating direction
    std::vector<double> peakTimesSeconds;   ///< every extremum of y
    std::vector<double> peakValuesMm;       ///< y there (signed)
    double measuredPeriodSeconds = std::numeric_limits<double>::quiet_NaN();
    double measuredAmplitudeMm = std::numeric_limits<double>::quiet_NaN();
    int cyclesMeasured = 0;
    std::vector<Diagnostic> warnings;
};

/// @throws InvalidInput as relayLimitCycle, and "initial_offset" (finite, nonzero),
///         "duration", "step" (finite, > 0; at most 2e6 steps), "cycles_to_measure" (>= 1).
RelaySimulation simulateRelayFeedback(const ThirdOrderPlant& plant,
                                      double modelUnitsPerPositionUnit, double relayAmplitudeVolts,
                                      const RelaySimulationOptions& options);

/// The ultimate-cycle tuning rules.
enum class UltimateCycleRule {
    /// Ziegler and Nichols (1942): PI P = 0.45 Ku, Ti = Tu/1.2; PID P = 0.6 Ku, Ti = Tu/2,
    /// Td = Tu/8.
    ZieglerNichols,
    /// Tyreus and Luyben (1992): PI P = Ku/3.2, Ti = 2.2 Tu; PID P = Ku/2.2, Ti = 2.2 Tu,
    /// Td = Tu/6.3.
    TyreusLuyben
};

/// "Ziegler-Nichols" / "Tyreus-Luyben".
std::string ultimateCycleRuleName(UltimateCycleRule rule);

/// LinuxCNC pid gains (position in mm) of an ultimate-cycle rule.
struct UltimateCycleGains {
    double p = 0.0; ///< V/mm
    double i = 0.0; ///< V/(mm s), = P / Ti
    double d = 0.0; ///< V s/mm, = P Td (0 for PI)
    double tiSeconds = 0.0;
    double tdSeconds = 0.0;
};

/**
 * P, I = P/Ti and D = P Td from the ultimate gain Ku (V/mm) and period Tu (s) by @p rule
 * (see UltimateCycleRule), for the ideal parallel form C(s) = P + I/s + D s.
 * @throws InvalidInput "ultimate_gain", "ultimate_period" unless finite and > 0.
 */
UltimateCycleGains ultimateCycleGains(double ultimateGainVoltsPerMm, double ultimatePeriodSeconds,
                                      UltimateCycleRule rule, PidStructure structure);

} // namespace xyt
