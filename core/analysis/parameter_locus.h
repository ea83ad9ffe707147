// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/model/diagnostic.h"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace xyt {

/// The values a parameter takes in a sweep.
struct ParameterSweep {
    double from = 0.0;
    double to = 0.0;
    int count = 100;         ///< base samples, ends included (>= 2)
    bool logSpacing = false; ///< geometric spacing (from and to must then be > 0)
    /// Refinement: an interval is bisected (at its arithmetic or, with logSpacing, geometric
    /// mean) while some pole moves more than this fraction of the extent of all base-sample
    /// poles across it, at most maxRefinements times deep.
    double maxStepFraction = 0.02;
    int maxRefinements = 6;
};

/// The base sample values of a sweep, from..to inclusive.
/// @throws InvalidInput "from"/"to" (finite; > 0 with logSpacing; from != to), "count" (>= 2,
///         <= 100000), "maxStepFraction" (in (0, 1]), "maxRefinements" (0..20).
std::vector<double> sweepValues(const ParameterSweep& sweep);

/// Where the swept loop crosses the stability boundary (a pole crosses Re s = 0).
struct StabilityChange {
    double value = 0.0;           ///< the parameter value, to a relative 1e-12 (bisection)
    std::complex<double> pole;    ///< the crossing pole at that value (upper half-plane)
    bool becomesUnstable = false; ///< stable below the value, unstable above it
};

/// Closed-loop poles traced as one parameter sweeps: branches[b][i] is a pole at values[i].
struct ParameterLocus {
    std::string parameterName;
    std::vector<double> values;
    std::vector<std::vector<std::complex<double>>> branches;
    std::vector<Diagnostic> warnings; ///< samples skipped because the pole count changed
    /// Every change of stability between consecutive samples (max Re of the poles changes
    /// sign), located by bisection on the parameter. A change between two samples that
    /// undoes itself (unstable and back within one interval) is not seen.
    std::vector<StabilityChange> stabilityChanges;
};

/**
 * A generic parameter locus: poles(value) at each sweep value, matched into continuous
 * branches by least total displacement (matchRoots), with adaptive refinement (see
 * ParameterSweep). A sample whose pole count differs from the first one's is skipped with a
 * warning.
 * @throws InvalidInput for the sweep (sweepValues) and whatever @p poles throws.
 */
ParameterLocus
parameterLocus(const std::string& parameterName, const ParameterSweep& sweep,
               const std::function<std::vector<std::complex<double>>(double)>& poles);

enum class GtSweptParameter {
    OmegaN, ///< "wn": omega_n sweeps, kp fixed
    Kp,     ///< "kp": kp sweeps, omega_n fixed
};

/**
 * The closed-loop poles of the Guillemin-Truxal design (designGuilleminTruxal), i.e. the roots
 * of s^4 + a1 s^3 + a2 s^2 + kp k0 s + wn^4 (Braga et al. Eq. 7 with Eq. 15-18), as omega_n
 * (rad/s) or kp sweeps with the other fixed at @p fixedValue.
 * @throws InvalidInput for the plant, "wn"/"kp" when a swept or fixed value is not > 0, and the
 *         sweep's fields.
 */
ParameterLocus gtParameterLocus(const ThirdOrderPlant& plant, GtSweptParameter parameter,
                                const ParameterSweep& sweep, double fixedValue);

} // namespace xyt
