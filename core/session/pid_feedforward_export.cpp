// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/pid_feedforward_export.h"

#include "core/session/c_export.h"
#include "core/session/pid_feedforward_method.h"

#include <sstream>
#include <utility>
#include <vector>

namespace xyt {

using namespace cexport;

std::string pidFeedforwardFirmwareBlock(const Session& session, const PidFeedforwardDesign& d,
                                        int i, const ExportOptions& options) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(i));
    const std::string id = axis.id, up = upper(id);
    const std::string k = "XYT_" + up + "_";
    const ServoPidGains& g = d.gains;
    const std::vector<std::pair<std::string, std::pair<double, std::string>>> constants = {
        {"P", {g.p, "p"}},
        {"I", {g.i, "i"}},
        {"D", {g.d, "d"}},
        {"FF0", {g.ff0, "ff0"}},
        {"FF1", {g.ff1, "ff1"}},
        {"FF2", {g.ff2, "ff2"}},
        {"FF3", {g.ff3, "ff3"}},
        {"BIAS", {g.bias, "bias"}},
        {"DEADBAND", {g.deadband, "deadband"}},
        {"MAXERROR_I", {g.maxErrorI, "max_error_i"}},
        {"MAXOUTPUT", {g.maxOutput, "max_output"}},
        {"DFILTER", {g.derivativeFilterSeconds, "derivative_filter"}},
        {"TS", {d.tsSeconds, ""}},
    };
    std::ostringstream out;
    out << "/* Axis " << id << labelComment(axis, CommentSyntax::C)
        << ": PID + feedforward with the semantics of LinuxCNC's pid component (2.8 and later),\n"
           " * position in mm, output in volts, one step per controller period TS:\n"
           " *   e = deadband(reference - measured); I += e TS unless the output was limited and "
           "e\n"
           " *   pushes further; D on the error's (or the measurement's) backward difference, "
           "low-\n"
           " *   pass filtered when DFILTER > 0; the command's derivatives by backward "
           "differences\n"
           " *   (xyt_"
        << id << "_step) or from the trajectory generator (xyt_" << id
        << "_step_derivatives);\n"
           " *   u = BIAS + P e + I ei + D de + FF0 r + FF1 r' + FF2 r'' + FF3 r''', limited to\n"
           " *   MAXOUTPUT, then to XYT_UMAX. The session runs it with "
        << (d.derivativeSource == CommandDerivativeSource::BackwardDifferences
                ? "backward differences."
                : "the trajectory generator's derivatives.")
        << "\n */\n";
    for (const auto& [name, value] : constants) {
        const std::string field = value.second.empty() ? std::string("controller_ts")
                                                       : axisField(i, "parameters." + value.second);
        out << "static const xyt_real " << k << name
            << " XYT_MAYBE_UNUSED = " << realNum(value.first, field, k + name, options.precision)
            << ";\n";
    }
    out << "#define " << k << "D_ON_MEASUREMENT " << (g.derivativeOnMeasurement ? 1 : 0) << "\n";
    out << "typedef struct {\n    xyt_real error_i, prev_cmd, prev_fb, cmd_d, cmd_dd, filtered_d,"
           " limit_state;\n    int started;\n} xyt_"
        << id << "_state;\n";
    out << "static inline XYT_MAYBE_UNUSED void xyt_" << id << "_init(xyt_" << id
        << "_state *s) {\n    s->error_i = s->prev_cmd = s->prev_fb = s->cmd_d = s->cmd_dd = "
           "s->filtered_d = s->limit_state = (xyt_real)0;\n    s->started = 0;\n}\n";
    out << "static inline xyt_real xyt_" << id << "_limited(xyt_real v, xyt_real limit) {\n"
        << "    if (limit == (xyt_real)0)\n        return v;\n"
        << "    return v > limit ? limit : (v < -limit ? -limit : v);\n}\n";
    // The PID step; given points at the trajectory generator's velocity, acceleration and jerk,
    // or is null for backward differences.
    out << "static inline xyt_real xyt_" << id << "_pid_output(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real measured, const xyt_real *given) {\n"
        << "    const xyt_real rate = (xyt_real)1 / " << k << "TS;\n"
        << "    xyt_real e = reference - measured, command_v, feedback_v, d, previous_d, "
           "previous_dd, command_ddd, feedback, feedforward, v, out;\n"
        << "    if (!s->started) {\n        s->prev_cmd = reference;\n"
        << "        s->prev_fb = measured;\n        s->started = 1;\n    }\n"
        << "    if (e > " << k << "DEADBAND)\n        e -= " << k << "DEADBAND;\n"
        << "    else if (e < -" << k << "DEADBAND)\n        e += " << k << "DEADBAND;\n"
        << "    else\n        e = (xyt_real)0;\n"
        << "    if (e * s->limit_state <= (xyt_real)0)\n        s->error_i += e * " << k << "TS;\n"
        << "    s->error_i = xyt_" << id << "_limited(s->error_i, " << k << "MAXERROR_I);\n"
        << "    command_v = given ? given[0] : (reference - s->prev_cmd) * rate;\n"
        << "    feedback_v = (measured - s->prev_fb) * rate;\n"
        << "    d = " << k << "D_ON_MEASUREMENT ? -feedback_v : command_v - feedback_v;\n"
        << "    if (" << k << "DFILTER > (xyt_real)0)\n        s->filtered_d = (" << k
        << "DFILTER * s->filtered_d + " << k << "TS * d) / (" << k << "DFILTER + " << k
        << "TS);\n    else\n        s->filtered_d = d;\n"
        << "    previous_d = s->cmd_d;\n    previous_dd = s->cmd_dd;\n"
        << "    s->cmd_d = command_v;\n    s->cmd_dd = (s->cmd_d - previous_d) * rate;\n"
        << "    if (given)\n        s->cmd_dd = given[1];\n"
        << "    command_ddd = given ? given[2] : (s->cmd_dd - previous_dd) * rate;\n"
        << "    s->prev_cmd = reference;\n    s->prev_fb = measured;\n"
        << "    feedback = " << k << "BIAS + " << k << "P * e + " << k << "I * s->error_i + " << k
        << "D * s->filtered_d;\n"
        << "    feedforward = " << k << "FF0 * reference + " << k << "FF1 * s->cmd_d + " << k
        << "FF2 * s->cmd_dd + " << k << "FF3 * command_ddd;\n"
        << "    v = feedback + feedforward;\n"
        << "    out = xyt_" << id << "_limited(v, " << k << "MAXOUTPUT);\n"
        << "    if (" << k << "MAXOUTPUT != (xyt_real)0)\n        s->limit_state = v > " << k
        << "MAXOUTPUT ? (xyt_real)1 : (v < -" << k << "MAXOUTPUT ? (xyt_real)-1 : (xyt_real)0);\n"
        << "    return out;\n}\n";
    // The PID's output limited to MAXOUTPUT, then to XYT_UMAX (the coupled step adds its
    // voltage in between: xyt_<id>_coupled).
    out << "static inline xyt_real xyt_" << id << "_pid(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real measured, const xyt_real *given) {\n"
        << "    const xyt_real out = xyt_" << id << "_pid_output(s, reference, measured, given);\n"
        << "    xyt_real u;\n"
        << "    " << cSaturate("u", "out") << "    return u;\n}\n";
    out << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real measured) {\n    return xyt_" << id
        << "_pid(s, reference, measured, 0);\n}\n";
    out << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step_derivatives(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real velocity, xyt_real acceleration, xyt_real "
           "jerk, xyt_real measured) {\n"
        << "    const xyt_real given[3] = {velocity, acceleration, jerk};\n"
        << "    return xyt_" << id << "_pid(s, reference, measured, given);\n}\n\n";
    return out.str();
}

OctaveLines pidFeedforwardOctaveLines(const Session& session, const PidFeedforwardDesign& d,
                                      int i) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(i));
    const std::string& id = axis.id;
    const std::string gt = axisField(i, "gt");
    const std::string pf = axisField(i, "parameters");
    const auto& p = axis.gt.plant;
    const ServoPidGains& g = d.gains;
    std::ostringstream out;
    out << "plant_" << id << " = tf(" << num(p.k0, gt + ".plant.k0") << ", [1 "
        << num(p.a1, gt + ".plant.a1") << " " << num(p.a2, gt + ".plant.a2") << " 0]);\n";
    out << "unit_" << id << " = " << num(d.unit, gt + ".model_unit_scale")
        << ";  % model units per mm\n";
    out << "% LinuxCNC pid gains in mm units: P, I, D, and the continuous model's derivative "
           "filter Tf\n";
    out << "P_" << id << " = " << num(g.p, pf + ".p") << "; I_" << id << " = "
        << num(g.i, pf + ".i") << "; D_" << id << " = " << num(g.d, pf + ".d") << "; Tf_" << id
        << " = " << num(d.continuousFilterSeconds, pf + ".derivative_filter") << ";\n";
    out << "FF_" << id << " = [" << num(g.ff3, pf + ".ff3") << " " << num(g.ff2, pf + ".ff2") << " "
        << num(g.ff1, pf + ".ff1") << " " << num(g.ff0, pf + ".ff0")
        << "];  % FF3 FF2 FF1 FF0, V per mm/s^n\n";
    out << "s = tf('s');\n";
    out << "controller_" << id << " = (P_" << id << " + I_" << id << " / s + D_" << id
        << " * s / (Tf_" << id << " * s + 1)) / unit_" << id << ";\n";
    out << "closed_loop_" << id << " = feedback(controller_" << id << " * plant_" << id
        << ", 1);\n";
    // F G / unit is proper: k0 (FF3 s^3 + FF2 s^2 + FF1 s + FF0) / (unit s (s^2 + a1 s + a2)).
    out << "ff_plant_" << id << " = tf(" << num(p.k0, gt + ".plant.k0") << " / unit_" << id
        << " * FF_" << id << ", [1 " << num(p.a1, gt + ".plant.a1") << " "
        << num(p.a2, gt + ".plant.a2") << " 0]);\n";
    out << "tracking_" << id << " = closed_loop_" << id << " + feedback(1, controller_" << id
        << " * plant_" << id << ") * ff_plant_" << id << ";\n";
    out << octaveTrajectoryLines(session.trajectory, i, id);
    out << "y_" << id << " = lsim(tracking_" << id << ", r_" << id << ", t);\n\n";
    return {out.str(), "t"};
}

} // namespace xyt
