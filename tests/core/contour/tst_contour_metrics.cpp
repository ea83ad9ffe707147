// SPDX-License-Identifier: GPL-3.0-or-later
// Contour error and the ISO 230-4 circular test (core/contour/contour_metrics.h), and the
// nearest-point search of core/contour/path.h they rest on. Sources: a traced path offset by a
// known distance d along the left normal has contour error +d (geometry); the nearest point
// equals a brute-force scan of every segment (invariant); an ellipse with semi-axes a >= b
// sampled at N equally spaced parameters (N divisible by 4) is symmetric under p -> -p, so both
// least-squares circles are centred at its centre, the Kasa radius is sqrt((a^2 + b^2)/2)
// (mean of x^2 + y^2), the radii range from b to a: G = a - b, F max = a - R0, F min = b - R0;
// two concentric runs of radii R + d1 and R + d2 have H = |d1 - d2| (closed forms).
#include "core/contour/contour_metrics.h"
#include "core/contour/gcode_reader.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>

using xyt::Path;
using xyt::PathSegment;
using xyt::Point2;

namespace {
constexpr double kPi = std::numbers::pi;

/// Samples along @p path at positions s (each away from the ends) offset by @p d to the left.
void offsetTrace(const Path& path, const std::vector<double>& s, double d, std::vector<double>& t,
                 std::vector<double>& x, std::vector<double>& y) {
    t.clear(), x.clear(), y.clear();
    for (std::size_t k = 0; k < s.size(); ++k) {
        const auto p = path.at(s[k]);
        const Point2 left{-p.tangent.y, p.tangent.x};
        t.push_back(0.01 * static_cast<double>(k));
        x.push_back(p.point.x + d * left.x);
        y.push_back(p.point.y + d * left.y);
    }
}

/// x = cx + a cos(2 pi k / n), y = cy + b sin(2 pi k / n).
void ellipse(double a, double b, Point2 c, int n, std::vector<double>& x, std::vector<double>& y) {
    x.resize(static_cast<std::size_t>(n)), y.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double t = 2.0 * kPi * k / n;
        x[static_cast<std::size_t>(k)] = c.x + a * std::cos(t);
        y[static_cast<std::size_t>(k)] = c.y + b * std::sin(t);
    }
}

/// Radius r(theta) about @p c sampled at n angles starting at @p phase (radians).
template <class R>
void polar(const R& radius, Point2 c, int n, double phase, std::vector<double>& x,
           std::vector<double>& y) {
    x.clear(), y.clear();
    for (int k = 0; k < n; ++k) {
        const double th = phase + 2.0 * kPi * k / n;
        x.push_back(c.x + radius(th) * std::cos(th));
        y.push_back(c.y + radius(th) * std::sin(th));
    }
}

/// A zig-zag of @p blocks segments: 1 mm lines up and down joined by tangent half circles of
/// radius 0.5 mm (the xytune-bench program).
Path zigZag(int blocks) {
    std::vector<PathSegment> s;
    double x = 0.0;
    bool up = true;
    for (int i = 0; s.size() < static_cast<std::size_t>(blocks); ++i) {
        const double y0 = up ? 0.0 : 1.0, y1 = up ? 1.0 : 0.0;
        s.push_back(PathSegment::line({x, y0}, {x, y1}));
        if (s.size() == static_cast<std::size_t>(blocks))
            break;
        // Up then a clockwise half turn over the top to x + 1; down then counter-clockwise.
        s.push_back(PathSegment::arc({x + 0.5, y1}, 0.5, up ? kPi : -kPi, up ? -kPi : kPi));
        x += 1.0;
        up = !up;
    }
    return Path(std::move(s));
}

double bruteForceDistance(const Path& path, Point2 q) {
    double best = INFINITY;
    for (const auto& seg : path.segments())
        best = std::min(best, seg.nearest(q).distance);
    return best;
}
} // namespace

class TstContourMetrics : public QObject {
    Q_OBJECT
private slots:
    void offsetLine();
    void offsetArcs();
    void offsetAlongMixedPath();
    void statistics();
    void cornerOvershoot();
    void rapidsLeftOut();
    void nearestIsGlobal();
    void nearestOnLargePathsIsExact();
    void ellipseClosedForms_data();
    void ellipseClosedForms();
    void hysteresisOfConcentricRuns();
    void reversalSpike();
    void badInput();
};

void TstContourMetrics::offsetLine() {
    // Travel along +x: left is +y. Points at y = +0.25 have e = +0.25, at y = -0.25, -0.25.
    const Path path({PathSegment::line({0.0, 0.0}, {100.0, 0.0})});
    for (const double d : {0.25, -0.25, 1e-6}) {
        std::vector<double> t{0.0, 1.0, 2.0}, x{1.0, 50.0, 99.0}, y(3, d);
        const auto r = xyt::contourError(path, t, x, y);
        for (std::size_t k = 0; k < 3; ++k) {
            XYT_COMPARE_NEAR(r.error[k], d, 1e-15, 0.0);
            XYT_COMPARE_NEAR(r.pathPosition[k], x[k], 1e-15, 0.0);
        }
    }
}

void TstContourMetrics::offsetArcs() {
    // A counter-clockwise circle: left is inside, so radius R - d gives +d; a clockwise one:
    // left is outside, R + d gives +d. R 25 about (3, -2), d = 0.01, 1e-12 (round-off of
    // hypot at 25 mm).
    for (const double sweep : {2.0 * kPi, -2.0 * kPi}) {
        const Point2 c{3.0, -2.0};
        const Path path({PathSegment::arc(c, 25.0, 0.3, sweep)});
        const double d = 0.01;
        const double traced = sweep > 0.0 ? 25.0 - d : 25.0 + d;
        std::vector<double> t, x, y;
        polar([&](double) { return traced; }, c, 64, 0.3 + 0.05, x, y);
        t.assign(x.size(), 0.0);
        const auto r = xyt::contourError(path, t, x, y);
        for (const double e : r.error)
            XYT_COMPARE_NEAR(e, d, 0.0, 1e-12);
        XYT_COMPARE_NEAR(r.maxAbs, d, 0.0, 1e-12);
        XYT_COMPARE_NEAR(r.rms, d, 0.0, 1e-12);
    }
}

void TstContourMetrics::offsetAlongMixedPath() {
    // Lines and arcs of both directions joined tangentially; offsets of +-0.1 mm along the left
    // normal at 500 positions (away from the final sharp corner and the ends).
    const auto program = xyt::readGcode(
        "G1 X10 Y0 F600\nG3 X10 Y10 I0 J5\nG1 X0 Y10\nG2 X0 Y20 I0 J5\nG1 X10 Y20\n");
    const Path& path = program.path;
    std::vector<double> s;
    for (int k = 0; k < 500; ++k)
        s.push_back(0.2 + (path.length() - 0.4) * k / 499.0);
    for (const double d : {0.1, -0.1}) {
        std::vector<double> t, x, y;
        offsetTrace(path, s, d, t, x, y);
        const auto r = xyt::contourError(path, t, x, y);
        for (std::size_t k = 0; k < s.size(); ++k) {
            XYT_COMPARE_NEAR(r.error[k], d, 0.0, 1e-12);
            XYT_COMPARE_NEAR(r.pathPosition[k], s[k], 0.0, 1e-9);
        }
    }
}

void TstContourMetrics::statistics() {
    // e_k = d sin(2 pi k / N), N = 40: mean of sin^2 over whole periods is 1/2, so rms = d /
    // sqrt 2; the largest |e| is d at k = 10 (t = 1.0 s, x = 10 + 10).
    const Path path({PathSegment::line({0.0, 0.0}, {100.0, 0.0})});
    const double d = 0.02;
    std::vector<double> t, x, y;
    for (int k = 0; k < 40; ++k) {
        t.push_back(0.1 * k);
        x.push_back(10.0 + k);
        y.push_back(d * std::sin(2.0 * kPi * k / 40.0));
    }
    const auto r = xyt::contourError(path, t, x, y);
    XYT_COMPARE_NEAR(r.rms, d / std::sqrt(2.0), 1e-13, 0.0);
    XYT_COMPARE_NEAR(r.maxAbs, d, 1e-15, 0.0);
    QCOMPARE(r.maxIndex, std::size_t(10));
    XYT_COMPARE_NEAR(r.maxTimeSeconds, 1.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(r.maxPathPosition, 20.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(r.maxSignedError, d, 1e-15, 0.0);
    QCOMPARE(r.measuredSamples, std::size_t(40));
}

void TstContourMetrics::cornerOvershoot() {
    // The square run counter-clockwise: a point beyond the first corner (40, 0), at
    // (40.05, -0.02), is nearest to the corner itself, at distance sqrt(0.05^2 + 0.02^2), and
    // outside the left turn (right of travel): negative.
    const auto square = xyt::readGcode("G1 X40 Y0 F600\nY40\nX0\nY0\n");
    std::vector<double> t{0.0, 1.0, 2.0, 3.0}, x{20.0, 40.05, 40.0, 39.0},
        y{0.001, -0.02, 20.0, 40.2};
    const auto r = xyt::contourError(square.path, t, x, y);
    QCOMPARE(r.corners.size(), std::size_t(3));
    const double expected = std::hypot(0.05, 0.02);
    // 1e-13 mm: 40.05 - 40 keeps the representation error of 40.05 (7e-15).
    XYT_COMPARE_NEAR(r.error[1], -expected, 0.0, 1e-13);
    XYT_COMPARE_NEAR(r.corners[0].maxAbsError, expected, 0.0, 1e-13);
    XYT_COMPARE_NEAR(r.corners[0].signedError, -expected, 0.0, 1e-13);
    XYT_COMPARE_NEAR(r.corners[0].timeSeconds, 1.0, 0.0, 0.0);
    QCOMPARE(r.corners[0].samples, std::size_t(1)); // (20, 0.001) is 20 mm before it
    // (39, 40.2): 1 mm after the second corner (40, 40), 0.2 outside: the window of 1 mm.
    XYT_COMPARE_NEAR(r.corners[1].maxAbsError, 0.2, 1e-13, 0.0);
    XYT_COMPARE_NEAR(r.corners[1].signedError, -0.2, 1e-13, 0.0);
    QCOMPARE(r.corners[2].samples, std::size_t(0));
    QCOMPARE(r.corners[1].corner, (Point2{40.0, 40.0}));
}

void TstContourMetrics::rapidsLeftOut() {
    // A rapid (segment 0) then a feed line: samples nearest the rapid are left out.
    const auto program = xyt::readGcode("G0 X10\nG1 Y10 F60\n");
    std::vector<bool> measured;
    for (const auto& s : program.segments)
        measured.push_back(!s.rapid);
    xyt::ContourErrorOptions options;
    options.measuredSegments = measured;
    std::vector<double> t{0.0, 1.0}, x{5.0, 10.1}, y{0.5, 5.0};
    const auto r = xyt::contourError(program.path, t, x, y, options);
    QCOMPARE(r.measuredSamples, std::size_t(1));
    QCOMPARE(r.measured, (std::vector<bool>{false, true}));
    XYT_COMPARE_NEAR(r.maxAbs, 0.1, 1e-13, 0.0); // right of +y travel: -0.1
    XYT_COMPARE_NEAR(r.maxSignedError, -0.1, 1e-13, 0.0);
    XYT_COMPARE_NEAR(r.error[0], 0.5, 1e-15, 0.0); // still computed
}

void TstContourMetrics::nearestIsGlobal() {
    // The star crosses itself five times: whatever the hint, the nearest distance is the
    // brute-force minimum over every segment (2000 random points, fixed seed, 1e-12 mm).
    const auto star = xyt::readGcode("G0 X0 Y30\nG1 X-17.634 Y-24.271 F900\nX28.532 Y9.271\n"
                                     "X-28.532 Y9.271\nX17.634 Y-24.271\nX0 Y30\nG2 I0 J-30\n");
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> coord(-35.0, 35.0);
    std::uniform_int_distribution<std::size_t> hint(0, star.path.size() + 3);
    for (int k = 0; k < 2000; ++k) {
        const Point2 q{coord(rng), coord(rng)};
        const auto p = star.path.nearest(q, hint(rng));
        XYT_COMPARE_NEAR(std::abs(p.signedDistance), bruteForceDistance(star.path, q), 0.0, 1e-12);
        XYT_COMPARE_NEAR(std::hypot(q.x - p.point.x, q.y - p.point.y), std::abs(p.signedDistance),
                         0.0, 1e-12);
    }
}

void TstContourMetrics::nearestOnLargePathsIsExact() {
    // 100 000 queries on a 10 000-segment path (the bench's zig-zag), each traced point 0.05 mm
    // left of its reference and hinted by the previous answer, as contourError queries: the
    // first 1000 against brute force, and every one at its 0.05 mm. How fast the search is
    // (a linear scan would do 1e9 segment distances) is xytune-bench's
    // gcode_contour_10000_blocks_contour_error figure, not a timed test: under the
    // sanitizers the same queries took 1.1 s, and a test must not fail on a loaded machine.
    const Path path = zigZag(10000);
    QCOMPARE(path.size(), std::size_t(10000));
    std::vector<double> s(100000);
    for (std::size_t k = 0; k < s.size(); ++k)
        s[k] = path.length() * (static_cast<double>(k) + 0.5) / static_cast<double>(s.size());
    std::vector<double> t, x, y;
    offsetTrace(path, s, 0.05, t, x, y);
    for (std::size_t k = 0; k < 1000; ++k)
        XYT_COMPARE_NEAR(std::abs(path.nearest({x[k], y[k]}).signedDistance),
                         bruteForceDistance(path, {x[k], y[k]}), 0.0, 1e-12);
    const auto r = xyt::contourError(path, t, x, y);
    for (const double e : r.error)
        XYT_COMPARE_NEAR(std::abs(e), 0.05, 0.0, 1e-12);
    XYT_COMPARE_NEAR(r.maxAbs, 0.05, 0.0, 1e-12);
}

void TstContourMetrics::ellipseClosedForms_data() {
    QTest::addColumn<bool>("geometric");
    QTest::addColumn<double>("cx");
    QTest::addColumn<double>("cy");
    QTest::newRow("kasa origin") << false << 0.0 << 0.0;
    QTest::newRow("geometric origin") << true << 0.0 << 0.0;
    QTest::newRow("geometric shifted") << true << 120.0 << -45.0;
}

void TstContourMetrics::ellipseClosedForms() {
    QFETCH(bool, geometric);
    QFETCH(double, cx);
    QFETCH(double, cy);
    // Semi-axes a = 25.012, b = 24.995 about c, N = 3600 (divisible by 4: t = 0 and pi/2 are
    // samples, so max r = a and min r = b are reached). Nominal circle R0 = 25 about c.
    const double a = 25.012, b = 24.995, r0 = 25.0;
    std::vector<double> x, y;
    ellipse(a, b, {cx, cy}, 3600, x, y);
    xyt::Iso230Options options;
    options.geometricFit = geometric;
    const auto iso = xyt::iso230Circular(x, y, {{cx, cy}, r0}, options);
    // 1e-10 mm: round-off of the fit (QR on 3600 rows) and of sums at 1e2 mm.
    XYT_COMPARE_NEAR(iso.leastSquares.centre.x, cx, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.leastSquares.centre.y, cy, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.circularDeviationG, a - b, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.radialDeviationFMax, a - r0, 0.0, 1e-12);
    XYT_COMPARE_NEAR(iso.radialDeviationFMin, b - r0, 0.0, 1e-12);
    QCOMPARE(iso.leastSquares.geometric, geometric);
    if (!geometric) {
        XYT_COMPARE_NEAR(iso.leastSquares.radius, std::sqrt((a * a + b * b) / 2.0), 0.0, 1e-10);
    } else {
        // The geometric radius given the centre is the mean distance (d/dR of the sum = 0).
        double mean = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k)
            mean += std::hypot(x[k] - cx, y[k] - cy);
        mean /= static_cast<double>(x.size());
        XYT_COMPARE_NEAR(iso.leastSquares.radius, mean, 0.0, 1e-10);
    }
    QVERIFY(!iso.hysteresisH);
}

void TstContourMetrics::hysteresisOfConcentricRuns() {
    // Run 1 radius R + 0.003 at 1000 angles, run 2 radius R - 0.001 at 777 other angles, both
    // about (5, 5): H = 0.004 and G(b) = 0.004, each run's own G = 0 (1e-10: fit round-off).
    const Point2 c{5.0, 5.0};
    std::vector<double> x1, y1, x2, y2;
    polar([](double) { return 30.003; }, c, 1000, 0.0, x1, y1);
    polar([](double) { return 29.999; }, c, 777, 0.123, x2, y2);
    const auto iso = xyt::iso230Circular(x1, y1, x2, y2, {c, 30.0});
    QVERIFY(iso.hysteresisH.has_value());
    XYT_COMPARE_NEAR(*iso.hysteresisH, 0.004, 0.0, 1e-10);
    XYT_COMPARE_NEAR(*iso.bidirectionalG, 0.004, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.circularDeviationG, 0.0, 0.0, 1e-10);
    XYT_COMPARE_NEAR(iso.radialDeviationFMax, 0.003, 0.0, 1e-12);
    // A run whose radius is R + 0.002 cos(theta)^2 against a constant R: the largest difference
    // is 0.002 at theta = 0 and pi (linear interpolation between samples 0.36 degrees apart
    // changes it by under 1e-7 mm).
    std::vector<double> x3, y3;
    polar([](double th) { return 30.0 + 0.002 * std::cos(th) * std::cos(th); }, {0.0, 0.0}, 1000,
          0.001, x3, y3);
    std::vector<double> x4, y4;
    polar([](double) { return 30.0; }, {0.0, 0.0}, 1000, 0.0, x4, y4);
    const auto h = xyt::iso230Circular(x3, y3, x4, y4, {{0.0, 0.0}, 30.0});
    XYT_COMPARE_NEAR(*h.hysteresisH, 0.002, 0.0, 1e-7);
}

void TstContourMetrics::reversalSpike() {
    // A 25 mm circle with a bump of 0.005 mm and 1 degree width at 90 degrees (where y
    // reverses): the spike there is the bump, measured against the window's median, which the
    // bump moves by less than 1 % (it covers 3.5 of the window's 20 degrees at under half its
    // height for all but 1.7 of them); the other quadrants show no spike. 3600 samples.
    const double h = 0.005;
    std::vector<double> x, y;
    polar(
        [&](double th) {
            const double d = (th - kPi / 2.0) / (kPi / 180.0);
            return 25.0 + h * std::exp(-d * d);
        },
        {0.0, 0.0}, 3600, 0.0, x, y);
    const auto iso = xyt::iso230Circular(x, y, {{0.0, 0.0}, 25.0});
    QCOMPARE(iso.reversalSpikes.size(), std::size_t(4));
    const auto& spike = iso.reversalSpikes[1];
    QCOMPARE(spike.axis, 'y');
    XYT_COMPARE_NEAR(spike.angleDeg, 90.0, 0.0, 0.0);
    XYT_COMPARE_NEAR(spike.heightMm, h, 0.01, 0.0);
    XYT_COMPARE_NEAR(spike.point.x, 0.0, 0.0, 1e-9);
    // +-10 degrees at 0.1 degree steps: 201 samples, the two on the edges up to round-off.
    QVERIFY(spike.samples >= 199 && spike.samples <= 201);
    for (const std::size_t q : {0u, 2u, 3u})
        QVERIFY2(std::abs(iso.reversalSpikes[q].heightMm) < 0.01 * h,
                 qPrintable(QString::number(iso.reversalSpikes[q].heightMm)));
    QCOMPARE(iso.reversalSpikes[0].axis, 'x');
}

void TstContourMetrics::badInput() {
    const Path path({PathSegment::line({0.0, 0.0}, {1.0, 0.0})});
    const auto fieldOf = [](auto f) { return xyt::test::invalidInputField(f); };
    QCOMPARE(fieldOf([&] {
                 xyt::contourError(path, {0.0}, {0.0, 1.0}, {0.0});
             }),
             QStringLiteral("traced"));
    QCOMPARE(fieldOf([&] { xyt::contourError(path, {}, {}, {}); }), QStringLiteral("traced"));
    QCOMPARE(fieldOf([&] { xyt::contourError(path, {0.0}, {NAN}, {0.0}); }),
             QStringLiteral("traced"));
    xyt::ContourErrorOptions o;
    o.measuredSegments = {true, false};
    QCOMPARE(fieldOf([&] { xyt::contourError(path, {0.0}, {0.0}, {0.0}, o); }),
             QStringLiteral("measured_segments"));
    // Collinear points have no circle.
    QCOMPARE(fieldOf([] {
                 xyt::fitCircleKasa({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0});
             }),
             QStringLiteral("points"));
    QCOMPARE(fieldOf([] { xyt::fitCircleKasa({0.0, 1.0}, {0.0, 1.0}); }), QStringLiteral("points"));
    QCOMPARE(fieldOf([] {
                 xyt::iso230Circular({1.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, {{0.0, 0.0}, 0.0});
             }),
             QStringLiteral("nominal_radius"));
    // Three points on the unit circle: both fits are exact.
    const auto fit = xyt::fitCircleGeometric({1.0, 0.0, -1.0}, {0.0, 1.0, 0.0});
    XYT_COMPARE_NEAR(fit.radius, 1.0, 1e-14, 0.0);
}

QTEST_APPLESS_MAIN(TstContourMetrics)
#include "tst_contour_metrics.moc"
