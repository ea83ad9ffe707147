// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/coupled_line_loop.h"
#include "core/model/diagnostic.h"

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

struct Session;

/// One straight stretch of a path the coupled loop runs along: its direction and where it is.
struct CoupledLine {
    double thetaRad = 0.0;
    Diagnostic where; ///< "program line 12", "the move"
};

/**
 * The cross-coupled loop's stability along a path, as a run checks it before it is simulated.
 *
 * On a straight line the coupled loop is linear and time-invariant (coupledLineLoop): each
 * line's direction is checked (directions equal modulo pi to 1e-9 rad once), and a line whose
 * loop is not bounded refuses the run, naming the line. On arcs the direction turns, and the
 * loop is time-varying: no check of the frozen loop is sufficient there. What is stated is the
 * frozen loop at 180 directions 1 degree apart (necessary for a slowly turning path, not
 * sufficient): a warning when any is unbounded.
 */
struct CouplingStability {
    double periodSeconds = 0.0;
    /// The checked direction of the largest spectral radius (the lines', else the frozen
    /// directions') with its loop and margins (coupledLineLoop with margins).
    double worstThetaRad = 0.0;
    CoupledLineLoop worst;
    std::size_t linesChecked = 0; ///< distinct line directions
    /// The frozen directions checked (0 without arcs) and how many of them are not bounded.
    std::size_t frozenDirections = 0;
    std::size_t unboundedFrozenDirections = 0;
    /// The arcs' warning ("" when none).
    Diagnostic warning;
};

/**
 * Checks @p session's cross-coupling along @p lines (and, when @p hasArcs, the frozen
 * directions), the axes' loops at period @p periodSeconds (a continuous axis runs at it; a
 * pole-placement axis at its Ts).
 * @throws InvalidInput "cross_coupling" when the axes run at different periods, or a line's loop
 *         is not bounded ("the coupled loop is unstable on program line 12 (direction 30 deg):
 *         spectral radius 1.02 ..."); the methods' refusals of their settings.
 */
CouplingStability checkCouplingStability(const Session& session, double periodSeconds,
                                         const std::vector<CoupledLine>& lines, bool hasArcs);

} // namespace xyt
