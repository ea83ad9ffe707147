// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

namespace xyt {

/**
 * The deflection q of a mode of @p frequencyHz and @p dampingRatio between the table and the
 * tool point while the table follows the commanded acceleration @p acceleration (mm/s^2, one
 * sample every @p dtSeconds): q'' + 2 zeta w q' + w^2 q = -a(t), the model input shapers are
 * designed for (Singer and Seering). Integrated exactly for an acceleration linear between the
 * samples (a first-order hold, discretizeFoh), from rest.
 * @returns q at the samples (mm).
 * @throws InvalidInput "frequency" unless > 0, "damping" unless in [0, 1), "dt" unless > 0.
 */
std::vector<double> modeDeflection(const std::vector<double>& acceleration, double dtSeconds,
                                   double frequencyHz, double dampingRatio);

/**
 * The amplitude of the free oscillation the mode carries at each sample:
 * sqrt(q^2 + ((q' + zeta w q) / wd)^2), wd = w sqrt(1 - zeta^2), with q and q' from the same
 * exact steps as modeDeflection (what would ring on if the acceleration stopped there).
 */
std::vector<double> modeAmplitudes(const std::vector<double>& acceleration, double dtSeconds,
                                   double frequencyHz, double dampingRatio);

} // namespace xyt
