// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/loop_responses.h"
#include "core/analysis/nyquist.h"
#include "core/analysis/stability_margins.h"
#include "core/model/diagnostic.h"
#include "core/session/session_evaluation.h"

#include <optional>
#include <string>

namespace xyt {

/**
 * The frequency-domain view of one evaluated axis: the loop's transfer functions,
 * their responses on one adaptive grid that holds every crossover, the exact stability margins
 * and the Nyquist curve; for a pole-placement axis with ZPETC also the tracking response with
 * and without the feedforward, on the same grid.
 */
struct AxisFrequencyAnalysis {
    bool ok = false;
    Diagnostic error; ///< when !ok: why there is no analysis (e.g. the axis has no design)
    LoopTransferFunctions loop;
    LoopFrequencyResponses responses; ///< L, S, T and u/r on `responses.openLoop.omegaRadPerSec`
    StabilityMargins margins;
    NyquistCurve nyquist;
    /// r -> y without and with the method's feedforward (DesignMethodModule::trackingResponses):
    /// pole placement + ZPETC, PID + feedforward.
    std::optional<TrackingFrequencyResponses> tracking;
    std::string feedforwardName; ///< what the views call that feedforward ("ZPETC")
    /// A Guillemin-Truxal axis with a notch: the open loop without it (the PI alone on the same
    /// plant) on the same grid, and its margins: what the notch changes.
    std::optional<FrequencyResponse> openLoopWithoutNotch;
    std::optional<StabilityMargins> marginsWithoutNotch;
    /// The reference frequency of the session's trajectory (the circle's omega), NaN for a
    /// point-to-point move.
    double referenceOmegaRadPerSec = 0.0;
};

/**
 * Analyses axis @p axis of @p session, whose evaluation is @p evaluation. Never throws: an
 * axis without a design, or a loop the analysis refuses, gives ok = false with the reason.
 */
AxisFrequencyAnalysis analyzeAxisFrequency(const Session& session,
                                           const AxisEvaluation& evaluation);

} // namespace xyt
