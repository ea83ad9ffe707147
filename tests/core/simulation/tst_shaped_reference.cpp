// SPDX-License-Identifier: GPL-3.0-or-later
// A shaped reference against closed forms: the amplitudes sum to 1 (same final value); a ramp
// shaped is the ramp delayed by the shaper's centroid sum A_i t_i once the shaper's duration has
// passed; impulse times on the sample grid read samples exactly; a circle of radius R at angular
// speed w becomes a circle of radius R |sum A_i e^{-j w t_i}|; a corner taken at constant speed
// v is cut by v sum_{t_i > ts} A_i (t_i - ts) (Klipper's 90 degree offset over sqrt 2 at zero
// acceleration). And the refusal of a shaper longer than the move.
#include "core/design/input_shaper.h"
#include "core/design/shaper_recommendation.h"
#include "core/design/shaper_sensitivity.h"
#include "core/model/errors.h"
#include "core/simulation/shaped_reference.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace xyt;

class TstShapedReference : public QObject {
    Q_OBJECT

private slots:
    /// A ramp of v = 50 mm/s from t = 0.1 s to 0.5 s (held before and after), breakpoints on
    /// samples, dt 1 ms, shaped by EI at 37 Hz, zeta 0.1 (times off the grid). Linear
    /// interpolation is exact on a ramp, so the closed forms hold to round-off (1e-12 of the
    /// 20 mm move): the run is longer by ceil(duration / dt) samples, ends at the final value,
    /// and between t_start + duration and t_end it equals v (t - t_start - sum A_i t_i).
    void rampIsDelayedByTheCentroid() {
        const double dt = 1e-3, v = 50.0, tStart = 0.1, tEnd = 0.5;
        std::vector<double> r;
        for (int k = 0; k <= 700; ++k) {
            const double t = k * dt;
            r.push_back(v * std::clamp(t - tStart, 0.0, tEnd - tStart));
        }
        const InputShaper ei = designInputShaper(ShaperType::Ei, 37.0, 0.1);
        const ShapedReference s = shapeReference(ei, r, dt, tEnd - tStart);
        const auto added = static_cast<std::size_t>(std::ceil(ei.duration() / dt));
        QCOMPARE(s.addedSamples, added);
        QCOMPARE(s.values.size(), r.size() + added);
        XYT_COMPARE_NEAR(s.values.back(), r.back(), 1e-12, 0.0);
        const double delay = shaperDelaySeconds(ei);
        // The centroid lies inside the shaper (0 < delay < duration) for positive amplitudes.
        QVERIFY(delay > 0.0 && delay < ei.duration());
        int checked = 0;
        for (std::size_t k = 0; k < s.values.size(); ++k) {
            const double t = static_cast<double>(k) * dt;
            if (t >= tStart + ei.duration() + 1e-9 && t <= tEnd) {
                XYT_COMPARE_NEAR(s.values[k], v * (t - tStart - delay), 0.0, 1e-12 * 20.0);
                ++checked;
            }
            if (t <= tStart) // at rest before the move: the start value, exactly weighted to 1
                XYT_COMPARE_NEAR(s.values[k], 0.0, 0.0, 1e-15);
        }
        QVERIFY(checked > 300);
    }

    /// Impulse times that are whole samples: ZV at 50 Hz undamped (0, 10 ms) and ZVD for zeta
    /// 0.1 at the frequency whose half damped period is 5 samples, on a random sequence: each
    /// shaped sample is sum A_i r[k - m_i] (r[0] before the start), the same operations in the
    /// same order, so equal to the last bit.
    void impulseTimesOnTheGridAreExact() {
        const double dt = 1e-3;
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<double> r(400);
        for (double& x : r)
            x = u(rng);
        const double zeta = 0.1;
        for (const InputShaper& sh :
             {designInputShaper(ShaperType::Zv, 50.0, 0.0),
              designInputShaper(ShaperType::Zvd, 1.0 / (10.0 * dt * std::sqrt(1.0 - zeta * zeta)),
                                zeta)}) {
            const ShapedReference s = shapeReference(sh, r, dt, 0.3);
            QCOMPARE(s.addedSamples, std::size_t(10)); // both last 10 ms
            for (std::size_t k = 0; k < s.values.size(); ++k) {
                double expected = 0.0;
                for (std::size_t i = 0; i < sh.amplitudes.size(); ++i) {
                    const auto m = static_cast<std::ptrdiff_t>(std::lround(sh.times[i] / dt));
                    const std::ptrdiff_t j = std::clamp<std::ptrdiff_t>(
                        static_cast<std::ptrdiff_t>(k) - m, 0, static_cast<std::ptrdiff_t>(399));
                    expected += sh.amplitudes[i] * r[static_cast<std::size_t>(j)];
                }
                QCOMPARE(s.values[k], expected);
            }
        }
    }

    /// ZV at 5 Hz lasts 0.1 s: a 0.05 s move is refused, naming the shaper's frequency.
    void aShaperLongerThanTheMoveIsRefused() {
        const InputShaper zv = designInputShaper(ShaperType::Zv, 5.0, 0.0);
        const std::vector<double> r(100, 1.0);
        try {
            shapeReference(zv, r, 1e-3, 0.05);
            QFAIL("no exception");
        } catch (const InvalidInput& e) {
            QCOMPARE(e.field(), std::string("shaper.frequency"));
            QCOMPARE(e.reason(), std::string("the shaper lasts 0.1 s, longer than the move of "
                                             "0.05 s"));
        }
        QVERIFY_THROWS_EXCEPTION(InvalidInput, shapeReference(zv, r, 0.0, 1.0));
        QVERIFY_THROWS_EXCEPTION(InvalidInput, shapeReference(zv, {}, 1e-3, 1.0));
        QVERIFY_THROWS_EXCEPTION(InvalidInput, shapePath(zv, r, {1.0}, 1e-3, 1.0));
    }

    /// A circle of R = 10 mm at 10 rev/s, dt 0.1 ms, for 0.3 s. After the shaper's duration
    /// every shaped point lies at R |H(w)| from the centre, H = sum A_i e^{-j w t_i}
    /// (ZV at 40 Hz undamped: |H| = cos(pi/8), Singer and Seering; EI at 40 Hz, zeta 0.1).
    /// Linear interpolation puts a point on a chord: its radius is low by at most
    /// 1 - cos(w dt / 2) = 4.9e-6 relative, the tolerance. ZV's deviation from the programmed
    /// path is R (1 - |H|) (for ZV the start and the end, shorter chords, deviate less): the
    /// programmed polyline lies inside the circle by at most the sagitta R (1 - cos(w dt/2)),
    /// so twice that is the tolerance.
    void circleShrinksByTheShapersGain() {
        const double radius = 10.0, w = 2.0 * std::numbers::pi * 10.0, dt = 1e-4;
        std::vector<double> x, y;
        for (int k = 0; k <= 3000; ++k) {
            x.push_back(radius * std::cos(w * k * dt));
            y.push_back(radius * std::sin(w * k * dt));
        }
        const double chord = 1.0 - std::cos(w * dt / 2.0);
        const InputShaper zv = designInputShaper(ShaperType::Zv, 40.0, 0.0);
        XYT_COMPARE_NEAR(shapedCircleRadiusRatio(zv, w), std::cos(std::numbers::pi / 8.0), 1e-15,
                         0.0);
        for (const InputShaper& sh : {zv, designInputShaper(ShaperType::Ei, 40.0, 0.1)}) {
            const ShapedPath p = shapePath(sh, x, y, dt, 0.3);
            const double ratio = shapedCircleRadiusRatio(sh, w);
            QVERIFY(ratio < 0.95); // the shaper visibly shrinks this circle
            const auto m = static_cast<std::size_t>(std::ceil(sh.duration() / dt));
            for (std::size_t k = m + 1; k < x.size(); ++k)
                XYT_COMPARE_NEAR(std::hypot(p.x[k], p.y[k]), radius * ratio, chord, 0.0);
        }
        const ShapedPath p = shapePath(zv, x, y, dt, 0.3);
        const PathDeviation d = shapedPathDeviation(p, x, y, zv, dt);
        XYT_COMPARE_NEAR(d.maxMm, radius * (1.0 - std::cos(std::numbers::pi / 8.0)), 0.0,
                         2.0 * radius * chord);
    }

    /// A 90 degree corner at constant v = 100 mm/s (20 mm along x into the corner, 20 mm along
    /// y out of it; the corner on a sample, dt 0.1 ms), shaped by ZVD at 40 Hz, zeta 0.1. At time
    /// t the shaped point is (-v sum_{t_i > t} A_i (t_i - t), v sum_{t_i < t} A_i (t - t_i))
    /// after the corner's time; its distance to the path, the smaller of the two, is largest
    /// where they are equal, at the centroid ts: v X, X = sum_{t_i > ts} A_i (t_i - ts). The
    /// distance changes at most v per second, so the sampled maximum is within v dt of it.
    /// Klipper's offset_90 at zero acceleration and scv = v is sqrt(2) v X (the distance to the
    /// corner's vertex).
    void cornerIsCutByTheCentroidOffset() {
        const double v = 100.0, dt = 1e-4, leg = 20.0;
        const int legSamples = static_cast<int>(std::lround(leg / v / dt));
        std::vector<double> x, y;
        for (int k = 0; k <= 2 * legSamples; ++k) {
            const double s = v * (k - legSamples) * dt;
            x.push_back(std::min(s, 0.0));
            y.push_back(std::max(s, 0.0));
        }
        const InputShaper zvd = designInputShaper(ShaperType::Zvd, 40.0, 0.1);
        const double ts = shaperDelaySeconds(zvd);
        double cut = 0.0;
        for (std::size_t i = 0; i < zvd.times.size(); ++i)
            if (zvd.times[i] > ts)
                cut += zvd.amplitudes[i] * (zvd.times[i] - ts);
        const ShapedPath p = shapePath(zvd, x, y, dt, 2.0 * leg / v);
        const PathDeviation d = shapedPathDeviation(p, x, y, zvd, dt);
        XYT_COMPARE_NEAR(d.maxMm, v * cut, 0.0, v * dt);
        XYT_COMPARE_NEAR(klipperShaperSmoothing(zvd, 0.0, v), std::sqrt(2.0) * v * cut, 1e-12, 0.0);
        // Where: near the corner's time plus the centroid.
        XYT_COMPARE_NEAR(static_cast<double>(d.index) * dt, legSamples * dt + ts, 0.0, 2.0 * dt);
    }
};

QTEST_APPLESS_MAIN(TstShapedReference)
#include "tst_shaped_reference.moc"
