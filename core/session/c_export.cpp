// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/c_export.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>

namespace xyt::cexport {

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

std::string num(double v, const std::string& field) {
    return exactNumber(exportableNumber(v, field));
}

void requireInPrecision(double v, const std::string& field, const std::string& constant,
                        CPrecision precision) {
    if (precision != CPrecision::Float)
        return;
    if (std::abs(v) > static_cast<double>(FLT_MAX))
        throw InvalidInput(field, makeDiagnostic("session_float_overflow",
                                                 {exactNumber(v), constant, exactNumber(FLT_MAX)}));
    if (v != 0.0 && static_cast<float>(v) == 0.0f)
        throw InvalidInput(field, makeDiagnostic("session_float_underflow",
                                                 {exactNumber(v), constant,
                                                  exactNumber(static_cast<double>(FLT_TRUE_MIN))}));
}

std::string realNum(double v, const std::string& field, const std::string& constant,
                    CPrecision precision) {
    const std::string text = num(v, field);
    requireInPrecision(v, field, constant, precision);
    return text;
}

void requireArrayInPrecision(const std::vector<double>& v, const std::string& field,
                             const std::string& array, CPrecision precision) {
    for (std::size_t i = 0; i < v.size(); ++i)
        requireInPrecision(v[i], field, array + "[" + std::to_string(i) + "]", precision);
}

std::string axisField(int axisIndex, const std::string& part) {
    return "axes[" + std::to_string(axisIndex) + "]" + (part.empty() ? "" : "." + part);
}

std::string labelComment(const AxisSettings& axis, CommentSyntax syntax) {
    return axis.label.empty() ? "" : " (" + commentText(axis.label, syntax) + ")";
}

std::string joined(const std::vector<double>& v, const std::string& separator,
                   const std::string& field) {
    std::string out;
    for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? separator : "") + num(v[i], field);
    return out;
}

std::string cArray(const std::string& name, const std::vector<double>& v,
                   const std::string& field) {
    return "#define " + name + "_LEN " + std::to_string(v.size()) + "\nstatic const double " +
           name + "[" + name + "_LEN] XYT_MAYBE_UNUSED = {" + joined(v, ", ", field) + "};\n";
}

std::string cReal(const std::string& constant) {
    return "(xyt_real)" + constant;
}

std::string cCoupledAxisFunction(const std::string& id, const std::string& command,
                                 bool usesGiven) {
    return "static inline XYT_MAYBE_UNUSED xyt_real xyt_" + id + "_coupled(xyt_" + id +
           "_state *s, xyt_real reference, xyt_real measured, xyt_real ff, xyt_real extra, "
           "const xyt_real *given) {\n"
           "    xyt_real t = " +
           command + " + ff;\n" + (usesGiven ? "" : "    (void)given;\n") +
           "    if (extra != (xyt_real)0)\n        t += extra;\n"
           "    return t > XYT_UMAX ? XYT_UMAX : (t < -XYT_UMAX ? -XYT_UMAX : t);\n}\n";
}

std::string cSaturate(const std::string& target, const std::string& v) {
    return target + " = " + v + " > XYT_UMAX ? XYT_UMAX : (" + v +
           " < -XYT_UMAX ? -XYT_UMAX : " + v + ");\n";
}

std::string cShift(const std::string& array, const std::string& length) {
    return "    for (i = " + length + " - 1; i > 0; --i)\n        " + array + "[i] = " + array +
           "[i - 1];\n";
}

} // namespace xyt::cexport
