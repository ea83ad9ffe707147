// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/frequency_response.h"
#include "core/design/shaper_sensitivity.h"
#include "core/identification/spectral_estimate.h"
#include "core/model/diagnostic.h"
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
    Diagnostic error; ///< when !ok: why (a pole-placement axis, a refused field)
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

/// The loop with the measured plant, as the Bode view draws it against the model's.
struct MeasuredOpenLoop {
    std::vector<double> omegaRadPerSec, magnitudeDb, phaseDeg;
};

/**
 * L = C H at the measured response's bins whose coherence is at least @p minCoherence: the
 * axis' @p controller (as the loop runs it, with its notch; V per model unit) times the
 * measured plant H (mm/V) in model units (H @p modelUnitsPerMm). The phase (H's, unwrapped,
 * plus C's) is moved by whole turns to lie within half a turn of @p model's phase at the first
 * bin, so both are drawn on one branch.
 * @throws InvalidInput "controller" unless continuous, "model_unit_scale" unless > 0.
 */
MeasuredOpenLoop measuredOpenLoop(const FrequencyResponseEstimate& measured,
                                  const TransferFunction& controller, double modelUnitsPerMm,
                                  const FrequencyResponse& model, double minCoherence = 0.5);

/// Never throws: an axis that cannot be analysed gives ok = false with the reason.
AxisVibration analyzeAxisVibration(const Session& session, int axisIndex);

} // namespace xyt
