// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/contour_run.h"

#include "core/model/diagnostic_catalogue.h"

#include "core/contour/ballbar_circles.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/coupling_stability.h"
#include "core/session/design_method_module.h"
#include "core/session/session_evaluation.h"
#include "core/session/shaped_program.h"
#include "core/simulation/cross_coupled_run.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/metrics.h"
#include "core/simulation/resample.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace xyt {

namespace {

/// Both axes of @p session along @p p's path in lockstep with the session's cross-coupling, off
/// on the segments @p rapid marks (null: none).
void coupledTrace(const Session& session, const Path& path, const std::vector<bool>* rapid,
                  ContourTrace& out) {
    const FeedProfile& p = out.profile;
    std::array<std::unique_ptr<SteppedLoop>, 2> loops;
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
        loops[static_cast<std::size_t>(i)] =
            designMethodModule(axis.method)
                .steppedPath(session, i, p.t, i == 0 ? p.x : p.y, p.dtSeconds);
    }
    if (std::abs(loops[0]->periodSeconds() - loops[1]->periodSeconds()) >
        1e-9 * loops[0]->periodSeconds())
        throw InvalidInput("cross_coupling",
                           makeDiagnostic("session_coupling_one_period_why",
                                          {formatNumber(loops[0]->periodSeconds()),
                                           formatNumber(loops[1]->periodSeconds())}));
    const CouplingDirections directions =
        pathCouplingDirections(path, p, loops[0]->periodSeconds(), loops[0]->samples(), rapid);
    out.coupling = runCrossCoupled(*loops[0], *loops[1], directions, session.crossCoupling);
    for (std::size_t i = 0; i < 2; ++i) {
        SimulationResult& run = out.axes[i] = loops[i]->takeResult();
        std::vector<double>& onPath = i == 0 ? out.x : out.y;
        onPath = run.t.size() == p.t.size() ? run.y : resampleLinear(run.t, run.y, p.t);
    }
}

/// Runs both axes of @p session along @p path at @p feeds: independently, or in lockstep with
/// the session's cross-coupling when it is on (@p coupled), off on the @p rapid segments.
ContourTrace trace(const Session& session, const Path& path, const std::vector<double>& feeds,
                   const ContourRunOptions& options, const FeedProfile* planned = nullptr,
                   bool coupled = true, const std::vector<bool>* rapid = nullptr) {
    requirePositive(session.umaxVolts, "umax");
    FeedProfileOptions profileOptions = options.profile;
    profileOptions.maxSamples = std::min(profileOptions.maxSamples, sampleLimit());
    ContourTrace out;
    out.profile = planned ? *planned : planFeedProfile(path, feeds, profileOptions);
    const FeedProfile& p = out.profile;
    if (coupled && session.crossCoupling.active()) {
        coupledTrace(session, path, rapid, out);
        return out;
    }
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
        const std::vector<double>& reference = i == 0 ? p.x : p.y;
        SimulationResult& run = out.axes[static_cast<std::size_t>(i)];
        AxisTrace traced =
            designMethodModule(axis.method).tracePath(session, i, p.t, reference, p.dtSeconds);
        run = std::move(traced.run);
        (i == 0 ? out.x : out.y) = std::move(traced.outputOnPath);
    }
    return out;
}

/// The traced points, in time order, of the samples whose reference lies on @p circle's segments.
void pointsOnSegments(const ContourTrace& t, const CircleSegments& circle, std::vector<double>& x,
                      std::vector<double>& y) {
    x.clear(), y.clear();
    for (std::size_t k = 0; k < t.profile.segment.size(); ++k)
        if (circle.contains(t.profile.segment[k])) {
            x.push_back(t.x[k]);
            y.push_back(t.y[k]);
        }
}

void addAxisWarnings(const ContourTrace& t, std::vector<Diagnostic>& warnings) {
    for (int i = 0; i < 2; ++i) {
        const SimulationResult& run = t.axes[static_cast<std::size_t>(i)];
        const TrackingMetrics m = trackingMetrics(run);
        const std::string axis = i == 0 ? "x" : "y";
        if (m.diverged)
            warnings.push_back(makeDiagnostic("contour_axis_diverged", {axis}));
        else if (m.saturated)
            warnings.push_back(
                makeDiagnostic("contour_axis_saturated", {axis, formatNumber(run.umaxVolts),
                                                          formatNumber(m.saturatedTimeSeconds)}));
    }
}

} // namespace

CouplingDirections pathCouplingDirections(const Path& path, const FeedProfile& profile,
                                          double period, std::size_t n,
                                          const std::vector<bool>* rapid) {
    CouplingDirections out;
    out.thetaRad.resize(n);
    out.curvaturePerMm.resize(n);
    if (rapid)
        out.active.resize(n);
    const bool sameGrid =
        n <= profile.t.size() && std::abs(period - profile.dtSeconds) <= 1e-9 * profile.dtSeconds;
    std::vector<double> s;
    if (!sameGrid) {
        std::vector<double> times(n);
        for (std::size_t k = 0; k < n; ++k)
            times[k] = static_cast<double>(k) * period;
        s = resampleLinear(profile.t, profile.s, times);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const PathPoint at = sameGrid ? path.at(profile.s[k], profile.segment[k]) : path.at(s[k]);
        out.thetaRad[k] = std::atan2(at.tangent.y, at.tangent.x);
        out.curvaturePerMm[k] = path.segments()[at.segment].curvature();
        if (rapid)
            out.active[k] = !(*rapid)[at.segment];
    }
    return out;
}

std::vector<bool> programRapidSegments(const GcodeProgram& program) {
    std::vector<bool> rapid(program.segments.size());
    for (std::size_t i = 0; i < program.segments.size(); ++i)
        rapid[i] = program.segments[i].rapid;
    return rapid;
}

ContourErrorOptions programContourErrorOptions(const GcodeProgram& program,
                                               const ContourRunOptions& options) {
    ContourErrorOptions out;
    out.cornerAngleDeg = options.profile.cornerAngleDeg;
    out.cornerWindowMm = options.cornerWindowMm;
    out.measuredSegments = programRapidSegments(program);
    out.measuredSegments.flip();
    return out;
}

std::optional<ContourCircularTest> ballbarTestOfProgram(const GcodeProgram& program,
                                                        const ContourTrace& trace,
                                                        const Iso230Options& iso,
                                                        std::vector<Diagnostic>& warnings) {
    const BallbarCircles circles = findBallbarCircles(program);
    if (!circles.first)
        return std::nullopt;
    const PathSegment& circle = program.path.segments()[circles.first->begin];
    ContourCircularTest test;
    test.nominal = {circle.centre(), circle.radius()};
    test.clockwise = circle.sweep() < 0.0;
    test.fromProgram = true;
    test.line = program.segments[circles.first->begin].line;
    pointsOnSegments(trace, *circles.first, test.x, test.y);
    if (circles.opposite) {
        test.reverseLine = program.segments[circles.opposite->begin].line;
        pointsOnSegments(trace, *circles.opposite, test.reverseX, test.reverseY);
    }
    if (!circles.note.text.empty())
        warnings.push_back(makeDiagnostic("session_iso230_note", {circles.note}));
    if (test.x.size() < 3 || (circles.opposite && test.reverseX.size() < 3)) {
        warnings.push_back(makeDiagnostic("iso230_circle_too_short"));
        return std::nullopt;
    }
    if (circles.opposite) {
        test.iso = iso230Circular(test.x, test.y, test.reverseX, test.reverseY, test.nominal, iso);
        test.reverseIso = iso230Circular(test.reverseX, test.reverseY, test.nominal, iso);
    } else {
        test.iso = iso230Circular(test.x, test.y, test.nominal, iso);
    }
    return test;
}

/// The height of the reversal spikes of a ballbar test on a table with friction: what the
/// table's friction leaves at the quadrant changes (a linear table's spikes are the loops' lag).
void addReversalSpikeWarning(const Session& session, ContourRun& out) {
    if (!out.circular || (!session.axes[0].friction.active() && !session.axes[1].friction.active()))
        return;
    double largest = 0.0;
    for (const ReversalSpike& spike : out.circular->iso.reversalSpikes)
        largest = std::max(largest, std::abs(spike.heightMm));
    if (largest > 0.0)
        out.warnings.push_back(makeDiagnostic("reversal_spikes", {formatNumber(largest, 4)}));
}

ContourRun runProgramContour(const Session& session, const GcodeProgram& program,
                             const ContourRunOptions& options, const FeedProfile* plannedProfile) {
    const std::vector<double> feeds = programFeeds(program, options.profile.feedScale);
    ContourRun out;
    if (session.crossCoupling.active()) {
        // The coupled loop on each line of the program, before anything is simulated.
        std::vector<CoupledLine> lines;
        bool arcs = false;
        for (std::size_t i = 0; i < program.path.size(); ++i) {
            const PathSegment& segment = program.path.segments()[i];
            if (segment.isArc()) {
                arcs = true;
            } else if (segment.length() > 0.0 && !program.segments[i].rapid) {
                const Point2 d = segment.end() - segment.start();
                lines.push_back({std::atan2(d.y, d.x),
                                 makeDiagnostic("session_program_line",
                                                {std::to_string(program.segments[i].line)})});
            }
        }
        out.couplingStability =
            checkCouplingStability(session, options.profile.dtSeconds, lines, arcs);
    }
    // An input shaper on the reference: the planned profile shaped (both axes, as each axis'
    // own run shapes its reference), and every run of this contour on it.
    std::optional<FeedProfile> shaped;
    if (const ReferenceShaping& shaping = session.trajectory.shaping; shaping.active()) {
        InputShaper shaper;
        try {
            shaper = designInputShaper(shaping.type, shaping.frequencyHz, shaping.dampingRatio);
        } catch (const InvalidInput& e) {
            throw InvalidInput("trajectory.shaping." + e.field(), e.reasonDiagnostic());
        }
        FeedProfileOptions profileOptions = options.profile;
        profileOptions.maxSamples = std::min(profileOptions.maxSamples, sampleLimit());
        const FeedProfile base =
            plannedProfile ? *plannedProfile : planFeedProfile(program.path, feeds, profileOptions);
        try {
            shaped = shapedFeedProfile(base, shaper);
        } catch (const InvalidInput& e) {
            throw InvalidInput(e.field() == "shaper.frequency" ? "trajectory.shaping.frequency"
                                                               : e.field(),
                               e.reasonDiagnostic());
        }
        plannedProfile = &*shaped;
    }
    const std::vector<bool> rapid = programRapidSegments(program);
    out.trace = trace(session, program.path, feeds, options, plannedProfile, true, &rapid);
    const ContourErrorOptions errorOptions = programContourErrorOptions(program, options);
    out.contour =
        contourError(program.path, out.trace.profile.t, out.trace.x, out.trace.y, errorOptions);
    // The comparison runs: the independent axes, and without their feedforward when they have
    // one (the session's design alone, then its feedback alone).
    std::optional<Session> feedbackOnly;
    if (session.crossCoupling.active() && options.compareIndependentAxes) {
        const auto independentRun = [&](const Session& s) {
            IndependentAxesRun run;
            run.trace = trace(s, program.path, feeds, options, &out.trace.profile, false);
            run.contour = contourError(program.path, run.trace.profile.t, run.trace.x, run.trace.y,
                                       errorOptions);
            return run;
        };
        out.independent = independentRun(session);
        Session plain = session;
        bool changed = false;
        for (std::size_t i = 0; i < 2; ++i)
            if (auto without = designMethodModule(session.axes[i].method)
                                   .withoutFeedforward(session.axes[i])) {
                plain.axes[i] = std::move(*without);
                changed = true;
            }
        if (changed) {
            out.feedbackOnly = independentRun(plain);
            feedbackOnly = std::move(plain);
        }
    }
    out.warnings.assign(program.warnings.begin(), program.warnings.end());
    addAxisWarnings(out.trace, out.warnings);
    if (out.couplingStability && !out.couplingStability->warning.text.empty())
        out.warnings.push_back(
            makeDiagnostic("session_cross_coupling_note", {out.couplingStability->warning}));

    if (program.isSingleFullCircle()) {
        const std::size_t c = program.fullCircleSegment();
        const PathSegment& circle = program.path.segments()[c];
        ContourCircularTest test;
        test.nominal = {circle.centre(), circle.radius()};
        test.clockwise = circle.sweep() < 0.0;
        test.line = program.segments[c].line;
        // As a ballbar test runs: the circle alone from rest at its start point, once in the
        // program's direction and once the other way, so that the approach to the circle (a
        // rapid the slow loops have not settled from) does not enter G and F.
        const std::vector<double> feed{feeds[c]};
        test.forward = trace(session, Path({circle}), feed, options);
        test.reverse = trace(session,
                             Path({PathSegment::arc(circle.centre(), circle.radius(),
                                                    circle.startAngle(), -circle.sweep())}),
                             feed, options);
        pointsOnSegments(test.forward, {0, 1}, test.x, test.y);
        pointsOnSegments(test.reverse, {0, 1}, test.reverseX, test.reverseY);
        if (session.axes[0].frictionCompensation.percent != 0.0 ||
            session.axes[1].frictionCompensation.percent != 0.0) {
            Session plain = session;
            for (AxisSettings& a : plain.axes)
                a.frictionCompensation.percent = 0.0;
            const ContourTrace without = trace(plain, Path({circle}), feed, options);
            pointsOnSegments(without, {0, 1}, test.uncompensatedX, test.uncompensatedY);
            if (test.uncompensatedX.size() >= 3)
                test.uncompensatedIso = iso230Circular(test.uncompensatedX, test.uncompensatedY,
                                                       test.nominal, options.iso);
        }
        // The comparison runs' first circle, alone as the test runs it.
        using Comparison = std::pair<std::optional<IndependentAxesRun>*, const Session*>;
        for (auto [run, s] :
             {Comparison{&out.independent, &session},
              Comparison{&out.feedbackOnly, feedbackOnly ? &*feedbackOnly : nullptr}}) {
            if (!*run || !s)
                continue;
            const ContourTrace alone = trace(*s, Path({circle}), feed, options, nullptr, false);
            pointsOnSegments(alone, {0, 1}, (*run)->circleX, (*run)->circleY);
            if ((*run)->circleX.size() >= 3)
                (*run)->iso =
                    iso230Circular((*run)->circleX, (*run)->circleY, test.nominal, options.iso);
        }
        if (test.x.size() >= 3 && test.reverseX.size() >= 3) {
            test.iso = iso230Circular(test.x, test.y, test.reverseX, test.reverseY, test.nominal,
                                      options.iso);
            test.reverseIso =
                iso230Circular(test.reverseX, test.reverseY, test.nominal, options.iso);
            out.circular = std::move(test);
        } else {
            out.warnings.push_back(makeDiagnostic("circle_too_short"));
        }
    } else {
        out.circular = ballbarTestOfProgram(program, out.trace, options.iso, out.warnings);
        if (out.circular) {
            const BallbarCircles circles = findBallbarCircles(program);
            for (std::optional<IndependentAxesRun>* run : {&out.independent, &out.feedbackOnly}) {
                if (!*run)
                    continue;
                IndependentAxesRun& alone = **run;
                pointsOnSegments(alone.trace, *circles.first, alone.circleX, alone.circleY);
                if (alone.circleX.size() >= 3)
                    alone.iso = iso230Circular(alone.circleX, alone.circleY, out.circular->nominal,
                                               options.iso);
            }
        }
    }
    addReversalSpikeWarning(session, out);
    return out;
}

} // namespace xyt
