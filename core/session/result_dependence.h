// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

namespace xyt {

/**
 * What a stored result was computed from, so that a view can tell whether it still describes
 * the session: two sessions "agree" for a result when everything it depends on is equal.
 */
enum class ResultScope {
    /// One axis' analysis (robustness of an axis): that axis' settings whole (method,
    /// controller, plant), the trajectory, the actuator limit and the specification.
    AxisDesign,
    /// The design space of a Guillemin–Truxal axis: its runs sweep ωn and kp, so they depend
    /// on the method, the plant and its unit scale, the trajectory, the actuator limit and the
    /// two limits that set a run's length and settle figures, never on the axis' own ωn and kp.
    AxisStudy,
    /// A joint XY result (contour robustness): both axes' settings, the trajectory, the limit
    /// and the specification.
    BothAxes,
};

/// True when @p a and @p b give the same result of @p scope for @p axis (ignored for
/// BothAxes). @throws std::out_of_range for an axis other than 0 or 1.
bool sessionsAgree(const Session& a, const Session& b, int axis, ResultScope scope);

} // namespace xyt
