// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/sweep_diagnosis.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

constexpr SpecCriterion kCriteria[] = {SpecCriterion::Stable,        SpecCriterion::SettlingTime,
                                       SpecCriterion::Overshoot,     SpecCriterion::NoSaturation,
                                       SpecCriterion::TrackingError, SpecCriterion::Settle,
                                       SpecCriterion::PhaseMargin,   SpecCriterion::GainMargin};

/// The margins are minimum limits: their best value is the largest.
bool largerIsBetter(SpecCriterion c) {
    return c == SpecCriterion::PhaseMargin || c == SpecCriterion::GainMargin;
}

/// The codes of what a criterion is called in a sentence, and of a value in its unit ("%1 s").
struct Wording {
    const char* name;
    const char* unit;
};
Wording wording(SpecCriterion c) {
    switch (c) {
    case SpecCriterion::Stable:
        return {"study_criterion_stability", ""};
    case SpecCriterion::SettlingTime:
        return {"study_criterion_settling_time", "study_value_seconds"};
    case SpecCriterion::Overshoot:
        return {"study_criterion_overshoot", "study_value_percent"};
    case SpecCriterion::NoSaturation:
        return {"study_criterion_clipped_time", "study_value_seconds"};
    case SpecCriterion::TrackingError:
        return {"study_criterion_tracking_error", "study_value_percent_of_travel"};
    case SpecCriterion::Settle:
        return {"study_criterion_settle_time", "study_value_seconds"};
    case SpecCriterion::PhaseMargin:
        return {"study_criterion_phase_margin", "study_value_degrees"};
    case SpecCriterion::GainMargin:
        return {"study_criterion_gain_margin", "study_value_decibels"};
    }
    return {"", ""};
}

/// The criterion's name.
Diagnostic nameOf(SpecCriterion c) {
    return makeDiagnostic(wording(c).name);
}

/// @p number (formatted) in the criterion's unit.
Diagnostic valueIn(SpecCriterion c, const std::string& number) {
    const char* unit = wording(c).unit;
    return *unit ? makeDiagnostic(unit, {number}) : Diagnostic(number);
}

bool passes(const SpecificationCheck& c, SpecCriterion criterion) {
    switch (criterion) {
    case SpecCriterion::Stable:
        return c.stable;
    case SpecCriterion::SettlingTime:
        return c.settlingTime;
    case SpecCriterion::Overshoot:
        return c.overshoot;
    case SpecCriterion::NoSaturation:
        return c.noSaturation;
    case SpecCriterion::TrackingError:
        return c.trackingError;
    case SpecCriterion::Settle:
        return c.settle;
    case SpecCriterion::PhaseMargin:
        return c.phaseMargin;
    case SpecCriterion::GainMargin:
        return c.gainMargin;
    }
    return false;
}

double limitOf(const Specification& spec, SpecCriterion c) {
    switch (c) {
    case SpecCriterion::Stable:
        return 0.0;
    case SpecCriterion::SettlingTime:
        return spec.maxSettlingTimeSeconds;
    case SpecCriterion::Overshoot:
        return spec.maxOvershootPct;
    case SpecCriterion::NoSaturation:
        return 0.0;
    case SpecCriterion::TrackingError:
        return spec.maxErrorPct;
    case SpecCriterion::Settle:
        return spec.maxSettleTimeSeconds;
    case SpecCriterion::PhaseMargin:
        return spec.minPhaseMarginDeg;
    case SpecCriterion::GainMargin:
        return spec.minGainMarginDb;
    }
    return 0.0;
}

/// The value a point has on a criterion (smaller is better, except largerIsBetter), or nullopt
/// when it has none. Margins count for a stable loop only (an unstable one fails them).
std::optional<double> valueOf(const DesignPoint& p, SpecCriterion c) {
    if (!p.computed)
        return std::nullopt;
    const bool stepDefined = p.stable && p.metricsFinite;
    switch (c) {
    case SpecCriterion::Stable:
        return std::nullopt;
    case SpecCriterion::SettlingTime:
        return stepDefined ? std::optional(p.step.settlingTimeSeconds) : std::nullopt;
    case SpecCriterion::Overshoot:
        return stepDefined ? std::optional(p.step.overshootPct) : std::nullopt;
    case SpecCriterion::NoSaturation:
        return p.metricsFinite ? std::optional(p.tracking.saturatedTimeSeconds) : std::nullopt;
    case SpecCriterion::TrackingError:
        return p.metricsFinite ? std::optional(p.tracking.maxAbsErrorPct) : std::nullopt;
    case SpecCriterion::Settle:
        return p.move && p.move->settleTimeSeconds ? p.move->settleTimeSeconds : std::nullopt;
    case SpecCriterion::PhaseMargin:
        return stepDefined && !std::isnan(p.phaseMarginDeg) ? std::optional(p.phaseMarginDeg)
                                                            : std::nullopt;
    case SpecCriterion::GainMargin:
        return stepDefined && !std::isnan(p.gainMarginDb) ? std::optional(p.gainMarginDb)
                                                          : std::nullopt;
    }
    return std::nullopt;
}

Diagnostic at(const DesignSweepResult& r, std::size_t i) {
    return makeDiagnostic("study_design_at",
                          {formatNumber(r.points[i].wn, 4), formatNumber(r.points[i].kp, 4)});
}

/// One edge warning: "kp = 60 is the upper end of the kp range 5..60: ...".
Diagnostic edgeDiagnostic(const char* axis, const std::vector<double>& values, bool upper) {
    const std::string v = formatNumber(upper ? values.back() : values.front(), 6);
    return makeDiagnostic(
        upper ? "study_best_at_upper_edge" : "study_best_at_lower_edge",
        {axis, v, axis, formatNumber(values.front(), 6), formatNumber(values.back(), 6), axis, v});
}

} // namespace

std::string specCriterionName(SpecCriterion criterion) {
    switch (criterion) {
    case SpecCriterion::Stable:
        return "stable";
    case SpecCriterion::SettlingTime:
        return "settling_time";
    case SpecCriterion::Overshoot:
        return "overshoot";
    case SpecCriterion::NoSaturation:
        return "no_saturation";
    case SpecCriterion::TrackingError:
        return "tracking_error";
    case SpecCriterion::Settle:
        return "settle";
    case SpecCriterion::PhaseMargin:
        return "phase_margin";
    case SpecCriterion::GainMargin:
        return "gain_margin";
    }
    return "";
}

SweepDiagnosis diagnoseSweep(const DesignSweepResult& result, const Specification& spec) {
    spec.validate();
    SweepDiagnosis d;
    const auto& points = result.points;
    const bool anyComputed =
        std::any_of(points.begin(), points.end(), [](const DesignPoint& p) { return p.computed; });
    const bool anyFeasible = std::any_of(points.begin(), points.end(), [](const DesignPoint& p) {
        return p.computed && p.feasible;
    });
    d.noneFeasible = anyComputed && !anyFeasible;

    if (d.noneFeasible) {
        // (a) Criteria that fail everywhere, with the best value the grid reaches on each.
        const bool settleApplies =
            std::any_of(points.begin(), points.end(),
                        [](const DesignPoint& p) { return p.computed && p.check.settleApplies; });
        for (SpecCriterion c : kCriteria) {
            if (c == SpecCriterion::Settle && !settleApplies)
                continue;
            const bool passedSomewhere =
                std::any_of(points.begin(), points.end(),
                            [&](const DesignPoint& p) { return p.computed && passes(p.check, c); });
            if (passedSomewhere)
                continue;
            CriterionFailure f;
            f.criterion = c;
            f.limit = limitOf(spec, c);
            f.bestValue = kNaN;
            for (std::size_t i = 0; i < points.size(); ++i) {
                const auto v = valueOf(points[i], c);
                if (v && std::isfinite(*v) &&
                    (!f.bestIndex || (largerIsBetter(c) ? *v > f.bestValue : *v < f.bestValue))) {
                    f.bestIndex = i;
                    f.bestValue = *v;
                }
            }
            Diagnostic diagnostic;
            if (c == SpecCriterion::Stable)
                diagnostic = makeDiagnostic("study_none_stable");
            else if (c == SpecCriterion::Settle && !f.bestIndex)
                diagnostic =
                    makeDiagnostic("study_none_settles",
                                   {formatNumber(spec.inPositionWindowMm), formatNumber(f.limit)});
            else if (!f.bestIndex)
                diagnostic = makeDiagnostic("study_limit_fails_everywhere",
                                            {nameOf(c), valueIn(c, formatNumber(f.limit))});
            else
                diagnostic = makeDiagnostic(
                    largerIsBetter(c) ? "study_limit_fails_largest" : "study_limit_fails_smallest",
                    {nameOf(c), valueIn(c, formatNumber(f.limit)), nameOf(c),
                     valueIn(c, formatNumber(f.bestValue, 4)), at(result, *f.bestIndex)});
            d.warnings.push_back(diagnostic);
            d.failingEverywhere.push_back(f);
        }

        // The least-violating design: smallest total normalized violation.
        double maxClipped = 0.0;
        for (const DesignPoint& p : points)
            if (p.computed && p.metricsFinite)
                maxClipped = std::max(maxClipped, p.tracking.saturatedTimeSeconds);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const DesignPoint& p = points[i];
            if (!p.computed || !p.stable || !p.metricsFinite)
                continue;
            double violation = 0.0;
            for (SpecCriterion c : kCriteria) {
                if (c == SpecCriterion::Stable || passes(p.check, c))
                    continue;
                const double limit = limitOf(spec, c);
                if (c == SpecCriterion::NoSaturation) {
                    violation +=
                        maxClipped > 0.0 ? p.tracking.saturatedTimeSeconds / maxClipped : 1.0;
                } else if (c == SpecCriterion::Settle) {
                    const double v =
                        p.move && p.move->settleTimeSeconds
                            ? *p.move->settleTimeSeconds
                            : (p.move ? p.move->runEndSeconds - p.move->moveEndSeconds : limit);
                    violation +=
                        std::max(0.0, v - limit) / limit + (p.move && p.move->settled ? 0.0 : 1.0);
                } else if (largerIsBetter(c)) {
                    // Below the minimum: by how much, in units of the minimum (at least 1 deg
                    // or dB, so a zero minimum still scales); no value (NaN margin) counts 1.
                    const auto v = valueOf(p, c);
                    violation += v ? std::max(0.0, limit - *v) / std::max(limit, 1.0) : 1.0;
                } else {
                    const double scale =
                        c == SpecCriterion::Overshoot ? std::max(limit, 1.0) : limit;
                    violation += std::max(0.0, *valueOf(p, c) - limit) / scale;
                }
            }
            if (!d.leastViolating || violation < d.leastViolation) {
                d.leastViolating = i;
                d.leastViolation = violation;
            }
        }
        if (d.leastViolating) {
            const DesignPoint& p = points[*d.leastViolating];
            Specification relaxed = spec;
            bool possible = true;
            std::vector<Diagnostic> changes;
            for (SpecCriterion c : kCriteria) {
                if (passes(p.check, c))
                    continue;
                const auto v = valueOf(p, c);
                if (c == SpecCriterion::NoSaturation || c == SpecCriterion::Stable || !v ||
                    (c == SpecCriterion::Settle && p.move &&
                     p.move->windowMm != spec.inPositionWindowMm)) {
                    possible = false;
                    continue;
                }
                if (largerIsBetter(c) && !(*v > 0.0)) { // a minimum below 0 is not offered
                    possible = false;
                    continue;
                }
                const double limit = largerIsBetter(c) ? roundDown3(*v) : roundUp3(*v);
                switch (c) {
                case SpecCriterion::SettlingTime:
                    relaxed.maxSettlingTimeSeconds = limit;
                    break;
                case SpecCriterion::Overshoot:
                    relaxed.maxOvershootPct = limit;
                    break;
                case SpecCriterion::TrackingError:
                    relaxed.maxErrorPct = limit;
                    break;
                case SpecCriterion::Settle:
                    relaxed.maxSettleTimeSeconds = limit;
                    break;
                case SpecCriterion::PhaseMargin:
                    relaxed.minPhaseMarginDeg = limit;
                    break;
                case SpecCriterion::GainMargin:
                    relaxed.minGainMarginDb = limit;
                    break;
                default:
                    break;
                }
                changes.push_back(makeDiagnostic(largerIsBetter(c) ? "study_change_at_least"
                                                                   : "study_change_at_most",
                                                 {nameOf(c), valueIn(c, formatNumber(limit))}));
            }
            const Diagnostic design = at(result, *d.leastViolating);
            const std::string point = std::to_string(*d.leastViolating);
            Diagnostic diagnostic = makeDiagnostic("study_least_violating", {design, point});
            if (possible && !changes.empty()) {
                d.relaxed = relaxed;
                diagnostic =
                    makeDiagnostic("study_least_violating_relaxed",
                                   {design, point, joinDiagnostics(changes, "list_comma")});
            } else if (!possible) {
                diagnostic = makeDiagnostic("study_least_violating_no_relaxing", {design, point});
            }
            d.warnings.push_back(diagnostic);
        }
    }

    // (b) The best design on the edge of the grid.
    if (result.bestIndex && !result.kpValues.empty()) {
        d.bestIndex = result.bestIndex;
        const std::size_t nKp = result.kpValues.size();
        const std::size_t iWn = *result.bestIndex / nKp, iKp = *result.bestIndex % nKp;
        if (result.wnValues.size() > 1) {
            d.wnAtLowerEdge = iWn == 0;
            d.wnAtUpperEdge = iWn + 1 == result.wnValues.size();
        }
        if (nKp > 1) {
            d.kpAtLowerEdge = iKp == 0;
            d.kpAtUpperEdge = iKp + 1 == nKp;
        }
        if (d.wnAtLowerEdge || d.wnAtUpperEdge)
            d.warnings.push_back(edgeDiagnostic("wn", result.wnValues, d.wnAtUpperEdge));
        if (d.kpAtLowerEdge || d.kpAtUpperEdge)
            d.warnings.push_back(edgeDiagnostic("kp", result.kpValues, d.kpAtUpperEdge));
    }
    return d;
}

} // namespace xyt
