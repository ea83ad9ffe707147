// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/feed_profile.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>

namespace xyt {

namespace {

/// Bisection steps for the S-curve's peak and junction speeds; largestFitting needs at most
/// about 70 of them for any bracket within the planner's range.
constexpr int kBisectionSteps = 200;

/**
 * The largest v in [lo, hi] with fits(v), given fits(lo) and not fits(hi). Halving the value
 * 200 times reaches only 2^-200 (6e-61) of hi, and within the planner's range a speed may be
 * 1e-70 of its cap (a jerk of 1e-100 on a 1e-40 mm segment): so the bracket is halved in the
 * logarithm while it spans more than a factor 2, and from lo = 0 the first steps try hi 2^-64,
 * hi 2^-128, ... until one fits; then in the value, to the double's resolution.
 */
template <class Fits> double largestFitting(double lo, double hi, const Fits& fits) {
    for (int k = 0; k < kBisectionSteps && hi - lo > 1e-14 * hi; ++k) {
        const double mid = lo == 0.0       ? hi * 0x1p-64
                           : hi > 2.0 * lo ? std::sqrt(lo) * std::sqrt(hi)
                                           : 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    return lo;
}

/// The largest v in [v0, cap] that can be reached from v0 within @p length.
double reachableSpeed(double v0, double length, double cap, double accel, double jerk) {
    if (cap <= v0)
        return cap;
    if (jerk == 0.0)
        return std::min(cap, std::sqrt(v0 * v0 + 2.0 * accel * length));
    if (speedChangeDistance(v0, cap, accel, jerk) <= length)
        return cap;
    return largestFitting(
        v0, cap, [&](double v) { return speedChangeDistance(v0, v, accel, jerk) <= length; });
}

/// The peak speed of a segment of @p length entered at vs, left at ve, limited to vmax.
double peakSpeed(double vs, double ve, double vmax, double length, double accel, double jerk) {
    const double floor = std::max(vs, ve);
    if (jerk == 0.0)
        return std::clamp(std::sqrt((2.0 * accel * length + vs * vs + ve * ve) / 2.0), floor,
                          std::max(vmax, floor));
    const auto distance = [&](double v) {
        return speedChangeDistance(vs, v, accel, jerk) + speedChangeDistance(v, ve, accel, jerk);
    };
    if (vmax <= floor || distance(vmax) <= length)
        return std::max(vmax, floor);
    return largestFitting(floor, vmax, [&](double v) { return distance(v) <= length; });
}

/// Appends pieces to a FeedProfile while keeping its running time, position and speed.
class PieceWriter {
public:
    PieceWriter(std::vector<FeedPiece>& pieces, double accel, double jerk)
        : pieces_(pieces), accel_(accel), jerk_(jerk) {}

    void startSegment(std::size_t segment, double s) {
        segment_ = segment;
        s_ = s;
    }
    void speedChange(double v0, double v1) {
        const double dv = std::abs(v1 - v0);
        if (dv == 0.0)
            return;
        const double sign = v1 > v0 ? 1.0 : -1.0;
        if (jerk_ == 0.0) {
            piece(v0, sign * accel_, 0.0, dv / accel_);
        } else if (dv >= accel_ * accel_ / jerk_) {
            const double tj = accel_ / jerk_;
            piece(v0, 0.0, sign * jerk_, tj);
            piece(v_, sign * accel_, 0.0, dv / accel_ - tj);
            piece(v_, sign * accel_, -sign * jerk_, tj);
        } else {
            const double tj = std::sqrt(dv / jerk_);
            piece(v0, 0.0, sign * jerk_, tj);
            piece(v_, sign * jerk_ * tj, -sign * jerk_, tj);
        }
        v_ = v1; // the exact end speed, not the sum of the rounded pieces
    }
    void cruise(double v, double distance) {
        if (v > 0.0 && distance > 0.0)
            piece(v, 0.0, 0.0, distance / v);
    }
    double time() const { return t_; }

private:
    void piece(double v0, double a0, double jerk, double duration) {
        if (!(duration > 0.0))
            return;
        pieces_.push_back({t_, duration, s_, v0, a0, jerk, segment_});
        const double d = duration;
        s_ += d * (v0 + d * (a0 / 2.0 + d * jerk / 6.0));
        v_ = v0 + d * (a0 + d * jerk / 2.0);
        t_ += duration;
    }

    std::vector<FeedPiece>& pieces_;
    double accel_, jerk_;
    double t_ = 0.0, s_ = 0.0, v_ = 0.0;
    std::size_t segment_ = 0;
};

/// "1.2e+03 s", or "more time than a double holds" for an overflowed bound.
Diagnostic secondsText(double seconds) {
    return std::isfinite(seconds) ? Diagnostic(formatNumber(seconds, 3) + " s")
                                  : makeDiagnostic("sim_more_than", {"1.8e+308 s"});
}

/// True when a run of @p seconds fits in maxSamples samples at dt: the planned profile's count
/// (see planFeedProfile), less 1e-9 of @p seconds for the round-off of a lower bound, so that
/// no profile that fits is refused by its bound.
bool fitsSamples(double seconds, const FeedProfileOptions& o) {
    const double steps = std::max(1.0, std::ceil(seconds * (1.0 - 1e-9) / o.dtSeconds - 1e-9));
    return steps + 1.0 <= static_cast<double>(o.maxSamples);
}

/// Refuses @p field when @p seconds, a lower bound on the run time, does not fit in the samples:
/// the diagnostic @p code, "<who> needs at least <seconds> <how>, more than the <n> samples at
/// dt <dt> s hold (<span>)", its arguments seconds, n, dt, span, then @p more.
void requireWithinSamples(double seconds, const std::string& field, std::string_view code,
                          const FeedProfileOptions& o, const std::vector<Diagnostic>& more = {}) {
    if (fitsSamples(seconds, o))
        return;
    const double span = (static_cast<double>(o.maxSamples) - 1.0) * o.dtSeconds;
    std::vector<Diagnostic> args = {secondsText(seconds), std::to_string(o.maxSamples),
                                    formatNumber(o.dtSeconds), secondsText(std::max(span, 0.0))};
    args.insert(args.end(), more.begin(), more.end());
    throw InvalidInput(field, makeDiagnostic(code, std::move(args)));
}

/// sum(L_i / f_i): the run time with every segment at its feed.
double feedSeconds(const Path& path, const std::vector<double>& feeds) {
    double sum = 0.0;
    for (std::size_t i = 0; i < feeds.size(); ++i)
        sum += path.segments()[i].length() / feeds[i];
    return sum;
}

void validate(const Path& path, const std::vector<double>& feeds, const FeedProfileOptions& o) {
    if (path.size() == 0)
        throw InvalidInput("path", makeDiagnostic("contour_has_no_segment"));
    if (feeds.size() != path.size())
        throw InvalidInput(
            "feed", makeDiagnostic("contour_feed_per_segment",
                                   {std::to_string(path.size()), std::to_string(feeds.size())}));
    for (std::size_t i = 0; i < feeds.size(); ++i)
        if (!(feeds[i] > 0.0) || !std::isfinite(feeds[i]))
            throw InvalidInput("feed", makeDiagnostic("contour_segment_feed_invalid",
                                                      {std::to_string(i), formatNumber(feeds[i])}));
    if (!(o.maxAccelMmPerS2 > 0.0) || !std::isfinite(o.maxAccelMmPerS2))
        throw InvalidInput("max_accel", makeDiagnostic("finite_positive"));
    if (!(o.maxJerkMmPerS3 >= 0.0) || !std::isfinite(o.maxJerkMmPerS3))
        throw InvalidInput("max_jerk", makeDiagnostic("contour_max_jerk"));
    if (!(o.cornerAngleDeg >= 0.0 && o.cornerAngleDeg < 180.0))
        throw InvalidInput("corner_angle", makeDiagnostic("contour_corner_angle"));
    if (!(o.dtSeconds > 0.0) || !std::isfinite(o.dtSeconds))
        throw InvalidInput("dt", makeDiagnostic("finite_positive"));
    // What each option alone asks of the run time (the header derives the bounds). The roots
    // are taken of the length and the rate apart, so that a subnormal rate gives a finite bound.
    const double length = path.length();
    const std::string pathMm = formatNumber(length);
    requireWithinSamples(feedSeconds(path, feeds), "feed", "contour_feeds_too_long", o, {pathMm});
    const double a = o.maxAccelMmPerS2;
    requireWithinSamples(2.0 * std::sqrt(length) / std::sqrt(a), "max_accel",
                         "contour_accel_too_long", o, {formatNumber(a), pathMm});
    const double j = o.maxJerkMmPerS3;
    if (j > 0.0)
        requireWithinSamples(4.0 * std::cbrt(length) / std::cbrt(2.0 * j), "max_jerk",
                             "contour_jerk_too_long", o, {formatNumber(j), pathMm});
    // What the arithmetic holds, for a dt so long that the sample bound does not bite.
    for (std::size_t i = 0; i < feeds.size(); ++i)
        requireProfileRate(
            feeds[i], "feed",
            makeDiagnostic("contour_rate_unit_segment", {"mm/s", std::to_string(i)}));
    requireProfileRate(a, "max_accel", "mm/s^2");
    requireProfileRate(j, "max_jerk", "mm/s^3", true);
}

} // namespace

double speedChangeTime(double v0, double v1, double accel, double jerk) {
    const double dv = std::abs(v1 - v0);
    if (jerk == 0.0)
        return dv / accel;
    if (dv >= accel * accel / jerk)
        return dv / accel + accel / jerk;
    return 2.0 * std::sqrt(dv / jerk);
}

double speedChangeDistance(double v0, double v1, double accel, double jerk) {
    // Both the trapezoid's ramp and the S-curve's are point-symmetric about their middle, so
    // the mean speed is (v0 + v1) / 2.
    return 0.5 * (v0 + v1) * speedChangeTime(v0, v1, accel, jerk);
}

FeedProfile planFeedProfile(const Path& path, const std::vector<double>& feedMmPerSec,
                            const FeedProfileOptions& options) {
    validate(path, feedMmPerSec, options);
    const double accel = options.maxAccelMmPerS2;
    const double jerk = options.maxJerkMmPerS3;
    const std::size_t n = path.size();
    const auto& segments = path.segments();

    // Speed limit of each segment: its feed, and the centripetal limit v^2/R <= a on arcs.
    std::vector<double> limit(n);
    for (std::size_t i = 0; i < n; ++i) {
        limit[i] = feedMmPerSec[i];
        if (segments[i].isArc())
            limit[i] = std::min(limit[i], std::sqrt(accel * segments[i].radius()));
    }
    FeedProfile out;
    out.dtSeconds = options.dtSeconds;
    out.corners = sharpCorners(path, options.cornerAngleDeg * std::numbers::pi / 180.0);
    std::vector<double>& v = out.junctionSpeed;
    v.assign(n + 1, 0.0);
    for (std::size_t i = 1; i < n; ++i)
        v[i] = std::min(limit[i - 1], limit[i]);
    for (const std::size_t c : out.corners)
        v[c] = 0.0;
    // Backward (deceleration) then forward (acceleration) pass.
    for (std::size_t i = n; i-- > 0;)
        v[i] = reachableSpeed(v[i + 1], segments[i].length(), v[i], accel, jerk);
    for (std::size_t i = 1; i <= n; ++i)
        v[i] = reachableSpeed(v[i - 1], segments[i - 1].length(), v[i], accel, jerk);

    PieceWriter writer(out.pieces, accel, jerk);
    for (std::size_t i = 0; i < n; ++i) {
        const double length = segments[i].length();
        const double peak = peakSpeed(v[i], v[i + 1], limit[i], length, accel, jerk);
        const double up = speedChangeDistance(v[i], peak, accel, jerk);
        const double down = speedChangeDistance(peak, v[i + 1], accel, jerk);
        const double before = writer.time();
        writer.startSegment(i, path.segmentStart(i));
        writer.speedChange(v[i], peak);
        writer.cruise(peak, length - up - down);
        writer.speedChange(peak, v[i + 1]);
        // A segment of positive length takes time; none (a peak speed that rounds to 0) would
        // leave the samples without a piece to read.
        if (!(writer.time() > before))
            throw InvalidInput("feed", makeDiagnostic("contour_segment_peak_speed",
                                                      {std::to_string(i), formatNumber(length),
                                                       formatNumber(peak)}));
    }
    out.totalTimeSeconds = writer.time();

    // Samples t_k = k dt, k = 0 .. ceil(T/dt) (1e-9 of a step forgives a T that is a whole
    // number of steps but for rounding), and at least one step: a run shorter than 1e-9 dt
    // still ends on a sample (at dt, holding the end of the path).
    const double steps = std::max(1.0, std::ceil(out.totalTimeSeconds / options.dtSeconds - 1e-9));
    if (!(steps + 1.0 <= static_cast<double>(options.maxSamples)))
        throw InvalidInput(
            "dt",
            makeDiagnostic("contour_profile_too_long",
                           {formatNumber(out.totalTimeSeconds), formatNumber(steps + 1.0),
                            formatNumber(options.dtSeconds), std::to_string(options.maxSamples)}));
    if (!options.withSamples)
        return out;
    const std::size_t count = static_cast<std::size_t>(std::max(steps, 0.0)) + 1;
    for (auto* signal : {&out.t, &out.s, &out.v, &out.a, &out.x, &out.y})
        signal->resize(count);
    out.segment.resize(count);
    std::size_t p = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double t = std::min(static_cast<double>(k) * options.dtSeconds, out.totalTimeSeconds);
        while (p + 1 < out.pieces.size() && out.pieces[p].t0 + out.pieces[p].duration < t)
            ++p;
        // At the run's end, the end of the last piece: pieces shorter than the round-off of
        // their start time (a segment of 1e28 s after 1e44 s) add nothing to t0 + duration,
        // so the search above can stop on an earlier piece whose end rounds to the same time.
        const bool end = t >= out.totalTimeSeconds;
        if (end)
            p = out.pieces.size() - 1;
        const FeedPiece& piece = out.pieces[p];
        const double tau = end ? piece.duration : std::clamp(t - piece.t0, 0.0, piece.duration);
        const double s =
            piece.s0 + tau * (piece.v0 + tau * (piece.a0 / 2.0 + tau * piece.jerk / 6.0));
        const PathPoint point = path.at(s, piece.segment);
        out.t[k] = static_cast<double>(k) * options.dtSeconds;
        out.s[k] = s;
        out.v[k] = std::max(0.0, piece.v0 + tau * (piece.a0 + tau * piece.jerk / 2.0));
        out.a[k] = piece.a0 + tau * piece.jerk;
        out.x[k] = point.point.x;
        out.y[k] = point.point.y;
        out.segment[k] = piece.segment;
    }
    return out;
}

std::vector<double> programFeeds(const GcodeProgram& program, double feedScale) {
    if (!(feedScale > 0.0) || !std::isfinite(feedScale))
        throw InvalidInput("feed_scale", makeDiagnostic("finite_positive"));
    std::vector<double> feeds(program.segments.size());
    for (std::size_t i = 0; i < feeds.size(); ++i) {
        const GcodeSegmentInfo& info = program.segments[i];
        feeds[i] = info.feedMmPerSec * (info.rapid ? 1.0 : feedScale);
        const std::string line = std::to_string(info.line);
        if (info.rapid)
            requireProfileRate(feeds[i], "rapid_feed",
                               makeDiagnostic("contour_rapid_of_line", {"mm/s", line}));
        else if (!(feeds[i] >= kMinProfileRate && feeds[i] <= kMaxProfileRate))
            throw InvalidInput(
                "feed_scale",
                makeDiagnostic("contour_feed_scale_outside",
                               {formatNumber(feedScale), line, formatNumber(info.feedMmPerSec),
                                formatNumber(feeds[i]), formatNumber(kMinProfileRate),
                                formatNumber(kMaxProfileRate)}));
    }
    return feeds;
}

FeedProfile planFeedProfile(const GcodeProgram& program, const FeedProfileOptions& options) {
    const std::vector<double> feeds = programFeeds(program, options.feedScale);
    if (options.dtSeconds > 0.0 && std::isfinite(options.dtSeconds)) {
        // The feeds' time bound by its cause. The program's feed moves at their own F words
        // are what the program asks for: when even they do not fit, the step is too fine for
        // the program (or its F words too slow), and dt is named.
        double rapid = 0.0, scaled = 0.0, programmed = 0.0;
        for (std::size_t i = 0; i < feeds.size(); ++i) {
            const double length = program.path.segments()[i].length();
            if (program.segments[i].rapid) {
                rapid += length / feeds[i];
            } else {
                scaled += length / feeds[i];
                programmed += length / program.segments[i].feedMmPerSec;
            }
        }
        requireWithinSamples(programmed, "dt", "contour_program_own_feeds_too_long", options);
        requireWithinSamples(rapid, "rapid_feed", "contour_rapids_too_long", options);
        // A scale is named when the program fits at scale 1; else the sum is the feeds' (below).
        if (fitsSamples(programmed + rapid, options))
            requireWithinSamples(scaled + rapid, "feed_scale", "contour_program_scaled_too_long",
                                 options, {formatNumber(options.feedScale)});
    }
    return planFeedProfile(program.path, feeds, options);
}

void requireProfileRate(double rate, const std::string& field, const Diagnostic& unit,
                        bool zeroAllowed) {
    if (zeroAllowed && rate == 0.0)
        return;
    if (rate >= kMinProfileRate && rate <= kMaxProfileRate)
        return;
    throw InvalidInput(field,
                       makeDiagnostic(zeroAllowed ? "contour_rate_outside_range_or_zero"
                                                  : "contour_rate_outside_range",
                                      {formatNumber(rate), unit, formatNumber(kMinProfileRate),
                                       formatNumber(kMaxProfileRate)}));
}

} // namespace xyt
