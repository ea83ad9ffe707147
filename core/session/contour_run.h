// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/session/session.h"
#include "core/simulation/simulation.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

struct ContourRunOptions {
    /// The profile (feed scale, acceleration, jerk, corner angle) and its step dt, which is
    /// also the simulation step of continuous (Guillemin-Truxal) axes. maxSamples is lowered
    /// to the machine's sampleLimit().
    FeedProfileOptions profile;
    /// Sharp corners and their window for the corner overshoot (cornerAngleDeg is the
    /// profile's).
    double cornerWindowMm = 1.0;
    Iso230Options iso;
};

/// Both axes traced along one direction of a program.
struct ContourTrace {
    FeedProfile profile;
    /// Each axis' own run: continuous axes at the profile's dt with saturation, discrete axes
    /// (pole placement) at their Ts, linear, with `clipped` marking |u| > umax.
    std::array<SimulationResult, 2> axes;
    /// The traced point on the profile's time grid (discrete axes interpolated linearly).
    std::vector<double> x, y;
};

/**
 * The circular test of a program that is one full circle, run as a ballbar test is: the circle
 * alone (the program's approach left out), from rest at its start point at its programmed
 * feed, once in the program's direction and once the other way (for the hysteresis).
 */
struct ContourCircularTest {
    NominalCircle nominal;
    bool clockwise = true; ///< the program's direction
    Iso230Circular iso;    ///< of the forward run; H and G(b) with the reverse run
    ContourTrace forward;  ///< the circle in the program's direction
    ContourTrace reverse;  ///< the same circle run the other way
    /// The traced points of each run (x, y forward; reverseX, reverseY reverse).
    std::vector<double> x, y, reverseX, reverseY;
};

/// A G-code program run by the session's two axes.
struct ContourRun {
    ContourTrace trace;
    ContourErrorResult contour; ///< of trace (G0 rapids left out of the statistics)
    std::optional<ContourCircularTest> circular; ///< when program.isSingleFullCircle()
    /// The program's warnings, then each axis' ("x axis: |u| reached the 2.5 V limit ...").
    std::vector<std::string> warnings;
};

/**
 * Runs @p program with the session's axes (x = axes[0] follows x(t), y = axes[1] follows y(t)),
 * each with its own method and controller, under the session's actuator limit. The profile is
 * planned once; each axis starts at rest at the program's start point. When the program is a
 * single full circle, that circle is also run alone both ways for the ISO 230-4 figures
 * (ContourCircularTest).
 * @throws InvalidInput naming the session field of a design that cannot be built
 *         ("axes[1].gt.wn", "axes[0].pp.b", "umax") or the option ("dt", "max_accel", ...).
 */
ContourRun runProgramContour(const Session& session, const GcodeProgram& program,
                             const ContourRunOptions& options = {});

} // namespace xyt
