// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/model/diagnostic.h"
#include "core/model/errors.h"
#include "core/session/contour_run.h"
#include "core/session/session.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * A program text with what was read and planned from it, shared by every copy of a session
 * holding the text (ProgramText): the text is read once, and each feed profile is planned once
 * per set of planning options (the G-code fields and dt), however many evaluations, copies and
 * edits of other fields follow. The text never changes; the reads and plans are filled on first
 * use, from any thread.
 */
struct ProgramState {
    explicit ProgramState(std::string programText);
    const std::string text;
    const std::size_t hash; ///< of the text, computed once

    /// The program read (readGcode), or its refusal, on first use.
    mutable std::once_flag readOnce;
    mutable std::shared_ptr<const GcodeProgram> program;
    mutable std::optional<InvalidInput> readError;
    /// How many times the text was read (0 or 1) and profiles were planned from it: what the
    /// cache saves is observable (tests).
    mutable std::atomic<int> reads{0};
    mutable std::atomic<int> plans{0};

    /// The last few profiles planned, newest last, keyed by their options.
    struct Plan {
        FeedProfileOptions options;
        std::shared_ptr<const FeedProfile> profile;
        std::optional<InvalidInput> error;
    };
    mutable std::mutex plansMutex;
    mutable std::vector<Plan> planned;
};

/**
 * The G-code trajectory of a session (TrajectoryKind::Gcode): its program read, the run options
 * its fields give, and what the editor shows of it. Every refusal names the session path:
 * "trajectory.gcode.program" with the reader's line, word and column ("line 12: unknown word G5
 * at column 4"), "trajectory.gcode.feed_scale", ".max_accel", ".max_jerk", "trajectory.dt".
 */

/// Reads the program text of @p gcode. @throws InvalidInput "trajectory.gcode.program".
GcodeProgram readTrajectoryProgram(const GcodeTrajectory& gcode);

/// readTrajectoryProgram, read once per program text and shared (ProgramState).
/// @throws InvalidInput "trajectory.gcode.program", the same refusal each time.
std::shared_ptr<const GcodeProgram> sessionProgram(const GcodeTrajectory& gcode);

/// The program's feed profile at the trajectory's dt, with its samples or (@p withSamples
/// false) only its pieces and run time, planned once per program text and planning options and
/// shared. @throws InvalidInput naming the session path (see above), the same refusal each time.
std::shared_ptr<const FeedProfile> sessionProgramProfile(const TrajectorySettings& trajectory,
                                                         bool withSamples = true);

/// The contour-run options of @p trajectory: the G-code fields and dt as the profile's step.
ContourRunOptions programRunOptions(const TrajectorySettings& trajectory);

/// The program's feed profile at the trajectory's dt (at most sampleLimit() samples).
/// @throws InvalidInput naming the session path (see above).
FeedProfile trajectoryProgramProfile(const TrajectorySettings& trajectory,
                                     const GcodeProgram& program);

/**
 * The profile options of @p gcode that are checked without its program: the feed scale finite
 * and > 0, the acceleration and the jerk within the planner's range (kMinProfileRate ..
 * kMaxProfileRate, feed_profile.h; a jerk also 0). What depends on the program (how long its
 * profile runs at dt) is checked when it is planned.
 * @throws InvalidInput "trajectory.gcode.feed_scale", ".max_accel" or ".max_jerk".
 */
void checkProgramOptions(const GcodeTrajectory& gcode);

/// The run time of the program's feed profile (s), planned without its samples but refused
/// as the sampled profile would be (more than sampleLimit() samples at the trajectory's dt, or
/// an option that alone needs that long: feed_profile.h). @throws InvalidInput as above.
double programRunSeconds(const TrajectorySettings& trajectory);

/// What the trajectory editor shows of a program.
struct ProgramSummary {
    std::size_t lines = 0;   ///< lines of the text
    std::size_t moves = 0;   ///< path segments (G0-G3 blocks that move)
    double lengthMm = 0.0;   ///< path length, rapids included
    double runSeconds = 0.0; ///< the feed profile's run time
    std::size_t corners = 0; ///< sharp corners where the profile stops
    bool singleFullCircle = false;
    std::vector<Diagnostic> warnings;
};
/// @throws InvalidInput as above.
ProgramSummary summarizeProgram(const TrajectorySettings& trajectory);

/// The position of axis @p axisIndex (0 = x, 1 = y) along the program's profile at time t
/// (linear between the profile's samples, held at the end). @throws InvalidInput as above.
std::function<double(double)> programAxisReference(const TrajectorySettings& trajectory,
                                                   int axisIndex);

/// The contour run of @p program (the session's, read) by the session's axes:
/// runProgramContour with programRunOptions. @throws InvalidInput as runProgramContour, naming
/// the session paths.
ContourRun runSessionProgram(const Session& session, const GcodeProgram& program);

} // namespace xyt
