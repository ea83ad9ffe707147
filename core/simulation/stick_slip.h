// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/simulation/simulation.h"

#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * What a run with dry friction (SimulationResult::sliding) shows:
 *  - stick-slip during the move: the table stopped while the reference kept moving the same way
 *    (a stuck interval that begins and ends with the reference moving and no reversal of the
 *    reference velocity inside it; the stops at a reversal are the reversal spikes' business);
 *  - hunting at rest: once the reference has stopped, the integral action winds up against
 *    stiction and breaks the table free again and again (two or more breakaways in the rest).
 */
struct StickSlipFindings {
    int stopsDuringMove = 0;
    double firstStopSeconds = 0.0; ///< of the first stop during the move
    int breakawaysAtRest = 0;
    double restPeakToPeakMm = 0.0; ///< of the position over the rest, after its first sample
};

/// @return none for a run without dry friction (sliding empty).
std::optional<StickSlipFindings> stickSlipFindings(const SimulationResult& run);

/// Which run the findings are of: the continuous run's are said as they are, the digital
/// implementation's are prefixed "the digital implementation: ".
enum class StickSlipRun { continuous, digitalImplementation };

/// The coded warnings of @p findings (none when there is nothing to say), of the run @p run.
std::vector<Diagnostic> stickSlipWarnings(const StickSlipFindings& findings,
                                          StickSlipRun run = StickSlipRun::continuous);

} // namespace xyt
