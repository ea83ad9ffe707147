// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "core/study/design_sweep.h"

#include <cstddef>

namespace xyt {

/// How finely the design-space study of a session is computed.
struct StudyFidelity {
    /// At most this many samples per run: a longer run is sampled at duration / (maxSamples - 1)
    /// instead of the session's dt (0: always the session's dt).
    std::size_t maxSamples = 0;
    int stepSamples = 500; ///< DesignProblem::stepSamples
};

/**
 * The live map's preview: 1,500 samples per run and 100 per step-scan span. The loop
 * is discretized exactly at any step (FOH on a reference linear between its samples), so the
 * runs stay exact at their samples for the piecewise-linear reference through them; what a
 * coarse step loses is what happens between samples (a peak of |e|, the instant a mode
 * switches or the error enters the window), which the full study, run when the inputs rest,
 * restores. On the default session's 50 x 50 map (330 s at 0.22 s instead of 0.01 s) the
 * preview's ITAE is within 0.05 % of the full study's for half the designs and within 3 % for
 * 90 %; designs that saturate hard differ most (up to a factor 4: their mode switches fall on
 * the coarse samples). It costs about 75 us of CPU per design (xytune-bench
 * design_space_live_50x50_1thread), so 50 x 50 on two cores takes under 100 ms.
 */
inline constexpr StudyFidelity kLivePreviewFidelity{1500, 100};

/**
 * The design problem of axis @p axis of @p session, as the design-space view studies it: the
 * axis's plant and model unit, the session's trajectory for that axis sampled at its dt (or
 * coarser, see StudyFidelity), its specification with umax as the actuator limit. A cubic with
 * the automatic duration runs tf + 2 x the allowed settle time (moveSweepDurationSeconds) and
 * is judged on its move and settle. A PID + feedforward axis with D = 0 is studied as its PI
 * over the same (wn, kp) family (P = kp u, I = ki u, ki = wn^4/k0) with its feedforward fixed
 * (DesignProblem::feedforwardVolts, its output limit the actuator's).
 * @throws InvalidInput "axis" when out of range, "method" when the axis is neither
 *         Guillemin-Truxal nor PID + feedforward, "axes[i].parameters.d" for a PID with D,
 *         and from the trajectory and the specification.
 */
DesignProblem sessionDesignProblem(const Session& session, int axis,
                                   const StudyFidelity& fidelity = {});

} // namespace xyt
