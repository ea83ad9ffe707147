// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/notch_filter.h"

#include <string>
#include <vector>

namespace xyt {

/**
 * A digital controller as a difference equation: U(z)/E(z) = N(z^-1)/D(z^-1) with both
 * polynomials in ascending powers of z^-1 and d[0] = 1, i.e.
 *   u[k] = sum_i n_i e[k-i] - sum_{i>=1} d_i u[k-i].
 */
struct DigitalController {
    std::vector<double> num; ///< n_0, n_1, ... (ascending powers of z^-1)
    std::vector<double> den; ///< 1, d_1, ... (ascending powers of z^-1)
    double tsSeconds = 0.0;
};

enum class PiDiscretization {
    Tustin,       ///< s = (2/Ts)(1 - z^-1)/(1 + z^-1)
    BackwardEuler ///< s = (1 - z^-1)/Ts
};

/**
 * The PI controller kp + ki/s at sample time Ts:
 *   Tustin:         [(kp + ki Ts/2) + (ki Ts/2 - kp) z^-1] / (1 - z^-1)
 *   backward Euler: [(kp + ki Ts) - kp z^-1] / (1 - z^-1)
 * @throws InvalidInput "kp", "ki" (finite), "ts" (> 0).
 */
DigitalController discretizePi(double kp, double ki, double tsSeconds, PiDiscretization method);

/// "tustin" / "backward-euler".
std::string discretizationName(PiDiscretization method);

/// How the digital PI keeps its integrator from winding up while the command is clipped.
enum class AntiWindup {
    None,  ///< the integrator runs on whatever the output does
    Clamp, ///< conditional integration: hold the integrator while clipped and pushing outwards
    BackCalculation ///< feed (u - v) Ts / Tt back into the integrator (tracking time Tt)
};

/// "none" / "clamp" / "back-calculation".
std::string antiWindupName(AntiWindup method);

/**
 * The PI of discretizePi in the integrator form the firmware runs, so that an anti-windup can act
 * on the integrator (e in model units, u in volts):
 *   I[k] = I[k-1] + c0 e[k] + c1 e[k-1],   v[k] = kp e[k] + I[k],
 * with c0 = c1 = ki Ts / 2 (Tustin) or c0 = ki Ts, c1 = 0 (backward Euler). Unclipped, v is the
 * difference equation of discretizePi: v[k] - v[k-1] = (kp + c0) e[k] + (c1 - kp) e[k-1].
 * The step with saturation at +-umax and anti-windup is stepDigitalPi.
 */
struct DigitalPi {
    double kp = 0.0;
    double c0 = 0.0;
    double c1 = 0.0;
    double tsSeconds = 0.0;
    AntiWindup antiWindup = AntiWindup::Clamp;
    /// Back-calculation gain Ts / Tt (0 for the other methods).
    double trackingGain = 0.0;
    /// A notch on the error the PI reads (core/design/notch_filter.h): e_f = N(z) e, then the
    /// PI of e_f. The loops and the exported code step it with stepBiquad before stepDigitalPi.
    bool hasNotch = false;
    Biquad errorNotch;
};

/**
 * @param trackingTimeSeconds back-calculation's Tt; 0 chooses Tt = Ti = kp / ki, the usual rule
 *        for a PI (Astrom and Hagglund, Advanced PID Control, 2006, section 3.5).
 * @throws InvalidInput "kp", "ki" (finite), "ts" (> 0), "tracking_time" (finite, >= 0; 0 with
 *         ki = 0 for back-calculation).
 */
DigitalPi digitalPi(double kp, double ki, double tsSeconds, PiDiscretization method,
                    AntiWindup antiWindup, double trackingTimeSeconds = 0.0);

/// The state the PI keeps between samples.
struct DigitalPiState {
    double integrator = 0.0;    ///< I[k-1]
    double previousError = 0.0; ///< e[k-1]
};

/**
 * One sample of the PI: from the error e (model units) the saturated command u in
 * [-umax, umax] (infinity: no limit), updating @p state:
 *   candidate = I[k-1] + (c0 e + c1 e[k-1]),  v = kp e + candidate,  u = sat(v);
 *   None: I[k] = candidate.  Clamp: when u != v and the increment c0 e + c1 e[k-1] has the sign
 *   of v, I[k] = I[k-1] and v, u are computed again from it; else I[k] = candidate.
 *   BackCalculation: I[k] = candidate + (Ts/Tt) (u - v).
 * Unclipped, all three give the same bits. The exported C code (exportCHeader) performs the
 * same operations in the same order.
 */
inline double stepDigitalPi(const DigitalPi& pi, DigitalPiState& state, double error,
                            double umaxVolts) {
    const double increment = pi.c0 * error + pi.c1 * state.previousError;
    const double candidate = state.integrator + increment;
    double v = pi.kp * error + candidate;
    double u = v > umaxVolts ? umaxVolts : (v < -umaxVolts ? -umaxVolts : v);
    switch (pi.antiWindup) {
    case AntiWindup::None:
        state.integrator = candidate;
        break;
    case AntiWindup::Clamp:
        if (u != v && increment * v > 0.0) {
            v = pi.kp * error + state.integrator; // integrator held
            u = v > umaxVolts ? umaxVolts : (v < -umaxVolts ? -umaxVolts : v);
        } else {
            state.integrator = candidate;
        }
        break;
    case AntiWindup::BackCalculation:
        state.integrator = candidate + pi.trackingGain * (u - v);
        break;
    }
    state.previousError = error;
    return u;
}

/**
 * Runs the difference equation N/D (ascending z^-1, D[0] != 0) on @p input from rest.
 * @throws InvalidInput "den" when D[0] is zero or D is empty, "num" when empty.
 */
std::vector<double> filterDifferenceEquation(const std::vector<double>& num,
                                             const std::vector<double>& den,
                                             const std::vector<double>& input);

} // namespace xyt
