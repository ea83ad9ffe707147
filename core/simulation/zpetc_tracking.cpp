// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/zpetc_tracking.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

struct ErrorFigures {
    double rmse = 0.0;
    double maxAbs = 0.0;
};

ErrorFigures errorFigures(const std::vector<double>& r, const std::vector<double>& y) {
    ErrorFigures e;
    double sum = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) {
        const double d = r[k] - y[k];
        sum += d * d;
        e.maxAbs = std::max(e.maxAbs, std::abs(d));
    }
    e.rmse = std::sqrt(sum / static_cast<double>(y.size()));
    return e;
}

} // namespace

ZpetcTrackingRun runZpetcTracking(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                                  const Sinusoid& reference, double durationSeconds,
                                  StartCondition start) {
    reference.validate();
    ZpetcTrackingRun run;
    run.t = sampleTimes(durationSeconds, loop.tsSeconds);
    const std::size_t n = run.t.size();
    if (n < 2) // one sample: every error figure would read 0, which is not a result
        throw InvalidInput("duration",
                           makeDiagnostic("sim_single_sample", {formatNumber(loop.tsSeconds),
                                                                formatNumber(durationSeconds)}));
    const auto p = static_cast<std::size_t>(zpetc.previewSteps);
    // The last time read (preview included) and its phase omega t must be finite, or sin() gives
    // NaN for a run that looks valid (found by fuzz_design with Ts = 1.8e308; regression input
    // tests/fuzz/corpus/fuzz_design/crash-sample-time-overflow).
    const double lastTime = static_cast<double>(n + p) * loop.tsSeconds;
    if (!std::isfinite(lastTime) ||
        !std::isfinite(reference.omegaRadPerSec * lastTime + reference.phaseRad))
        throw InvalidInput("duration", makeDiagnostic("sim_time_overflows"));
    std::vector<double> previewed(n + p);
    for (std::size_t k = 0; k < n + p; ++k)
        previewed[k] = reference.value(static_cast<double>(k) * loop.tsSeconds);
    run.r.assign(previewed.begin(), previewed.begin() + static_cast<std::ptrdiff_t>(n));
    run.feedbackOnly = simulateFeedbackLoop(loop, run.r, start);
    run.withZpetc = simulateZpetcLoop(loop, zpetc, previewed, n, start);
    run.trajectoryZpetc = simulateTrajectoryZpetc(zpetc, previewed, n, start);
    const ErrorFigures without = errorFigures(run.r, run.feedbackOnly.y);
    const ErrorFigures with = errorFigures(run.r, run.withZpetc.y);
    run.rmseWithoutFf = without.rmse;
    run.rmseWithFf = with.rmse;
    run.maxAbsErrorWithoutFf = without.maxAbs;
    run.maxAbsErrorWithFf = with.maxAbs;
    run.improvementPct = without.rmse > 0.0 ? 100.0 * (1.0 - with.rmse / without.rmse) : 0.0;
    return run;
}

ZpetcCircleRun runZpetcCircle(const PolePlacementDesign& xLoop, const ZpetcDesign& xZpetc,
                              const PolePlacementDesign& yLoop, const ZpetcDesign& yZpetc,
                              const Circle& circle, double durationSeconds, StartCondition start) {
    if (xLoop.tsSeconds != yLoop.tsSeconds)
        throw InvalidInput("ts", makeDiagnostic("sim_axes_share_ts"));
    ZpetcCircleRun out;
    out.x = runZpetcTracking(xLoop, xZpetc, circle.xAxis(), durationSeconds, start);
    out.y = runZpetcTracking(yLoop, yZpetc, circle.yAxis(), durationSeconds, start);
    out.contourWithoutFf =
        circleContourError(out.x.t, out.x.feedbackOnly.y, out.y.feedbackOnly.y, circle);
    out.contourWithFf = circleContourError(out.x.t, out.x.withZpetc.y, out.y.withZpetc.y, circle);
    return out;
}

} // namespace xyt
