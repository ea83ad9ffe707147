// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/input_shaper.h"

#include <vector>

namespace xyt {

/**
 * The shaper's sensitivity curve: the residual vibration V(f) of a mode of frequency f and the
 * shaper's own damping ratio (residualVibration's formula, Singer and Seering), on the uniform
 * grid f_k = k fmax / (points - 1), k = 0 .. points - 1, fmax = maxFrequencyRatio times the
 * design frequency (0 to 2.5 f_design by default: ZV's and ZVD's first zero, EI's hump and both
 * of its zeros and the multi-hump shapers' bands all fall inside). At f = 0 the formula gives
 * sum A_i = 1 (a static move is neither cancelled nor amplified).
 */
struct ShaperSensitivity {
    double dampingRatio = 0.0;
    std::vector<double> frequencyHz;
    std::vector<double> vibration; ///< fraction of the unshaped command's residual vibration
};

/// @throws InvalidInput "points" unless >= 2, "maxFrequencyRatio" unless finite and > 0.
ShaperSensitivity shaperSensitivity(const InputShaper& shaper, int points = 251,
                                    double maxFrequencyRatio = 2.5);

/**
 * The shaper's delay: the centroid of its impulses, sum A_i t_i (s; amplitudes summing to 1).
 * A shaped ramp r(t) = v t equals, once the shaper's duration has passed, the ramp delayed by
 * exactly this time (sum A_i v (t - t_i) = v (t - sum A_i t_i)), so this is the lag a constant-
 * velocity move sees; Klipper's shaper_calibrate.py calls it the shaper's shift (ts in
 * _get_shaper_smoothing). The shaper's duration (InputShaper::duration(), the last impulse
 * time) is different: it is how much longer the shaped move lasts, not its lag.
 */
double shaperDelaySeconds(const InputShaper& shaper);

} // namespace xyt
