// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

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
    Tustin,        ///< s = (2/Ts)(1 - z^-1)/(1 + z^-1)
    BackwardEuler  ///< s = (1 - z^-1)/Ts
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

/**
 * Runs the difference equation N/D (ascending z^-1, D[0] != 0) on @p input from rest.
 * @throws InvalidInput "den" when D[0] is zero or D is empty, "num" when empty.
 */
std::vector<double> filterDifferenceEquation(const std::vector<double>& num,
                                             const std::vector<double>& den,
                                             const std::vector<double>& input);

} // namespace xyt
