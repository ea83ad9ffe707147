// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/session/session_evaluation.h"

#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * Why a session's design fails its specification, in words a newcomer can act on, and the
 * limits it would pass. Braga et al.'s specification (the default) asks for 0 % overshoot,
 * which no Guillemin-Truxal design meets (its reference model is type 2: the step error
 * integrates to zero, so y overshoots), and a 0.01 mm in-position window that the slow
 * closed-loop pole beside the PI zero reaches only hundreds of seconds after the move.
 */
struct SpecificationAdvice {
    /// One sentence per failing criterion and axis, the cause where it is known.
    std::vector<Diagnostic> reasons;
    /**
     * The specification with each failing limit moved to what the worse of the two axes
     * reaches (the worse of its design and its implementation), rounded to 3 significant
     * digits so the value passes (roundUp3 for maxima, roundDown3 for the margin minima). A
     * settle that the run does not reach cannot be given a time the run would confirm; the
     * in-position window is widened instead to the largest |e| from tf + the settle limit to
     * the end of the run (design and implementation), so the settle then passes.
     * Unset when relaxing a limit cannot make the design pass: an axis without a design, an
     * unstable loop, a clipped actuator, a settle that never happens; or when nothing fails.
     */
    std::optional<Specification> relaxed;
    /// The limits relaxed, e.g. "max overshoot 1 %", for a button's tooltip.
    std::vector<Diagnostic> changes;
};

SpecificationAdvice adviseSpecification(const Session& session,
                                        const SessionEvaluation& evaluation);

} // namespace xyt
