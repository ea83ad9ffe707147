// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/specification_advice.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

Diagnostic axisName(const Session& session, std::size_t i) {
    std::string id = session.axes[i].id;
    for (char& c : id)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return makeDiagnostic("session_advice_axis", {id});
}

/// The slowest closed-loop decay of a Guillemin-Truxal axis (rad/s), NaN otherwise.
double slowestPole(const AxisEvaluation& a) {
    if (!a.gt || a.gt->closedLoopPoles.empty())
        return std::numeric_limits<double>::quiet_NaN();
    double slowest = std::numeric_limits<double>::infinity();
    for (const auto& p : a.gt->closedLoopPoles)
        slowest = std::min(slowest, -p.real());
    return slowest;
}

/// The settle after the move of an axis, the worse of design and implementation (s after tf);
/// unset when either did not settle in the run.
std::optional<double> settleSeconds(const AxisEvaluation& a) {
    std::optional<double> worst;
    for (const std::optional<MoveSettleMetrics>* m :
         {&a.moveSettle, a.digital ? &a.digital->moveSettle : nullptr}) {
        if (!m || !*m)
            continue;
        if ((*m)->diverged || !(*m)->settleTimeSeconds)
            return std::nullopt;
        worst = std::max(worst.value_or(0.0), *(*m)->settleTimeSeconds);
    }
    return worst;
}

/// The largest |e| from @p fromSeconds to the end of the axis' runs (design and digital);
/// unset when a run does not reach that time or has a non-finite error there.
std::optional<double> errorBeyond(const AxisEvaluation& a, double fromSeconds) {
    double largest = 0.0;
    const SimulationResult* runs[] = {&a.run, a.digital ? &a.digital->run.result : nullptr};
    for (const SimulationResult* r : runs) {
        if (!r)
            continue;
        if (r->t.empty() || r->t.back() <= fromSeconds)
            return std::nullopt;
        for (std::size_t k = 0; k < r->t.size() && k < r->e.size(); ++k)
            if (r->t[k] >= fromSeconds) {
                if (!std::isfinite(r->e[k]))
                    return std::nullopt;
                largest = std::max(largest, std::abs(r->e[k]));
            }
    }
    return largest;
}

/// One limit of the specification the advice may move: whether an axis fails it, and the worst
/// value the axes reach (the largest for a maximum, the smallest for a minimum).
struct LimitMove {
    double Specification::*limit;
    const char* label; ///< the code of its name in a change, e.g. "max overshoot"
    const char* unit;
    bool maximum;
    bool needed = false;
    double worst = maximum ? 0.0 : std::numeric_limits<double>::infinity();

    void failedAt(double reached) {
        needed = true;
        worst = maximum ? std::max(worst, reached) : std::min(worst, reached);
    }
};

/// Moves the limit of @p move in @p relaxed to what the axes reach, rounded to 3 significant
/// digits on the side that passes (up for a maximum, down for a minimum), and names the change.
void relax(const LimitMove& move, Specification& relaxed, std::vector<Diagnostic>& changes) {
    if (!move.needed)
        return;
    double& limit = relaxed.*move.limit;
    limit = move.maximum ? roundUp3(move.worst) : roundDown3(move.worst);
    changes.push_back(makeDiagnostic("session_advice_change",
                                     {makeDiagnostic(move.label), formatNumber(limit), move.unit}));
}

} // namespace

SpecificationAdvice adviseSpecification(const Session& session,
                                        const SessionEvaluation& evaluation) {
    SpecificationAdvice out;
    Specification relaxed = session.spec;
    bool possible = true, anyFailure = false;
    LimitMove overshoot{&Specification::maxOvershootPct, "session_limit_max_overshoot", "%", true};
    LimitMove settling{&Specification::maxSettlingTimeSeconds, "session_limit_max_settling_time",
                       "s", true};
    LimitMove error{&Specification::maxErrorPct, "session_limit_max_error", "%", true};
    LimitMove settle{&Specification::maxSettleTimeSeconds, "session_limit_max_settle_time", "s",
                     true};
    LimitMove window{&Specification::inPositionWindowMm, "session_limit_in_position_window", "mm",
                     true};
    LimitMove phase{&Specification::minPhaseMarginDeg, "session_limit_min_phase_margin", "deg",
                    false};
    LimitMove gain{&Specification::minGainMarginDb, "session_limit_min_gain_margin", "dB", false};
    const Specification& spec = session.spec;
    for (std::size_t i = 0; i < 2; ++i) {
        const AxisEvaluation& a = evaluation.axes[i];
        const Diagnostic name = axisName(session, i);
        if (!a.ok) {
            possible = false;
            anyFailure = true;
            out.reasons.push_back(
                makeDiagnostic("session_advice_no_design", {name, a.errorField, a.error}));
            continue;
        }
        const SpecificationCheck& c = a.check;
        if (c.allPassed())
            continue;
        anyFailure = true;
        if (!c.stable) {
            possible = false;
            out.reasons.push_back(makeDiagnostic("session_advice_unstable", {name}));
            continue;
        }
        if (!c.overshoot) {
            overshoot.failedAt(a.step.overshootPct);
            out.reasons.push_back(makeDiagnostic(
                a.gt && spec.maxOvershootPct == 0.0 ? "session_advice_overshoot_gt"
                                                    : "session_advice_overshoot",
                {name, formatNumber(a.step.overshootPct, 3), formatNumber(spec.maxOvershootPct)}));
        }
        if (!c.settlingTime) {
            settling.failedAt(a.step.settlingTimeSeconds);
            out.reasons.push_back(makeDiagnostic("session_advice_settling",
                                                 {name, formatNumber(a.step.settlingTimeSeconds, 3),
                                                  formatNumber(spec.maxSettlingTimeSeconds)}));
        }
        if (!c.noSaturation) {
            possible = false;
            out.reasons.push_back(makeDiagnostic("session_advice_saturation",
                                                 {name, formatNumber(session.umaxVolts)}));
        }
        if (!c.trackingError) {
            const double worst = std::max(a.metrics.maxAbsErrorPct,
                                          a.digital ? a.digital->metrics.maxAbsErrorPct : 0.0);
            if (!std::isfinite(worst))
                possible = false;
            error.failedAt(worst);
            out.reasons.push_back(
                makeDiagnostic("session_advice_tracking",
                               {name, formatNumber(worst, 3), formatNumber(spec.maxErrorPct)}));
        }
        if (c.settleApplies && !c.settle) {
            std::optional<double> t = settleSeconds(a);
            const bool estimated = !t;
            if (!t && std::isfinite(evaluation.duration.settleEstimateSeconds) &&
                evaluation.duration.settleEstimateSeconds > 0.0)
                t = evaluation.duration.settleEstimateSeconds;
            const std::string windowMm = formatNumber(spec.inPositionWindowMm);
            const std::string limit = formatNumber(spec.maxSettleTimeSeconds);
            Diagnostic why =
                !t ? makeDiagnostic("session_advice_settle_not_within", {name, windowMm, limit})
                   : makeDiagnostic(estimated ? "session_advice_settle_estimated"
                                              : "session_advice_settle_after",
                                    {name, windowMm, formatNumber(*t, 3), limit});
            const double slow = slowestPole(a);
            if (std::isfinite(slow) && slow > 0.0)
                why = makeDiagnostic("session_advice_slowest_pole", {why, formatNumber(slow, 3)});
            out.reasons.push_back(why);
            if (!estimated) {
                settle.failedAt(*t);
            } else if (const auto w = errorBeyond(a, session.trajectory.tfSeconds +
                                                         spec.maxSettleTimeSeconds)) {
                // Not settled within the run: the settle limit cannot be checked, but the window
                // the error stays in from the limit on can (the run reaches past it).
                window.failedAt(*w);
            } else {
                possible = false;
            }
        }
        if (c.marginsApply && a.margins) {
            if (!c.phaseMargin) {
                phase.failedAt(a.margins->phaseMarginDeg);
                out.reasons.push_back(
                    makeDiagnostic("session_advice_phase_margin",
                                   {name, formatNumber(a.margins->phaseMarginDeg, 3),
                                    formatNumber(spec.minPhaseMarginDeg)}));
            }
            if (!c.gainMargin) {
                gain.failedAt(a.margins->gainMarginDb);
                out.reasons.push_back(makeDiagnostic(
                    "session_advice_gain_margin", {name, formatNumber(a.margins->gainMarginDb, 3),
                                                   formatNumber(spec.minGainMarginDb)}));
            }
        }
    }
    if (!anyFailure || !possible)
        return out;
    if ((phase.needed && !(phase.worst > 0.0)) || (gain.needed && !(gain.worst > 0.0)))
        return out; // a minimum below 0 is no requirement to offer
    for (const LimitMove* move : {&overshoot, &settling, &error, &settle})
        relax(*move, relaxed, out.changes);
    if (window.needed && !(window.worst > 0.0))
        return out; // no window of 0 mm or less holds the error
    for (const LimitMove* move : {&window, &phase, &gain})
        relax(*move, relaxed, out.changes);
    out.relaxed = relaxed;
    return out;
}

} // namespace xyt
