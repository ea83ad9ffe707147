// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/shaper_recommendation.h"
#include "core/identification/accelerometer_log.h"
#include "core/model/flexible_mode.h"

#include <string>

namespace xyt {

/**
 * The spectrum Klipper's recommendation reads from an accelerometer log's spectra: the axis'
 * PSD @p axis ("x", "y", "z" or "sum", the sum calibrate_shaper.py fits by default), normalized
 * as Klipper normalizes it (klipperNormalizeToFrequencies).
 * @throws InvalidInput "axis" for another name.
 */
PowerSpectrum accelerometerShaperSpectrum(const AccelerometerSpectra& spectra,
                                          const std::string& axis);

/**
 * The spectrum of a modelled mode: |R(j 2 pi f)|^2 of FlexibleMode::transferFunction on
 * 0, step, 2 step .. maxHz, the power a unit-spectrum excitation leaves at each frequency.
 * @throws InvalidInput as validateFlexibleMode, "frequency" without a mode, "step" or "max"
 *         unless > 0.
 */
PowerSpectrum flexibleModeSpectrum(const FlexibleMode& mode, double maxHz = 200.0,
                                   double stepHz = 0.2);

} // namespace xyt
