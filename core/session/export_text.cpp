// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/export_text.h"

#include "core/design/pole_placement.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/simulation/resample.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace xyt {

std::string exactNumber(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

double exportableNumber(double v, const std::string& field) {
    if (!std::isfinite(v))
        throw InvalidInput(field, "gives " + exactNumber(v) +
                                      " in the export, not a finite number; nothing was exported");
    return v;
}

namespace {

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

/// A number for an export, or the reason it cannot be one (exportableNumber).
std::string num(double v, const std::string& field) {
    return exactNumber(exportableNumber(v, field));
}

/**
 * Refuses a constant that the controller's arithmetic cannot hold: in float, a magnitude above
 * FLT_MAX becomes inf when compiled (silently: even -Werror -pedantic says nothing), and
 * a non-zero one below the smallest subnormal becomes 0 (umax 5e-324 clipped every command to 0).
 * Double holds every finite number, which exportableNumber already requires.
 * @throws InvalidInput naming @p field, with the value and the C constant @p constant.
 */
void requireInPrecision(double v, const std::string& field, const std::string& constant,
                        CPrecision precision) {
    if (precision != CPrecision::Float)
        return;
    if (std::abs(v) > static_cast<double>(FLT_MAX))
        throw InvalidInput(
            field, "gives " + exactNumber(v) + " for " + constant + ", beyond the largest float (" +
                       exactNumber(FLT_MAX) +
                       "): it would be inf in float arithmetic; export in double precision; "
                       "nothing was exported");
    if (v != 0.0 && static_cast<float>(v) == 0.0f)
        throw InvalidInput(field, "gives " + exactNumber(v) + " for " + constant +
                                      ", which rounds to 0 in float (the smallest is " +
                                      exactNumber(static_cast<double>(FLT_TRUE_MIN)) +
                                      "); export in double precision; nothing was exported");
}

/// A constant of the controller's arithmetic (xyt_real), checked as num() and requireInPrecision().
std::string realNum(double v, const std::string& field, const std::string& constant,
                    CPrecision precision) {
    const std::string text = num(v, field);
    requireInPrecision(v, field, constant, precision);
    return text;
}

/// requireInPrecision for every coefficient of an array the step function casts to xyt_real.
void requireArrayInPrecision(const std::vector<double>& v, const std::string& field,
                             const std::string& array, CPrecision precision) {
    for (std::size_t i = 0; i < v.size(); ++i)
        requireInPrecision(v[i], field, array + "[" + std::to_string(i) + "]", precision);
}

std::string axisField(int axisIndex, const std::string& part) {
    return "axes[" + std::to_string(axisIndex) + "]" + (part.empty() ? "" : "." + part);
}

/// " (label)" as safe comment text, or nothing for an empty label.
std::string labelComment(const AxisSettings& axis, CommentSyntax syntax) {
    return axis.label.empty() ? "" : " (" + commentText(axis.label, syntax) + ")";
}

const AxisEvaluation& validAxis(const SessionEvaluation& evaluation, int axisIndex) {
    const AxisEvaluation& a = evaluation.axes.at(static_cast<std::size_t>(axisIndex));
    if (!a.ok)
        throw InvalidInput("axes[" + std::to_string(axisIndex) + "]",
                           "cannot be exported: " + a.errorField + ": " + a.error);
    return a;
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

/// The RST law and ZPETC filter of a pole-placement axis as C arrays.
std::string rstHeaderBlock(const AxisSettings& axis, const AxisEvaluation& a, const std::string& id,
                           int axisIndex) {
    const PolePlacementDesign& pp = *a.pp;
    const std::string field = axisField(axisIndex, "pp");
    std::ostringstream out;
    out << "/* Axis " << axis.id << labelComment(axis, CommentSyntax::C)
        << ": pole placement (Patrick, Ishak and Adnan), Ts = " << num(pp.tsSeconds, field + ".ts")
        << " s, T = 1 " << (pp.t.coefficient(1) < 0 ? "- " : "+ ")
        << num(std::abs(pp.t.coefficient(1)), field + ".t1") << " z^-1. Every Ts:\n"
        << " *   F(z^-1) u[k] = KF w[k] - G(z^-1) y[k], i.e. (F[0] is 1 up to round-off)\n"
        << " *   u[k] = (KF w[k] - sum_i G[i] y[k-i] - sum_{i>=1} F[i] u[k-i]) / F[0]\n";
    if (axis.pp.zpetcEnabled && a.zpetc)
        out << " * with the ZPETC feedforward reading the reference PREVIEW samples ahead:\n"
            << " *   sum_i FF_DEN[i] w[k-i] = sum_i FF_NUM[i] r[k + PREVIEW - i]\n";
    else
        out << " * with w = r (no feedforward).\n";
    out << " */\n";
    out << "#define XYT_" << id << "_TS " << num(pp.tsSeconds, field + ".ts") << "\n";
    out << "static const double XYT_" << id
        << "_KF XYT_MAYBE_UNUSED = " << num(pp.kf, field + " (Kf)") << ";\n";
    out << cArray("XYT_" + id + "_F", pp.f.ascending(), field + " (F)");
    out << cArray("XYT_" + id + "_G", pp.g.ascending(), field + " (G)");
    if (axis.pp.zpetcEnabled && a.zpetc) {
        out << "#define XYT_" << id << "_PREVIEW " << a.zpetc->previewSteps << "\n";
        out << cArray("XYT_" + id + "_FF_NUM", a.zpetc->feedforwardNum.ascending(),
                      field + ".zpetc (feedforward)");
        out << cArray("XYT_" + id + "_FF_DEN", a.zpetc->feedforwardDen.ascending(),
                      field + ".zpetc (feedforward)");
    }
    out << "\n";
    return out.str();
}

/// The axis id as it names C identifiers (xyt_<id>_step): the session file allows only these.
void requireCIdentifier(const Session& session, int axisIndex) {
    const std::string& id = session.axes.at(static_cast<std::size_t>(axisIndex)).id;
    const bool ok = !id.empty() && id.size() <= 16 && std::all_of(id.begin(), id.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    });
    if (!ok)
        throw InvalidInput(axisField(axisIndex, "id"),
                           "must be 1 to 16 lower-case letters or digits "
                           "(it names the exported C functions)");
    if (axisIndex == 1 && session.axes[0].id == id)
        throw InvalidInput(axisField(1, "id"), "must differ from axes[0].id");
}

/// The controller's arithmetic: "x * y" as C with constants of xyt_real type.
std::string cReal(const std::string& constant) {
    return "(xyt_real)" + constant;
}

/// The saturation of v at +-XYT_UMAX into u, as stepDigitalPi writes it.
std::string cSaturate(const std::string& target, const std::string& v) {
    return target + " = " + v + " > XYT_UMAX ? XYT_UMAX : (" + v +
           " < -XYT_UMAX ? -XYT_UMAX : " + v + ");\n";
}

/// The complete digital PI of a Guillemin-Truxal axis (stepDigitalPi in C).
std::string piImplementationBlock(const AxisSettings& axis, const DigitalPi& pi,
                                  const std::string& id, int axisIndex, CPrecision precision) {
    const std::string up = upper(id);
    const std::string gt = axisField(axisIndex, "gt");
    const std::string f = gt + " (digital PI at controller_ts)";
    std::ostringstream out;
    out << "/* Axis " << id << labelComment(axis, CommentSyntax::C)
        << ": the controller. Every XYT_" << up
        << "_TS seconds, with the table's measured\n * position in mm (encoder counts times "
           "XYT_ENCODER_RESOLUTION_MM when the session gives it)\n * and the reference r(k) in "
           "mm:\n"
        << " *   u = xyt_" << id << "_step(&state, r, measured);   (volts, within +-XYT_UMAX)\n"
        << " * after xyt_" << id
        << "_init(&state) with the table at rest. The PI in integrator form, e in\n"
        << " * model units:\n"
        << " *   e = (r - measured) UNIT,  I[k] = I[k-1] + C0 e[k] + C1 e[k-1],  v = KP e + I[k],\n"
        << " *   u = v clipped to +-XYT_UMAX, anti-windup: " << antiWindupName(pi.antiWindup);
    if (pi.antiWindup == AntiWindup::Clamp)
        out << " (the integrator holds while u is\n *   clipped and the increment has the sign of "
               "v)";
    else if (pi.antiWindup == AntiWindup::BackCalculation)
        out << " (I[k] += AW_GAIN (u - v), AW_GAIN = Ts/Tt)";
    out << ".\n */\n";
    const auto constant = [&](const std::string& name, double v, const std::string& field) {
        const std::string constantName = "XYT_" + up + "_" + name;
        out << "static const xyt_real " << constantName
            << " XYT_MAYBE_UNUSED = " << realNum(v, field, constantName, precision) << ";\n";
    };
    constant("KP", pi.kp, gt + ".kp");
    constant("C0", pi.c0, f);
    constant("C1", pi.c1, f);
    constant("UNIT", axis.gt.modelUnitsPerPositionUnit, gt + ".model_unit_scale");
    if (pi.antiWindup == AntiWindup::BackCalculation)
        constant("AW_GAIN", pi.trackingGain, "implementation.tracking_time");
    out << "typedef struct {\n    xyt_real integrator;     /* I[k-1] */\n"
           "    xyt_real previous_error; /* e[k-1] */\n} xyt_"
        << id << "_state;\n"
        << "static inline XYT_MAYBE_UNUSED void xyt_" << id << "_init(xyt_" << id
        << "_state *s) {\n"
        << "    s->integrator = 0;\n    s->previous_error = 0;\n}\n"
        << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real measured) {\n"
        << "    const xyt_real e = (reference - measured) * XYT_" << up << "_UNIT;\n"
        << "    const xyt_real increment = XYT_" << up << "_C0 * e + XYT_" << up
        << "_C1 * s->previous_error;\n"
        << "    const xyt_real candidate = s->integrator + increment;\n"
        << "    xyt_real v = XYT_" << up << "_KP * e + candidate;\n"
        << "    xyt_real u;\n"
        << "    " << cSaturate("u", "v");
    switch (pi.antiWindup) {
    case AntiWindup::None:
        out << "    s->integrator = candidate;\n";
        break;
    case AntiWindup::Clamp:
        out << "    if (u != v && increment * v > 0) { /* clipped and pushing outwards: hold I */\n"
            << "        v = XYT_" << up << "_KP * e + s->integrator;\n"
            << "        " << cSaturate("u", "v") << "    } else {\n"
            << "        s->integrator = candidate;\n    }\n";
        break;
    case AntiWindup::BackCalculation:
        out << "    s->integrator = candidate + XYT_" << up << "_AW_GAIN * (u - v);\n";
        break;
    }
    out << "    s->previous_error = e;\n    return u;\n}\n\n";
    return out.str();
}

/// A shift register update "for i = n-1 .. 1: a[i] = a[i-1]" in C.
std::string cShift(const std::string& array, const std::string& length) {
    return "    for (i = " + length + " - 1; i > 0; --i)\n        " + array + "[i] = " + array +
           "[i - 1];\n";
}

/// The RST law (and ZPETC) of a pole-placement axis in C: the operations of simulateSampledRst.
std::string rstImplementationBlock(const AxisSettings& axis, const AxisEvaluation& a,
                                   AntiWindup antiWindup, const std::string& id, int axisIndex,
                                   CPrecision precision) {
    const PolePlacementDesign& pp = *a.pp;
    const bool ff = axis.pp.zpetcEnabled && a.zpetc;
    const std::string up = upper(id), X = "XYT_" + upper(id);
    const std::string field = axisField(axisIndex, "pp");
    std::ostringstream out;
    out << "/* Axis " << id << labelComment(axis, CommentSyntax::C) << ": the controller. Every "
        << X << "_TS seconds, with the measured position y(k) in mm:\n";
    if (ff)
        out << " *   u(k) = xyt_" << id << "_step(&state, r(k + " << X
            << "_PREVIEW), y(k));   (volts)\n"
            << " * THE CALLER SUPPLIES THE REFERENCE " << X
            << "_PREVIEW SAMPLES AHEAD (the ZPETC is\n"
            << " * non-causal: it needs r(k + PREVIEW) at time k). Start with xyt_" << id
            << "_init(&state, r(0)) with the table\n"
            << " * at rest at r(0), and call step from k = -PREVIEW on (the table may leave r(0) "
               "before k = 0).\n";
    else
        out << " *   u(k) = xyt_" << id << "_step(&state, r(k), y(k));   (volts)\n"
            << " * after xyt_" << id << "_init(&state, r(0)) with the table at rest at r(0).\n";
    out << " * The step runs F u = KF w - G y (w the ZPETC output, or r), clips u to +-XYT_UMAX "
           "and\n"
        << " * remembers "
        << (antiWindup == AntiWindup::None ? "its unclipped output v"
                                           : "the clipped u (anti-windup)")
        << " in the past-u terms. U_REST = A(1)/B(1) is u at rest per mm.\n */\n";
    // The coefficient arrays are double, but the step multiplies with them cast to xyt_real.
    requireInPrecision(pp.kf, field + " (Kf)", X + "_KF", precision);
    requireArrayInPrecision(pp.f.ascending(), field + " (F)", X + "_F", precision);
    requireArrayInPrecision(pp.g.ascending(), field + " (G)", X + "_G", precision);
    if (ff) {
        requireArrayInPrecision(a.zpetc->feedforwardNum.ascending(), field + ".zpetc (feedforward)",
                                X + "_FF_NUM", precision);
        requireArrayInPrecision(a.zpetc->feedforwardDen.ascending(), field + ".zpetc (feedforward)",
                                X + "_FF_DEN", precision);
    }
    out << "static const xyt_real " << X << "_U_REST XYT_MAYBE_UNUSED = "
        << realNum(pp.a(1.0) / pp.b(1.0), field + " (A(1)/B(1))", X + "_U_REST", precision)
        << ";\n";
    out << "typedef struct {\n";
    if (ff)
        out << "    xyt_real r[" << X << "_FF_NUM_LEN]; /* r(k+P), r(k+P-1), ... */\n"
            << "    xyt_real w[" << X << "_FF_DEN_LEN]; /* w(k), w(k-1), ... */\n";
    out << "    xyt_real y[" << X << "_G_LEN]; /* y(k), y(k-1), ... measured */\n"
        << "    xyt_real u[" << X << "_F_LEN]; /* u(k), u(k-1), ... */\n} xyt_" << id
        << "_state;\n";
    out << "static inline XYT_MAYBE_UNUSED void xyt_" << id << "_init(xyt_" << id
        << "_state *s, xyt_real rest_position) {\n    int i;\n";
    if (ff)
        out << "    for (i = 0; i < " << X
            << "_FF_NUM_LEN; ++i)\n        s->r[i] = rest_position;\n"
            << "    for (i = 0; i < " << X
            << "_FF_DEN_LEN; ++i)\n        s->w[i] = rest_position;\n";
    out << "    for (i = 0; i < " << X << "_G_LEN; ++i)\n        s->y[i] = rest_position;\n"
        << "    for (i = 0; i < " << X << "_F_LEN; ++i)\n        s->u[i] = " << X
        << "_U_REST * rest_position;\n}\n";
    out << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
        << "_state *s, xyt_real " << (ff ? "reference_ahead" : "reference")
        << ", xyt_real measured) {\n    int i;\n    xyt_real w, v, u;\n";
    if (ff) {
        out << cShift("s->r", X + "_FF_NUM_LEN") << cShift("s->w", X + "_FF_DEN_LEN")
            << "    s->r[0] = reference_ahead;\n    w = 0;\n"
            << "    for (i = 0; i < " << X
            << "_FF_NUM_LEN; ++i)\n        w += " << cReal(X + "_FF_NUM[i]") << " * s->r[i];\n"
            << "    for (i = 1; i < " << X
            << "_FF_DEN_LEN; ++i)\n        w -= " << cReal(X + "_FF_DEN[i]") << " * s->w[i];\n"
            << "    w = w / " << cReal(X + "_FF_DEN[0]") << ";\n    s->w[0] = w;\n";
    } else {
        out << "    w = reference;\n";
    }
    out << cShift("s->y", X + "_G_LEN") << cShift("s->u", X + "_F_LEN")
        << "    s->y[0] = measured;\n"
        << "    v = " << cReal(X + "_KF") << " * w;\n"
        << "    for (i = 0; i < " << X << "_G_LEN; ++i)\n        v -= " << cReal(X + "_G[i]")
        << " * s->y[i];\n"
        << "    for (i = 1; i < " << X << "_F_LEN; ++i)\n        v -= " << cReal(X + "_F[i]")
        << " * s->u[i];\n"
        << "    v = v / " << cReal(X + "_F[0]") << ";\n"
        << "    " << cSaturate("u", "v")
        << "    s->u[0] = " << (antiWindup == AntiWindup::None ? "v" : "u")
        << ";\n    return u;\n}\n\n";
    return out.str();
}

/// The DAC conversion of dacOutput in C (no library call: floor by truncation and correction).
std::string dacBlock(const Session& session, CPrecision precision) {
    const int bits = session.implementation.dacBits;
    requireInPrecision(2.0 * session.umaxVolts / std::ldexp(1.0, bits), "umax",
                       "XYT_DAC_LSB (2 umax / 2^dac_bits)", precision);
    std::ostringstream out;
    out << "/* The DAC: " << bits
        << " bits over +-XYT_UMAX, LSB XYT_DAC_LSB = 2 umax / 2^bits, codes\n"
        << " * -2^(bits-1) .. 2^(bits-1) - 1 (0 V is code 0). Write xyt_dac_code(u) to the "
           "converter;\n"
        << " * xyt_dac_volts(code) is what it outputs. */\n"
        << "#define XYT_DAC_BITS " << bits << "\n"
        << "static const xyt_real XYT_DAC_LSB XYT_MAYBE_UNUSED = (xyt_real)(2.0 * "
        << num(session.umaxVolts, "umax") << " / "
        << num(std::ldexp(1.0, bits), "implementation.dac_bits") << ");\n"
        << "static inline XYT_MAYBE_UNUSED long long xyt_dac_code(xyt_real volts) {\n"
        << "    const xyt_real t = volts / XYT_DAC_LSB + (xyt_real)0.5;\n"
        << "    const long long half = " << static_cast<long long>(std::ldexp(1.0, bits - 1))
        << "LL;\n"
        << "    long long code = (long long)t;\n"
        << "    if ((xyt_real)code > t)\n        code -= 1; /* floor for negative t */\n"
        << "    return code < -half ? -half : (code > half - 1 ? half - 1 : code);\n}\n"
        << "static inline XYT_MAYBE_UNUSED xyt_real xyt_dac_volts(long long code) {\n"
        << "    return (xyt_real)code * XYT_DAC_LSB;\n}\n\n";
    return out.str();
}

} // namespace

std::string precisionName(CPrecision precision) {
    return precision == CPrecision::Double ? "double" : "float";
}

namespace {

/// The digital PI the export runs for a GT axis: the session's, discretized as @p options say.
DigitalPi exportPi(const Session& session, const GtDesign& design, const ExportOptions& options) {
    Session s = session;
    s.piDiscretization = options.piMethod;
    return sessionDigitalPi(s, design);
}

} // namespace

DigitalController axisDigitalController(const Session& session, const SessionEvaluation& evaluation,
                                        int axisIndex, const ExportOptions& options) {
    const AxisEvaluation& a = validAxis(evaluation, axisIndex);
    if (a.gt)
        return discretizePi(a.gt->kp, a.gt->ki, session.controllerTsSeconds, options.piMethod);
    throw InvalidInput("axes[" + std::to_string(axisIndex) + "].method",
                       "this axis has no digital controller to export");
}

std::string exportCHeader(const Session& session, const SessionEvaluation& evaluation,
                          const ExportOptions& options) {
    std::ostringstream out;
    out << "/* XY Tune: controller coefficients for firmware (generated file).\n"
           " * Coefficient order: ascending powers of z^-1. Each axis runs\n"
           " *   u[k] = sum_i NUM[i] e[k-i] - sum_{i>=1} DEN[i] u[k-i],   e = r - y,\n"
           " * every TS seconds (DEN[0] is 1). u is the motor command in volts; clamp it to\n"
           " * +-"
        << num(session.umaxVolts, "umax")
        << " V as the design assumed.\n"
           " *\n"
           " * Each axis also comes as a complete controller (state struct, init, step with the\n"
           " * saturation and the anti-windup), in xyt_real arithmetic ("
        << precisionName(options.precision)
        << " in this file).\n"
           " * C99, no dynamic memory, no recursion, no library call. It performs the operations "
           "of\n"
           " * XY Tune's sampled-data simulation in the same order, and was checked in closed "
           "loop\n"
           " * against it. Implementation settings: anti-windup "
        << antiWindupName(session.implementation.antiWindup) << ", computation delay "
        << session.implementation.delaySamples << " sample(s).\n */\n"
        << "#ifndef XYT_CONTROLLER_COEFFICIENTS_H\n#define XYT_CONTROLLER_COEFFICIENTS_H\n\n"
        << "#if defined(__GNUC__)\n#define XYT_MAYBE_UNUSED __attribute__((unused))\n#else\n"
           "#define XYT_MAYBE_UNUSED\n#endif\n\n"
        << "#define XYT_UMAX_VOLTS " << num(session.umaxVolts, "umax") << "\n\n"
        << "typedef " << precisionName(options.precision) << " xyt_real;\n"
        << "static const xyt_real XYT_UMAX XYT_MAYBE_UNUSED = "
        << realNum(session.umaxVolts, "umax", "XYT_UMAX", options.precision) << ";\n"
        << "#define XYT_DELAY_SAMPLES " << session.implementation.delaySamples << "\n";
    const SampledDataOptions implementation = sessionSampledDataOptions(session); // validates
    if (implementation.encoderResolution > 0.0)
        out << "#define XYT_ENCODER_RESOLUTION_MM "
            << num(implementation.encoderResolution, "implementation.encoder_resolution") << "\n";
    out << "\n";
    if (implementation.dacBits > 0)
        out << dacBlock(session, options.precision);
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
        requireCIdentifier(session, i);
        const std::string id = upper(axis.id);
        const AxisEvaluation& a = validAxis(evaluation, i);
        if (a.pp) {
            out << rstHeaderBlock(axis, a, id, i);
            out << rstImplementationBlock(axis, a, implementation.antiWindup, axis.id, i,
                                          options.precision);
            continue;
        }
        const DigitalController c = axisDigitalController(session, evaluation, i, options);
        const std::string gt = axisField(i, "gt");
        const std::string pi = gt + " (digital PI at controller_ts)";
        out << "/* Axis " << axis.id << labelComment(axis, CommentSyntax::C) << ": ";
        if (a.gt)
            out << "Guillemin-Truxal PI, kp = " << num(a.gt->kp, gt + ".kp")
                << " V/model unit, ki = " << num(a.gt->ki, gt + " (ki)")
                << " V/(model unit s),\n * " << discretizationName(options.piMethod)
                << " discretization at Ts = " << num(c.tsSeconds, "controller_ts")
                << " s. Position in model units ("
                << num(axis.gt.modelUnitsPerPositionUnit, gt + ".model_unit_scale")
                << " per mm).\n";
        out << " *   u[k] = ";
        for (std::size_t k = 1; k < c.den.size(); ++k)
            out << "- XYT_" << id << "_DEN[" << k << "] u[k-" << k << "] ";
        for (std::size_t k = 0; k < c.num.size(); ++k)
            out << "+ XYT_" << id << "_NUM[" << k << "] e[k" << (k ? "-" + std::to_string(k) : "")
                << "] ";
        out << "\n */\n";
        out << "#define XYT_" << id << "_NUM_LEN " << c.num.size() << "\n";
        out << "#define XYT_" << id << "_DEN_LEN " << c.den.size() << "\n";
        out << "static const double XYT_" << id << "_NUM[XYT_" << id
            << "_NUM_LEN] XYT_MAYBE_UNUSED = {" << joined(c.num, ", ", pi) << "};\n";
        out << "static const double XYT_" << id << "_DEN[XYT_" << id
            << "_DEN_LEN] XYT_MAYBE_UNUSED = {" << joined(c.den, ", ", pi) << "};\n";
        out << "static const double XYT_" << id
            << "_TS XYT_MAYBE_UNUSED = " << num(c.tsSeconds, "controller_ts") << ";\n\n";
        out << piImplementationBlock(axis, exportPi(session, *a.gt, options), axis.id, i,
                                     options.precision);
    }
    out << "#endif /* XYT_CONTROLLER_COEFFICIENTS_H */\n";
    return out.str();
}

namespace {

/// Octave/MATLAB expression lines computing r_<id> on the vector t.
std::string trajectoryLines(const TrajectorySettings& t, int axisIndex, const std::string& id) {
    std::ostringstream out;
    if (t.kind == TrajectoryKind::Cubic) {
        const CubicTrajectory cubic(t.x0, t.xf, t.t0Seconds, t.tfSeconds, t.v0, t.vf);
        const auto& l = cubic.localCoefficients();
        const std::string f = "trajectory.cubic (tf - t0 too short for the move?)";
        out << "tau = min(max(t - " << num(t.t0Seconds, "trajectory.cubic.t0") << ", 0), "
            << num(t.tfSeconds - t.t0Seconds, "trajectory.cubic.tf") << ");\n";
        out << "r_" << id << " = " << num(l[0], f) << " + " << num(l[1], f) << " * tau + "
            << num(l[2], f) << " * tau.^2 + " << num(l[3], f)
            << " * tau.^3;  % cubic point-to-point (Braga et al. Eq. 4)\n";
    } else if (t.kind == TrajectoryKind::Gcode) {
        throw InvalidInput("trajectory.kind",
                           "a G-code program's feed profile has no closed form for the "
                           "script; export the simulated signals as CSV instead");
    } else {
        out << "envelope = "
            << (t.rampInSeconds > 0
                    ? "min(t / " + num(t.rampInSeconds, "trajectory.circle.ramp_in") + ", 1)"
                    : "ones(size(t))")
            << ";\n";
        out << "r_" << id << " = " << num(t.radius, "trajectory.circle.radius") << " * envelope .* "
            << (axisIndex == 0 ? "sin" : "cos") << "("
            << num(t.omegaRadPerSec, "trajectory.circle.omega")
            << " * t);  % circle (Braga et al. Eq. 23-24)\n";
    }
    return out.str();
}

} // namespace

std::string exportOctaveScript(const Session& session, const SessionEvaluation& evaluation,
                               const ExportOptions& options) {
    std::ostringstream out;
    out << "% XY Tune: plant, controller and closed loop of each axis (generated script).\n"
           "% Runs in GNU Octave (with the control package) and in MATLAB.\n"
           "if exist('OCTAVE_VERSION', 'builtin')\n  pkg load control\nend\n\n";
    // The implementation travels into every export; this script simulates the linear
    // loops, so it states the settings the C export runs instead of applying them.
    const ImplementationSettings& impl = session.implementation;
    out << "% Implementation the firmware runs (the C export applies it; the lsim runs below are "
           "the\n"
           "% linear loops, without saturation or quantization): anti-windup "
        << antiWindupName(impl.antiWindup);
    if (impl.antiWindup == AntiWindup::BackCalculation)
        out << " (tracking time " << num(impl.trackingTimeSeconds, "implementation.tracking_time")
            << " s; 0: kp/ki)";
    out << ",\n% computation delay " << impl.delaySamples << " samples, encoder "
        << num(impl.encoderResolutionMm, "implementation.encoder_resolution") << " mm/count, DAC "
        << impl.dacBits << " bits (0: ideal), umax " << num(session.umaxVolts, "umax") << " V.\n\n";
    // The run the evaluation chose (an automatic cubic includes the settle after tf).
    const double duration = evaluation.duration.seconds > 0.0
                                ? evaluation.duration.seconds
                                : session.trajectory.effectiveDurationSeconds();
    out << "t = (0:" << num(session.trajectory.dtSeconds, "trajectory.dt") << ":"
        << num(duration, "trajectory.duration") << ")';\n\n";
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
        const AxisEvaluation& a = validAxis(evaluation, i);
        const std::string& id = axis.id;
        out << "% Axis " << id << labelComment(axis, CommentSyntax::Octave) << "\n";
        const std::string gt = axisField(i, "gt"), ppField = axisField(i, "pp");
        if (a.gt) {
            const auto& p = axis.gt.plant;
            out << "plant_" << id << " = tf(" << num(p.k0, gt + ".plant.k0") << ", [1 "
                << num(p.a1, gt + ".plant.a1") << " " << num(p.a2, gt + ".plant.a2") << " 0]);\n";
            out << "controller_" << id << " = tf([" << num(a.gt->kp, gt + ".kp") << " "
                << num(a.gt->ki, gt + " (ki)") << "], [1 0]);  % kp + ki/s\n";
            out << "closed_loop_" << id << " = feedback(controller_" << id << " * plant_" << id
                << ", 1);\n";
            out << "% The same PI as the firmware runs it (" << discretizationName(options.piMethod)
                << ", Ts = " << num(session.controllerTsSeconds, "controller_ts") << " s):\n";
            const DigitalController c = axisDigitalController(session, evaluation, i, options);
            out << "digital_controller_" << id << " = filt(["
                << joined(c.num, " ", gt + " (digital PI)") << "], ["
                << joined(c.den, " ", gt + " (digital PI)") << "], "
                << num(c.tsSeconds, "controller_ts") << ");  % in z^-1\n";
            out << trajectoryLines(session.trajectory, i, id);
            out << "unit_" << id << " = "
                << num(axis.gt.modelUnitsPerPositionUnit, gt + ".model_unit_scale")
                << ";  % model units per mm\n";
            out << "y_" << id << " = lsim(closed_loop_" << id << ", r_" << id << " * unit_" << id
                << ", t) / unit_" << id << ";\n\n";
        } else if (a.pp) {
            const PolePlacementDesign& pp = *a.pp;
            const std::string ts = num(pp.tsSeconds, ppField + ".ts");
            out << "Ts_" << id << " = " << ts << ";\n";
            out << "plant_" << id << " = filt([" << joined(pp.b.ascending(), " ", ppField + ".b")
                << "], [" << joined(pp.a.ascending(), " ", ppField + ".a") << "], Ts_" << id
                << ");  % B/A in z^-1\n";
            out << "% RST pole placement: F u = Kf w - G y (Patrick, Ishak and Adnan Eq. 7-8)\n";
            out << "F_" << id << " = [" << joined(pp.f.ascending(), " ", ppField + " (F)")
                << "];\n";
            out << "G_" << id << " = [" << joined(pp.g.ascending(), " ", ppField + " (G)")
                << "];\n";
            out << "Kf_" << id << " = " << num(pp.kf, ppField + " (Kf)") << ";\n";
            out << "controller_" << id << " = filt(G_" << id << ", F_" << id << ", Ts_" << id
                << ");  % feedback path G/F\n";
            out << "closed_loop_" << id << " = Kf_" << id << " * feedback(plant_" << id
                << " * filt(1, F_" << id << ", Ts_" << id << "), filt(G_" << id << ", 1, Ts_" << id
                << "));  % = Kf B / T\n";
            out << "t_" << id << " = (0:Ts_" << id << ":" << num(duration, "trajectory.duration")
                << ")';\n";
            out << "t_saved = t; t = t_" << id << ";\n"
                << trajectoryLines(session.trajectory, i, id) << "t = t_saved;\n";
            out << "y_" << id << " = lsim(closed_loop_" << id << ", r_" << id << ", t_" << id
                << ");  % the loop alone, without the ZPETC feedforward\n\n";
        }
    }
    out << "figure;\n";
    for (int i = 0; i < 2; ++i) {
        const std::string& id = session.axes[static_cast<std::size_t>(i)].id;
        const std::string tt = evaluation.axes[static_cast<std::size_t>(i)].pp ? "t_" + id : "t";
        out << "subplot(2, 1, " << (i + 1) << ");\nplot(" << tt << ", r_" << id << ", '--', " << tt
            << ", y_" << id << ");\ngrid on;\nxlabel('time (s)');\nylabel('" << id
            << " (mm)');\nlegend('reference', 'output');\n";
    }
    return out.str();
}

namespace {

/// The session's dt grid over the run: a continuous axis' own times, else k dt up to the run's
/// duration (both pole-placement axes run at their Ts, which the export does not use as its grid).
std::vector<double> csvTimes(const Session& session, const SessionEvaluation& evaluation) {
    for (const AxisEvaluation& a : evaluation.axes)
        if (a.gt && a.run.dtSeconds == session.trajectory.dtSeconds)
            return a.run.t;
    try {
        return sampleTimes(evaluation.duration.seconds, session.trajectory.dtSeconds);
    } catch (const InvalidInput& e) {
        throw InvalidInput(e.field() == "dt" ? "trajectory.dt" : "trajectory.duration", e.reason());
    }
}

/// For each exported time, the sample of @p run shown there: the row itself when the run is on
/// the exported grid, else the sample held (the last one at or before the time).
std::vector<std::size_t> csvRows(const std::vector<double>& runTimes,
                                 const std::vector<double>& times) {
    if (runTimes == times)
        return {};
    return heldSampleIndices(runTimes, times);
}

} // namespace

void exportCsv(const Session& session, const SessionEvaluation& evaluation, const ByteSink& sink) {
    const AxisEvaluation& x = validAxis(evaluation, 0);
    const AxisEvaluation& y = validAxis(evaluation, 1);
    const std::string& ix = session.axes[0].id;
    const std::string& iy = session.axes[1].id;
    // Refuse before writing anything: an unstable loop or an overflowing unit scale gives
    // inf/nan samples, and a CSV of them is not a result.
    for (int i = 0; i < 2; ++i) {
        const SimulationResult& run = (i == 0 ? x : y).run;
        const std::string& id = session.axes[static_cast<std::size_t>(i)].id;
        const std::pair<const char*, const std::vector<double>*> columns[] = {
            {"r", &run.r}, {"y", &run.y}, {"e", &run.e}, {"u", &run.u}};
        for (const auto& [name, v] : columns)
            for (std::size_t k = 0; k < v->size(); ++k)
                if (!std::isfinite((*v)[k]))
                    throw InvalidInput(axisField(i, ""),
                                       std::string("the simulated ") + name + "_" + id + " is " +
                                           exactNumber((*v)[k]) +
                                           " at t = " + exactNumber(run.t[k]) +
                                           " s (an unstable loop, or model_unit_scale or the "
                                           "trajectory out of range); nothing was exported");
    }
    const std::vector<double> times = csvTimes(session, evaluation);
    const std::array<const AxisEvaluation*, 2> axes{&x, &y};
    std::array<std::vector<std::size_t>, 2> runRow, digitalRow;
    for (std::size_t i = 0; i < 2; ++i) {
        runRow[i] = csvRows(axes[i]->run.t, times);
        if (axes[i]->digital)
            digitalRow[i] = heldSampleIndices(axes[i]->digital->run.result.t, times);
    }
    sink("t,r_" + ix + ",y_" + ix + ",e_" + ix + ",u_" + ix + ",r_" + iy + ",y_" + iy + ",e_" + iy +
         ",u_" + iy + ",t_digital_" + ix + ",y_digital_" + ix + ",e_digital_" + ix + ",u_digital_" +
         ix + ",t_digital_" + iy + ",y_digital_" + iy + ",e_digital_" + iy + ",u_digital_" + iy +
         "\n");
    std::string line;
    char cell[40];
    const auto put = [&](const char* format, double v) {
        const int n = std::isfinite(v) ? std::snprintf(cell, sizeof cell, format, v) : 0;
        line.append(cell, static_cast<std::size_t>(n));
    };
    for (std::size_t k = 0; k < times.size(); ++k) {
        line.clear();
        put("%.10g", times[k]);
        for (std::size_t i = 0; i < 2; ++i) {
            const SimulationResult& run = axes[i]->run;
            const std::size_t j = runRow[i].empty() ? k : runRow[i][k];
            for (const std::vector<double>* v : {&run.r, &run.y, &run.e, &run.u}) {
                line += ',';
                put("%.10g", (*v)[j]);
            }
        }
        // The digital runs with 17 digits: they read back as the core computed them, to
        // compare with the firmware's logs bit for bit. A non-finite value (a diverging
        // implementation) is left empty.
        for (std::size_t i = 0; i < 2; ++i) {
            if (!axes[i]->digital) {
                line += ",,,,";
                continue;
            }
            const SimulationResult& d = axes[i]->digital->run.result;
            const std::size_t j = digitalRow[i][k];
            for (const std::vector<double>* v : {&d.t, &d.y, &d.e, &d.u}) {
                line += ',';
                put("%.17g", (*v)[j]);
            }
        }
        line += '\n';
        sink(line);
    }
}

std::string exportCsv(const Session& session, const SessionEvaluation& evaluation) {
    std::string out;
    exportCsv(session, evaluation, [&out](std::string_view bytes) { out.append(bytes); });
    return out;
}

} // namespace xyt
