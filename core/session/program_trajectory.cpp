// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/program_trajectory.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace xyt {

namespace {

/// The profile's and the run's own field names as session paths.
[[noreturn]] void rethrowAsSessionPath(const InvalidInput& e) {
    const std::string& f = e.field();
    if (f == "dt")
        throw InvalidInput("trajectory.dt", e.reasonDiagnostic());
    if (f == "feed_scale" || f == "max_accel" || f == "max_jerk")
        throw InvalidInput("trajectory.gcode." + f, e.reasonDiagnostic());
    if (f == "feed" || f == "corner_angle" || f == "rapid_feed" || f == "path")
        throw InvalidInput("trajectory.gcode.program",
                           makeDiagnostic("field_reason", {f, e.reasonDiagnostic()}));
    throw e;
}

} // namespace

ProgramState::ProgramState(std::string programText)
    : text(std::move(programText)), hash(std::hash<std::string>{}(text)) {}

namespace {

GcodeProgram readProgramText(const std::string& text) {
    try {
        return readGcode(text);
    } catch (const InvalidInput& e) {
        // The reader names the line ("line 12") or the whole program ("program").
        throw InvalidInput("trajectory.gcode.program",
                           e.field() == "program"
                               ? e.reasonDiagnostic()
                               : makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()}));
    }
}

/// The empty program's state (a default ProgramText holds none): read like any other.
const ProgramState& stateOf(const ProgramText& text) {
    static const ProgramState empty{std::string()};
    return text.state() ? *text.state() : empty;
}

} // namespace

GcodeProgram readTrajectoryProgram(const GcodeTrajectory& gcode) {
    return *sessionProgram(gcode);
}

std::shared_ptr<const GcodeProgram> sessionProgram(const GcodeTrajectory& gcode) {
    const ProgramState& state = stateOf(gcode.program);
    std::call_once(state.readOnce, [&state] {
        ++state.reads;
        try {
            state.program = std::make_shared<const GcodeProgram>(readProgramText(state.text));
        } catch (const InvalidInput& e) {
            state.readError = e;
        }
    });
    if (state.readError)
        throw *state.readError;
    return state.program;
}

ContourRunOptions programRunOptions(const TrajectorySettings& trajectory) {
    ContourRunOptions options;
    options.profile.feedScale = trajectory.gcode.feedScale;
    options.profile.maxAccelMmPerS2 = trajectory.gcode.maxAccelMmPerS2;
    options.profile.maxJerkMmPerS3 = trajectory.gcode.maxJerkMmPerS3;
    options.profile.dtSeconds = trajectory.dtSeconds;
    options.profile.maxSamples = sampleLimit();
    return options;
}

FeedProfile trajectoryProgramProfile(const TrajectorySettings& trajectory,
                                     const GcodeProgram& program) {
    try {
        return planFeedProfile(program, programRunOptions(trajectory).profile);
    } catch (const InvalidInput& e) {
        rethrowAsSessionPath(e);
    }
}

namespace {

bool sameOptions(const FeedProfileOptions& a, const FeedProfileOptions& b) {
    return a.feedScale == b.feedScale && a.maxAccelMmPerS2 == b.maxAccelMmPerS2 &&
           a.maxJerkMmPerS3 == b.maxJerkMmPerS3 && a.cornerAngleDeg == b.cornerAngleDeg &&
           a.dtSeconds == b.dtSeconds && a.maxSamples == b.maxSamples &&
           a.withSamples == b.withSamples;
}

/// Profiles kept per program: the sampled and the unsampled one of the current options, and as
/// many of the options just left (a slider step back reuses them). A sampled profile holds up
/// to the sample limit's vectors, so few are kept.
constexpr std::size_t kKeptPlans = 4;

} // namespace

std::shared_ptr<const FeedProfile> sessionProgramProfile(const TrajectorySettings& trajectory,
                                                         bool withSamples) {
    const std::shared_ptr<const GcodeProgram> program = sessionProgram(trajectory.gcode);
    FeedProfileOptions options = programRunOptions(trajectory).profile;
    options.withSamples = withSamples;
    const ProgramState& state = stateOf(trajectory.gcode.program);
    std::unique_lock lock(state.plansMutex);
    for (auto it = state.planned.begin(); it != state.planned.end(); ++it) {
        if (!sameOptions(it->options, options))
            continue;
        ProgramState::Plan plan = *it;
        state.planned.erase(it);
        state.planned.push_back(plan); // the newest last
        if (plan.error)
            throw *plan.error;
        return plan.profile;
    }
    // Planned under the lock: the two axes' evaluations ask for the same profile at once, and
    // the second waits for the first rather than planning it again.
    ProgramState::Plan plan{options, nullptr, std::nullopt};
    ++state.plans;
    try {
        try {
            plan.profile = std::make_shared<const FeedProfile>(planFeedProfile(*program, options));
        } catch (const InvalidInput& e) {
            rethrowAsSessionPath(e);
        }
    } catch (const InvalidInput& e) {
        plan.error = e;
    }
    if (state.planned.size() >= kKeptPlans)
        state.planned.erase(state.planned.begin());
    state.planned.push_back(plan);
    if (plan.error)
        throw *plan.error;
    return plan.profile;
}

void checkProgramOptions(const GcodeTrajectory& gcode) {
    requirePositive(gcode.feedScale, "trajectory.gcode.feed_scale");
    requireProfileRate(gcode.maxAccelMmPerS2, "trajectory.gcode.max_accel", "mm/s^2");
    requireProfileRate(gcode.maxJerkMmPerS3, "trajectory.gcode.max_jerk", "mm/s^3", true);
}

double programRunSeconds(const TrajectorySettings& trajectory) {
    // Planned without its samples but refused as the sampled profile would be.
    return sessionProgramProfile(trajectory, false)->totalTimeSeconds;
}

ProgramSummary summarizeProgram(const TrajectorySettings& trajectory) {
    const GcodeProgram& program = *sessionProgram(trajectory.gcode);
    const FeedProfile& profile = *sessionProgramProfile(trajectory, false);
    ProgramSummary out;
    out.lines = program.lines;
    out.moves = program.path.size();
    out.lengthMm = program.path.length();
    out.runSeconds = profile.totalTimeSeconds;
    out.corners = profile.corners.size();
    out.singleFullCircle = program.isSingleFullCircle();
    out.warnings.assign(program.warnings.begin(), program.warnings.end());
    return out;
}

std::function<double(double)> programAxisReference(const TrajectorySettings& trajectory,
                                                   int axisIndex) {
    // The shared profile itself, not a copy of its samples.
    const std::shared_ptr<const FeedProfile> profile = sessionProgramProfile(trajectory);
    return [profile, axisIndex](double time) {
        const std::vector<double>& ts = profile->t;
        const std::vector<double>& ys = axisIndex == 0 ? profile->x : profile->y;
        if (time <= ts.front())
            return ys.front();
        if (time >= ts.back())
            return ys.back();
        const auto it = std::upper_bound(ts.begin(), ts.end(), time);
        const std::size_t j = static_cast<std::size_t>(it - ts.begin()) - 1;
        const double w = (time - ts[j]) / (ts[j + 1] - ts[j]);
        return ys[j] + w * (ys[j + 1] - ys[j]);
    };
}

ContourRun runSessionProgram(const Session& session, const GcodeProgram& program) {
    try {
        // The session's own program runs on its shared profile, planned already for the axes.
        std::shared_ptr<const GcodeProgram> own;
        try {
            own = sessionProgram(session.trajectory.gcode);
        } catch (const InvalidInput&) {
            // not the session's program: it is planned by the run
        }
        const std::shared_ptr<const FeedProfile> planned =
            own.get() == &program ? sessionProgramProfile(session.trajectory) : nullptr;
        return runProgramContour(session, program, programRunOptions(session.trajectory),
                                 planned.get());
    } catch (const InvalidInput& e) {
        rethrowAsSessionPath(e);
    }
}

} // namespace xyt
