// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/shaper_sensitivity.h"
#include "core/identification/spectral_estimate.h"
#include "core/session/session.h"

#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * What the Vibration view draws for one axis: the magnitude of the rigid plant and of the plant
 * with its flexible mode, of the notch, and of the loop L with and without the notch, on one
 * grid in Hz that holds the mode; and, with an input shaper on the reference, its sensitivity
 * curve and its residual vibration at the axis' mode (the shaper's own frequency when the axis
 * has none).
 */
struct AxisVibration {
    bool ok = false;
    std::string error; ///< when !ok: why (a pole-placement axis, a refused field)
    std::vector<double> frequencyHz;
    /// |G| and |G R| in dB re 1 mm/V (the model's units per mm taken out, so a measured
    /// response in mm/V lies on them; R the mode, 1 without one)
    std::vector<double> rigidDb, plantDb;
    std::vector<double> notchDb; ///< |N| (dB), empty without a notch
    double modeHz = 0.0;         ///< 0: no mode
    double notchHz = 0.0;        ///< 0: no notch
    std::optional<InputShaper> shaper;
    ShaperSensitivity sensitivity;      ///< empty without a shaper
    double residualAtModePercent = 0.0; ///< 100 V at modeHz (or the shaper's frequency)
};

/**
 * The mode a measured frequency response shows above the axis' rigid plant: the half-power
 * pick (pickResonance) of |H| / |G_rigid| (G in mm/V) over the bins whose coherence is at least
 * @p minCoherence, where the rigid part divides out and the mode's peak remains. Empty when
 * fewer than three bins qualify or the pick is refused.
 */
std::optional<ResonancePick> measuredModePick(const FrequencyResponseEstimate& measured,
                                              const GtAxisSettings& gt, double minCoherence = 0.5);

/// Never throws: an axis that cannot be analysed gives ok = false with the reason.
AxisVibration analyzeAxisVibration(const Session& session, int axisIndex);

} // namespace xyt
