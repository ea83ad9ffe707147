// SPDX-License-Identifier: GPL-3.0-or-later
// The friction experiment (core/identification/jog_experiment.h) and its estimator
// (core/identification/friction_identification.h): the jog reference against the closed form
// of the trapezoid; the steady points of a jog log made here in closed form (position = the
// reference delayed by a whole number of samples, command = the Stribeck curve of the delayed
// reference velocity plus white or AR(1) noise at fixed seeds); the curve fit exact on exact
// data, within 3 reported standard deviations at a fixed seed, its standard deviations against
// the spread over 200 seeds, the Stribeck model kept where the data hold a dip and not on a
// line; invalid input by field.
#include "core/identification/friction_identification.h"
#include "core/identification/jog_experiment.h"
#include "core/model/errors.h"
#include "tests/support/identification_data.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace xyt;
using namespace xyt::test;

namespace {

/// u(v) = sign(v) (Fc + (Fs - Fc) exp(-(|v| / vs)^2)) + b v, written out again here; Fs = Fc
/// (and any vs) is the straight line.
struct Curve {
    double fc = 0.3;
    double fs = 0.3;
    double vs = 1.0;
    double b = 0.02;

    double operator()(double v) const {
        if (v == 0.0)
            return 0.0;
        const double sign = v > 0 ? 1.0 : -1.0;
        const double x = std::abs(v) / vs;
        return sign * (fc + (fs - fc) * std::exp(-x * x)) + b * v;
    }
};

/// A line: Fc = 0.3 V, b = 0.02 V per mm/s.
Curve line() {
    return Curve{};
}

/// A clear Stribeck dip: Fs = 0.5 V above Fc = 0.3 V, vs = 2 mm/s.
Curve dip() {
    return Curve{0.3, 0.5, 2.0, 0.02};
}

/// One point per speed and direction (+v then -v), volts = curve + N(0, sigma^2) at @p seed.
std::vector<FrictionPoint> curvePoints(const Curve& curve, const std::vector<double>& speeds,
                                       double sigma, std::uint64_t seed) {
    const std::vector<double> noise = gaussianNoise(2 * speeds.size(), sigma, seed);
    std::vector<FrictionPoint> points;
    for (std::size_t i = 0; i < speeds.size(); ++i)
        for (double sign : {1.0, -1.0}) {
            const double v = sign * speeds[i];
            points.push_back(FrictionPoint{v, curve(v) + noise[points.size()], sigma, 100});
        }
    return points;
}

const std::vector<double> kLineSpeeds{2, 5, 10, 20, 40, 80};   // 12 points
const std::vector<double> kDipSpeeds{0.5, 1, 2, 4, 8, 16, 32}; // 14 points, vs = 2 inside
constexpr std::size_t kDelaySamples = 5;                       // the loop's lag: 50 ms
constexpr double kOffsetMm = 12.5;                             // where the table starts

/// A jog log: t, reference, position, command.
struct JogLog {
    JogReference reference;
    std::vector<double> position;
    std::vector<double> command;
};

/// The reference velocity at time @p t, in closed form from the program's segments and ramps.
double referenceVelocity(const JogReference& r, double accel, double t) {
    for (const JogSegment& s : r.segments) {
        const double ramp = std::abs(s.velocityMmPerS) / accel;
        if (t >= s.startSeconds - ramp && t < s.startSeconds)
            return s.velocityMmPerS * (t - (s.startSeconds - ramp)) / ramp;
        if (t >= s.startSeconds && t <= s.endSeconds)
            return s.velocityMmPerS;
        if (t > s.endSeconds && t < s.endSeconds + ramp)
            return s.velocityMmPerS * (s.endSeconds + ramp - t) / ramp;
    }
    return 0.0;
}

/**
 * The log of a loop that follows the reference with a pure delay of kDelaySamples: position[k] =
 * kOffsetMm + reference[k - delay] (the start value before), command[k] = curve(reference
 * velocity at t[k] - delay) + noise[k]; the noise is AR(1), n[k] = phi n[k-1] + e[k] with e
 * white of standard deviation sigma (phi = 0: white), at @p seed.
 */
JogLog jogLog(const JogProgram& program, const Curve& curve, double sigma, double phi,
              std::uint64_t seed) {
    JogLog log;
    log.reference = jogReference(program);
    const std::vector<double>& r = log.reference.position;
    const std::size_t n = r.size();
    const std::vector<double> e = gaussianNoise(n, sigma, seed);
    log.position.resize(n);
    log.command.resize(n);
    const double delay = static_cast<double>(kDelaySamples) * program.tsSeconds;
    double noise = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        log.position[k] = kOffsetMm + (k >= kDelaySamples ? r[k - kDelaySamples] : r[0]);
        noise = phi * noise + e[k];
        log.command[k] = curve(referenceVelocity(log.reference, program.accelMmPerS2,
                                                 log.reference.t[k] - delay)) +
                         noise;
    }
    return log;
}

/// Speeds 1, 2, 5, 10, 20 mm/s over 20 mm at 100 mm/s^2, Ts = 10 ms (85.8 s).
JogProgram logProgram() {
    JogProgram p;
    p.speedsMmPerS = {1, 2, 5, 10, 20};
    return p;
}

/// The field of the InvalidInput that @p call throws, or "" when it throws none.
std::string fieldOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const InvalidInput& e) {
        return e.field();
    }
    return {};
}

/// The relative sampling error of a standard deviation estimated from @p draws draws:
/// 1 / sqrt(2 (draws - 1)) (normal data).
double sdSamplingError(std::size_t draws) {
    return 1.0 / std::sqrt(2.0 * static_cast<double>(draws - 1));
}

} // namespace

class TstFrictionIdentification : public QObject {
    Q_OBJECT

private slots:
    // Closed form of the program speeds {5, 10} mm/s, 20 mm, 100 mm/s^2, dwell 1 s, Ts 10 ms:
    // move times T = D / V + V / A = 4.05 s and 2.1 s, duration 1 + 2 (4.05 + 1) + 2 (2.1 + 1)
    // = 17.3 s, so 1731 samples; rests at 0 at both ends and at exactly 20 mm between moves.
    // Times are sums of a few doubles: 1e-12 s absolute.
    void jogReferenceClosedForm() {
        JogProgram p;
        p.speedsMmPerS = {5, 10};
        const JogReference r = jogReference(p);
        QCOMPARE(r.t.size(), std::size_t(1731));
        QCOMPARE(r.position.size(), r.t.size());
        for (std::size_t k = 0; k < r.t.size(); ++k)
            QCOMPARE(r.t[k], static_cast<double>(k) * 0.01); // the same product, bit for bit
        XYT_COMPARE_NEAR(r.t.back(), 17.3, 0.0, 1e-12);
        // Exactly at rest at 0 at both ends, exactly at D while the axis dwells out there.
        XYT_COMPARE_NEAR(r.position.front(), 0.0, 0.0, 0.0);
        XYT_COMPARE_NEAR(r.position.back(), 0.0, 0.0, 0.0);
        XYT_COMPARE_NEAR(*std::max_element(r.position.begin(), r.position.end()), 20.0, 0.0, 0.0);
        XYT_COMPARE_NEAR(*std::min_element(r.position.begin(), r.position.end()), 0.0, 0.0, 0.0);
        XYT_COMPARE_NEAR(r.position[550], 20.0, 0.0, 0.0); // t = 5.5 s: in the first dwell out
        // Segments: start = move start + V / A, end = move start + D / V.
        const std::vector<JogSegment> expected{
            {1.05, 5.0, 5.0}, {6.1, 10.05, -5.0}, {11.2, 13.1, 10.0}, {14.3, 16.2, -10.0}};
        QCOMPARE(r.segments.size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            XYT_COMPARE_NEAR(r.segments[i].startSeconds, expected[i].startSeconds, 0.0, 1e-12);
            XYT_COMPARE_NEAR(r.segments[i].endSeconds, expected[i].endSeconds, 0.0, 1e-12);
            QCOMPARE(r.segments[i].velocityMmPerS, expected[i].velocityMmPerS);
        }
    }

    // Finite differences of the closed form: inside a cruise (p[k+1] - p[k]) / Ts = V; inside a
    // ramp the second difference is A Ts^2 (a parabola's is exact). Positions of up to 20 mm
    // carry 4e-15 mm of round-off, 8e-13 of the 5e-3 mm cruise step and 4e-10 of the 1e-2 mm
    // second difference: 1e-10 and 1e-8 relative. No step exceeds V Ts.
    void jogReferenceFiniteDifferences() {
        JogProgram p;
        p.speedsMmPerS = {5, 10};
        const JogReference r = jogReference(p);
        const double ts = p.tsSeconds, a = p.accelMmPerS2;
        std::size_t cruiseSteps = 0, rampSteps = 0;
        for (std::size_t k = 1; k + 1 < r.t.size(); ++k) {
            QVERIFY(std::abs(r.position[k + 1] - r.position[k]) <= 10.0 * ts * (1 + 1e-12));
            for (const JogSegment& s : r.segments) {
                const double ramp = std::abs(s.velocityMmPerS) / a;
                const double margin = 1e-9;
                if (r.t[k] >= s.startSeconds + margin && r.t[k + 1] <= s.endSeconds - margin) {
                    XYT_COMPARE_NEAR((r.position[k + 1] - r.position[k]) / ts, s.velocityMmPerS,
                                     1e-10, 0.0);
                    ++cruiseSteps;
                }
                const double rampStart = s.startSeconds - ramp;
                if (r.t[k - 1] >= rampStart + margin && r.t[k + 1] <= s.startSeconds - margin) {
                    const double second =
                        (r.position[k + 1] - 2.0 * r.position[k] + r.position[k - 1]) / (ts * ts);
                    XYT_COMPARE_NEAR(second, s.velocityMmPerS > 0 ? a : -a, 1e-8, 0.0);
                    ++rampSteps;
                }
            }
        }
        // About 394 + 394 + 189 + 189 cruise steps; the ramps up of 5 and 10 samples hold 2 and 7
        // samples whose neighbours lie strictly inside, in each direction.
        QVERIFY2(cruiseSteps >= 1160, qPrintable(QString::number(cruiseSteps)));
        QCOMPARE(rampSteps, std::size_t(18));
    }

    void jogReferenceRefusals() {
        const auto field = [](const std::function<void(JogProgram&)>& change) {
            JogProgram p;
            p.speedsMmPerS = {5, 10};
            change(p);
            return fieldOf([&] { jogReference(p); });
        };
        QCOMPARE(field([](JogProgram&) {}), std::string());
        QCOMPARE(field([](JogProgram& p) { p.speedsMmPerS.clear(); }), std::string("speeds"));
        QCOMPARE(field([](JogProgram& p) { p.speedsMmPerS[1] = NAN; }), std::string("speeds"));
        QCOMPARE(field([](JogProgram& p) { p.speedsMmPerS[1] = 0.0; }), std::string("speeds"));
        QCOMPARE(field([](JogProgram& p) { p.speedsMmPerS[0] = -5.0; }), std::string("speeds"));
        QCOMPARE(field([](JogProgram& p) { p.speedsMmPerS.assign(kMaxJogSpeeds + 1, 5.0); }),
                 std::string("speeds"));
        QCOMPARE(field([](JogProgram& p) { p.travelMm = 0.0; }), std::string("travel"));
        QCOMPARE(field([](JogProgram& p) { p.travelMm = INFINITY; }), std::string("travel"));
        // 3 V^2 / A = 12 mm at 20 mm/s: 11.9 mm is too short for the cruise to last half the
        // move, 12 mm is just enough.
        QCOMPARE(field([](JogProgram& p) {
                     p.speedsMmPerS = {20};
                     p.travelMm = 11.9;
                 }),
                 std::string("travel"));
        QCOMPARE(field([](JogProgram& p) {
                     p.speedsMmPerS = {20};
                     p.travelMm = 12.0;
                 }),
                 std::string());
        QCOMPARE(field([](JogProgram& p) { p.accelMmPerS2 = -1.0; }), std::string("accel"));
        QCOMPARE(field([](JogProgram& p) { p.accelMmPerS2 = NAN; }), std::string("accel"));
        QCOMPARE(field([](JogProgram& p) { p.dwellSeconds = -0.1; }), std::string("dwell"));
        QCOMPARE(field([](JogProgram& p) { p.dwellSeconds = NAN; }), std::string("dwell"));
        QCOMPARE(field([](JogProgram& p) { p.dwellSeconds = 0.0; }), std::string());
        QCOMPARE(field([](JogProgram& p) { p.tsSeconds = 0.0; }), std::string("ts"));
        QCOMPARE(field([](JogProgram& p) { p.tsSeconds = NAN; }), std::string("ts"));
        // 17.3 s at 1 us: 1.7e7 samples, over kMaxJogSamples.
        QCOMPARE(field([](JogProgram& p) { p.tsSeconds = 1e-6; }), std::string("ts"));
    }

    // The log of jogLog with white noise of 10 mV: one point per cruise, in time order, at the
    // cruise's velocity to round-off (the delayed reference is exactly linear over the steady
    // part; positions of 32.5 mm carry 7e-15 mm of round-off and times 2e-14 s, so the slope
    // over >= 0.4 s is off by < 1e-12 mm/s: 1e-10 relative), the mean command within 3 of its
    // reported standard deviations of the curve, and that standard deviation near
    // sigma / sqrt(n) = the truth for white noise: s within 4 of its standard errors
    // (1 / sqrt(2 (n - 1)) relative) and the lag-1 estimate r within 4 of its (1 / sqrt(n)),
    // each bound taken at its end. (The box is wide at the 41 samples of the 20 mm/s cruise, where
    // this seed's r is 0.56, 3.6 standard errors, and tight at the 1000 samples of 1 mm/s.)
    void steadyPointsOfJogLog() {
        const JogProgram program = logProgram();
        const double sigma = 0.01;
        const JogLog log = jogLog(program, dip(), sigma, 0.0, 2024);
        const std::vector<FrictionPoint> points =
            steadyJogPoints(log.reference.t, log.reference.position, log.position, log.command, {});
        const std::vector<JogSegment>& segments = log.reference.segments;
        QCOMPARE(points.size(), segments.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const FrictionPoint& p = points[i];
            const double v = segments[i].velocityMmPerS;
            XYT_COMPARE_NEAR(p.velocityMmPerS, v, 1e-10, 0.0);
            QVERIFY2(std::abs(p.volts - dip()(v)) <= 3.0 * p.voltsStd,
                     qPrintable(QStringLiteral("v %1: %2 V vs %3 V +- %4")
                                    .arg(v)
                                    .arg(p.volts)
                                    .arg(dip()(v))
                                    .arg(p.voltsStd)));
            // The second half of the cruise: (end - start) / (2 Ts) samples, +-2 for where the
            // run's ends and the half fall between samples.
            const double half =
                0.5 * (segments[i].endSeconds - segments[i].startSeconds) / program.tsSeconds;
            QVERIFY2(
                std::abs(static_cast<double>(p.samples) - half) <= 2.0,
                qPrintable(QStringLiteral("%1 samples, %2 expected").arg(p.samples).arg(half)));
            const double n = static_cast<double>(p.samples);
            const double ideal = sigma / std::sqrt(n);
            const double sBand = 4.0 / std::sqrt(2.0 * (n - 1.0));
            const double rhoMax = 4.0 / std::sqrt(n);
            const double low = (1.0 - sBand) * ideal; // r clamped at 0: factor >= 1
            const double high = (1.0 + sBand) * std::sqrt((1.0 + rhoMax) / (1.0 - rhoMax)) * ideal;
            QVERIFY2(p.voltsStd >= low && p.voltsStd <= high,
                     qPrintable(QStringLiteral("n %1: voltsStd %2 outside [%3, %4]")
                                    .arg(n)
                                    .arg(p.voltsStd)
                                    .arg(low)
                                    .arg(high)));
        }
    }

    // AR(1) command noise (phi = 0.5, the loop's correlation): the standard deviation of the
    // mean is sigma_n / sqrt(n) sqrt((1 + phi) / (1 - phi)), 1.73 times the white-noise
    // formula. Over 200 seeds the spread of volts at the two slowest cruises (about 1000
    // samples each, where the lag-1 estimate's O(1/n) bias is 0.3 %) agrees with the mean
    // reported voltsStd within 4 sampling errors of a standard deviation from 200 draws
    // (4 / sqrt(398) = 20 %).
    void voltsStdFollowsCorrelatedNoise() {
        JogProgram program;
        program.speedsMmPerS = {1, 2};
        std::vector<std::vector<double>> volts(2), reported(2);
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            const JogLog log = jogLog(program, dip(), 0.01, 0.5, 5000 + seed);
            const std::vector<FrictionPoint> points = steadyJogPoints(
                log.reference.t, log.reference.position, log.position, log.command, {});
            QCOMPARE(points.size(), std::size_t(4));
            for (std::size_t i = 0; i < 2; ++i) {
                volts[i].push_back(points[i].volts);
                reported[i].push_back(points[i].voltsStd);
            }
        }
        for (std::size_t i = 0; i < 2; ++i) {
            double mean = 0, spread = 0, meanSd = 0, unused = 0;
            meanAndSpread(volts[i], mean, spread);
            meanAndSpread(reported[i], meanSd, unused);
            qInfo("point %zu: spread of volts %.4g V, mean reported voltsStd %.4g V (ratio %.3f)",
                  i, spread, meanSd, spread / meanSd);
            XYT_COMPARE_NEAR(spread, meanSd, 4.0 * sdSamplingError(200), 0.0);
        }
    }

    void steadyPointsRefusals() {
        const JogLog log = jogLog(logProgram(), dip(), 0.01, 0.0, 1);
        const std::vector<double>& t0 = log.reference.t;
        const std::vector<double>& r0 = log.reference.position;
        const auto field = [&](std::vector<double> t, std::vector<double> r, std::vector<double> p,
                               std::vector<double> u, FrictionIdentificationOptions o = {}) {
            return fieldOf([&] { steadyJogPoints(t, r, p, u, o); });
        };
        const auto with = [](std::vector<double> v, std::size_t k, double x) {
            v[k] = x;
            return v;
        };
        const auto shorter = [](std::vector<double> v) {
            v.pop_back();
            return v;
        };
        QCOMPARE(field(t0, r0, log.position, log.command), std::string());
        QCOMPARE(field(with(t0, 10, NAN), r0, log.position, log.command), std::string("t"));
        QCOMPARE(field(with(t0, 10, t0[9]), r0, log.position, log.command), std::string("t"));
        // A step 1e-4 of Ts off: beyond the 1e-6 uniformity.
        QCOMPARE(field(with(t0, 10, t0[10] + 1e-6), r0, log.position, log.command),
                 std::string("t"));
        QCOMPARE(field({0.0}, {0.0}, {0.0}, {0.0}), std::string("t"));
        QCOMPARE(field(t0, shorter(r0), log.position, log.command), std::string("reference"));
        QCOMPARE(field(t0, with(r0, 3, INFINITY), log.position, log.command),
                 std::string("reference"));
        QCOMPARE(field(t0, r0, shorter(log.position), log.command), std::string("position"));
        QCOMPARE(field(t0, r0, with(log.position, 3, NAN), log.command), std::string("position"));
        QCOMPARE(field(t0, r0, log.position, shorter(log.command)), std::string("command"));
        QCOMPARE(field(t0, r0, log.position, with(log.command, 3, NAN)), std::string("command"));
        FrictionIdentificationOptions o;
        o.settleFraction = 1.0;
        QCOMPARE(field(t0, r0, log.position, log.command, o), std::string("settle_fraction"));
        o = {};
        o.referenceTolerance = 0.0;
        QCOMPARE(field(t0, r0, log.position, log.command, o), std::string("reference_tolerance"));
        // A reference at rest, and a program of one speed: too few segments, said so.
        try {
            steadyJogPoints(t0, std::vector<double>(t0.size(), 1.0), log.position, log.command);
            QFAIL("no exception");
        } catch (const InvalidInput& e) {
            QCOMPARE(e.field(), std::string("reference"));
            QVERIFY(
                std::string(e.what()).find("needs jogs in both directions at two or more speeds") !=
                std::string::npos);
        }
        JogProgram one;
        one.speedsMmPerS = {5};
        const JogLog single = jogLog(one, dip(), 0.01, 0.0, 1);
        QCOMPARE(
            field(single.reference.t, single.reference.position, single.position, single.command),
            std::string("reference"));
    }

    // Exact points on a line: F_c and b to round-off (volts of up to 1.9 V carry 2e-16 V of
    // round-off; the column-scaled QR of [sign v, v] has a condition number of about 10, so
    // 1e-12 relative leaves three orders of margin), standard deviations of round-off size,
    // and no Stribeck model (the line fits to round-off).
    void exactLineIsRecovered() {
        const FrictionEstimate e = fitFrictionCurve(curvePoints(line(), kLineSpeeds, 0.0, 0));
        XYT_COMPARE_NEAR(e.coulombVolts, 0.3, 1e-12, 0.0);
        XYT_COMPARE_NEAR(e.viscousVoltsPerMmPerS, 0.02, 1e-12, 0.0);
        QVERIFY(e.coulombStd <= 1e-12);
        QVERIFY(e.viscousStd <= 1e-12);
        QVERIFY(!e.hasStribeck);
        QCOMPARE(e.degreesOfFreedom, std::size_t(10));
        QCOMPARE(e.points.size(), std::size_t(12));
    }

    // Exact points on the Stribeck curve: the search stops when its relative step is below
    // sqrt(eps) = 1.5e-8; at a zero-residual minimum Gauss-Newton converges quadratically, so
    // the estimate is far closer than that: 1e-8 relative bounds it from the stopping rule.
    void exactStribeckIsRecovered() {
        const FrictionEstimate e = fitFrictionCurve(curvePoints(dip(), kDipSpeeds, 0.0, 0));
        QVERIFY2(e.hasStribeck, e.modelSelection.text.c_str());
        XYT_COMPARE_NEAR(e.coulombVolts, 0.3, 1e-8, 0.0);
        XYT_COMPARE_NEAR(e.staticVolts, 0.5, 1e-8, 0.0);
        XYT_COMPARE_NEAR(e.stribeckVelocityMmPerS, 2.0, 1e-8, 0.0);
        XYT_COMPARE_NEAR(e.viscousVoltsPerMmPerS, 0.02, 1e-8, 0.0);
        QCOMPARE(e.degreesOfFreedom, std::size_t(10));
    }

    // 10 mV of noise on each point, seed 42: F_c and b within 3 reported standard deviations;
    // the residual standard deviation near sigma (s^2 (N - 2) / sigma^2 is chi^2 with 10
    // degrees of freedom: its 0.05 % and 99.95 % points are 1.7 and 31.4, so s / sigma lies
    // in [0.41, 1.78]).
    void noisyLineWithinThreeSigma() {
        const double sigma = 0.01;
        const FrictionEstimate e = fitFrictionCurve(curvePoints(line(), kLineSpeeds, sigma, 42));
        XYT_COMPARE_NEAR(e.coulombVolts, 0.3, 0.0, 3.0 * e.coulombStd);
        XYT_COMPARE_NEAR(e.viscousVoltsPerMmPerS, 0.02, 0.0, 3.0 * e.viscousStd);
        QVERIFY(e.residualStdVolts >= 0.41 * sigma && e.residualStdVolts <= 1.78 * sigma);
        QVERIFY(!e.hasStribeck);
    }

    // Over 200 seeds the sample standard deviation of F_c and of b agrees with the mean
    // reported one within 4 sampling errors of a standard deviation from 200 draws
    // (4 / sqrt(2 199) = 20 %; the mean reported s is below sigma by c4 = 0.975 at 10 degrees
    // of freedom, 2.5 %, inside that), and the mean estimate lies within 4 standard errors
    // (spread / sqrt(200)) of the truth: the line's estimate is unbiased.
    void spreadOverSeedsMatchesReportedSd() {
        FrictionIdentificationOptions o;
        o.allowStribeck = false;
        std::vector<std::vector<double>> est, sd;
        collectOverSeeds(
            200, 2,
            [&](std::size_t seed, std::vector<double>& p, std::vector<double>& s) {
                const FrictionEstimate e =
                    fitFrictionCurve(curvePoints(line(), kLineSpeeds, 0.01, 9000 + seed), o);
                p = {e.coulombVolts, e.viscousVoltsPerMmPerS};
                s = {e.coulombStd, e.viscousStd};
            },
            est, sd);
        const std::vector<double> truth{0.3, 0.02};
        for (std::size_t i = 0; i < 2; ++i) {
            double mean = 0, spread = 0, meanSd = 0, unused = 0;
            meanAndSpread(est[i], mean, spread);
            meanAndSpread(sd[i], meanSd, unused);
            qInfo("parameter %zu: spread %.4g, mean reported SD %.4g, ratio %.4f", i, spread,
                  meanSd, spread / meanSd);
            XYT_COMPARE_NEAR(spread, meanSd, 4.0 * sdSamplingError(200), 0.0);
            XYT_COMPARE_NEAR(mean, truth[i], 0.0, 4.0 * spread / std::sqrt(200.0));
        }
    }

    // A clear dip (0.2 V, 40 times the 5 mV noise) at seed 7: the Stribeck model is kept and
    // F_c, F_s, v_s, b lie within 3 reported standard deviations; the same noise on the line
    // leaves the line.
    void stribeckKeptOnlyWhereTheDataHoldIt() {
        const double sigma = 0.005;
        const FrictionEstimate e = fitFrictionCurve(curvePoints(dip(), kDipSpeeds, sigma, 7));
        QVERIFY2(e.hasStribeck, e.modelSelection.text.c_str());
        XYT_COMPARE_NEAR(e.coulombVolts, 0.3, 0.0, 3.0 * e.coulombStd);
        XYT_COMPARE_NEAR(e.staticVolts, 0.5, 0.0, 3.0 * e.staticStd);
        XYT_COMPARE_NEAR(e.stribeckVelocityMmPerS, 2.0, 0.0, 3.0 * e.stribeckStd);
        XYT_COMPARE_NEAR(e.viscousVoltsPerMmPerS, 0.02, 0.0, 3.0 * e.viscousStd);
        QCOMPARE(e.degreesOfFreedom, std::size_t(10));
        const FrictionEstimate flat = fitFrictionCurve(curvePoints(line(), kDipSpeeds, sigma, 7));
        QVERIFY2(!flat.hasStribeck, flat.modelSelection.text.c_str());
        QCOMPARE(flat.staticVolts, 0.0);
        QCOMPARE(flat.degreesOfFreedom, std::size_t(12));
        // Not tried below 3 distinct speeds per direction, nor when not allowed.
        QVERIFY(!fitFrictionCurve(curvePoints(dip(), {0.5, 1}, sigma, 7)).hasStribeck);
        FrictionIdentificationOptions o;
        o.allowStribeck = false;
        const FrictionEstimate notAllowed =
            fitFrictionCurve(curvePoints(dip(), kDipSpeeds, sigma, 7), o);
        QVERIFY(!notAllowed.hasStribeck);
        // The selection is told to the user in words of a code the workbench translates.
        QCOMPARE(notAllowed.modelSelection.code, std::string("ident_stribeck_not_allowed"));
        QCOMPARE(notAllowed.modelSelection.text,
                 std::string("Stribeck model not tried (not allowed)"));
    }

    // The F-test at the 1 % level on data without a dip: over 2000 seeds (10 mV of noise on the
    // 12 and 14 points of both speed sets) the Stribeck model is kept at most 37 times, 1 % of
    // 2000 plus 4 binomial standard deviations (sqrt(2000 0.01 0.99) = 4.45). The nested-model
    // test is not exact here (under a line v_s is not identified), so the level is checked
    // rather than assumed; F_s > F_c alone halves it.
    void stribeckFalseAlarmRateIsAtMostTheLevel() {
        for (const std::vector<double>* speeds : {&kLineSpeeds, &kDipSpeeds}) {
            std::size_t kept = 0;
            for (std::uint64_t seed = 0; seed < 2000; ++seed)
                kept +=
                    fitFrictionCurve(curvePoints(line(), *speeds, 0.01, 100000 + seed)).hasStribeck;
            qInfo("%zu speeds: Stribeck model kept on %zu of 2000 lines", speeds->size(), kept);
            QVERIFY2(kept <= 37, qPrintable(QString::number(kept)));
        }
    }

    // The whole path on a jog log of the dip (20 mV white noise on the command): the Stribeck
    // model is kept and each parameter lies within 3 reported standard deviations.
    void identifyFrictionFromJogLog() {
        JogProgram program;
        program.speedsMmPerS = {0.5, 1, 2, 4, 8, 16};
        program.travelMm = 10; // 3 V^2 / A = 7.7 mm at 16 mm/s
        const JogLog log = jogLog(program, dip(), 0.02, 0.0, 77);
        const FrictionEstimate e = identifyFriction(log.reference.t, log.reference.position,
                                                    log.position, log.command, {});
        QCOMPARE(e.points.size(), std::size_t(12));
        QVERIFY2(e.hasStribeck, e.modelSelection.text.c_str());
        XYT_COMPARE_NEAR(e.coulombVolts, 0.3, 0.0, 3.0 * e.coulombStd);
        XYT_COMPARE_NEAR(e.staticVolts, 0.5, 0.0, 3.0 * e.staticStd);
        XYT_COMPARE_NEAR(e.stribeckVelocityMmPerS, 2.0, 0.0, 3.0 * e.stribeckStd);
        XYT_COMPARE_NEAR(e.viscousVoltsPerMmPerS, 0.02, 0.0, 3.0 * e.viscousStd);
    }

    void fitRefusals() {
        const std::vector<FrictionPoint> good = curvePoints(line(), {2, 5}, 0.0, 0);
        const auto field = [](const std::vector<FrictionPoint>& points) {
            return fieldOf([&] { fitFrictionCurve(points); });
        };
        QCOMPARE(field(good), std::string());
        std::vector<FrictionPoint> bad = good;
        bad[1].volts = NAN;
        QCOMPARE(field(bad), std::string("points"));
        bad = good;
        bad[2].voltsStd = INFINITY;
        QCOMPARE(field(bad), std::string("points"));
        bad = good;
        bad[0].velocityMmPerS = 0.0;
        QCOMPARE(field(bad), std::string("points"));
        bad = good;
        bad.pop_back(); // one point left in the - direction
        QCOMPARE(field(bad), std::string("points"));
        QCOMPARE(field({}), std::string("points"));
        // Both directions at one speed: F_c and b cannot be told apart.
        QCOMPARE(field(curvePoints(line(), {5, 5}, 0.01, 3)), std::string("points"));
    }
};

QTEST_APPLESS_MAIN(TstFrictionIdentification)
#include "tst_friction_identification.moc"
