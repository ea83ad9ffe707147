// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/friction_export.h"

#include "core/session/axis_run.h"

#include <sstream>

namespace xyt {

using namespace cexport;

std::string frictionCompensationCBlock(const Session& session, int axisIndex,
                                       CPrecision precision) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
    const FrictionCompensation& c = axis.frictionCompensation;
    if (c.percent == 0.0)
        return "";
    const std::string field = axisFieldPath(axisIndex, "friction.");
    validateFrictionCompensation(c, field + "compensation.");
    const std::string id = axis.id, up = upper(axis.id);
    const std::string k = "XYT_" + up + "_FRICTION_";
    std::ostringstream out;
    out << "/* Axis " << id << labelComment(axis, CommentSyntax::C)
        << ": friction compensation, p/100 (Fc sat(v/w) + bv v), from the\n"
           " * trajectory generator's velocity v (mm/s). Add it to the controller's output before\n"
           " * the limit: u = sat(v_controller + xyt_"
        << id << "_friction_ff(v)), as XY Tune simulates it.\n */\n"
        << "static const xyt_real " << k << "SCALE XYT_MAYBE_UNUSED = "
        << realNum(c.percent / 100.0, field + "compensation.percent", k + "SCALE", precision)
        << ";\n"
        << "static const xyt_real " << k << "COULOMB XYT_MAYBE_UNUSED = "
        << realNum(axis.friction.coulombVolts, field + "coulomb", k + "COULOMB", precision) << ";\n"
        << "static const xyt_real " << k << "VISCOUS XYT_MAYBE_UNUSED = "
        << realNum(axis.friction.viscousVoltsPerMmPerS, field + "viscous", k + "VISCOUS", precision)
        << ";\n"
        << "static const xyt_real " << k << "BAND XYT_MAYBE_UNUSED = "
        << realNum(c.bandMmPerS, field + "compensation.band", k + "BAND", precision) << ";\n"
        << "static xyt_real xyt_" << id << "_friction_ff(xyt_real velocity) XYT_MAYBE_UNUSED;\n"
        << "static xyt_real xyt_" << id << "_friction_ff(xyt_real velocity) {\n"
        << "    xyt_real ramp = velocity / " << k << "BAND;\n"
        << "    if (ramp > (xyt_real)1)\n        ramp = (xyt_real)1;\n"
        << "    else if (ramp < (xyt_real)-1)\n        ramp = (xyt_real)-1;\n"
        << "    return " << k << "SCALE * (" << k << "COULOMB * ramp + " << k
        << "VISCOUS * velocity);\n}\n\n";
    return out.str();
}

std::string linuxCncFrictionNote(const AxisSettings& axis, int axisIndex, std::size_t joint) {
    const FrictionCompensation& c = axis.frictionCompensation;
    if (c.percent == 0.0)
        return "";
    const std::string field = axisFieldPath(axisIndex, "friction.");
    std::ostringstream out;
    out << "# Friction compensation of joint " << joint
        << ": LinuxCNC's pid has no sign-dependent term, so it needs a component of its own\n"
           "# summed into pid."
        << joint
        << ".output (e.g. one written with halcompile), from the commanded velocity v (mm/s):\n"
           "#   u_fc = S (Fc sat(v / w) + bv v),  sat(x) = max(-1, min(1, x))\n"
           "#   S = "
        << num(c.percent / 100.0, field + "compensation.percent")
        << "  Fc = " << num(axis.friction.coulombVolts, field + "coulomb")
        << " V  bv = " << num(axis.friction.viscousVoltsPerMmPerS, field + "viscous")
        << " V per mm/s  w = " << num(c.bandMmPerS, field + "compensation.band") << " mm/s\n";
    return out.str();
}

} // namespace xyt
