// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/simulation/metrics.h"

namespace xyt {

/**
 * Step figures of the system a pole-placement axis with ZPETC runs (Patrick, Ishak and Adnan Fig. 6
 * ahead of Fig. 9): a unit step of the desired output at sample K, read p samples ahead by the
 * ZPETC, through the feedback loop (simulateZpetcLoop, structure (2)). The feedback loop's own step
 * (Kf B / T alone) overshoots through the non-minimum-phase zero; with the feedforward the
 * axis follows B-(z) B-(z^-1) / [B-(1)]^2, a zero-phase FIR whose step rises before K and
 * settles deg B- samples after it.
 *
 * settlingTimeSeconds and peakTimeSeconds count from the step instant K Ts (the response may
 * move before it: the preview acts ahead); overshootPct = (max y - final) / |final| * 100,
 * at least 0; finalValue = the response at the end of the run (1 up to round-off). Unstable T:
 * stable = false and nothing else is set.
 * @throws InvalidInput "band" unless 0 < band < 1.
 */
StepCharacteristics zpetcStepCharacteristics(const PolePlacementDesign& loop,
                                             const ZpetcDesign& zpetc, double band = 0.02);

/**
 * Step figures of the pole-placement loop Kf B / T alone (no feedforward) from its exact sampled
 * step response over 12 time constants of its slowest pole (50 to 1e6 samples); it settles at
 * the first sample inside the 2 % band for good. Unstable: stable = false and nothing else set.
 */
StepCharacteristics loopStepCharacteristics(const PolePlacementDesign& loop);

} // namespace xyt
