// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/simulation.h"

#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace xyt {

/// The lane counts trackBatch is compiled for.
inline constexpr int kTrackingBatchWidths[] = {1, 2, 4, 8};

/// What every loop of a batch shares: the sampled reference, the step and the actuator limit.
struct TrackingRun {
    const std::vector<double>* reference = nullptr; ///< r(k dt) in trajectory units, not empty
    double dtSeconds = 0.01;
    double umaxVolts = std::numeric_limits<double>::infinity(); ///< infinity: no limit
    double modelUnitsPerPositionUnit = 1.0;
    /// A command feedforward added to every loop's controller output (V at the reference's
    /// samples, linear between them), as LoopSimulationOptions::feedforwardVolts; null: none.
    const std::vector<double>* feedforwardVolts = nullptr;
};

/**
 * The tracking figures of several loops of a third-order plant under a PI controller (4
 * states, as every Guillemin-Truxal design), each on the same reference, without storing their
 * signals: the design sweep's kernel.
 *
 * The loops are stepped @p width at a time in structure-of-arrays form (one lane per loop: every
 * coefficient and state is an array over the lanes), so that the compiler vectorizes each
 * operation across designs. Each lane chooses its own mode every step (linear, or clipped at
 * +-umax) from its own command v, exactly as simulateLoop does; the clipped-mode step (a second
 * matrix exponential) of a lane is computed when that lane first clips. Per lane the arithmetic
 * is that of simulateLoop (the same exact FOH matrices, the same summation order, no fused
 * multiply-add: the build sets -ffp-contract=off) followed by trackingMetrics, so each lane's
 * figures equal trackingMetrics(simulateLoop(...)) bit for bit, whatever the width and whatever
 * the other lanes of its batch do.
 *
 * results[i] is nullopt when loop i diverged: some sample of y, e or u was not finite (where
 * trackingMetrics says `diverged`), or its figures overflowed. moves[i], when given and not
 * null, receives add(t, y, e) for every sample until the loop diverges (then nothing more).
 *
 * @param width 1, 2, 4 or 8 (kTrackingBatchWidths); any number of loops is processed, in
 *        groups of width.
 * @throws InvalidInput "batch_width" for another width, "lanes" when results (or a non-empty
 *         moves) differ in size from lanes, "reference" when empty; "dt" when a step's exact
 *         discretization fails (as simulateLoop); std::logic_error when a loop is not 3 + 1 states.
 */
void trackBatch(std::span<const LoopModes> lanes, const TrackingRun& run,
                std::span<MoveSettleAccumulator* const> moves,
                std::span<std::optional<TrackingMetrics>> results, int width);

} // namespace xyt
