// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/specification.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>

namespace xyt {

namespace {

void requireNonNegative(double value, const std::string& field) {
    requireFinite(value, field);
    if (value < 0.0)
        throw InvalidInput(field, makeDiagnostic("study_zero_or_more"));
}

/// Comparisons written so that NaN fails: !(NaN <= x) is true.
bool atMost(double value, double limit) {
    return std::isfinite(value) && value <= limit;
}
/// At least the limit; +infinity (no crossing) passes, NaN fails.
bool atLeast(double value, double limit) {
    return !std::isnan(value) && value >= limit;
}

} // namespace

void Specification::validate() const {
    requirePositive(maxSettlingTimeSeconds, "max_settling_time");
    requireNonNegative(maxOvershootPct, "max_overshoot_pct");
    requirePositive(umaxVolts, "umax");
    requirePositive(maxErrorPct, "max_error_pct");
    requirePositive(inPositionWindowMm, "in_position_window_mm");
    requirePositive(maxSettleTimeSeconds, "max_settle_time");
    requireNonNegative(minPhaseMarginDeg, "min_phase_margin");
    if (minPhaseMarginDeg > 180.0)
        throw InvalidInput("min_phase_margin", makeDiagnostic("study_phase_margin_at_most_180"));
    requireNonNegative(minGainMarginDb, "min_gain_margin");
}

SpecificationCheck checkSpecification(const Specification& spec, const TrackingMetrics& tracking,
                                      const StepCharacteristics& step,
                                      const std::optional<MoveSettleMetrics>& move,
                                      const std::optional<LoopMarginFigures>& margins) {
    spec.validate();
    SpecificationCheck c;
    c.stable = step.stable;
    c.settlingTime = step.stable && atMost(step.settlingTimeSeconds, spec.maxSettlingTimeSeconds);
    c.overshoot =
        step.stable &&
        atMost(step.overshootPct, spec.maxOvershootPct + Specification::kOvershootRoundOffPct);
    // A diverged run has no figures: it fails both tracking criteria (atMost(NaN) is false too).
    c.noSaturation =
        !tracking.diverged && !tracking.saturated && atMost(tracking.maxAbsU, spec.umaxVolts);
    c.trackingError = !tracking.diverged && atMost(tracking.maxAbsErrorPct, spec.maxErrorPct);
    if (move) {
        c.settleApplies = true;
        c.settle = !move->diverged && move->settled && move->windowMm == spec.inPositionWindowMm &&
                   atMost(move->settleTimeSeconds.value_or(NAN), spec.maxSettleTimeSeconds);
    }
    if (margins) {
        c.marginsApply = true;
        c.phaseMargin = step.stable && atLeast(margins->phaseMarginDeg, spec.minPhaseMarginDeg);
        c.gainMargin = step.stable && atLeast(margins->gainMarginDb, spec.minGainMarginDb);
    }
    return c;
}

SpecificationCheck bothPass(const SpecificationCheck& a, const SpecificationCheck& b) {
    SpecificationCheck c;
    c.stable = a.stable && b.stable;
    c.settlingTime = a.settlingTime && b.settlingTime;
    c.overshoot = a.overshoot && b.overshoot;
    c.noSaturation = a.noSaturation && b.noSaturation;
    c.trackingError = a.trackingError && b.trackingError;
    c.settle = a.settle && b.settle;
    c.settleApplies = a.settleApplies || b.settleApplies;
    c.phaseMargin = a.phaseMargin && b.phaseMargin;
    c.gainMargin = a.gainMargin && b.gainMargin;
    c.marginsApply = a.marginsApply || b.marginsApply;
    return c;
}

} // namespace xyt
