// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/loop_responses.h"
#include "core/analysis/pole_zero_map.h"
#include "core/session/session_evaluation.h"

#include <optional>
#include <vector>

namespace xyt {

/**
 * The loop of an evaluated axis, whatever its design method (its DesignMethodModule says):
 * margins, frequency responses, the root locus and the views read the loop from here and never
 * ask which method made it.
 *
 * Guillemin-Truxal: gtLoopTransferFunctions (continuous, unity feedback). Pole placement:
 * rstLoopTransferFunctions (the loop broken at the plant input, L = B G/(A F), in z with the
 * design's Ts). Unset when the axis has no design (invalid settings).
 */
std::optional<LoopTransferFunctions> axisLoop(const AxisEvaluation& axis);

/**
 * The pole-zero sets of an evaluated axis with @p settings, in the order a map lists them.
 * Guillemin-Truxal: gtPoleZeroSets. Pole placement: "plant B/A", "feedback G/F", "closed loop
 * Kf B/T" and, when the feedforward runs, "ZPETC feedforward". Empty without a design.
 */
std::vector<PoleZeroSet> axisPoleZeroSets(const AxisEvaluation& axis, const AxisSettings& settings);

} // namespace xyt
