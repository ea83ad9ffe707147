// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/cross_coupling.h"
#include "core/simulation/loop_stepper.h"

#include <vector>

namespace xyt {

/// The path's direction of travel theta (rad, from +x) and signed curvature (1/mm, +1/R
/// counter-clockwise) at each sample of a coupled run.
struct CouplingDirections {
    std::vector<double> thetaRad, curvaturePerMm;
    /// Whether the coupling acts at each sample (empty: everywhere). A program's rapid moves
    /// (G0) are positioning, not contouring: there the coupling gives no voltage and its
    /// integral restarts.
    std::vector<bool> active;
};

/// What the coupling did at each sample of a coupled run.
struct CouplingSignals {
    std::vector<double> estimate;   ///< eps (mm), CrossCoupling's sign
    std::vector<double> correction; ///< u_c (V) before it is shared by the coupling gains
};

/**
 * Runs @p x and @p y in lockstep with @p coupling between them (CrossCoupling's law, in its
 * order): at each sample the axis errors e = r - y of both loops, the estimate of
 * coupling.estimate along @p directions, the PI and the voltages Cx u_c and Cy u_c added to the
 * axes' commands before their limits. Both loops end fully run (index() == samples()).
 * @throws InvalidInput "cross_coupling" when the loops' periods differ (relative 1e-9), their
 *         sample counts differ, or @p directions does not hold one entry per sample; as
 *         validateCrossCoupling ("cross_coupling.kp").
 */
CouplingSignals runCrossCoupled(SteppedLoop& x, SteppedLoop& y,
                                const CouplingDirections& directions,
                                const CrossCoupling& coupling);

} // namespace xyt
