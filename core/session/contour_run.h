// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/model/diagnostic.h"
#include "core/session/coupling_stability.h"
#include "core/session/session.h"
#include "core/simulation/cross_coupled_run.h"
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
    /// With cross-coupling on (Session::crossCoupling): run the program once more with the axes
    /// independent, for the comparison (ContourRun::independent).
    bool compareIndependentAxes = true;
};

/// Both axes traced along one direction of a program.
struct ContourTrace {
    FeedProfile profile;
    /// Each axis' own run: continuous axes at the profile's dt with saturation, discrete axes
    /// (pole placement) at their Ts, linear, with `clipped` marking |u| > umax.
    std::array<SimulationResult, 2> axes;
    /// The traced point on the profile's time grid (discrete axes interpolated linearly).
    std::vector<double> x, y;
    /// With cross-coupling (Session::crossCoupling on): what the coupling did at each sample of
    /// the axes' runs.
    std::optional<CouplingSignals> coupling;
};

/**
 * The circular test of ISO 230-4 on a program's circles.
 *  - A program that is one full circle is run as a ballbar test is: the circle alone (the
 *    program's approach left out), from rest at its start point at its programmed feed, once in
 *    the program's direction and once the other way (for the hysteresis).
 *  - A ballbar program as machine shops write it (full circles among feed-in and feed-out moves,
 *    each written as one arc or as consecutive arcs such as semicircles or quadrants,
 *    findBallbarCircles): the runs are the program's own, its first full circle and the first
 *    one on the same circle the other way, measured on the program's trace where the reference
 *    lies on their segments (the feed-in moves bring the axes onto the circle as on the
 *    machine). With one direction only, G and F without H (ContourRun::warnings says why).
 */
struct ContourCircularTest {
    NominalCircle nominal;
    bool clockwise = true; ///< the direction of the first run
    Iso230Circular iso;    ///< of the first run; H and G(b) with the reverse run
    /// G and F of the reverse run alone (about its own least-squares circle and the nominal).
    std::optional<Iso230Circular> reverseIso;
    /// The runs are the program's own circles (not the circle re-run alone).
    bool fromProgram = false;
    /// The program line of the first run's circle (of its first arc when written as several).
    std::size_t line = 0;
    std::size_t reverseLine = 0; ///< of the reverse run's (0: re-run alone, or none)
    ContourTrace forward;        ///< the circle in the program's direction (re-run alone only)
    ContourTrace reverse;        ///< the same circle run the other way (re-run alone only)
    /// The traced points of each run (x, y forward; reverseX, reverseY reverse).
    std::vector<double> x, y, reverseX, reverseY;
    /// When an axis compensates its table's friction (AxisSettings::frictionCompensation): the
    /// first run again without the compensation, its points and its figures (re-run alone
    /// only), for the compensated/uncompensated comparison.
    std::optional<Iso230Circular> uncompensatedIso;
    std::vector<double> uncompensatedX, uncompensatedY;
};

/// The program run with the axes independent (no cross-coupling), beside a coupled run.
struct IndependentAxesRun {
    ContourTrace trace;
    ContourErrorResult contour; ///< of trace
    /// The first run of the circular test (ContourCircularTest: its circle, its direction) with
    /// independent axes: its points and figures, when the coupled run has the test.
    std::vector<double> circleX, circleY;
    std::optional<Iso230Circular> iso;
};

/// A G-code program run by the session's two axes.
struct ContourRun {
    ContourTrace trace;
    ContourErrorResult contour; ///< of trace (G0 rapids left out of the statistics)
    /// When the program holds a full circle (see ContourCircularTest).
    std::optional<ContourCircularTest> circular;
    /// The program's warnings, then each axis' ("x axis: |u| reached the 2.5 V limit ...").
    std::vector<Diagnostic> warnings;
    /// With cross-coupling on and ContourRunOptions::compareIndependentAxes: the same program
    /// with independent axes.
    std::optional<IndependentAxesRun> independent;
    /// Beside it, when an axis has a command feedforward (ZPETC, a PID's FF0..FF3): the
    /// independent axes without it, the feedback alone (DesignMethodModule::withoutFeedforward).
    std::optional<IndependentAxesRun> feedbackOnly;
    /// With cross-coupling on: the coupled loop's stability on the program's lines and arcs
    /// (a line where it is unstable refuses the run instead).
    std::optional<CouplingStability> couplingStability;
};

/**
 * The direction of travel and signed curvature of @p path at the times k @p periodSeconds
 * (k < @p n) of a run along @p profile (its samples when the period is its dt, else its arc
 * length interpolated), and with @p rapid (one flag per segment, or null) whether the coupling
 * acts there: what the cross-coupled controller is given each period.
 */
CouplingDirections pathCouplingDirections(const Path& path, const FeedProfile& profile,
                                          double periodSeconds, std::size_t n,
                                          const std::vector<bool>* rapid);

/// Whether each segment of @p program is a rapid move (G0): no contouring there.
std::vector<bool> programRapidSegments(const GcodeProgram& program);

/// How a program's contour error is measured: the corners of @p options' profile and window,
/// rapids (G0) left out of the statistics.
ContourErrorOptions programContourErrorOptions(const GcodeProgram& program,
                                               const ContourRunOptions& options);

/**
 * Runs @p program with the session's axes (x = axes[0] follows x(t), y = axes[1] follows y(t)),
 * each with its own method and controller, under the session's actuator limit. The profile is
 * planned once; each axis starts at rest at the program's start point. When the program is a
 * single full circle, that circle is also run alone both ways for the ISO 230-4 figures; when it
 * holds full circles among other moves, the figures are of its own runs (ContourCircularTest).
 * @throws InvalidInput naming the session field of a design that cannot be built
 *         ("axes[1].gt.wn", "axes[0].pp.b", "umax") or the option ("dt", "max_accel", ...).
 * @p plannedProfile: the program's profile when the caller has planned it already with
 * options.profile (the session's shared one, runSessionProgram), so it is not planned again.
 */
ContourRun runProgramContour(const Session& session, const GcodeProgram& program,
                             const ContourRunOptions& options = {},
                             const FeedProfile* plannedProfile = nullptr);

/**
 * The circular test of a program holding full circles among other moves, on its traced run
 * @p trace (findBallbarCircles; see ContourCircularTest): unset when it holds no full circle,
 * or when a circle lasts fewer than 3 samples (said in @p warnings, as is
 * BallbarCircles::note, each prefixed "ISO 230-4: ").
 * @throws InvalidInput as iso230Circular.
 */
std::optional<ContourCircularTest> ballbarTestOfProgram(const GcodeProgram& program,
                                                        const ContourTrace& trace,
                                                        const Iso230Options& iso,
                                                        std::vector<Diagnostic>& warnings);

} // namespace xyt
