// SPDX-License-Identifier: GPL-3.0-or-later
// The batched tracking kernel of the design sweep against the scalar path it
// replaces: simulateLoop, then trackingMetrics and moveSettleMetrics on the stored run. The
// source of every expected number is that scalar path; the claim is equality bit for bit
// (the same exact FOH matrices and the same operations in the same order per lane).
#include "core/design/guillemin_truxal.h"
#include "core/model/errors.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/simulation.h"
#include "core/simulation/tracking_batch.h"
#include "core/simulation/trajectory.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

using namespace xyt;

namespace {

std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

struct Case {
    std::vector<GtDesign> designs;
    std::vector<LoopModes> modes;
};

/// @p count designs of the lower base with log-uniform wn in [0.3, 40] rad/s and kp in
/// [2, 3000], from a fixed seed: stable and unstable loops (Routh: wn^4 > kp k0 (a1 a2 - kp k0)
/// / a1^2 is unstable), gentle and saturating ones.
Case randomDesigns(int count, unsigned seed) {
    const GtPreset lower = *findGtPreset("lower-base");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> logWn(std::log(0.3), std::log(40.0));
    std::uniform_real_distribution<double> logKp(std::log(2.0), std::log(3000.0));
    Case c;
    for (int i = 0; i < count; ++i) {
        // Drawn in this order on purpose: the order in which a call's arguments are evaluated
        // is unspecified (gcc and clang drew different designs from one seed).
        const double wn = std::exp(logWn(rng));
        const double kp = std::exp(logKp(rng));
        c.designs.push_back(designGuilleminTruxal(lower.plant, wn, kp));
        c.modes.push_back(loopModes(lower.plant.transferFunction(), c.designs.back().controller));
    }
    return c;
}

} // namespace

class TstTrackingBatch : public QObject {
    Q_OBJECT
private slots:
    void equalsScalarLoopBitForBit_data();
    void equalsScalarLoopBitForBit();
    void badArgumentsNamed();
};

void TstTrackingBatch::equalsScalarLoopBitForBit_data() {
    QTest::addColumn<double>("tf");
    QTest::addColumn<double>("umax");
    QTest::addColumn<double>("duration");
    QTest::addColumn<int>("width");
    // A cubic 0 -> 600 mm: in 10 s its 90 mm/s peak needs ~4 V, so gentle designs stay inside
    // 2.5 V and aggressive ones clip (run 20 s: the move and as long again to settle); without
    // a limit the unstable designs grow until they overflow (diverge, within 600 s) while the
    // stable ones in the same batch run on.
    for (int width : {1, 2, 4, 8}) {
        const QByteArray w = QByteArray::number(width);
        QTest::newRow("limited, width " + w) << 10.0 << 2.5 << 20.0 << width;
        QTest::newRow("unlimited, width " + w)
            << 10.0 << std::numeric_limits<double>::infinity() << 600.0 << width;
    }
}

void TstTrackingBatch::equalsScalarLoopBitForBit() {
    QFETCH(double, tf);
    QFETCH(double, umax);
    QFETCH(double, duration);
    QFETCH(int, width);
    const GtPreset lower = *findGtPreset("lower-base");
    // 27 designs, so that the last batch of every width is partial: 25 random ones and two
    // strongly unstable ones (Routh: wn^4 > kp k0 (a1 a2 - kp k0) / a1^2; wn 40, kp 2 and wn 30,
    // kp 5 grow past 1e308 within 600 s without a limit) placed among them, so that diverging
    // lanes share batches with finite ones.
    Case c = randomDesigns(25, 2026);
    const GtPreset plant = *findGtPreset("lower-base");
    for (const auto& [at, wn, kp] : {std::tuple{10, 40.0, 2.0}, std::tuple{20, 30.0, 5.0}}) {
        c.designs.insert(c.designs.begin() + at, designGuilleminTruxal(plant.plant, wn, kp));
        c.modes.insert(c.modes.begin() + at,
                       loopModes(plant.plant.transferFunction(),
                                 c.designs[static_cast<std::size_t>(at)].controller));
    }
    const CubicTrajectory cubic(0.0, 600.0, 0.0, tf);
    const std::vector<double> reference =
        sampled([&](double t) { return cubic.position(t); }, sampleTimes(duration, 0.01));
    const PointToPointMove move{0.0, 600.0, tf};
    const double window = 0.01;

    std::vector<std::optional<MoveSettleAccumulator>> moves(c.modes.size());
    std::vector<MoveSettleAccumulator*> movePointers;
    for (auto& m : moves)
        movePointers.push_back(&m.emplace(move, window));
    std::vector<std::optional<TrackingMetrics>> results(c.modes.size());
    TrackingRun run;
    run.reference = &reference;
    run.dtSeconds = 0.01;
    run.umaxVolts = umax;
    run.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
    trackBatch(c.modes, run, movePointers, results, width);

    int clipping = 0, gentle = 0, diverged = 0, finite = 0;
    for (std::size_t i = 0; i < c.modes.size(); ++i) {
        LoopSimulationOptions o;
        o.dtSeconds = 0.01;
        o.umaxVolts = umax;
        o.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
        const SimulationResult scalar =
            simulateLoop(lower.plant.transferFunction(), c.designs[i].controller, reference, o);
        const TrackingMetrics m = trackingMetrics(scalar);
        const QByteArray which = "design " + QByteArray::number(static_cast<int>(i));
        // The kernel gives no figures for a diverged run, nor for one whose figures overflowed
        // (e^2 beyond 1e308 makes the RMSE infinite while trackingMetrics says not diverged).
        const bool noFigures = m.diverged || !std::isfinite(m.rmse) || !std::isfinite(m.itae) ||
                               !std::isfinite(m.maxAbsU) || !std::isfinite(m.maxAbsErrorPct);
        if (noFigures) {
            ++diverged;
            QVERIFY2(!results[i], which);
            continue;
        }
        ++finite;
        QVERIFY2(results[i].has_value(), which);
        const TrackingMetrics& b = *results[i];
        QCOMPARE(bits(b.rmse), bits(m.rmse));
        QCOMPARE(bits(b.maxAbsError), bits(m.maxAbsError));
        QCOMPARE(bits(b.maxAbsErrorPct), bits(m.maxAbsErrorPct));
        QCOMPARE(bits(b.maxAbsU), bits(m.maxAbsU));
        QCOMPARE(bits(b.itae), bits(m.itae));
        QCOMPARE(b.saturated, m.saturated);
        QCOMPARE(bits(b.saturatedTimeSeconds), bits(m.saturatedTimeSeconds));
        (m.saturated ? clipping : gentle) += 1;
        const MoveSettleMetrics expected = moveSettleMetrics(scalar, move, window);
        const MoveSettleMetrics got = moves[i]->finish();
        QCOMPARE(got.settled, expected.settled);
        QCOMPARE(got.settleTimeSeconds.has_value(), expected.settleTimeSeconds.has_value());
        if (expected.settleTimeSeconds)
            QCOMPARE(bits(*got.settleTimeSeconds), bits(*expected.settleTimeSeconds));
        QCOMPARE(bits(got.finalErrorMm), bits(expected.finalErrorMm));
        QCOMPARE(bits(got.finalOvershootMm), bits(expected.finalOvershootMm));
    }
    // The batch mixes what it must keep apart: clipping and gentle lanes with a limit,
    // diverging and finite lanes without one.
    if (std::isfinite(umax))
        QVERIFY2(clipping > 0 && gentle > 0,
                 qPrintable(QString("clipping %1, gentle %2").arg(clipping).arg(gentle)));
    else
        QVERIFY2(diverged > 0 && finite > 0,
                 qPrintable(QString("diverged %1, finite %2").arg(diverged).arg(finite)));
}

void TstTrackingBatch::badArgumentsNamed() {
    const Case c = randomDesigns(3, 1);
    const std::vector<double> reference(10, 1.0);
    std::vector<std::optional<TrackingMetrics>> results(3);
    TrackingRun run;
    run.reference = &reference;
    const auto field = [&](int width, std::size_t resultCount) -> std::string {
        std::vector<std::optional<TrackingMetrics>> r(resultCount);
        try {
            trackBatch(c.modes, run, {}, r, width);
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return {};
    };
    QCOMPARE(field(3, 3), std::string("batch_width"));
    QCOMPARE(field(16, 3), std::string("batch_width"));
    QCOMPARE(field(4, 2), std::string("lanes"));
    QCOMPARE(field(4, 3), std::string());
    const std::vector<double> empty;
    run.reference = &empty;
    QCOMPARE(field(4, 3), std::string("reference"));
}

QTEST_APPLESS_MAIN(TstTrackingBatch)
#include "tst_tracking_batch.moc"
