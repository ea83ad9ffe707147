// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/guillemin_truxal_method.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/number_format.h"
#include "core/model/root_matching.h"
#include "core/model/translatable_text.h"
#include "core/session/axis_run.h"
#include "core/session/c_export.h"
#include "core/session/continuous_plant_method.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/trajectory.h"

#include <cmath>
#include <sstream>

namespace xyt {

namespace {

/// The digital implementation of a Guillemin-Truxal axis (its failures become a warning: the
/// export names the field when asked for the code).
void evaluateGtDigital(const Session& session, const AxisSettings& axis, int axisIndex,
                       double duration, AxisEvaluation& out) {
    try {
        DigitalEvaluation d;
        const DigitalPi pi = sessionDigitalPi(session, *out.gt, axisIndex);
        d.tsSeconds = pi.tsSeconds;
        SampledDataOptions options = sessionSampledDataOptions(session);
        const TransferFunction plant = axisPlantTransferFunction(axis.gt, axisIndex);
        // At the simulation step (the default: both 10 ms) the continuous run already holds the
        // reference at the controller's sample times.
        const bool sameTimes = pi.tsSeconds == session.trajectory.dtSeconds;
        const std::vector<double> reference =
            sameTimes ? out.run.r
                      : sampled(sessionReference(session.trajectory, axisIndex),
                                axisSampleTimes(session.trajectory, duration, pi.tsSeconds,
                                                "controller_ts"));
        options.table = axisTable(axis, axisIndex);
        const std::vector<double> ff =
            frictionFeedforward(axis, axisIndex, reference, pi.tsSeconds);
        options.feedforwardVolts = &ff;
        d.run = simulateSampledPi(plant, pi, reference, options, axis.gt.modelUnitsPerPositionUnit);
        d.poles = sampledPiLoopPoles(sampledPlant(plant, pi.tsSeconds), pi, options.delaySamples);
        d.designMinDamping = minContinuousDamping(out.gt->closedLoopPoles);
        for (const auto& p : out.gt->closedLoopPoles)
            d.designPoles.push_back(std::exp(p * pi.tsSeconds));
        sortRoots(d.designPoles);
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    } catch (const InvalidInput& e) {
        out.warnings.push_back(
            makeDiagnostic("no_digital_implementation",
                           {makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()})}));
    }
}

void evaluateGt(const Session& session, const AxisSettings& axis, int axisIndex, double duration,
                bool withDigital, AxisEvaluation& out) {
    const GtAxisSettings& gt = axis.gt;
    out.gt = sessionGtDesign(gt, axisIndex);
    LoopSimulationOptions options;
    options.dtSeconds = session.trajectory.dtSeconds;
    options.umaxVolts = session.umaxVolts;
    options.modelUnitsPerPositionUnit = gt.modelUnitsPerPositionUnit;
    // The reference first: an unreadable program has no run time, and its refusal names the
    // program rather than the step that a run of no length would be blamed on.
    const auto reference = sessionReference(session.trajectory, axisIndex);
    const auto times =
        axisSampleTimes(session.trajectory, duration, options.dtSeconds, "trajectory.dt");
    options.table = axisTable(axis, axisIndex);
    const std::vector<double> r = sampled(reference, times);
    const std::vector<double> ff = frictionFeedforward(axis, axisIndex, r, options.dtSeconds);
    options.feedforwardVolts = &ff;
    out.run = simulateLoop(out.gt->loopPlant, out.gt->controller, r, options);
    out.metrics = trackingMetrics(out.run);
    out.step = stepCharacteristics(out.gt->closedLoop);
    if (!out.gt->stable)
        out.warnings.push_back(makeDiagnostic("closed_loop_unstable"));
    if (withDigital)
        evaluateGtDigital(session, axis, axisIndex, duration, out);
}

using namespace cexport;

/// The digital PI the export runs for a GT axis: the session's, discretized as @p options say.
DigitalPi exportPi(const Session& session, const GtDesign& design, const ExportOptions& options,
                   int axisIndex) {
    Session s = session;
    s.piDiscretization = options.piMethod;
    return sessionDigitalPi(s, design, axisIndex);
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
    const std::string notchField = gt + ".notch (prewarped at its centre, controller_ts)";
    if (pi.hasNotch) {
        out << "/* The notch on the error the PI reads, a biquad in direct form II transposed:\n"
               " *   e = B0 e_raw + s1,  s1 = B1 e_raw - A1 e + s2,  s2 = B2 e_raw - A2 e. */\n";
        constant("NOTCH_B0", pi.errorNotch.b0, notchField);
        constant("NOTCH_B1", pi.errorNotch.b1, notchField);
        constant("NOTCH_B2", pi.errorNotch.b2, notchField);
        constant("NOTCH_A1", pi.errorNotch.a1, notchField);
        constant("NOTCH_A2", pi.errorNotch.a2, notchField);
    }
    out << "typedef struct {\n    xyt_real integrator;     /* I[k-1] */\n"
           "    xyt_real previous_error; /* e[k-1] */\n"
        << (pi.hasNotch ? "    xyt_real notch_s1, notch_s2; /* the notch's state */\n" : "")
        << "} xyt_" << id << "_state;\n"
        << "static inline XYT_MAYBE_UNUSED void xyt_" << id << "_init(xyt_" << id
        << "_state *s) {\n"
        << "    s->integrator = 0;\n    s->previous_error = 0;\n"
        << (pi.hasNotch ? "    s->notch_s1 = 0;\n    s->notch_s2 = 0;\n" : "") << "}\n"
        << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
        << "_state *s, xyt_real reference, xyt_real measured) {\n";
    if (pi.hasNotch)
        out << "    const xyt_real e_raw = (reference - measured) * XYT_" << up << "_UNIT;\n"
            << "    const xyt_real e = XYT_" << up << "_NOTCH_B0 * e_raw + s->notch_s1;\n"
            << "    s->notch_s1 = XYT_" << up << "_NOTCH_B1 * e_raw - XYT_" << up
            << "_NOTCH_A1 * e + s->notch_s2;\n"
            << "    s->notch_s2 = XYT_" << up << "_NOTCH_B2 * e_raw - XYT_" << up
            << "_NOTCH_A2 * e;\n";
    else
        out << "    const xyt_real e = (reference - measured) * XYT_" << up << "_UNIT;\n";
    out << "    const xyt_real increment = XYT_" << up << "_C0 * e + XYT_" << up
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

/// The Guillemin-Truxal axis' block of the firmware header: the PI as a difference equation
/// and its complete step function.
std::string gtFirmwareBlock(const Session& session, const AxisEvaluation& a, int i,
                            const ExportOptions& options) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(i));
    const std::string id = upper(axis.id);
    std::ostringstream out;
    const DigitalController c =
        discretizePi(a.gt->kp, a.gt->ki, session.controllerTsSeconds, options.piMethod);
    const std::string gt = axisField(i, "gt");
    const std::string pi = gt + " (digital PI at controller_ts)";
    out << "/* Axis " << axis.id << labelComment(axis, CommentSyntax::C) << ": ";
    out << "Guillemin-Truxal PI, kp = " << num(a.gt->kp, gt + ".kp")
        << " V/model unit, ki = " << num(a.gt->ki, gt + " (ki)") << " V/(model unit s),\n * "
        << discretizationName(options.piMethod)
        << " discretization at Ts = " << num(c.tsSeconds, "controller_ts")
        << " s. Position in model units ("
        << num(axis.gt.modelUnitsPerPositionUnit, gt + ".model_unit_scale") << " per mm).\n";
    out << " *   u[k] = ";
    for (std::size_t k = 1; k < c.den.size(); ++k)
        out << "- XYT_" << id << "_DEN[" << k << "] u[k-" << k << "] ";
    for (std::size_t k = 0; k < c.num.size(); ++k)
        out << "+ XYT_" << id << "_NUM[" << k << "] e[k" << (k ? "-" + std::to_string(k) : "")
            << "] ";
    out << "\n */\n";
    out << "#define XYT_" << id << "_NUM_LEN " << c.num.size() << "\n";
    out << "#define XYT_" << id << "_DEN_LEN " << c.den.size() << "\n";
    out << "static const double XYT_" << id << "_NUM[XYT_" << id << "_NUM_LEN] XYT_MAYBE_UNUSED = {"
        << joined(c.num, ", ", pi) << "};\n";
    out << "static const double XYT_" << id << "_DEN[XYT_" << id << "_DEN_LEN] XYT_MAYBE_UNUSED = {"
        << joined(c.den, ", ", pi) << "};\n";
    out << "static const double XYT_" << id
        << "_TS XYT_MAYBE_UNUSED = " << num(c.tsSeconds, "controller_ts") << ";\n\n";
    out << piImplementationBlock(axis, exportPi(session, *a.gt, options, i), axis.id, i,
                                 options.precision);
    return out.str();
}

/// The Guillemin-Truxal axis in the Octave/MATLAB script: plant, PI, closed loop, its digital
/// form, the reference and the linear response on t.
OctaveLines gtOctaveLines(const Session& session, const AxisEvaluation& a, int i,
                          const ExportOptions& options) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(i));
    const std::string& id = axis.id;
    const std::string gt = axisField(i, "gt");
    std::ostringstream out;
    const auto& p = axis.gt.plant;
    out << "plant_" << id << " = tf(" << num(p.k0, gt + ".plant.k0") << ", [1 "
        << num(p.a1, gt + ".plant.a1") << " " << num(p.a2, gt + ".plant.a2") << " 0]);\n";
    out << "controller_" << id << " = tf([" << num(a.gt->kp, gt + ".kp") << " "
        << num(a.gt->ki, gt + " (ki)") << "], [1 0]);  % kp + ki/s\n";
    // The table's flexible mode and the notch, as every run of the workbench has them.
    const auto tfLine = [&](const std::string& name, const TransferFunction& g,
                            const std::string& field, const char* comment) {
        out << name << "_" << id << " = tf([" << joined(g.num().descending(), " ", field) << "], ["
            << joined(g.den().descending(), " ", field) << "]);  % " << comment << "\n";
    };
    if (axis.gt.flexibleMode.present()) {
        tfLine("mode", axis.gt.flexibleMode.transferFunction(), gt + ".flexible_mode",
               "the flexible mode, unit static gain");
        out << "plant_" << id << " = plant_" << id << " * mode_" << id << ";\n";
    }
    if (axis.gt.notch.present()) {
        tfLine("notch", axis.gt.notch.transferFunction(), gt + ".notch",
               "the notch on the error ahead of the PI");
        out << "controller_" << id << " = controller_" << id << " * notch_" << id << ";\n";
    }
    out << "closed_loop_" << id << " = feedback(controller_" << id << " * plant_" << id
        << ", 1);\n";
    out << "% The same PI as the firmware runs it (" << discretizationName(options.piMethod)
        << ", Ts = " << num(session.controllerTsSeconds, "controller_ts") << " s):\n";
    const DigitalController c =
        discretizePi(a.gt->kp, a.gt->ki, session.controllerTsSeconds, options.piMethod);
    out << "digital_controller_" << id << " = filt([" << joined(c.num, " ", gt + " (digital PI)")
        << "], [" << joined(c.den, " ", gt + " (digital PI)") << "], "
        << num(c.tsSeconds, "controller_ts") << ");  % in z^-1\n";
    if (axis.gt.notch.present()) {
        const Biquad b = discreteNotch(axis.gt.notch, c.tsSeconds, gt + ".notch.");
        const std::string f = gt + ".notch (bilinear, prewarped)";
        out << "digital_controller_" << id << " = digital_controller_" << id << " * filt(["
            << joined({b.b0, b.b1, b.b2}, " ", f) << "], [" << joined({1.0, b.a1, b.a2}, " ", f)
            << "], " << num(c.tsSeconds, "controller_ts") << ");  % the notch, prewarped\n";
    }
    out << octaveTrajectoryLines(session.trajectory, i, id);
    out << "unit_" << id << " = "
        << num(axis.gt.modelUnitsPerPositionUnit, gt + ".model_unit_scale")
        << ";  % model units per mm\n";
    out << "y_" << id << " = lsim(closed_loop_" << id << ", r_" << id << " * unit_" << id
        << ", t) / unit_" << id << ";\n\n";
    return {out.str(), "t"};
}

class GuilleminTruxalMethod final : public ContinuousPlantMethod {
public:
    DesignMethod method() const override { return DesignMethod::GuilleminTruxal; }
    std::string_view id() const override { return "guillemin-truxal"; }
    std::string_view displayName() const override {
        return XYT_TRANSLATE_NOOP("xyt::MethodName", "Guillemin-Truxal PI");
    }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        evaluateGt(session, session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex,
                   durationSeconds, withDigital, out);
    }

    TransferFunction evaluatedController(const AxisEvaluation& axis) const override {
        return axis.gt->controller;
    }
    TransferFunction designedController(const Session& session, int axisIndex) const override {
        return sessionGtDesign(session.axes.at(static_cast<std::size_t>(axisIndex)).gt, axisIndex)
            .controller;
    }

    std::unique_ptr<SampledLoopStepper>
    steppedDigitalPath(const Session& session, int axisIndex, const std::vector<double>& t,
                       const std::vector<double>& reference) const override {
        // As evaluateGtDigital: the digital PI at controller_ts, the session's implementation,
        // the table and its friction compensation.
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        const DigitalPi pi =
            sessionDigitalPi(session, sessionGtDesign(axis.gt, axisIndex), axisIndex);
        const std::vector<double> r = programAtPeriod(t, reference, pi.tsSeconds, "controller_ts");
        SampledDataOptions options = sessionSampledDataOptions(session);
        options.table = axisTable(axis, axisIndex);
        const std::vector<double> ff = frictionFeedforward(axis, axisIndex, r, pi.tsSeconds);
        options.feedforwardVolts = &ff;
        return steppedSampledPi(axisPlantTransferFunction(axis.gt, axisIndex), pi, r, options,
                                axis.gt.modelUnitsPerPositionUnit);
    }

    std::string cCoupledAxis(const Session& session, const AxisEvaluation& /*axis*/,
                             int axisIndex) const override {
        // The PI's own step (its limit and anti-windup), then the feedforward and the
        // coupling's voltage, clipped again: SampledPiLoop::advance's operations.
        const std::string& id = session.axes.at(static_cast<std::size_t>(axisIndex)).id;
        return cexport::cCoupledAxisFunction(id, "xyt_" + id + "_step(s, reference, measured)",
                                             false);
    }

    std::string cController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                            const ExportOptions& options) const override {
        return gtFirmwareBlock(session, axis, axisIndex, options);
    }

    OctaveLines octaveController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                                 const ExportOptions& options,
                                 double /*durationSeconds*/) const override {
        return gtOctaveLines(session, axis, axisIndex, options);
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.gt)
            return std::nullopt;
        return gtLoopTransferFunctions(*axis.gt);
    }

    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        if (!axis.gt)
            throw InvalidInput("axis", makeDiagnostic("session_axis_no_design"));
        return axis.gt->closedLoop;
    }

    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& /*settings*/) const override {
        if (!axis.gt)
            return {};
        return gtPoleZeroSets(*axis.gt);
    }

    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.gt ? continuousDecayPerSecond(axis.gt->closedLoopPoles) : 0.0;
    }

    std::vector<DesignCoefficient> coefficients(const AxisEvaluation& axis) const override {
        if (!axis.gt)
            return {};
        return {{"ωn", axis.gt->omegaNRadPerSec, "rad/s"},
                {"kp", axis.gt->kp, "V/model unit"},
                {"ki", axis.gt->ki, "V/(model unit s)"}};
    }

    std::vector<std::string> reportLines(const AxisSettings& /*settings*/,
                                         const AxisEvaluation& axis) const override {
        if (!axis.gt)
            return {};
        const GtDesign& d = *axis.gt;
        return {"wn = " + formatNumber(d.omegaNRadPerSec) + " rad/s, kp = " + formatNumber(d.kp) +
                ", ki = " + formatNumber(d.ki, 8) + (d.stable ? "" : "  UNSTABLE")};
    }
};

} // namespace

const DesignMethodModule& guilleminTruxalMethod() {
    static const GuilleminTruxalMethod module;
    return module;
}

} // namespace xyt
