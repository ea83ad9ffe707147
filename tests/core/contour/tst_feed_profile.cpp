// SPDX-License-Identifier: GPL-3.0-or-later
// The feed-rate profile (core/contour/feed_profile.h) against closed forms: a trapezoidal move
// of length L at speed v and acceleration a takes T = L/v + v/a when L >= v^2/a and
// 2 sqrt(L/a) when shorter (triangular); an S-curve with jerk J (v >= a^2/J) takes
// L/v + v/a + a/J. Invariants: the integral of the speed is the path length; speed,
// acceleration and jerk stay within their limits and the centripetal limit v^2/R <= a holds on
// arcs; the profile stops at sharp corners and keeps its speed through tangent joins.
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <string>

using xyt::FeedProfile;
using xyt::FeedProfileOptions;

namespace {

FeedProfileOptions options(double accel, double jerk = 0.0, double dt = 0.001) {
    FeedProfileOptions o;
    o.maxAccelMmPerS2 = accel;
    o.maxJerkMmPerS3 = jerk;
    o.dtSeconds = dt;
    return o;
}

FeedProfile profileOf(const std::string& gcode, const FeedProfileOptions& o) {
    return xyt::planFeedProfile(xyt::readGcode(gcode), o);
}

/// One straight move of @p length mm along x at @p feed mm/s.
FeedProfile straightMove(double length, double feed, const FeedProfileOptions& o) {
    const xyt::Path path({xyt::PathSegment::line({0.0, 0.0}, {length, 0.0})});
    return xyt::planFeedProfile(path, {feed}, o);
}

/// Checks every piece against the limits: |a| <= A, |jerk| <= J (when J > 0, else 0),
/// 0 <= v <= the segment's limit (feed, and sqrt(A R) on arcs) at both ends of each piece
/// (the speed is monotonic within a piece: its acceleration keeps one sign). Relative slack
/// 1e-9 for the round-off of the bisection and the piece sums.
void checkLimits(const FeedProfile& p, const xyt::Path& path, const std::vector<double>& feeds,
                 const FeedProfileOptions& o) {
    const double slack = 1e-9;
    for (const auto& piece : p.pieces) {
        const double aEnd = piece.a0 + piece.jerk * piece.duration;
        const double vEnd =
            piece.v0 + piece.duration * (piece.a0 + piece.duration * piece.jerk / 2.0);
        QVERIFY(std::abs(piece.a0) <= o.maxAccelMmPerS2 * (1.0 + slack));
        QVERIFY(std::abs(aEnd) <= o.maxAccelMmPerS2 * (1.0 + slack));
        QVERIFY(std::abs(piece.jerk) <= o.maxJerkMmPerS3 * (1.0 + slack));
        const auto& seg = path.segments()[piece.segment];
        double limit = feeds[piece.segment];
        if (seg.isArc())
            limit = std::min(limit, std::sqrt(o.maxAccelMmPerS2 * seg.radius()));
        for (const double v : {piece.v0, vEnd}) {
            QVERIFY2(v >= -slack * limit, qPrintable(QString::number(v)));
            QVERIFY2(v <= limit * (1.0 + slack),
                     qPrintable(QStringLiteral("%1 > %2").arg(v).arg(limit)));
        }
    }
}

/// Trapezoidal-rule integral of the sampled speed.
double integratedSpeed(const FeedProfile& p) {
    double s = 0.0;
    for (std::size_t k = 1; k < p.t.size(); ++k)
        s += 0.5 * (p.v[k] + p.v[k - 1]) * (p.t[k] - p.t[k - 1]);
    return s;
}

const char* kStar = "G0 X0 Y30\nG1 X-17.634 Y-24.271 F900\nX28.532 Y9.271\nX-28.532 Y9.271\n"
                    "X17.634 Y-24.271\nX0 Y30\n";
/// Line, tangent half circle, line, tangent quarter circle, with a sharp corner at the end.
const char* kTangentJoins =
    "G1 X10 Y0 F600\nG3 X10 Y10 I0 J5\nG1 X0 Y10\nG3 X-5 Y5 I0 J-5\nG1 X10 Y5\n";

} // namespace

class TstFeedProfile : public QObject {
    Q_OBJECT
private slots:
    void trapezoidClosedForm_data();
    void trapezoidClosedForm();
    void sCurveClosedForm();
    void speedIntegratesToLength_data();
    void speedIntegratesToLength();
    void limitsHold_data();
    void limitsHold();
    void stopsAtSharpCornersOnly();
    void smallKinksKeepSpeed();
    void centripetalLimit();
    void samplesFollowThePath();
    void badOptions();
    void degenerateOptionsAreRefused_data();
    void degenerateOptionsAreRefused();
    void eachOptionsTimeBoundIsTight_data();
    void eachOptionsTimeBoundIsTight();
    void tinyPeakSpeedsArePlanned();
    void unsampledPlanKeepsTheRefusals();
    void runShorterThanAStepEndsOnASample();
};

void TstFeedProfile::trapezoidClosedForm_data() {
    QTest::addColumn<double>("length");
    QTest::addColumn<double>("feed");
    QTest::addColumn<double>("accel");
    QTest::addColumn<double>("expected");
    // L >= v^2/a: T = L/v + v/a. 100 mm at 20 mm/s, 100 mm/s^2: 5 + 0.2 = 5.2 s.
    QTest::newRow("trapezoid") << 100.0 << 20.0 << 100.0 << 5.2;
    // Exactly v^2/a = 4 mm: the cruise vanishes, T = 4/20 + 0.2 = 0.4 = 2 sqrt(4/100).
    QTest::newRow("boundary") << 4.0 << 20.0 << 100.0 << 0.4;
    // L < v^2/a: triangular, T = 2 sqrt(L/a) = 2 sqrt(0.02) s.
    QTest::newRow("triangle") << 2.0 << 20.0 << 100.0 << 2.0 * std::sqrt(0.02);
    QTest::newRow("long slow") << 600.0 << 1.5 << 10.0 << 600.0 / 1.5 + 1.5 / 10.0;
}

void TstFeedProfile::trapezoidClosedForm() {
    QFETCH(double, length);
    QFETCH(double, feed);
    QFETCH(double, accel);
    QFETCH(double, expected);
    const FeedProfile p = straightMove(length, feed, options(accel));
    // A few divisions and square roots: 1e-13 relative.
    XYT_COMPARE_NEAR(p.totalTimeSeconds, expected, 1e-13, 0.0);
    XYT_COMPARE_NEAR(p.s.back(), length, 1e-13, 0.0);
    XYT_COMPARE_NEAR(p.x.back(), length, 1e-13, 0.0);
    XYT_COMPARE_NEAR(p.v.back(), 0.0, 0.0, 1e-9);
}

void TstFeedProfile::sCurveClosedForm() {
    // With jerk J and v >= a^2/J each speed change takes v/a + a/J and covers v/2 of that
    // time, so T = L/v + v/a + a/J: 100 mm, 20 mm/s, 100 mm/s^2, 1000 mm/s^3: 5.3 s.
    const FeedProfile p = straightMove(100.0, 20.0, options(100.0, 1000.0));
    XYT_COMPARE_NEAR(p.totalTimeSeconds, 5.3, 1e-13, 0.0);
    QCOMPARE(p.pieces.size(), std::size_t(7)); // jerk, accel, jerk, cruise, jerk, decel, jerk
    // v < a^2/J: no constant-acceleration phase; 2 mm at 20 mm/s, a 100, J 1000 peaks where
    // 2 v sqrt(v/J) = 2 (each change covers v sqrt(v/J)): v = (J)^(1/3) = 10 mm/s, T = 4 sqrt(v/J)
    // = 0.4 s.
    const FeedProfile q = straightMove(2.0, 20.0, options(100.0, 1000.0));
    XYT_COMPARE_NEAR(q.totalTimeSeconds, 0.4, 1e-12, 0.0);
    XYT_COMPARE_NEAR(*std::max_element(q.v.begin(), q.v.end()), 10.0, 1e-3, 0.0); // sampled at 1 ms
    XYT_COMPARE_NEAR(xyt::speedChangeDistance(0.0, 20.0, 100.0, 1000.0), 3.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(xyt::speedChangeDistance(20.0, 0.0, 100.0, 0.0), 2.0, 1e-15, 0.0);
}

void TstFeedProfile::speedIntegratesToLength_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<double>("jerk");
    QTest::newRow("star trapezoid") << kStar << 0.0;
    QTest::newRow("star s-curve") << kStar << 5000.0;
    QTest::newRow("tangent joins trapezoid") << kTangentJoins << 0.0;
    QTest::newRow("tangent joins s-curve") << kTangentJoins << 2000.0;
    QTest::newRow("full circle") << "G0 X0 Y25\nG2 I0 J-25 F90\n" << 0.0;
}

void TstFeedProfile::speedIntegratesToLength() {
    QFETCH(QString, program);
    QFETCH(double, jerk);
    const auto gcode = xyt::readGcode(program.toStdString());
    const FeedProfile p = xyt::planFeedProfile(gcode, options(200.0, jerk, 1e-3));
    // The pieces' own distances sum to the length (round-off: 1e-12 relative).
    double pieces = 0.0;
    for (const auto& piece : p.pieces) {
        const double d = piece.duration;
        pieces += d * (piece.v0 + d * (piece.a0 / 2.0 + d * piece.jerk / 6.0));
    }
    XYT_COMPARE_NEAR(pieces, gcode.path.length(), 1e-12, 0.0);
    // The sampled speed, integrated by the trapezoidal rule at 1 ms: exact on the linear
    // stretches; each kink of v off the sample grid costs at most |jump of a| dt^2/8
    // = 400 x 1e-6 / 8 = 5e-5 mm, and there are at most 4 per segment (< 40 here): 2e-3 mm.
    XYT_COMPARE_NEAR(integratedSpeed(p), gcode.path.length(), 0.0, 2e-3);
    XYT_COMPARE_NEAR(p.s.back(), gcode.path.length(), 1e-12, 0.0);
}

void TstFeedProfile::limitsHold_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<double>("accel");
    QTest::addColumn<double>("jerk");
    QTest::newRow("star") << kStar << 200.0 << 0.0;
    QTest::newRow("star jerk") << kStar << 200.0 << 3000.0;
    QTest::newRow("joins") << kTangentJoins << 50.0 << 0.0;
    QTest::newRow("joins jerk") << kTangentJoins << 50.0 << 500.0;
    QTest::newRow("short segments jerk") << "G1 X0.1 F3000\nX0.2 Y0.001\nX0.3\nX0.4 Y0.002\nX5\n"
                                         << 1000.0 << 1e5;
}

void TstFeedProfile::limitsHold() {
    QFETCH(QString, program);
    QFETCH(double, accel);
    QFETCH(double, jerk);
    const auto gcode = xyt::readGcode(program.toStdString());
    const auto o = options(accel, jerk);
    const FeedProfile p = xyt::planFeedProfile(gcode, o);
    std::vector<double> feeds;
    for (const auto& s : gcode.segments)
        feeds.push_back(s.feedMmPerSec);
    checkLimits(p, gcode.path, feeds, o);
    // The samples agree: |a| within the limit, v >= 0.
    for (std::size_t k = 0; k < p.t.size(); ++k) {
        QVERIFY(std::abs(p.a[k]) <= accel * (1.0 + 1e-9));
        QVERIFY(p.v[k] >= 0.0);
    }
}

void TstFeedProfile::stopsAtSharpCornersOnly() {
    // The square of resources/examples: three inner corners of 90 degrees, speed 0 there.
    const auto square = xyt::readGcode("G1 X40 Y0 F600\nY40\nX0\nY0\n");
    const FeedProfile p = xyt::planFeedProfile(square, options(100.0));
    QCOMPARE(p.corners, (std::vector<std::size_t>{1, 2, 3}));
    for (std::size_t i = 0; i <= 4; ++i)
        QCOMPARE(p.junctionSpeed[i], 0.0);
    // Each side alone: T = 40/10 + 10/100 = 4.1 s, four sides 16.4 s (closed form).
    XYT_COMPARE_NEAR(p.totalTimeSeconds, 4 * 4.1, 1e-13, 0.0);
    // The sample at a corner's time has speed 0 (1 ms grid: the corner at 4.1 s is a sample).
    XYT_COMPARE_NEAR(p.v[4100], 0.0, 0.0, 1e-9);

    // Tangent joins: line -> half circle (R 5) -> line -> quarter circle -> line, 10 mm/s,
    // sqrt(a R) = sqrt(100 x 5) = 22 > 10: the joins pass at the full 10 mm/s. The last join
    // (the quarter circle ends heading down, the line heads +x) is a 90-degree corner.
    const auto joins = xyt::readGcode(kTangentJoins);
    const FeedProfile q = xyt::planFeedProfile(joins, options(100.0));
    QCOMPARE(q.corners, (std::vector<std::size_t>{4}));
    for (std::size_t i = 1; i <= 3; ++i)
        XYT_COMPARE_NEAR(q.junctionSpeed[i], 10.0, 1e-15, 0.0);
    QCOMPARE(q.junctionSpeed[4], 0.0);
}

void TstFeedProfile::smallKinksKeepSpeed() {
    // A join turning 0.5 degree (under the 1-degree threshold) keeps the speed; 2 degrees stops.
    const auto kink = [](double deg) {
        const double r = deg * 3.14159265358979323846 / 180.0;
        return "G1 X10 F600\nX" + std::to_string(10.0 + 10.0 * std::cos(r)) + " Y" +
               std::to_string(10.0 * std::sin(r)) + "\n";
    };
    XYT_COMPARE_NEAR(profileOf(kink(0.5), options(100.0)).junctionSpeed[1], 10.0, 1e-15, 0.0);
    QCOMPARE(profileOf(kink(2.0), options(100.0)).junctionSpeed[1], 0.0);
    auto wide = options(100.0);
    wide.cornerAngleDeg = 5.0;
    XYT_COMPARE_NEAR(profileOf(kink(2.0), wide).junctionSpeed[1], 10.0, 1e-15, 0.0);
}

void TstFeedProfile::centripetalLimit() {
    // R 25 at F6000 (100 mm/s) with a = 100 mm/s^2: v <= sqrt(a R) = 50 mm/s on the circle.
    const FeedProfile p = profileOf("G0 X0 Y25\nG2 I0 J-25 F6000\n", options(100.0));
    double peak = 0.0;
    for (std::size_t k = 0; k < p.t.size(); ++k)
        if (p.segment[k] == 1)
            peak = std::max(peak, p.v[k]);
    XYT_COMPARE_NEAR(peak, 50.0, 1e-12, 0.0);
}

void TstFeedProfile::samplesFollowThePath() {
    // Every sampled point lies on the path at its s: |(x, y) - path(s)| = 0, and successive
    // samples are as far apart as the speed says (|dp| <= v_max dt).
    const auto gcode = xyt::readGcode(kTangentJoins);
    const FeedProfile p = xyt::planFeedProfile(gcode, options(100.0, 0.0, 0.002));
    for (std::size_t k = 0; k < p.t.size(); ++k) {
        const auto at = gcode.path.at(p.s[k]);
        XYT_COMPARE_NEAR(p.x[k], at.point.x, 0.0, 1e-9);
        XYT_COMPARE_NEAR(p.y[k], at.point.y, 0.0, 1e-9);
        XYT_COMPARE_NEAR(p.t[k], 0.002 * static_cast<double>(k), 1e-15, 0.0);
        if (k > 0)
            QVERIFY(std::hypot(p.x[k] - p.x[k - 1], p.y[k] - p.y[k - 1]) <=
                    10.0 * 0.002 * (1.0 + 1e-9));
    }
    QVERIFY(p.t.back() >= p.totalTimeSeconds);
    QVERIFY(p.t.back() - 0.002 < p.totalTimeSeconds);
}

void TstFeedProfile::badOptions() {
    const auto gcode = xyt::readGcode("G1 X10 F600\n");
    const auto fieldOf = [&](FeedProfileOptions o) {
        return xyt::test::invalidInputField([&] { xyt::planFeedProfile(gcode, o); });
    };
    auto o = options(100.0);
    o.maxAccelMmPerS2 = 0.0;
    QCOMPARE(fieldOf(o), QStringLiteral("max_accel"));
    o = options(100.0, -1.0);
    QCOMPARE(fieldOf(o), QStringLiteral("max_jerk"));
    o = options(100.0, 0.0, 0.0);
    QCOMPARE(fieldOf(o), QStringLiteral("dt"));
    o = options(100.0);
    o.feedScale = std::nan("");
    QCOMPARE(fieldOf(o), QStringLiteral("feed_scale"));
    o = options(100.0);
    o.cornerAngleDeg = 180.0;
    QCOMPARE(fieldOf(o), QStringLiteral("corner_angle"));
    // 10 mm at 10 mm/s lasts 1.1 s: 1101 samples at 1 ms, over a limit of 1000.
    o = options(100.0);
    o.maxSamples = 1000;
    QCOMPARE(fieldOf(o), QStringLiteral("dt"));
    o.maxSamples = 1101;
    QCOMPARE(fieldOf(o), QStringLiteral("<no exception>"));
    QVERIFY_THROWS_EXCEPTION(xyt::InvalidInput,
                             xyt::planFeedProfile(gcode.path, {1.0, 2.0}, options(1.0)));
}

void TstFeedProfile::degenerateOptionsAreRefused_data() {
    QTest::addColumn<QString>("option");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("reason"); // a part of it; empty: any
    const double nan = std::nan(""), inf = HUGE_VAL, subnormal = 5e-324;
    // "G0 X5 / G1 F600 X10": 5 mm of rapid and 5 mm at 10 mm/s; acceleration 100, dt 1 ms, at
    // most 2e7 samples (2e4 s). The times are the header's lower bounds over L = 10 mm:
    // 4 (L / 2J)^(1/3) for the jerk, 2 sqrt(L / A) for the acceleration. A jerk of 1e-200 is the
    // shared session that crashed the workbench (the bisection ended at 0, no piece written).
    QTest::newRow("jerk 1e-200") << "max_jerk" << 1e-200 << "max_jerk"
                                 << "1e-200 mm/s^3 needs at least 3.17e+67 s";
    QTest::newRow("jerk 1e-300") << "max_jerk" << 1e-300 << "max_jerk"
                                 << "needs at least 6.84e+100 s";
    QTest::newRow("jerk subnormal") << "max_jerk" << subnormal << "max_jerk"
                                    << "needs at least 4.02e+108 s";
    QTest::newRow("jerk 1e300") << "max_jerk" << 1e300 << "max_jerk"
                                << "is outside the planner's range [1e-100, 1e+100]";
    QTest::newRow("jerk inf") << "max_jerk" << inf << "max_jerk"
                              << "";
    QTest::newRow("jerk nan") << "max_jerk" << nan << "max_jerk"
                              << "";
    QTest::newRow("accel 1e-300") << "max_accel" << 1e-300 << "max_accel"
                                  << "needs at least 6.32e+150 s";
    QTest::newRow("accel subnormal") << "max_accel" << subnormal << "max_accel"
                                     << "needs at least 2.85e+162 s";
    QTest::newRow("accel 1e300") << "max_accel" << 1e300 << "max_accel"
                                 << "is outside the planner's range";
    QTest::newRow("accel inf") << "max_accel" << inf << "max_accel"
                               << "";
    QTest::newRow("accel nan") << "max_accel" << nan << "max_accel"
                               << "";
    QTest::newRow("scale 1e-300") << "feed_scale" << 1e-300 << "feed_scale"
                                  << "makes the feed of line 2 (10 mm/s) 1e-299 mm/s";
    QTest::newRow("scale subnormal") << "feed_scale" << subnormal << "feed_scale"
                                     << "";
    QTest::newRow("scale 1e-5") << "feed_scale" << 1e-5 << "feed_scale"
                                << "the program needs at least 5e+04 s";
    QTest::newRow("scale 1e300") << "feed_scale" << 1e300 << "feed_scale"
                                 << "1e+301 mm/s, outside";
    QTest::newRow("scale inf") << "feed_scale" << inf << "feed_scale"
                               << "";
    QTest::newRow("scale nan") << "feed_scale" << nan << "feed_scale"
                               << "";
    QTest::newRow("corner nan") << "corner_angle" << nan << "corner_angle"
                                << "";
    QTest::newRow("corner 1e300") << "corner_angle" << 1e300 << "corner_angle"
                                  << "";
    QTest::newRow("corner -1") << "corner_angle" << -1.0 << "corner_angle"
                               << "";
    QTest::newRow("dt subnormal") << "dt" << subnormal << "dt"
                                  << "the program needs at least 0.5 s at its own feeds";
    QTest::newRow("dt inf") << "dt" << inf << "dt"
                            << "";
    QTest::newRow("dt nan") << "dt" << nan << "dt"
                            << "";
}

void TstFeedProfile::degenerateOptionsAreRefused() {
    QFETCH(QString, option);
    QFETCH(double, value);
    QFETCH(QString, field);
    QFETCH(QString, reason);
    const auto gcode = xyt::readGcode("G0 X5\nG1 F600 X10\n");
    FeedProfileOptions o = options(100.0);
    (option == "max_jerk"       ? o.maxJerkMmPerS3
     : option == "max_accel"    ? o.maxAccelMmPerS2
     : option == "feed_scale"   ? o.feedScale
     : option == "corner_angle" ? o.cornerAngleDeg
                                : o.dtSeconds) = value;
    for (const bool withSamples : {true, false}) {
        o.withSamples = withSamples;
        const QString message =
            xyt::test::invalidInputMessage([&] { xyt::planFeedProfile(gcode, o); });
        QVERIFY2(message.startsWith(field + ": ") && message.contains(reason), qPrintable(message));
    }
}

void TstFeedProfile::eachOptionsTimeBoundIsTight_data() {
    QTest::addColumn<QString>("option");
    QTest::addColumn<double>("bound"); // the value whose lower bound on the run time is 1 s
    // 10 mm with the other two limits out of the way (1e100): the profile is the bound's own
    // closed form, so the option at its bound plans a 1 s run, which 1001 samples at 1 ms hold.
    // Feed: T = L / f + f / A -> f = 10 mm/s. Acceleration: T = 2 sqrt(L / A) -> A = 4 L = 40.
    // Jerk: T = 4 (L / 2J)^(1/3) -> J = 32 L = 320.
    QTest::newRow("feed") << "feed" << 10.0;
    QTest::newRow("max_accel") << "max_accel" << 40.0;
    QTest::newRow("max_jerk") << "max_jerk" << 320.0;
}

void TstFeedProfile::eachOptionsTimeBoundIsTight() {
    QFETCH(QString, option);
    QFETCH(double, bound);
    const xyt::Path path({xyt::PathSegment::line({0.0, 0.0}, {10.0, 0.0})});
    const auto plan = [&](double value) {
        FeedProfileOptions o =
            options(option == "max_accel" ? value : 1e100, option == "max_jerk" ? value : 0.0);
        o.maxSamples = 1001;
        return xyt::planFeedProfile(path, {option == "feed" ? value : 1e100}, o);
    };
    // 1e-6 above the bound: planned, lasting the closed form's 1 s less a hair.
    const FeedProfile p = plan(bound * (1.0 + 1e-6));
    XYT_COMPARE_NEAR(p.totalTimeSeconds, 1.0, 1e-6, 0.0);
    QCOMPARE(p.t.size(), std::size_t(1001));
    XYT_COMPARE_NEAR(p.s.back(), 10.0, 1e-12, 0.0);
    // 1e-6 below: refused by the option's name before planning, not by "dt" after it.
    QCOMPARE(xyt::test::invalidInputField([&] { plan(bound * (1.0 - 1e-6)); }), option);
}

void TstFeedProfile::tinyPeakSpeedsArePlanned() {
    // A 1e-30 mm move at the smallest jerk the planner takes (1e-100), with a step long enough
    // for the samples to hold it: the peak is (L sqrt(J) / 2)^(2/3) = 2.9e-54 mm/s, 3e-154 of the
    // 1e100 cap, beyond 200 halvings of the value (the old bisection returned 0 and wrote no
    // piece). T = 4 (L / 2J)^(1/3) = 6.8e23 s.
    const double length = 1e-30, jerk = 1e-100;
    FeedProfileOptions o = options(1e100, jerk, 1e30);
    const xyt::Path path({xyt::PathSegment::line({0.0, 0.0}, {length, 0.0})});
    const FeedProfile p = xyt::planFeedProfile(path, {1e100}, o);
    XYT_COMPARE_NEAR(p.totalTimeSeconds, 4.0 * std::cbrt(length / (2.0 * jerk)), 1e-9, 0.0);
    double peak = 0.0;
    for (const auto& piece : p.pieces)
        peak = std::max(peak, piece.v0);
    XYT_COMPARE_NEAR(peak, std::pow(length * std::sqrt(jerk) / 2.0, 2.0 / 3.0), 1e-9, 0.0);
    XYT_COMPARE_NEAR(p.s.back(), length, 1e-12, 0.0);
    // The same between rests on a 10 mm arc-free move with a fine step: a jerk of 1e-6 needs
    // 4 (5e6)^(1/3) = 684 s, which 1e6 samples at 1 ms hold.
    o = options(100.0, 1e-6, 1e-3);
    o.maxSamples = 1'000'000;
    const FeedProfile q = straightMove(10.0, 10.0, o);
    XYT_COMPARE_NEAR(q.totalTimeSeconds, 4.0 * std::cbrt(10.0 / 2e-6), 1e-9, 0.0);
    XYT_COMPARE_NEAR(q.s.back(), 10.0, 1e-9, 0.0);
}

void TstFeedProfile::unsampledPlanKeepsTheRefusals() {
    const auto gcode = xyt::readGcode(kStar);
    FeedProfileOptions o = options(200.0, 5000.0);
    const FeedProfile sampled = xyt::planFeedProfile(gcode, o);
    o.withSamples = false;
    const FeedProfile unsampled = xyt::planFeedProfile(gcode, o);
    QCOMPARE(unsampled.totalTimeSeconds, sampled.totalTimeSeconds);
    QCOMPARE(unsampled.pieces.size(), sampled.pieces.size());
    QVERIFY(unsampled.t.empty());
    // The sample bound holds without the samples: one sample short of the run is refused.
    o.maxSamples = sampled.t.size() - 1;
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::planFeedProfile(gcode, o); }),
             QStringLiteral("dt"));
    o.maxSamples = sampled.t.size();
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::planFeedProfile(gcode, o); }),
             QStringLiteral("<no exception>"));
    // A path without segments is refused, not read past its end.
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::planFeedProfile(xyt::Path(), {}, o); }),
             QStringLiteral("path"));
}

void TstFeedProfile::runShorterThanAStepEndsOnASample() {
    // A 1 mm move at 100 mm/s and 1e6 mm/s^2 takes 1/100 + 100/1e6 = 0.0101 s (trapezoid closed
    // form); at dt = 1e9 s the run is 1e-11 of a step, less than the 1e-9 of a step forgiven to
    // a whole number of steps, which once gave a single sample at t = 0 and s = 0. The samples
    // are t = 0 and t = dt, the second holding the end of the path at rest.
    FeedProfileOptions o = options(1e6, 0.0, 1e9);
    const FeedProfile p = straightMove(1.0, 100.0, o);
    XYT_COMPARE_NEAR(p.totalTimeSeconds, 0.0101, 1e-12, 0.0);
    QCOMPARE(p.t.size(), std::size_t(2));
    QCOMPARE(p.t.back(), 1e9);
    XYT_COMPARE_NEAR(p.s.back(), 1.0, 1e-12, 0.0);
    QCOMPARE(p.v.back(), 0.0);
    // Two samples need a bound of two: one is refused, with or without the samples, by the
    // first bound checked (the feed alone needs 0.01 s, one step).
    o.maxSamples = 1;
    QCOMPARE(xyt::test::invalidInputField([&] { straightMove(1.0, 100.0, o); }),
             QStringLiteral("feed"));
    o.withSamples = false;
    QCOMPARE(xyt::test::invalidInputField([&] { straightMove(1.0, 100.0, o); }),
             QStringLiteral("feed"));
}

QTEST_APPLESS_MAIN(TstFeedProfile)
#include "tst_feed_profile.moc"
