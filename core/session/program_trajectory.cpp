// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/program_trajectory.h"

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
        throw InvalidInput("trajectory.dt", e.reason());
    if (f == "feed_scale" || f == "max_accel" || f == "max_jerk")
        throw InvalidInput("trajectory.gcode." + f, e.reason());
    if (f == "feed" || f == "corner_angle" || f == "rapid_feed" || f == "path")
        throw InvalidInput("trajectory.gcode.program", f + ": " + e.reason());
    throw e;
}

} // namespace

GcodeProgram readTrajectoryProgram(const GcodeTrajectory& gcode) {
    try {
        return readGcode(gcode.program);
    } catch (const InvalidInput& e) {
        // The reader names the line ("line 12") or the whole program ("program").
        throw InvalidInput("trajectory.gcode.program",
                           e.field() == "program" ? e.reason() : e.field() + ": " + e.reason());
    }
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

/// The program's profile without its samples (the pieces and the run time), refused as the
/// sampled one would be: the sample bound at the trajectory's dt is checked all the same.
FeedProfile unsampledProfile(const TrajectorySettings& trajectory, const GcodeProgram& program) {
    try {
        FeedProfileOptions options = programRunOptions(trajectory).profile;
        options.withSamples = false;
        return planFeedProfile(program, options);
    } catch (const InvalidInput& e) {
        rethrowAsSessionPath(e);
    }
}

} // namespace

void checkProgramOptions(const GcodeTrajectory& gcode) {
    requirePositive(gcode.feedScale, "trajectory.gcode.feed_scale");
    requireProfileRate(gcode.maxAccelMmPerS2, "trajectory.gcode.max_accel", "mm/s^2");
    requireProfileRate(gcode.maxJerkMmPerS3, "trajectory.gcode.max_jerk", "mm/s^3", true);
}

double programRunSeconds(const TrajectorySettings& trajectory) {
    return unsampledProfile(trajectory, readTrajectoryProgram(trajectory.gcode)).totalTimeSeconds;
}

ProgramSummary summarizeProgram(const TrajectorySettings& trajectory) {
    const GcodeProgram program = readTrajectoryProgram(trajectory.gcode);
    const FeedProfile profile = unsampledProfile(trajectory, program);
    ProgramSummary out;
    out.lines = program.lines;
    out.moves = program.path.size();
    out.lengthMm = program.path.length();
    out.runSeconds = profile.totalTimeSeconds;
    out.corners = profile.corners.size();
    out.singleFullCircle = program.isSingleFullCircle();
    out.warnings = program.warnings;
    return out;
}

std::function<double(double)> programAxisReference(const TrajectorySettings& trajectory,
                                                   int axisIndex) {
    const FeedProfile profile =
        trajectoryProgramProfile(trajectory, readTrajectoryProgram(trajectory.gcode));
    auto t = std::make_shared<const std::vector<double>>(profile.t);
    auto v = std::make_shared<const std::vector<double>>(axisIndex == 0 ? profile.x : profile.y);
    return [t, v](double time) {
        const std::vector<double>& ts = *t;
        const std::vector<double>& ys = *v;
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
        return runProgramContour(session, program, programRunOptions(session.trajectory));
    } catch (const InvalidInput& e) {
        rethrowAsSessionPath(e);
    }
}

} // namespace xyt
