// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/study/design_sweep.h"
#include "core/study/specification.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// The criteria of a Specification, as SpecificationCheck names them.
enum class SpecCriterion {
    Stable,
    SettlingTime,
    Overshoot,
    NoSaturation,
    TrackingError,
    Settle,
    PhaseMargin, ///< a minimum: larger is better
    GainMargin,  ///< a minimum: larger is better
};

/// "stable", "settling_time", "overshoot", "no_saturation", "tracking_error", "settle",
/// "phase_margin", "gain_margin" (the keys of the CLI's checks).
std::string specCriterionName(SpecCriterion criterion);

/// A criterion that no computed design of the grid passes.
struct CriterionFailure {
    SpecCriterion criterion = SpecCriterion::Stable;
    /// The design that comes closest on this criterion alone (smallest step overshoot, shortest
    /// settle, ...); unset when no design has a value for it (no stable design, none settled).
    std::optional<std::size_t> bestIndex;
    /// Its value, in the unit of the limit: % (overshoot, tracking error), s (settling, settle),
    /// s of clipping (no_saturation, whose limit is 0 s), deg and dB (the margins, where the
    /// best is the largest); NaN when bestIndex is unset.
    double bestValue = 0.0;
    double limit = 0.0; ///< the specification's limit, same unit
};

/**
 * What a finished sweep says beyond its best point: why nothing is feasible, and whether the
 * best design sits on the edge of the grid. Everything is also said in `warnings`, one sentence
 * each, ready to show (the CLI puts them in its JSON "warnings", the design-space view under
 * the map).
 */
struct SweepDiagnosis {
    std::vector<Diagnostic> warnings;

    /// No computed design is feasible (and at least one was computed).
    bool noneFeasible = false;
    /// Criteria failed by every computed design, in SpecCriterion order.
    std::vector<CriterionFailure> failingEverywhere;
    /**
     * When none is feasible: the stable design with finite figures of the smallest total
     * normalized violation V = sum over the criteria it fails of (value - limit) / scale, where
     * scale is the limit, or 1 % for a zero overshoot limit; saturation counts the clipped time
     * as a fraction of the longest clipped time on the grid (0..1); a settle that never happened
     * counts as (run time after tf - limit) / limit + 1 (the run time is a lower bound of the
     * settle). Ties: the lowest index. Unset when no design is stable with finite figures.
     */
    std::optional<std::size_t> leastViolating;
    double leastViolation = 0.0; ///< V of leastViolating
    /**
     * The specification relaxed just enough for leastViolating to pass: each limit it fails is
     * raised to its value there, rounded up to 3 significant digits (umax is not relaxed: a
     * clipped design keeps clipping at any error limit, so a spec it would still fail is
     * given only when no saturation is involved). Unset when it cannot be made to pass.
     */
    std::optional<Specification> relaxed;

    /// The point judged for the edge test: the refined design when there is one, else the best
    /// grid point (unset when nothing is feasible).
    std::optional<std::size_t> bestIndex;
    bool wnAtLowerEdge = false,
         wnAtUpperEdge = false; ///< the best wn is the first / last grid value
    bool kpAtLowerEdge = false, kpAtUpperEdge = false; ///< the same for kp
    bool onEdge() const { return wnAtLowerEdge || wnAtUpperEdge || kpAtLowerEdge || kpAtUpperEdge; }
};

/**
 * Diagnoses @p result against @p spec (the specification it was judged with). Only computed
 * points count; a cancelled sweep is diagnosed on what it computed. An axis of a single value
 * has no edge to widen. The edge test uses the best grid point's indices (the refinement never
 * leaves the grid's box, so a refined best at the box's bound is on the same edge).
 * @throws InvalidInput from Specification::validate.
 */
SweepDiagnosis diagnoseSweep(const DesignSweepResult& result, const Specification& spec);

} // namespace xyt
