// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/model/diagnostic.h"

#include <limits>
#include <string>
#include <vector>

namespace xyt {

/// The controller structures a loop-shaping or ultimate-cycle rule returns.
enum class PidStructure {
    Pi, ///< C(s) = P + I/s (D = 0)
    Pid ///< C(s) = P + I/s + D s, with Ti = 4 Td (see tunePidForMargin)
};

/// @throws InvalidInput "k0", "a1", "a2" unless each is finite and > 0: the motor base
///         k0/(s^3 + a1 s^2 + a2 s) with a positive gain and both other poles in the open left
///         half plane, the plant the tuning rules of this folder assume.
void requirePositivePlant(const ThirdOrderPlant& plant);

/// Why a target crossover and phase margin give no gains.
enum class PidTuningStatus {
    Ok,
    PhaseOutOfReach, ///< the controller phase needed at the crossover is beyond the structure's
    GainsOutOfRange  ///< a gain overflows double precision (an extreme crossover frequency)
};

/// The gains for a target crossover and phase margin, and the loop they give (tunePidForMargin).
struct PidTuningResult {
    PidStructure structure = PidStructure::Pi;
    PidTuningStatus status = PidTuningStatus::Ok;
    Diagnostic reason; ///< empty (uncoded) when status is Ok, else why (coded, for the user)

    double targetCrossoverRadPerSec = 0.0;
    double targetPhaseMarginDeg = 0.0;
    /// arg G(j wc) in degrees, in (-270, -90) for the positive plant.
    double plantPhaseDeg = 0.0;
    /// The controller phase the target needs: phi_c = -180 + PM - arg G(j wc), degrees.
    double requiredControllerPhaseDeg = 0.0;
    /// The controller gain the target needs: |C(j wc)| = u / |G(j wc)|, V/mm.
    double requiredControllerGainVoltsPerMm = 0.0;

    /// LinuxCNC pid gains (position in mm): P in V/mm, I in V/(mm s), D in V s/mm; zero unless
    /// status is Ok.
    double p = 0.0;
    double i = 0.0;
    double d = 0.0;
    double tiSeconds = std::numeric_limits<double>::infinity(); ///< P / I (infinite when I = 0)
    double tdSeconds = 0.0;                                     ///< D / P

    /// The gain crossover of L = C G / u computed back from p, i, d (the one nearest the target
    /// in log frequency when there are several), rad/s; NaN unless status is Ok.
    double achievedCrossoverRadPerSec = std::numeric_limits<double>::quiet_NaN();
    /// 180 + arg L there, degrees, wrapped to (-180, 180]; NaN unless status is Ok.
    double achievedPhaseMarginDeg = std::numeric_limits<double>::quiet_NaN();
    /// How many gain crossovers L has (1 for a1^2 >= 2 a2, where |L| falls monotonically).
    int gainCrossoverCount = 0;
    /// The closed loop 1/(1 + L) has all its poles in the open left half plane (Routh-Hurwitz).
    bool closedLoopStable = false;
    /// Oddities: several gain crossovers, an unstable closed loop despite the margin.
    std::vector<Diagnostic> warnings;

    bool ok() const { return status == PidTuningStatus::Ok; }
};

/**
 * PI or PID gains from a target gain crossover wc (rad/s) and phase margin PM (degrees), in
 * closed form, on the third-order plant G(s) = k0/(s^3 + a1 s^2 + a2 s) (Braga et al. Eq. 9,
 * model units per volt).
 *
 * The controller is LinuxCNC's ideal parallel PID with position in mm,
 * \f$ C(s) = P + I/s + D s = P (1 + 1/(T_i s) + T_d s) \f$ (P in V/mm, I in V/(mm s), D in
 * V s/mm), and with u = @p modelUnitsPerPositionUnit model units per mm (0.001 for a model in
 * metres) the loop is \f$ L(s) = C(s) G(s) / u \f$. The target asks
 * \f$ |L(j\omega_c)| = 1 \f$ and \f$ \arg L(j\omega_c) = -180° + PM \f$, i.e.
 *   \f$ |C(j\omega_c)| = u / |G(j\omega_c)| \f$,
 *   \f$ \varphi_c = \arg C(j\omega_c) = PM - 90° + \operatorname{atan2}(a_1\omega_c,
 *       a_2 - \omega_c^2) \f$.
 *
 * - PI (D = 0): \f$ C(j\omega) = P (1 - j/(\omega T_i)) \f$, phase
 *   \f$ -\arctan(1/(\omega_c T_i)) \f$, which covers -90° < phi_c <= 0°:
 *   \f$ P = |C| \cos\varphi_c \f$, \f$ I = P \omega_c \tan(-\varphi_c) \f$.
 * - PID with the third condition \f$ T_i = 4 T_d \f$ (the ratio of Ziegler and Nichols' PID
 *   rule, Ti = Tu/2, Td = Tu/8; it makes the two zeros of C coincide,
 *   \f$ C(s) = P (2 T_d s + 1)^2 / (4 T_d s) \f$):
 *   \f$ C(j\omega) = P (1 + j(\omega T_d - 1/(4\omega T_d))) \f$, phase
 *   \f$ \arctan(\omega_c T_d - 1/(4\omega_c T_d)) \f$, which covers -90° < phi_c < 90°. The
 *   quadratic \f$ 4\tau^2 - 4\tau\tan\varphi_c - 1 = 0 \f$ in \f$ \tau = \omega_c T_d \f$ has
 *   the positive root \f$ \tau = \tan(45° + \varphi_c/2)/2 \f$ (the half-angle form, free of
 *   the cancellation of \f$ (\tan\varphi_c + \sec\varphi_c)/2 \f$ near -90°); then
 *   \f$ P = |C| \cos\varphi_c \f$, \f$ I = P/(4 T_d) \f$, \f$ D = P T_d \f$.
 *
 * A phase outside the structure's range, or gains that overflow, is a status in the result,
 * not a throw: a slider can ask for it. With the gains the loop is checked back: the gain
 * crossovers are the positive roots of the quartic \f$ |C|^2 |G|^2 = u^2 \f$ in
 * \f$ (\omega/\omega_c)^2 \f$ (polished roots of Polynomial::roots), the phase margin is
 * 180° + arg L there, and the closed-loop polynomial
 * \f$ u s^2 (s^2 + a_1 s + a_2) + k_0 (D s^2 + P s + I) \f$ is tested by Routh-Hurwitz.
 *
 * @throws InvalidInput "k0", "a1", "a2" (requirePositivePlant), "model_unit_scale",
 *         "crossover" and "phase_margin" unless finite and > 0.
 */
PidTuningResult tunePidForMargin(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit,
                                 PidStructure structure, double crossoverRadPerSec,
                                 double phaseMarginDeg);

/// "PI" / "PID".
std::string pidStructureName(PidStructure structure);

} // namespace xyt
