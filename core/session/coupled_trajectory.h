// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/coupling_stability.h"
#include "core/simulation/cross_coupled_run.h"
#include "core/simulation/simulation.h"

#include <array>
#include <string>
#include <vector>

namespace xyt {

struct Session;

/// How far a traced contour strays from the commanded one (mm).
struct ContourDeviation {
    double maxAbs = 0.0;
    double rms = 0.0;
    std::size_t samples = 0;
};

/**
 * A session trajectory that moves both axes (the point-to-point move, whose two axes travel the
 * diagonal together, or the circle) run by both axes with the session's cross-coupling, beside
 * the same run with the axes independent: what the XY contour view compares. Both runs start
 * at rest at the reference's first sample (as a program's contour run).
 *
 * The direction of travel and the curvature the coupling needs come from the reference by
 * central differences (theta = atan2(ry', rx'), kappa = (rx' ry'' - ry' rx'') / |r'|^3); where
 * the reference stands still the last direction of travel is kept (before it first moves, the
 * first one), and the curvature is 0.
 *
 * The contour error: for the circle the radial deviation after the ramp-in (circleContourError);
 * for the move the distance from the straight line between the reference's first and last
 * points.
 */
struct CoupledTrajectoryRun {
    std::vector<double> t; ///< the axes' common sample times
    std::vector<double> referenceX, referenceY;
    std::array<SimulationResult, 2> coupled; ///< each axis' run, coupled
    std::array<SimulationResult, 2> independent;
    CouplingSignals coupling; ///< what the coupling did
    /// The coupled loop on the move's line, or frozen along the circle (its warning then).
    CouplingStability stability;
    ContourDeviation coupledError, independentError;
};

/// The independent half of CoupledTrajectoryRun: each axis' own run along its reference and
/// their contour error, what the trajectory gives with the coupling off.
struct IndependentTrajectoryRun {
    std::array<SimulationResult, 2> axes;
    ContourDeviation error;
};

/**
 * The axes of @p session run independently on the references of @p x and @p y as
 * runCoupledTrajectory runs them beside the coupled run (the same runs, bit for bit), whatever
 * the coupling's gains.
 * @throws InvalidInput "cross_coupling" when the axes run at different periods; as the methods'
 *         runs for their settings.
 */
IndependentTrajectoryRun runIndependentTrajectory(const Session& session, const SimulationResult& x,
                                                  const SimulationResult& y);

/**
 * The direction of travel and curvature of a two-axis reference (@p x, @p y at the same
 * samples) by central differences, the samples where it stands still given the nearest
 * direction of travel (see CoupledTrajectoryRun).
 */
CouplingDirections referenceCouplingDirections(const std::vector<double>& x,
                                               const std::vector<double>& y);

/**
 * Runs @p session's trajectory as CoupledTrajectoryRun says, on the references @p x and @p y of
 * its axes' evaluated runs (their t and r).
 * @throws InvalidInput "cross_coupling" when the axes run at different periods, the coupling is
 *         off or its loop is unstable on the move's line (checkCouplingStability), as the
 *         methods' runs for their settings.
 */
CoupledTrajectoryRun runCoupledTrajectory(const Session& session, const SimulationResult& x,
                                          const SimulationResult& y);

} // namespace xyt
