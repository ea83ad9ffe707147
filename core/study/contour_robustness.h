// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/contour_metrics.h"
#include "core/contour/path.h"
#include "core/model/diagnostic.h"
#include "core/simulation/cross_coupled_run.h"
#include "core/simulation/trajectory.h"
#include "core/study/robustness.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * The XY contour both axes trace together, and how it is judged (the contour error
 * of mismatched plants). Exactly one of:
 *  - circle: the radial deviation e = rho - R (positive outside), rho the traced distance from
 *    the centre, measured after the ramp-in (t >= rampInSeconds), as circleContourError;
 *  - path (a G-code program): the signed distance e from the path (positive LEFT of travel),
 *    measured on the segments options.measuredSegments marks, as contourError.
 * Both axes' outputs are read on the time base @p t (each axis' run linearly interpolated onto
 * it, core/simulation/resample.h; a run on the same grid is taken as it is).
 */
struct ContourGeometry {
    std::optional<Circle> circle;
    std::shared_ptr<const Path> path;
    ContourErrorOptions pathOptions;
    std::vector<double> t;
};

/// Koren's cross-coupled controller over both axes of a joint analysis: its gains and the
/// direction of travel and curvature of the path at each sample of the axes' runs.
struct ContourCoupling {
    CrossCoupling gains;
    CouplingDirections directions;
};

/// Both axes of a joint analysis: each with its nominal controller, its parameters and ranges.
struct ContourRobustnessProblem {
    RobustnessProblem x, y;
    ContourGeometry geometry;
    /// With a coupling, every pair runs cross-coupled (runCrossCoupled over
    /// steppedPerturbedRun), the same controller on each plant drawn; both axes must then run
    /// on one grid (one period, as many samples).
    std::optional<ContourCoupling> coupling;
};

/// One pair of plants (x's parameters then y's) and the contour the two traced.
struct JointPlantRun {
    std::vector<double> values;
    bool corner = false;
    bool stable = false; ///< both closed loops stable
    bool finite = false; ///< both runs finite
    /// mm, over the samples this pair's own trace is judged on (after the ramp-in; for a path,
    /// those nearest a measured segment, as contourError selects them)
    double maxAbsContourError = 0.0;
    double rmsContourError = 0.0; ///< mm, over the same samples
};

struct ContourRobustnessResult {
    RobustnessStatus status = RobustnessStatus::Completed;
    /// "x.k0", ..., "y.b3": x's parameters then y's, as JointPlantRun::values.
    std::vector<std::string> parameterNames;
    JointPlantRun nominal;
    std::vector<JointPlantRun> runs; ///< the random pairs, then the corners
    int computedCount = 0;
    Distribution maxAbsContourError, rmsContourError;
    /// The signed contour error e(t) over the stable, finite runs, at measured samples only.
    SignalEnvelope error;
    /// At the envelope's instants: the programmed point nearest the nominal traced point, and
    /// the unit vector along which e is measured there (outward radius; left normal of the
    /// path), so that base + m e normal draws an error e magnified m times about the contour.
    std::vector<Point2> base, normal;
    std::vector<std::size_t>
        unstable; ///< indices into runs: unstable or diverged, not in the statistics
    std::optional<std::size_t> worst; ///< the stable run of largest max |e|
    int threadsUsed = 0;
    std::vector<Diagnostic> warnings;
};

/**
 * Monte Carlo and corner analysis of the XY contour: options.samples random pairs of
 * plants drawn from the seed over the joint parameter list (x's then y's: drawPlants), and
 * (options.corners) the 2^p corners of the joint box, each axis simulated with its unchanged
 * controller (runPerturbedPlant) and the traced contour judged by the geometry; on all cores,
 * bit-identical for any thread count.
 * @throws InvalidInput "nominal" when the nominal pair's run diverges, "geometry" (neither or both
 * of circle and path, a time base that is empty or not increasing, no measured sample), "x."/"y." +
 * the axis' fields (validateRobustnessProblem), "samples", "envelope_points", "corners".
 */
ContourRobustnessResult analyzeContourRobustness(const ContourRobustnessProblem& problem,
                                                 const RobustnessOptions& options = {});

/// The max |contour error| of every stable, finite run, in run order.
std::vector<double> contourFigureValues(const ContourRobustnessResult& result);

} // namespace xyt
