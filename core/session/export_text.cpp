// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/export_text.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/session/friction_export.h"

#include "core/design/pole_placement.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"
#include "core/session/c_export.h"
#include "core/session/coupling_export.h"
#include "core/session/design_method_module.h"
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

using namespace cexport;

std::string exactNumber(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

double exportableNumber(double v, const std::string& field) {
    if (!std::isfinite(v))
        throw InvalidInput(field, makeDiagnostic("session_export_not_finite", {exactNumber(v)}));
    return v;
}

namespace {

const AxisEvaluation& validAxis(const SessionEvaluation& evaluation, int axisIndex) {
    const AxisEvaluation& a = evaluation.axes.at(static_cast<std::size_t>(axisIndex));
    if (!a.ok)
        throw InvalidInput("axes[" + std::to_string(axisIndex) + "]",
                           makeDiagnostic("session_cannot_export", {a.errorField, a.error}));
    return a;
}

/// The axis id as it names C identifiers (xyt_<id>_step): the session file allows only these.
void requireCIdentifier(const Session& session, int axisIndex) {
    const std::string& id = session.axes.at(static_cast<std::size_t>(axisIndex)).id;
    const bool ok = !id.empty() && id.size() <= 16 && std::all_of(id.begin(), id.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    });
    if (!ok)
        throw InvalidInput(axisField(axisIndex, "id"), makeDiagnostic("session_bad_axis_id"));
    if (axisIndex == 1 && session.axes[0].id == id)
        throw InvalidInput(axisField(1, "id"), makeDiagnostic("session_axis_id_not_unique"));
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

DigitalController axisDigitalController(const Session& session, const SessionEvaluation& evaluation,
                                        int axisIndex, const ExportOptions& options) {
    const AxisEvaluation& a = validAxis(evaluation, axisIndex);
    if (a.gt)
        return discretizePi(a.gt->kp, a.gt->ki, session.controllerTsSeconds, options.piMethod);
    throw InvalidInput("axes[" + std::to_string(axisIndex) + "].method",
                       makeDiagnostic("session_no_digital_controller"));
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
        requireCIdentifier(session, i);
        const AxisEvaluation& a = validAxis(evaluation, i);
        out << designMethodModule(a.method).cController(session, a, i, options);
        out << frictionCompensationCBlock(session, i, options.precision);
    }
    if (session.crossCoupling.active())
        out << crossCouplingCBlock(session, evaluation, options);
    out << "#endif /* XYT_CONTROLLER_COEFFICIENTS_H */\n";
    return out.str();
}

std::string octaveTrajectoryLines(const TrajectorySettings& t, int axisIndex,
                                  const std::string& id) {
    std::ostringstream out;
    if (t.kind == TrajectoryKind::Cubic && t.profile == MoveProfile::Quintic) {
        const QuinticTrajectory quintic(t.x0, t.xf, t.t0Seconds, t.tfSeconds, t.v0, t.vf);
        const auto& c = quintic.localCoefficients();
        const std::string f = "trajectory.cubic (tf - t0 too short for the move?)";
        out << "tau = min(max(t - " << num(t.t0Seconds, "trajectory.cubic.t0") << ", 0), "
            << num(t.tfSeconds - t.t0Seconds, "trajectory.cubic.tf") << ");\n";
        out << "r_" << id << " = " << num(c[0], f) << " + " << num(c[1], f) << " * tau + "
            << num(c[3], f) << " * tau.^3 + " << num(c[4], f) << " * tau.^4 + " << num(c[5], f)
            << " * tau.^5;  % quintic point-to-point (zero acceleration at both ends)\n";
    } else if (t.kind == TrajectoryKind::Cubic) {
        const CubicTrajectory cubic(t.x0, t.xf, t.t0Seconds, t.tfSeconds, t.v0, t.vf);
        const auto& l = cubic.localCoefficients();
        const std::string f = "trajectory.cubic (tf - t0 too short for the move?)";
        out << "tau = min(max(t - " << num(t.t0Seconds, "trajectory.cubic.t0") << ", 0), "
            << num(t.tfSeconds - t.t0Seconds, "trajectory.cubic.tf") << ");\n";
        out << "r_" << id << " = " << num(l[0], f) << " + " << num(l[1], f) << " * tau + "
            << num(l[2], f) << " * tau.^2 + " << num(l[3], f)
            << " * tau.^3;  % cubic point-to-point (Braga et al. Eq. 4)\n";
    } else if (t.kind == TrajectoryKind::Gcode) {
        throw InvalidInput("trajectory.kind", makeDiagnostic("session_program_no_closed_form"));
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
    std::array<std::string, 2> timeVectors;
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& axis = session.axes[static_cast<std::size_t>(i)];
        const AxisEvaluation& a = validAxis(evaluation, i);
        out << "% Axis " << axis.id << labelComment(axis, CommentSyntax::Octave) << "\n";
        const OctaveLines lines =
            designMethodModule(a.method).octaveController(session, a, i, options, duration);
        out << lines.text;
        timeVectors[static_cast<std::size_t>(i)] = lines.timeVector;
    }
    out << "figure;\n";
    for (int i = 0; i < 2; ++i) {
        const std::string& id = session.axes[static_cast<std::size_t>(i)].id;
        const std::string& tt = timeVectors[static_cast<std::size_t>(i)];
        out << "subplot(2, 1, " << (i + 1) << ");\nplot(" << tt << ", r_" << id << ", '--', " << tt
            << ", y_" << id << ");\ngrid on;\nxlabel('time (s)');\nylabel('" << id
            << " (mm)');\nlegend('reference', 'output');\n";
    }
    return out.str();
}

namespace {

/// The session's dt grid over the run: the times of an axis that runs on it (both come from
/// sampleTimes over the run), else k dt up to the run's duration (axes that run at their own Ts
/// are not the export's grid).
std::vector<double> csvTimes(const Session& session, const SessionEvaluation& evaluation) {
    for (const AxisEvaluation& a : evaluation.axes)
        if (a.run.dtSeconds == session.trajectory.dtSeconds)
            return a.run.t;
    try {
        return sampleTimes(evaluation.duration.seconds, session.trajectory.dtSeconds);
    } catch (const InvalidInput& e) {
        throw InvalidInput(e.field() == "dt" ? "trajectory.dt" : "trajectory.duration",
                           e.reasonDiagnostic());
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
                    throw InvalidInput(
                        axisField(i, ""),
                        makeDiagnostic("session_simulated_not_finite",
                                       {std::string(name) + "_" + id, exactNumber((*v)[k]),
                                        exactNumber(run.t[k])}));
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
