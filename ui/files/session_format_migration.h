// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QJsonObject>

namespace xyt::files {

/**
 * The session format's versions, and how an older one is read.
 *
 * - Version 1: grew field by field; a reader took each of these as optional, with its default
 *   when missing: the "implementation" object and each of its fields, "trajectory.gcode" (and
 *   each snapshot's) unless the kind is "gcode", and the specification's
 *   "in_position_window_mm", "max_settle_time", "min_phase_margin" and "min_gain_margin".
 * - Version 2: the same fields, all of them required. Files that were written by a version-1
 *   writer and hold every field read the same in both.
 * - Version 3 (written now): each axis has a "parameters" object, the numbers of a method
 *   registered at start-up (AxisSettings::parameters). A version-2 axis has none: it reads as
 *   an empty object.
 * - Version 4: the point-to-point move has a "profile" ("cubic" or "quintic",
 *   TrajectorySettings::profile) in the trajectory's "cubic" object. A version-3 move reads as
 *   "cubic".
 * - Version 5: an axis may have a "friction" object (AxisSettings::friction and
 *   frictionCompensation), written when any of it is set. A version-4 axis has none: the linear
 *   table, no compensation.
 * - Version 6: the session may have a "cross_coupling" object (Session::crossCoupling: kp, ki,
 *   estimate), written when it differs from the default (off). A version-5 session has none:
 *   the axes run independently.
 * - Version 7: an axis' "gt" object may have a "flexible_mode" (GtAxisSettings::flexibleMode:
 *   frequency, damping, anti_resonance, anti_resonance_damping) and a "notch" (centre, width,
 *   depth), each written when set, and the trajectory a "shaping" object (ReferenceShaping:
 *   type, frequency, damping), written when on. A version-6 session has none of them: the rigid
 *   table, no notch, the reference unshaped.
 *
 * Reading an older version is this migration to the current one, then the current reader.
 */
inline constexpr int kSessionFormatVersion = 7;

/// @p root (a document of format version @p version, 1 <= version < kSessionFormatVersion)
/// as a document of the current version: each field that version did not require and that
/// @p root lacks gets the value its reader gave it (the default session's), "version" says the
/// current version. Values that are there are kept as they are, wrong ones included: the
/// reader names them afterwards.
QJsonObject migrateSessionJson(QJsonObject root, int version);

} // namespace xyt::files
