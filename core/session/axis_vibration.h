// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// A shaper's residual vibration against the frequency of the mode, at the shaper's damping.
struct ShaperSensitivityCurve {
    std::vector<double> frequencyHz;
    std::vector<double> vibration; ///< fraction of the unshaped (0: cancelled, 1: as unshaped)
};

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
    std::vector<double> rigidDb, plantDb; ///< |G| and |G R| (dB; R the mode, 1 without one)
    std::vector<double> notchDb;          ///< |N| (dB), empty without a notch
    double modeHz = 0.0;                  ///< 0: no mode
    double notchHz = 0.0;                 ///< 0: no notch
    std::optional<InputShaper> shaper;
    ShaperSensitivityCurve sensitivity; ///< empty without a shaper
    double residualAtModePercent = 0.0; ///< 100 V at modeHz (or the shaper's frequency)
};

/// The curve of @p shaper on @p points frequencies from 0 to @p upToHz (> 0), by
/// residualVibration at the shaper's damping. @throws InvalidInput "points" below 2.
ShaperSensitivityCurve shaperSensitivityCurve(const InputShaper& shaper, double upToHz,
                                              int points = 400);

/// Never throws: an axis that cannot be analysed gives ok = false with the reason.
AxisVibration analyzeAxisVibration(const Session& session, int axisIndex);

} // namespace xyt
