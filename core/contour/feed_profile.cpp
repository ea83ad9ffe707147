// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/contour/feed_profile.h"

#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace xyt {

namespace {

/// Bisection steps for the S-curve's peak and junction speeds: 200 halvings of the interval
/// reach the double's resolution from any start; the loop stops there.
constexpr int kBisectionSteps = 200;

/// The largest v in [v0, cap] that can be reached from v0 within @p length.
double reachableSpeed(double v0, double length, double cap, double accel, double jerk) {
    if (cap <= v0)
        return cap;
    if (jerk == 0.0)
        return std::min(cap, std::sqrt(v0 * v0 + 2.0 * accel * length));
    if (speedChangeDistance(v0, cap, accel, jerk) <= length)
        return cap;
    double lo = v0, hi = cap;
    for (int k = 0; k < kBisectionSteps && hi - lo > 1e-14 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (speedChangeDistance(v0, mid, accel, jerk) <= length ? lo : hi) = mid;
    }
    return lo;
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
    double lo = floor, hi = vmax;
    for (int k = 0; k < kBisectionSteps && hi - lo > 1e-14 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (distance(mid) <= length ? lo : hi) = mid;
    }
    return lo;
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

void validate(const Path& path, const std::vector<double>& feeds, const FeedProfileOptions& o) {
    if (feeds.size() != path.size())
        throw InvalidInput("feed", "needs one value per path segment (" + std::to_string(path.size()) +
                                       "), got " + std::to_string(feeds.size()));
    for (std::size_t i = 0; i < feeds.size(); ++i)
        if (!(feeds[i] > 0.0) || !std::isfinite(feeds[i]))
            throw InvalidInput("feed", "segment " + std::to_string(i) + ": must be a finite number > 0, got " +
                                           formatNumber(feeds[i]));
    if (!(o.maxAccelMmPerS2 > 0.0) || !std::isfinite(o.maxAccelMmPerS2))
        throw InvalidInput("max_accel", "must be a finite number greater than zero");
    if (!(o.maxJerkMmPerS3 >= 0.0) || !std::isfinite(o.maxJerkMmPerS3))
        throw InvalidInput("max_jerk", "must be a finite number >= 0 (0: no jerk limit)");
    if (!(o.cornerAngleDeg >= 0.0 && o.cornerAngleDeg < 180.0))
        throw InvalidInput("corner_angle", "must be in [0, 180) degrees");
    if (!(o.dtSeconds > 0.0) || !std::isfinite(o.dtSeconds))
        throw InvalidInput("dt", "must be a finite number greater than zero");
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
        writer.startSegment(i, path.segmentStart(i));
        writer.speedChange(v[i], peak);
        writer.cruise(peak, length - up - down);
        writer.speedChange(peak, v[i + 1]);
    }
    out.totalTimeSeconds = writer.time();

    // Samples t_k = k dt, k = 0 .. ceil(T/dt) (1e-9 of a step forgives a T that is a whole
    // number of steps but for rounding).
    const double steps = std::ceil(out.totalTimeSeconds / options.dtSeconds - 1e-9);
    if (!(steps + 1.0 <= static_cast<double>(options.maxSamples)))
        throw InvalidInput("dt", "the profile lasts " + formatNumber(out.totalTimeSeconds) + " s, " +
                                     formatNumber(steps + 1.0) + " samples at dt " +
                                     formatNumber(options.dtSeconds) + " s, more than the limit of " +
                                     std::to_string(options.maxSamples));
    const std::size_t count = static_cast<std::size_t>(std::max(steps, 0.0)) + 1;
    for (auto* signal : {&out.t, &out.s, &out.v, &out.a, &out.x, &out.y})
        signal->resize(count);
    out.segment.resize(count);
    std::size_t p = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double t = std::min(static_cast<double>(k) * options.dtSeconds, out.totalTimeSeconds);
        while (p + 1 < out.pieces.size() && out.pieces[p].t0 + out.pieces[p].duration < t)
            ++p;
        const FeedPiece& piece = out.pieces[p];
        const double tau = std::clamp(t - piece.t0, 0.0, piece.duration);
        const double s = piece.s0 + tau * (piece.v0 + tau * (piece.a0 / 2.0 + tau * piece.jerk / 6.0));
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
        throw InvalidInput("feed_scale", "must be a finite number greater than zero");
    std::vector<double> feeds(program.segments.size());
    for (std::size_t i = 0; i < feeds.size(); ++i)
        feeds[i] = program.segments[i].feedMmPerSec * (program.segments[i].rapid ? 1.0 : feedScale);
    return feeds;
}

FeedProfile planFeedProfile(const GcodeProgram& program, const FeedProfileOptions& options) {
    return planFeedProfile(program.path, programFeeds(program, options.feedScale), options);
}

} // namespace xyt
