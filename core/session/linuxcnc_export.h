// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <string>

namespace xyt {

/// The margin of the suggested following-error limits over the simulated following error.
inline constexpr double kFollowingErrorMargin = 2.0;

/**
 * The session's axes as LinuxCNC's `pid` component runs them (2.8 and later): per axis, joint
 * i = the axis' index, a HAL fragment `setp pid.i.Pgain ...` (Pgain, Igain, Dgain, bias, FF0,
 * FF1, FF2, FF3, deadband, maxerrorI, maxoutput, each with 17 significant digits) and, as
 * comments (so that the file loads with halcmd -f), an INI `[JOINT_i]` section with FERROR and
 * MIN_FERROR suggested as kFollowingErrorMargin times the
 * largest following error of the digital run (of the design's run when there is none): at any
 * speed (FERROR) and while the command moves at most a tenth of its peak speed (MIN_FERROR).
 * The comments state the units: position in mm, output in volts before the DAC's scale.
 *
 * A PID + feedforward axis exports its gains; a Guillemin-Truxal axis the same PI (P = kp u,
 * I = ki u per mm). With @p feedforwardFromModel every axis gets the plant's exact inverse as
 * FF1..FF3 (withModelFeedforward), where the session has none too. Throws InvalidInput naming
 * "axes[i].method" for a pole-placement axis (no pid equivalent), and the field of an axis
 * that was not evaluated.
 */
std::string exportLinuxCnc(const Session& session, const SessionEvaluation& evaluation,
                           bool feedforwardFromModel = false);

} // namespace xyt
