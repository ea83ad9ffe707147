// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/digital_controller.h"
#include "core/io/file_io.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"

#include <string>

namespace xyt {

/// The arithmetic of the exported C controller.
enum class CPrecision { Double, Float };

/// "double" / "float".
std::string precisionName(CPrecision precision);

/// Options shared by the coefficient exports.
struct ExportOptions {
    PiDiscretization piMethod = PiDiscretization::Tustin;
    /// The C export's xyt_real (the controller's arithmetic; the coefficient arrays stay double).
    CPrecision precision = CPrecision::Double;
};

/// The digital controller that the firmware runs for one axis: the PI of a continuous design
/// discretized at session.controllerTsSeconds, or the feedback part of a discrete design.
/// @throws InvalidInput when the axis could not be designed.
DigitalController axisDigitalController(const Session& session, const SessionEvaluation& evaluation,
                                        int axisIndex, const ExportOptions& options);

// Every export copies user text (axis labels) only as escaped comment text (core/io/text_escape.h),
// so a session file cannot put code into a header or script, and refuses a non-finite number
// with InvalidInput naming the session field it comes from.

/**
 * A C99 header for firmware: per axis the coefficients, `static const double XYT_<AXIS>_NUM[]`,
 * `XYT_<AXIS>_DEN[]` (ascending powers of z^-1), `XYT_<AXIS>_TS`, the lengths as macros, and a
 * comment with the difference equation; and the complete controller, self-contained
 * (no dynamic memory, no recursion, no library call), in `xyt_real` = double or float
 * (options.precision):
 *  - Guillemin-Truxal axes: `xyt_<axis>_state`, `xyt_<axis>_init(&s)`,
 *    `u = xyt_<axis>_step(&s, reference_mm, measured_mm)`: the PI of stepDigitalPi with the
 *    session's anti-windup, saturated at +-umax;
 *  - pole-placement axes: `xyt_<axis>_init(&s, rest_mm)` and
 *    `u = xyt_<axis>_step(&s, reference_ahead_mm, measured_mm)`: the RST law and, with ZPETC,
 *    its feedforward reading the reference XYT_<AXIS>_PREVIEW samples ahead (the header says so);
 *  - with a DAC in the session, `xyt_dac_code(u)` and `xyt_dac_volts(code)` (dacOutput).
 * The steps perform the operations of the core's sampled-data loop (sampled_data.h) in the same
 * order, so in double they give its bits. Compiles standalone with
 * `cc -std=c99 -Wall -Wextra -Werror -pedantic`. Numbers are printed with 17 significant digits,
 * so they read back exactly. User text (labels) enters only as comment text; axis ids, which
 * name the functions, must be 1 to 16 lower-case letters or digits and differ.
 * In float, every constant of the controller's arithmetic (XYT_UMAX, the PI's KP, C0, C1, UNIT,
 * AW_GAIN, the RST law's KF, F, G, U_REST and feedforward, XYT_DAC_LSB) must keep its value: one
 * beyond FLT_MAX (inf when compiled) or a non-zero one that rounds to 0 is refused.
 * @throws InvalidInput naming the session field of a non-finite number, or of a constant float
 *         cannot hold (the message names the constant and its value), "axes[i].id" for an id
 *         that cannot name a C function, "implementation.*" / "controller_ts" for settings the
 *         controller cannot run with.
 */
std::string exportCHeader(const Session& session, const SessionEvaluation& evaluation,
                          const ExportOptions& options = {});

/// Octave/MATLAB lines computing the reference r_<id> of axis @p axisIndex on the vector t.
std::string octaveTrajectoryLines(const TrajectorySettings& t, int axisIndex,
                                  const std::string& id);

/**
 * A GNU Octave / MATLAB script defining per axis `plant_<axis>`, `controller_<axis>` and
 * `closed_loop_<axis>` as tf objects, then plotting the closed-loop response to the session's
 * trajectory (linear: lsim, no actuator limit). Runs with `pkg load control` in Octave.
 */
std::string exportOctaveScript(const Session& session, const SessionEvaluation& evaluation,
                               const ExportOptions& options = {});

/**
 * The simulated signals as CSV, one row per step of the session's dt (trajectory.dt) over the
 * run: t,r_<x>,y_<x>,e_<x>,u_<x>,r_<y>,y_<y>,e_<y>,u_<y> (10 significant digits), then the
 * digital implementation of each axis (DigitalEvaluation::run, as the firmware runs it):
 * t_digital_<x>,y_digital_<x>,e_digital_<x>,u_digital_<x>, the same for <y> (17 significant
 * digits, so they read back exactly).
 * A Guillemin-Truxal axis is simulated at dt, so its columns are its samples. A pole-placement
 * axis and every digital implementation run at their own sample time (Ts, controller_ts): each
 * row shows the sample held at t, the last one at or before it (heldSampleIndices), as the
 * controller's output register holds u; t_digital_<id> is the instant of that sample, so the
 * rows where t_digital changes are the controller's samples, one to one with a firmware log.
 * y_digital is the plant output at that instant, e_digital = r - y_digital, u_digital the
 * controller's saturated command (before the DAC). Digital cells are empty for an axis without
 * a digital implementation, or where its value is not finite.
 * @throws InvalidInput "axes[i]" when an axis has no simulation or a simulated signal is not
 *         finite (before anything is written to @p sink).
 */
void exportCsv(const Session& session, const SessionEvaluation& evaluation, const ByteSink& sink);
/// The same CSV as one string (for small sessions; files are streamed with the sink form).
std::string exportCsv(const Session& session, const SessionEvaluation& evaluation);

/// A double with 17 significant digits ("%.17g").
std::string exactNumber(double v);

/// @p v itself when it may go into an export. A header, script or JSON file with inf or NaN in
/// it does not compile, does not parse (JSON writes null), or means something the session does not.
/// @throws InvalidInput naming @p field (the session path it comes from) when @p v is not finite.
double exportableNumber(double v, const std::string& field);

} // namespace xyt
