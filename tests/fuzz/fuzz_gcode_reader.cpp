// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the G-code reader (core/contour/gcode_reader.h) on arbitrary bytes, then
// the feed profile and the contour error of what it accepts. Either the text is rejected with
// xyt::InvalidInput whose message is one line, or the program is consistent: one info per
// segment, finite geometry within the coordinate bound, lines within the text, at most
// kMaxGcodeWarnings + 1 warnings; its profile (bounded to 20 000 samples, else refused naming
// "dt") ends at the path's length; nearest points are no farther than the segment scan says.
#include "tests/fuzz/fuzz_support.h"

#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace {

void checkProgram(const xyt::GcodeProgram& p, std::size_t textSize) {
    XYT_FUZZ_REQUIRE(p.path.size() > 0);
    XYT_FUZZ_REQUIRE(p.segments.size() == p.path.size());
    XYT_FUZZ_REQUIRE(p.warnings.size() <= xyt::kMaxGcodeWarnings + 1);
    XYT_FUZZ_REQUIRE(p.lines >= 1 && p.lines <= textSize + 1);
    XYT_FUZZ_REQUIRE_FINITE(p.path.length());
    const double bound = 4.0 * xyt::kMaxGcodeCoordinateMm; // centres lie within 2e9 mm, arcs 2 radii more
    for (std::size_t i = 0; i < p.path.size(); ++i) {
        const auto& s = p.path.segments()[i];
        for (const xyt::Point2 q : {s.start(), s.end(), s.centre()})
            XYT_FUZZ_REQUIRE(std::abs(q.x) <= bound && std::abs(q.y) <= bound);
        XYT_FUZZ_REQUIRE(s.length() > 0.0 && std::isfinite(s.length()));
        XYT_FUZZ_REQUIRE(p.segments[i].feedMmPerSec > 0.0 && std::isfinite(p.segments[i].feedMmPerSec));
        XYT_FUZZ_REQUIRE(p.segments[i].line >= 1 && p.segments[i].line <= p.lines);
    }
}

void checkProfile(const xyt::GcodeProgram& program) {
    xyt::FeedProfileOptions options;
    options.maxAccelMmPerS2 = 1000.0;
    options.maxJerkMmPerS3 = program.path.size() % 2 ? 20000.0 : 0.0;
    options.dtSeconds = 0.01;
    options.maxSamples = 20000;
    xyt::FeedProfile profile;
    try {
        profile = xyt::planFeedProfile(program, options);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        XYT_FUZZ_REQUIRE(e.field() == "dt"); // only the sample bound may refuse a read program
        return;
    }
    XYT_FUZZ_REQUIRE(!profile.t.empty() && profile.t.size() <= options.maxSamples);
    XYT_FUZZ_REQUIRE_FINITE(profile.totalTimeSeconds);
    XYT_FUZZ_REQUIRE_FINITE(profile.x);
    XYT_FUZZ_REQUIRE_FINITE(profile.y);
    XYT_FUZZ_REQUIRE_FINITE(profile.v);
    const double length = program.path.length();
    XYT_FUZZ_REQUIRE(std::abs(profile.s.back() - length) <= 1e-6 * std::max(1.0, length));
    for (std::size_t k = 1; k < profile.s.size(); ++k)
        XYT_FUZZ_REQUIRE(profile.s[k] >= profile.s[k - 1] - 1e-9 * std::max(1.0, length));
    // The reference itself traced: the contour error is round-off (relative to the path's size).
    const xyt::ContourErrorResult e = xyt::contourError(program.path, profile.t, profile.x, profile.y);
    XYT_FUZZ_REQUIRE_FINITE(e.maxAbs);
    double extent = 1.0;
    for (std::size_t k = 0; k < profile.x.size(); ++k)
        extent = std::max({extent, std::abs(profile.x[k]), std::abs(profile.y[k])});
    XYT_FUZZ_REQUIRE(e.maxAbs <= 1e-6 * extent);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    xyt::GcodeProgram program;
    try {
        program = xyt::readGcode(text);
    } catch (const xyt::InvalidInput& e) {
        xyt::fuzz::requireOneLine(e);
        return 0;
    }
    checkProgram(program, size);
    checkProfile(program);
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
        XYT_FUZZ_REQUIRE(std::abs(std::abs(p.signedDistance) - scan) <= 1e-12 * (extent + scan + 100.0));
    }
    return 0;
}
