// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/c_export.h"
#include "core/session/session.h"

#include <string>

namespace xyt {

/**
 * The friction compensation of axis @p axisIndex as C for firmware, or "" when the axis has none:
 * its constants and `xyt_<id>_friction_ff(velocity)`, FrictionCompensation's
 *   u_fc = p / 100 (Fc sat(v / w) + bv v)
 * with the same operations in the same order, in xyt_real arithmetic. The firmware adds it to the
 * controller's output before the limit, from its trajectory generator's velocity (mm/s), as the
 * simulation does. @throws InvalidInput naming "axes[i].friction..." for a value C cannot hold.
 */
std::string frictionCompensationCBlock(const Session& session, int axisIndex, CPrecision precision);

/**
 * LinuxCNC's note on the friction compensation of @p axis (joint @p joint), as "#" comment lines,
 * or "" without one: `pid` has no sign-dependent term, so the values go to a separate component
 * (e.g. a `comp`-written friction feedforward summed into the pid output) and are given here.
 */
std::string linuxCncFrictionNote(const AxisSettings& axis, int axisIndex, std::size_t joint);

} // namespace xyt
