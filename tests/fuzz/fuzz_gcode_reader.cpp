// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the G-code reader (core/contour/gcode_reader.h) on arbitrary bytes, then
// the feed profile and the contour error of what it accepts. The input is the program text,
// optionally followed by a NUL byte and the planner's options (the reader refuses a NUL in a
// program, so nothing is lost): feed scale, acceleration, jerk, corner angle, rapid feed and dt,
// one to three bytes each (planOption: the shared special values such as 0, subnormals,
// 1e+-300, NaN and inf, the edges of the planner's range, or m 10^e with e in -106 .. 124);
// without them the options are the fixed ones of a typical run. Either the text is rejected with
// xyt::InvalidInput whose message is one line, or the program is consistent: one info per
// segment, finite geometry within the coordinate bound, lines within the text, at most
// kMaxGcodeWarnings + 1 warnings. Its profile (at most 20 000 samples) is either refused in one
// line naming one of the planner's options (with the fixed options, by the sample bound), or ends
// at the path's length, lasts no less than each option's lower bound (feed_profile.h), and holds a
// piece on every segment; the reference traced against the path has no contour error beyond
// round-off; nearest points are no farther than the segment scan says.
#include "tests/fuzz/fuzz_support.h"

#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace {

/// The options of one run: the planner's and the reader's rapid feed.
struct PlanOptions {
    xyt::FeedProfileOptions profile;
    xyt::GcodeReadOptions read;
    bool fuzzed = false; ///< taken from the input (else the fixed ones)
};

/// The edges of the planner's range and an angle, picked by the byte values after the shared
/// special values (16-23).
constexpr double kPlannerEdges[] = {1e-200,
                                    1e-160,
                                    xyt::kMinProfileRate,
                                    0.99 * xyt::kMinProfileRate,
                                    xyt::kMaxProfileRate,
                                    1.01 * xyt::kMaxProfileRate,
                                    1e200,
                                    180.0};

/**
 * One option from the bytes: 255 (or no byte left) keeps @p fallback; 0 .. 15 a value that breaks
 * naive code (kSpecialValues, fuzz_support.h), 16 .. 23 an edge of the planner's range
 * (kPlannerEdges; the order is the seeds' encoding, tests/fuzz/README.md); above, (1 + 9 w /
 * 65536) 10^e with e = byte - 130 (-106 .. 124) and w the next two bytes.
 */
double planOption(xyt::fuzz::FuzzInput& in, double fallback) {
    constexpr std::size_t shared = std::size(xyt::fuzz::kSpecialValues);
    const std::uint8_t kind = in.byte(255);
    if (kind == 255)
        return fallback;
    if (kind < shared)
        return xyt::fuzz::kSpecialValues[kind];
    if (kind < shared + std::size(kPlannerEdges))
        return kPlannerEdges[kind - shared];
    const int exponent = static_cast<int>(kind) - 130;
    const double mantissa = 1.0 + 9.0 * static_cast<double>(in.word()) / 65536.0;
    return mantissa * std::pow(10.0, exponent);
}

/// The fuzzed options from @p bytes (the fixed ones as fallbacks: 255 or no byte left).
PlanOptions planOptions(std::string_view bytes) {
    PlanOptions o;
    o.fuzzed = true;
    o.profile.maxAccelMmPerS2 = 1000.0;
    o.profile.dtSeconds = 0.01;
    o.profile.maxSamples = 20000;
    xyt::fuzz::FuzzInput in(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    o.profile.feedScale = planOption(in, o.profile.feedScale);
    o.profile.maxAccelMmPerS2 = planOption(in, o.profile.maxAccelMmPerS2);
    o.profile.maxJerkMmPerS3 = planOption(in, o.profile.maxJerkMmPerS3);
    o.profile.cornerAngleDeg = planOption(in, o.profile.cornerAngleDeg);
    o.read.rapidFeedMmPerMin = planOption(in, o.read.rapidFeedMmPerMin);
    o.profile.dtSeconds = planOption(in, o.profile.dtSeconds);
    return o;
}

void checkProgram(const xyt::GcodeProgram& p, std::size_t textSize) {
    XYT_FUZZ_REQUIRE(p.path.size() > 0);
    XYT_FUZZ_REQUIRE(p.segments.size() == p.path.size());
    XYT_FUZZ_REQUIRE(p.warnings.size() <= xyt::kMaxGcodeWarnings + 1);
    XYT_FUZZ_REQUIRE(p.lines >= 1 && p.lines <= textSize + 1);
    XYT_FUZZ_REQUIRE_FINITE(p.path.length());
    const double bound =
        4.0 * xyt::kMaxGcodeCoordinateMm; // centres lie within 2e9 mm, arcs 2 radii more
    for (std::size_t i = 0; i < p.path.size(); ++i) {
        const auto& s = p.path.segments()[i];
        for (const xyt::Point2 q : {s.start(), s.end(), s.centre()})
            XYT_FUZZ_REQUIRE(std::abs(q.x) <= bound && std::abs(q.y) <= bound);
        XYT_FUZZ_REQUIRE(s.length() > 0.0 && std::isfinite(s.length()));
        XYT_FUZZ_REQUIRE(p.segments[i].feedMmPerSec > 0.0 &&
                         std::isfinite(p.segments[i].feedMmPerSec));
        XYT_FUZZ_REQUIRE(p.segments[i].line >= 1 && p.segments[i].line <= p.lines);
    }
}

/// The planner's refusals name one of its options (feed_profile.h).
bool isPlannerField(const std::string& f) {
    return f == "feed" || f == "feed_scale" || f == "max_accel" || f == "max_jerk" ||
           f == "corner_angle" || f == "dt" || f == "rapid_feed";
}

void checkProfile(const xyt::GcodeProgram& program, const PlanOptions& plan) {
    const xyt::FeedProfileOptions& options = plan.profile;
    xyt::FeedProfile profile;
    try {
        profile = xyt::planFeedProfile(program, options);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        // With the fixed options only the sample bound may refuse a read program: the run the
        // feeds, the rapids, the acceleration or the jerk need, or the planned one, is longer
        // than the samples at dt hold (each names its option).
        XYT_FUZZ_REQUIRE(isPlannerField(e.field()));
        XYT_FUZZ_REQUIRE(plan.fuzzed || std::string_view(e.what()).find(" samples at dt ") !=
                                            std::string_view::npos);
        // The same refusal without the samples: a summary refuses what a run would.
        xyt::FeedProfileOptions unsampled = options;
        unsampled.withSamples = false;
        bool refused = false;
        try {
            xyt::planFeedProfile(program, unsampled);
        } catch (const xyt::InvalidInput& again) {
            refused = again.field() == e.field();
        }
        XYT_FUZZ_REQUIRE(refused);
        return;
    }
    XYT_FUZZ_REQUIRE(!profile.t.empty() && profile.t.size() <= options.maxSamples);
    XYT_FUZZ_REQUIRE(profile.totalTimeSeconds > 0.0);
    XYT_FUZZ_REQUIRE_FINITE(profile.totalTimeSeconds);
    XYT_FUZZ_REQUIRE_FINITE(profile.x);
    XYT_FUZZ_REQUIRE_FINITE(profile.y);
    XYT_FUZZ_REQUIRE_FINITE(profile.v);
    // Every segment has a piece (a segment with none was an empty result the samples read past).
    std::size_t next = 0;
    for (const xyt::FeedPiece& piece : profile.pieces) {
        XYT_FUZZ_REQUIRE(piece.segment == next || piece.segment + 1 == next);
        next = piece.segment + 1;
    }
    XYT_FUZZ_REQUIRE(next == program.path.size());
    const double length = program.path.length();
    XYT_FUZZ_REQUIRE(std::abs(profile.s.back() - length) <= 1e-6 * std::max(1.0, length));
    for (std::size_t k = 1; k < profile.s.size(); ++k)
        XYT_FUZZ_REQUIRE(profile.s[k] >= profile.s[k - 1] - 1e-9 * std::max(1.0, length));
    // No faster than each option's lower bound (feed_profile.h), up to the sums' round-off.
    const double slack = 1.0 - 1e-9;
    const std::vector<double> feeds = xyt::programFeeds(program, options.feedScale);
    double atFeed = 0.0;
    for (std::size_t i = 0; i < feeds.size(); ++i)
        atFeed += program.path.segments()[i].length() / feeds[i];
    XYT_FUZZ_REQUIRE(profile.totalTimeSeconds >= slack * atFeed);
    XYT_FUZZ_REQUIRE(profile.totalTimeSeconds >=
                     slack * 2.0 * std::sqrt(length / options.maxAccelMmPerS2));
    if (options.maxJerkMmPerS3 > 0.0)
        XYT_FUZZ_REQUIRE(profile.totalTimeSeconds >=
                         slack * 4.0 * std::cbrt(length / (2.0 * options.maxJerkMmPerS3)));
    // Planned without the samples: the same pieces and run time.
    xyt::FeedProfileOptions unsampled = options;
    unsampled.withSamples = false;
    const xyt::FeedProfile summary = xyt::planFeedProfile(program, unsampled);
    XYT_FUZZ_REQUIRE(summary.totalTimeSeconds == profile.totalTimeSeconds && summary.t.empty());
    // The reference itself traced: the contour error is round-off (relative to the path's size).
    const xyt::ContourErrorResult e =
        xyt::contourError(program.path, profile.t, profile.x, profile.y);
    XYT_FUZZ_REQUIRE_FINITE(e.maxAbs);
    double extent = 1.0;
    for (std::size_t k = 0; k < profile.x.size(); ++k)
        extent = std::max({extent, std::abs(profile.x[k]), std::abs(profile.y[k])});
    XYT_FUZZ_REQUIRE(e.maxAbs <= 1e-6 * extent);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    const std::string_view text = input.substr(0, nul);
    PlanOptions plan =
        planOptions(nul == std::string_view::npos ? std::string_view() : input.substr(nul + 1));
    plan.fuzzed = nul != std::string_view::npos;
    xyt::GcodeProgram program;
    try {
        program = xyt::readGcode(text, plan.read);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        // The rapid feed is the only option the reader takes; its default is in range.
        XYT_FUZZ_REQUIRE(e.field() != "rapid_feed" || plan.fuzzed);
        return 0;
    }
    // The fixed options: a trapezoid or an S-curve by the parity of the segment count.
    if (!plan.fuzzed)
        plan.profile.maxJerkMmPerS3 = program.path.size() % 2 ? 20000.0 : 0.0;
    checkProgram(program, text.size());
    checkProfile(program, plan);
    // Nearest points from a few places: the distance a scan of every segment finds, up to the
    // round-off of coordinates as large as the path's.
    double extent = 1.0;
    for (const auto& s : program.path.segments())
        extent = std::max({extent, std::abs(s.centre().x), std::abs(s.centre().y), s.radius(),
                           std::abs(s.start().x), std::abs(s.start().y)});
    const xyt::Point2 probes[] = {{0.0, 0.0}, {1.0, -1.0}, {-3.5, 2.25}, {100.0, 100.0}};
    for (const xyt::Point2 q : probes) {
        const auto p = program.path.nearest(q, size);
        double scan = INFINITY;
        for (const auto& s : program.path.segments())
            scan = std::min(scan, s.nearest(q).distance);
        XYT_FUZZ_REQUIRE(std::abs(std::abs(p.signedDistance) - scan) <=
                         1e-12 * (extent + scan + 100.0));
    }
    return 0;
}
