// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <string>

namespace xyt {

/// Which of the two real poles of s^2 + a1 s + a2 is the drive's electrical lag (the other is
/// the moving mass' mechanical pole, where friction acts).
enum class ElectricalPole { Faster, Slower };

/**
 * The nonlinear elements of one axis of the table, in the units an engineer measures them in.
 * Forces are stated in volts of equivalent input: the command that would produce the same force
 * on the moving mass in steady state (so a Coulomb level of 0.1 V means the axis needs 0.1 V more
 * than its linear model to keep sliding). Every field at zero is the linear table of the papers.
 *
 * Friction (acting on the mass while sliding at velocity v, mm/s):
 *   f(v) = sign(v) (Fc + (Fs - Fc) exp(-(v / vs)^2)) + bv v,
 * the Stribeck curve with a Gaussian decay (Armstrong-Helouvry, Dupont and Canudas de Wit, 1994,
 * "A survey of models, analysis tools and compensation methods for the control of machines with
 * friction", Automatica 30(7), Eq. 1); at rest the mass sticks while the applied force is at most
 * Fs (core/simulation/table_dynamics.h says how).
 */
struct TableFriction {
    double coulombVolts = 0.0;           ///< Fc >= 0
    double staticVolts = 0.0;            ///< Fs: 0 means Fs = Fc (no Stribeck dip); else Fs >= Fc
    double stribeckVelocityMmPerS = 0.0; ///< vs > 0 when Fs > Fc
    /// bv >= 0, beyond the model's own damping (which a2/k0 already holds): 0 by default.
    double viscousVoltsPerMmPerS = 0.0;
    /// The play between motor and table (mm): the table stays while the motor crosses the gap.
    double backlashMm = 0.0;
    /// The amplifier's deadband (V): |u| <= d gives no output, beyond it u - d sign(u).
    double amplifierDeadbandVolts = 0.0;
    ElectricalPole electricalPole = ElectricalPole::Faster;

    /// Fs as the simulation uses it: max(Fs, Fc).
    double breakawayVolts() const {
        return staticVolts > coulombVolts ? staticVolts : coulombVolts;
    }
    /// Any element set: the table is not the linear model.
    bool active() const;
    friend bool operator==(const TableFriction&, const TableFriction&) = default;
};

/**
 * The friction of TableFriction's header while sliding at velocity @p v in @p direction (+1 or
 * -1; the sign of v except at the instant of a breakaway, v = 0), for levels in any one set of
 * units (volts and mm/s, or the simulation's model units):
 *   direction (coulomb + (breakaway - coulomb) exp(-(v / stribeckVelocity)^2)) + viscous v,
 * the dip left out when breakaway <= coulomb. The simulation, the jog estimate's curve and the
 * workbench's drawing of it all read it here.
 */
inline double stribeckFriction(double coulomb, double breakaway, double stribeckVelocity,
                               double viscous, double v, double direction) {
    double level = coulomb;
    if (breakaway > coulomb) {
        const double q = v / stribeckVelocity;
        level += (breakaway - coulomb) * std::exp(-q * q);
    }
    return direction * level + viscous * v;
}

/**
 * Friction compensation as drive firmware does it: a feedforward from the reference velocity v
 * (mm/s), a percentage of the friction levels the compensation believes in,
 *   u_fc = p / 100 (Fc sat(v / w) + bv v),   sat(x) = max(-1, min(1, x)),
 * where w is the smoothing band through zero velocity (mm/s): the Coulomb term ramps linearly
 * across |v| < w rather than jumping, so a reference at rest or creeping through zero does not
 * make the command chatter between +-Fc. The levels are the axis' own friction settings (what
 * the engineer identified); percent = 0 is no compensation.
 */
struct FrictionCompensation {
    double percent = 0.0;
    /// 0.05 mm/s: on a 25 mm ballbar circle at 150 mm/min an axis' velocity crosses it within
    /// 1.2 degrees of the quadrant change; a band ten times wider leaves the friction half
    /// compensated over +-11 degrees and the reversal spikes barely smaller.
    double bandMmPerS = 0.05;
    friend bool operator==(const FrictionCompensation&, const FrictionCompensation&) = default;
};

/// u_fc for reference velocity @p velocityMmPerS (see FrictionCompensation).
double frictionCompensationVolts(const TableFriction& friction,
                                 const FrictionCompensation& compensation, double velocityMmPerS);

/**
 * @throws InvalidInput naming @p prefix + the field ("coulomb", "static", "stribeck_velocity",
 *         "viscous", "backlash", "amplifier_deadband"): not finite or negative; static below
 *         Coulomb (other than 0); a Stribeck dip (Fs > Fc) without a Stribeck velocity > 0.
 */
void validateTableFriction(const TableFriction& friction, const std::string& prefix = "");
/// @throws InvalidInput naming @p prefix + "percent" (not finite, < 0 or > 200) or "band" (<= 0).
void validateFrictionCompensation(const FrictionCompensation& compensation,
                                  const std::string& prefix = "");

} // namespace xyt
