// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/io/text_escape.h"
#include "core/session/export_text.h"
#include "core/session/session.h"

#include <string>
#include <vector>

namespace xyt {

/// The pieces the exports are written with: numbers that refuse what C cannot hold, C arrays
/// and statements. Each design method writes its controller's block of the firmware header
/// with them (DesignMethodModule::cController).
namespace cexport {

std::string upper(std::string s);
/// A number for an export, or the reason it cannot be one (exportableNumber).
std::string num(double v, const std::string& field);
/**
 * Refuses a constant that the controller's arithmetic cannot hold: in float, a magnitude above
 * FLT_MAX becomes inf when compiled (silently: even -Werror -pedantic says nothing), and
 * a non-zero one below the smallest subnormal becomes 0 (umax 5e-324 clipped every command to 0).
 * Double holds every finite number, which exportableNumber already requires.
 * @throws InvalidInput naming @p field, with the value and the C constant @p constant.
 */
void requireInPrecision(double v, const std::string& field, const std::string& constant,
                        CPrecision precision);
/// A constant of the controller's arithmetic (xyt_real), checked as num() and requireInPrecision().
std::string realNum(double v, const std::string& field, const std::string& constant,
                    CPrecision precision);
/// requireInPrecision for every coefficient of an array the step function casts to xyt_real.
void requireArrayInPrecision(const std::vector<double>& v, const std::string& field,
                             const std::string& array, CPrecision precision);
/// "axes[i].part" (or "axes[i]" for an empty part).
std::string axisField(int axisIndex, const std::string& part);
/// " (label)" as safe comment text, or nothing for an empty label.
std::string labelComment(const AxisSettings& axis, CommentSyntax syntax);
/// The numbers of @p v as num() writes them, separated by @p separator.
std::string joined(const std::vector<double>& v, const std::string& separator,
                   const std::string& field);
/// "#define NAME_LEN n" and the static double array NAME.
std::string cArray(const std::string& name, const std::vector<double>& v, const std::string& field);
/// The controller's arithmetic: "x * y" as C with constants of xyt_real type.
std::string cReal(const std::string& constant);
/// The saturation of v at +-XYT_UMAX into u, as stepDigitalPi writes it.
std::string cSaturate(const std::string& target, const std::string& v);
/**
 * An axis' xyt_<id>_coupled for the cross-coupled step (DesignMethodModule::cCoupledAxis): the
 * axis' own command @p command (a C expression of s, reference, measured and, when
 * @p usesGiven, given), plus the feedforward ff and the coupling's extra volts, clipped to
 * +-XYT_UMAX.
 */
std::string cCoupledAxisFunction(const std::string& id, const std::string& command, bool usesGiven);
/// A shift register update "for i = n-1 .. 1: a[i] = a[i-1]" in C.
std::string cShift(const std::string& array, const std::string& length);

} // namespace cexport

} // namespace xyt
