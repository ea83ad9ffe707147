// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/design_method_module.h"

#include <string>

namespace xyt {

struct PidFeedforwardDesign; // core/session/pid_feedforward_method.h

/**
 * The PID + feedforward axis' block of the firmware header: its gains as constants, its state
 * (LinuxCNC's error_i, prev_cmd, prev_fb, cmd_d, cmd_dd, limit_state and the filtered D) and
 *   xyt_<id>_step(s, reference, measured)      the command's derivatives by backward differences,
 *   xyt_<id>_step_derivatives(s, reference, velocity, acceleration, jerk, measured)
 *                                               the trajectory generator's,
 * each performing stepServoPid's operations in its order, then the clip at +-XYT_UMAX of the
 * sampled-data loop (simulateSampledServoPid). The first step takes the command as the previous
 * command and the measurement as the previous feedback (no derivative kick).
 */
std::string pidFeedforwardFirmwareBlock(const Session& session, const PidFeedforwardDesign& design,
                                        int axisIndex, const ExportOptions& options);

/// The axis in the Octave/MATLAB script: plant_<id>, controller_<id> C(s), closed_loop_<id>,
/// the feedforward's share ff_plant_<id> = F G / unit, tracking_<id> = T + S F G / unit, r_<id> and
/// y_<id> = lsim(tracking_<id>, ...), the continuous loop with the feedforward and no limit.
OctaveLines pidFeedforwardOctaveLines(const Session& session, const PidFeedforwardDesign& design,
                                      int axisIndex);

} // namespace xyt
