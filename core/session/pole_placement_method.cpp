// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/pole_placement_method.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/number_format.h"
#include "core/model/translatable_text.h"
#include "core/session/axis_run.h"
#include "core/session/c_export.h"
#include "core/session/robustness_problem.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/resample.h"
#include "core/simulation/zpetc_step.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace xyt {

namespace {

Polynomial fromCoefficients(const std::vector<double>& c, const std::string& field) {
    return Polynomial::fromAscending(c, field);
}

/**
 * A plant that does not integrate (A(1) != 0) holds a position y only with the steady command
 * u = y A(1) / B(1): beyond the actuator limit the axis cannot stay where the trajectory goes,
 * whatever the controller (Patrick, Ishak and Adnan's x-axis model needs 3.03 V at 600 mm).
 */
std::optional<Diagnostic> reachWarning(const PpAxisSettings& pp,
                                       const std::vector<double>& reference, double umaxVolts) {
    double a1 = 0.0, b1 = 0.0, farthest = 0.0;
    for (double c : pp.a)
        a1 += c;
    for (double c : pp.b)
        b1 += c;
    for (double r : reference)
        farthest = std::max(farthest, std::abs(r));
    // |A(1)| below 1e-9 of the coefficients' scale: an integrator within round-off.
    double scale = 0.0;
    for (double c : pp.a)
        scale = std::max(scale, std::abs(c));
    if (!(std::abs(a1) > 1e-9 * scale) || b1 == 0.0 || !std::isfinite(farthest))
        return std::nullopt;
    const double hold = farthest * a1 / b1;
    if (!(std::abs(hold) > umaxVolts))
        return std::nullopt;
    return makeDiagnostic("session_out_of_reach",
                          {formatNumber(farthest, 4), formatNumber(std::abs(hold), 3),
                           formatNumber(b1 / a1, 4), formatNumber(umaxVolts)});
}

void evaluatePp(const Session& session, const AxisSettings& axis, int axisIndex, double duration,
                bool withDigital, AxisEvaluation& out) {
    const PpAxisSettings& pp = axis.pp;
    const double deadzone = arxInputDeadzoneVolts(axis, axisIndex);
    requireFinite(pp.t1, "t1");
    if (std::abs(pp.t1) >= 1.0)
        throw InvalidInput("t1", makeDiagnostic("session_t1_outside_unit_circle"));
    out.pp = designPolePlacement(fromCoefficients(pp.a, "a"), fromCoefficients(pp.b, "b"),
                                 Polynomial::fromAscending({1.0, pp.t1}), pp.tsSeconds);
    out.zpetc = designZpetc(*out.pp);
    out.warnings.insert(out.warnings.end(), out.pp->warnings.begin(), out.pp->warnings.end());
    const auto reference = sessionReference(session.trajectory, axisIndex); // first, as evaluateGt
    const auto times = axisSampleTimes(session.trajectory, duration, pp.tsSeconds,
                                       "axes[" + std::to_string(axisIndex) + "].pp.ts");
    const std::size_t n = times.size();
    std::vector<double> r(n + static_cast<std::size_t>(out.zpetc->previewSteps));
    for (std::size_t k = 0; k < r.size(); ++k)
        r[k] = reference(static_cast<double>(k) * pp.tsSeconds);
    const std::vector<double> rLoop(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n));
    out.feedbackOnlyRun = discreteRun(
        times, r, simulateFeedbackLoop(*out.pp, rLoop, StartCondition::AtReference, deadzone),
        session.umaxVolts, pp.tsSeconds);
    out.rmseWithoutFf = rootMeanSquare(out.feedbackOnlyRun.e);
    if (pp.zpetcEnabled) {
        out.run = discreteRun(
            times, r,
            simulateZpetcLoop(*out.pp, *out.zpetc, r, n, StartCondition::AtReference, deadzone),
            session.umaxVolts, pp.tsSeconds);
        const double with = rootMeanSquare(out.run.e);
        out.improvementPct =
            out.rmseWithoutFf > 0.0 ? 100.0 * (1.0 - with / out.rmseWithoutFf) : 0.0;
    } else {
        out.run = out.feedbackOnlyRun;
    }
    out.metrics = trackingMetrics(out.run);
    if (const auto reachDiagnostic = reachWarning(pp, out.run.r, session.umaxVolts))
        out.warnings.push_back(*reachDiagnostic);
    // The step figures of the system the axis runs: with ZPETC the step previewed through the
    // feedforward and the loop (the loop Kf B / T alone overshoots 52 % through the
    // NMP zero, which the axis never does); without it the loop alone.
    out.step = pp.zpetcEnabled && out.zpetc && out.pp->closedLoop().isStable()
                   ? zpetcStepCharacteristics(*out.pp, *out.zpetc)
                   : loopStepCharacteristics(*out.pp);
    if (!out.step.stable)
        out.warnings.push_back(makeDiagnostic("closed_loop_unstable"));
    if (out.metrics.saturated)
        out.warnings.push_back(makeDiagnostic("pp_u_exceeds_limit"));
    if (!withDigital)
        return;
    try {
        DigitalEvaluation d;
        d.tsSeconds = pp.tsSeconds;
        SampledDataOptions options = sessionSampledDataOptions(session);
        options.table = axisTable(axis, axisIndex);
        const ZpetcDesign* zpetc = pp.zpetcEnabled ? &*out.zpetc : nullptr;
        d.run = simulateSampledRst(*out.pp, zpetc, r, n, options);
        d.poles = sampledRstLoopPoles(*out.pp, options.delaySamples);
        d.designPoles = sampledRstLoopPoles(*out.pp, 0);
        d.designMinDamping = minDigitalDamping(d.designPoles);
        finishDigital(session, d, out);
        out.digital = std::make_shared<const DigitalEvaluation>(std::move(d));
    } catch (const InvalidInput& e) {
        out.warnings.push_back(makeDiagnostic("no_digital_implementation", {e.what()}));
    }
}

/// What a discrete axis' program run needs: its design, its sample times k Ts (n of them) and
/// the reference resampled on them (held at the end for the ZPETC's preview).
struct PpProgramRun {
    PolePlacementDesign loop;
    ZpetcDesign zpetc;
    std::vector<double> times, r;
    std::size_t n = 0;
};

PpProgramRun ppProgramRun(const PpAxisSettings& pp, int axisIndex, const std::vector<double>& t,
                          const std::vector<double>& reference) {
    PpProgramRun out;
    try {
        requireFinite(pp.t1, "t1");
        if (std::abs(pp.t1) >= 1.0)
            throw InvalidInput("t1", makeDiagnostic("session_t1_outside_unit_circle"));
        out.loop = designPolePlacement(Polynomial::fromAscending(pp.a, "a"),
                                       Polynomial::fromAscending(pp.b, "b"),
                                       Polynomial::fromAscending({1.0, pp.t1}), pp.tsSeconds);
        out.zpetc = designZpetc(out.loop);
    } catch (const InvalidInput& e) {
        throw InvalidInput(axisFieldPath(axisIndex, "pp." + e.field()), e.reasonDiagnostic());
    }
    const double steps = std::floor(t.back() / pp.tsSeconds + 1e-9);
    if (!(steps >= 1.0))
        throw InvalidInput(axisFieldPath(axisIndex, "pp.ts"),
                           makeDiagnostic("session_period_longer_than_run",
                                          {formatNumber(pp.tsSeconds), formatNumber(t.back())}));
    if (steps + 1.0 > static_cast<double>(sampleLimit()))
        throw InvalidInput(axisFieldPath(axisIndex, "pp.ts"),
                           makeDiagnostic("session_too_many_samples"));
    out.n = static_cast<std::size_t>(steps) + 1;
    out.times.resize(out.n + static_cast<std::size_t>(out.zpetc.previewSteps));
    for (std::size_t k = 0; k < out.times.size(); ++k)
        out.times[k] = static_cast<double>(k) * pp.tsSeconds;
    out.r = resampleLinear(t, reference, out.times);
    out.times.resize(out.n);
    return out;
}

/// A discrete axis: the reference resampled at its Ts (held at the end for the ZPETC's
/// preview), the table at rest at the first sample (StartCondition::AtReference).
SimulationResult tracePp(const PpAxisSettings& pp, int axisIndex, const std::vector<double>& t,
                         const std::vector<double>& reference, double umaxVolts, double deadzone) {
    const PpProgramRun p = ppProgramRun(pp, axisIndex, t, reference);
    const DiscreteRun run =
        pp.zpetcEnabled
            ? simulateZpetcLoop(p.loop, p.zpetc, p.r, p.n, StartCondition::AtReference, deadzone)
            : simulateFeedbackLoop(
                  p.loop,
                  std::vector<double>(p.r.begin(), p.r.begin() + static_cast<std::ptrdiff_t>(p.n)),
                  StartCondition::AtReference, deadzone);
    return discreteRun(p.times, p.r, run, umaxVolts, pp.tsSeconds);
}

using namespace cexport;

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
    // The step with a voltage added before the limit (the cross-coupling's; 0 in
    // xyt_<id>_step): the law remembers its own share of the clipped command.
    out << "static inline xyt_real xyt_" << id << "_step_with(xyt_" << id << "_state *s, xyt_real "
        << (ff ? "reference_ahead" : "reference")
        << ", xyt_real measured, xyt_real extra) {\n    int i;\n    xyt_real w, v, t, u;\n";
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
        << "    t = extra != (xyt_real)0 ? v + extra : v;\n"
        << "    " << cSaturate("u", "t") << "    s->u[0] = "
        << (antiWindup == AntiWindup::None ? "v" : "extra != (xyt_real)0 ? u - extra : u")
        << ";\n    return u;\n}\n";
    out << "static inline XYT_MAYBE_UNUSED xyt_real xyt_" << id << "_step(xyt_" << id
        << "_state *s, xyt_real " << (ff ? "reference_ahead" : "reference")
        << ", xyt_real measured) {\n    return xyt_" << id << "_step_with(s, "
        << (ff ? "reference_ahead" : "reference") << ", measured, 0);\n}\n\n";
    return out.str();
}

/// The pole-placement axis in the Octave/MATLAB script: plant, RST law, closed loop Kf B/T, the
/// reference and the response of the loop alone on its own time vector t_<id>.
OctaveLines ppOctaveLines(const Session& session, const AxisEvaluation& a, int i, double duration) {
    const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(i));
    const std::string& id = axis.id;
    const std::string ppField = axisField(i, "pp");
    std::ostringstream out;
    const PolePlacementDesign& pp = *a.pp;
    const std::string ts = num(pp.tsSeconds, ppField + ".ts");
    out << "Ts_" << id << " = " << ts << ";\n";
    out << "plant_" << id << " = filt([" << joined(pp.b.ascending(), " ", ppField + ".b") << "], ["
        << joined(pp.a.ascending(), " ", ppField + ".a") << "], Ts_" << id << ");  % B/A in z^-1\n";
    out << "% RST pole placement: F u = Kf w - G y (Patrick, Ishak and Adnan Eq. 7-8)\n";
    out << "F_" << id << " = [" << joined(pp.f.ascending(), " ", ppField + " (F)") << "];\n";
    out << "G_" << id << " = [" << joined(pp.g.ascending(), " ", ppField + " (G)") << "];\n";
    out << "Kf_" << id << " = " << num(pp.kf, ppField + " (Kf)") << ";\n";
    out << "controller_" << id << " = filt(G_" << id << ", F_" << id << ", Ts_" << id
        << ");  % feedback path G/F\n";
    out << "closed_loop_" << id << " = Kf_" << id << " * feedback(plant_" << id << " * filt(1, F_"
        << id << ", Ts_" << id << "), filt(G_" << id << ", 1, Ts_" << id << "));  % = Kf B / T\n";
    out << "t_" << id << " = (0:Ts_" << id << ":" << num(duration, "trajectory.duration")
        << ")';\n";
    out << "t_saved = t; t = t_" << id << ";\n"
        << octaveTrajectoryLines(session.trajectory, i, id) << "t = t_saved;\n";
    out << "y_" << id << " = lsim(closed_loop_" << id << ", r_" << id << ", t_" << id
        << ");  % the loop alone, without the ZPETC feedforward\n\n";
    return {out.str(), "t_" + id};
}

class PolePlacementMethod final : public DesignMethodModule {
public:
    DesignMethod method() const override { return DesignMethod::PolePlacementZpetc; }
    std::string_view id() const override { return "pole-placement-zpetc"; }
    std::string_view displayName() const override {
        return XYT_TRANSLATE_NOOP("xyt::MethodName", "pole placement + ZPETC");
    }
    std::optional<TrackingFrequencyResponses>
    trackingResponses(const AxisEvaluation& axis,
                      const std::vector<double>& omegaRadPerSec) const override {
        if (!axis.pp || !axis.zpetc)
            return std::nullopt;
        return zpetcTrackingFrequencyResponses(*axis.pp, *axis.zpetc, omegaRadPerSec);
    }
    std::string_view feedforwardName() const override { return "ZPETC"; }

    std::optional<AxisSettings> withoutFeedforward(const AxisSettings& settings) const override {
        if (!settings.pp.zpetcEnabled)
            return std::nullopt;
        AxisSettings out = settings;
        out.pp.zpetcEnabled = false;
        return out;
    }

    std::string designRunDescription() const override {
        return "the linear loop at Ts, |u| over the limit flagged, not applied";
    }

    void evaluate(const Session& session, int axisIndex, double durationSeconds, bool withDigital,
                  AxisEvaluation& out) const override {
        evaluatePp(session, session.axes.at(static_cast<std::size_t>(axisIndex)), axisIndex,
                   durationSeconds, withDigital, out);
    }

    AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& t,
                        const std::vector<double>& reference, double /*dtSeconds*/) const override {
        AxisTrace out;
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        out.run = tracePp(axis.pp, axisIndex, t, reference, session.umaxVolts,
                          arxInputDeadzoneVolts(axis, axisIndex));
        out.outputOnPath = resampleLinear(out.run.t, out.run.y, t);
        return out;
    }

    SampledAxisModel couplingModel(const Session& session, int axisIndex,
                                   double /*periodSeconds*/) const override {
        // The same design as the program's run (ppProgramRun's): its period is its Ts.
        const PpAxisSettings& pp = session.axes.at(static_cast<std::size_t>(axisIndex)).pp;
        try {
            return rstAxisModel(designPolePlacement(
                Polynomial::fromAscending(pp.a, "a"), Polynomial::fromAscending(pp.b, "b"),
                Polynomial::fromAscending({1.0, pp.t1}), pp.tsSeconds));
        } catch (const InvalidInput& e) {
            throw InvalidInput(axisFieldPath(axisIndex, "pp." + e.field()), e.reasonDiagnostic());
        }
    }

    std::unique_ptr<SampledLoopStepper>
    steppedDigitalPath(const Session& session, int axisIndex, const std::vector<double>& t,
                       const std::vector<double>& reference) const override {
        // As evaluatePp's digital run: the RST law (and ZPETC) at Ts with the session's
        // implementation, the table as the input's dead zone.
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        const PpProgramRun p = ppProgramRun(axis.pp, axisIndex, t, reference);
        SampledDataOptions options = sessionSampledDataOptions(session);
        options.table = axisTable(axis, axisIndex);
        return steppedSampledRst(p.loop, axis.pp.zpetcEnabled ? &p.zpetc : nullptr, p.r, p.n,
                                 options);
    }

    std::string cCoupledAxis(const Session& session, const AxisEvaluation& /*axis*/,
                             int axisIndex) const override {
        // The RST step with the coupling's voltage before its limit (SampledRstLoop::advance);
        // an ARX axis takes no feedforward.
        const std::string& id = session.axes.at(static_cast<std::size_t>(axisIndex)).id;
        return "static inline XYT_MAYBE_UNUSED xyt_real xyt_" + id + "_coupled(xyt_" + id +
               "_state *s, xyt_real reference, xyt_real measured, xyt_real ff, xyt_real extra, "
               "const xyt_real *given) {\n"
               "    (void)ff;\n    (void)given;\n"
               "    return xyt_" +
               id + "_step_with(s, reference, measured, extra);\n}\n";
    }

    std::unique_ptr<SteppedLoop> steppedPath(const Session& session, int axisIndex,
                                             const std::vector<double>& t,
                                             const std::vector<double>& reference,
                                             double /*dtSeconds*/) const override {
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        const PpProgramRun p = ppProgramRun(axis.pp, axisIndex, t, reference);
        return steppedRstRun(p.loop, axis.pp.zpetcEnabled ? &p.zpetc : nullptr, p.r, p.n,
                             session.umaxVolts, arxInputDeadzoneVolts(axis, axisIndex));
    }

    std::vector<UncertainParameter> plantParameters(const AxisSettings& settings) const override {
        // As designPolePlacement uses the model: A and B divided by A(0).
        const Polynomial a = Polynomial::fromAscending(settings.pp.a, "a");
        const Polynomial b = Polynomial::fromAscending(settings.pp.b, "b");
        const double a0 = a.coefficient(0);
        if (a0 == 0.0)
            throw InvalidInput("a", makeDiagnostic("analysis_a0_nonzero"));
        std::vector<UncertainParameter> out;
        const auto& ac = a.ascending();
        for (std::size_t i = 1; i < ac.size(); ++i)
            out.push_back({"a" + std::to_string(i), ac[i] / a0, 0.0});
        const auto& bc = b.ascending();
        for (std::size_t i = 1; i < bc.size(); ++i)
            if (bc[i] != 0.0)
                out.push_back({"b" + std::to_string(i), bc[i] / a0, 0.0});
        return out;
    }

    /// The RST law and the ZPETC filter as C arrays, then the complete step function.
    std::string cController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                            const ExportOptions& options) const override {
        const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axisIndex));
        const SampledDataOptions implementation = sessionSampledDataOptions(session);
        return rstHeaderBlock(settings, axis, upper(settings.id), axisIndex) +
               rstImplementationBlock(settings, axis, implementation.antiWindup, settings.id,
                                      axisIndex, options.precision);
    }

    OctaveLines octaveController(const Session& session, const AxisEvaluation& axis, int axisIndex,
                                 const ExportOptions& /*options*/,
                                 double durationSeconds) const override {
        return ppOctaveLines(session, axis, axisIndex, durationSeconds);
    }

    std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const override {
        if (!axis.pp)
            return std::nullopt;
        return rstLoopTransferFunctions(*axis.pp);
    }

    TransferFunction closedLoop(const AxisEvaluation& axis) const override {
        if (!axis.pp)
            throw InvalidInput("axis", makeDiagnostic("session_axis_no_design"));
        return axis.pp->closedLoop();
    }

    /// "plant B/A", "feedback G/F", "closed loop Kf B/T" and, when the feedforward runs,
    /// "ZPETC feedforward" (it is designed for the with/without comparison even when switched
    /// off; the map shows what runs).
    std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                          const AxisSettings& settings) const override {
        std::vector<PoleZeroSet> sets;
        if (!axis.pp)
            return sets;
        const PolePlacementDesign& pp = *axis.pp;
        const double ts = pp.tsSeconds;
        sets.push_back(poleZeroSet("plant B/A", TransferFunction::fromZInverse(pp.b, pp.a, ts)));
        sets.push_back(poleZeroSet("feedback G/F", TransferFunction::fromZInverse(pp.g, pp.f, ts)));
        sets.push_back(poleZeroSet("closed loop Kf B/T", pp.closedLoop()));
        if (axis.zpetc && settings.pp.zpetcEnabled)
            sets.push_back(poleZeroSet("ZPETC feedforward", TransferFunction::fromZInverse(
                                                                axis.zpetc->feedforwardNum,
                                                                axis.zpetc->feedforwardDen, ts)));
        return sets;
    }

    double slowestDecayPerSecond(const AxisEvaluation& axis) const override {
        return axis.pp ? discreteDecayPerSecond(axis.pp->closedLoop().poles(), axis.pp->tsSeconds)
                       : 0.0;
    }

    /// F's and G's coefficients (ascending z^-1), Kf and Ts.
    std::vector<DesignCoefficient> coefficients(const AxisEvaluation& axis) const override {
        if (!axis.pp)
            return {};
        std::vector<DesignCoefficient> out;
        const auto& f = axis.pp->f.ascending();
        for (std::size_t i = 0; i < f.size(); ++i)
            out.push_back({"f" + std::to_string(i), f[i], ""});
        const auto& g = axis.pp->g.ascending();
        for (std::size_t i = 0; i < g.size(); ++i)
            out.push_back({"g" + std::to_string(i), g[i], ""});
        out.push_back({"Kf", axis.pp->kf, ""});
        out.push_back({"Ts", axis.pp->tsSeconds, "s"});
        return out;
    }

    /// F, G, Kf and Ts, and the ZPETC's figures when it runs.
    std::vector<std::string> reportLines(const AxisSettings& settings,
                                         const AxisEvaluation& axis) const override {
        if (!axis.pp)
            return {};
        const auto poly = [](const Polynomial& p) {
            std::string out;
            for (double c : p.ascending())
                out += (out.empty() ? "" : " ") + formatNumber(c);
            return "[" + out + "]";
        };
        const auto fixed = [](double v, int decimals) {
            if (!std::isfinite(v))
                return std::string("n/a");
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
            return std::string(buf);
        };
        std::vector<std::string> lines{"F = " + poly(axis.pp->f) + ", G = " + poly(axis.pp->g) +
                                       " (ascending z^-1), Kf = " + formatNumber(axis.pp->kf) +
                                       ", Ts = " + formatNumber(axis.pp->tsSeconds) + " s"};
        if (settings.pp.zpetcEnabled && axis.zpetc)
            lines.push_back("ZPETC (as designed): preview " +
                            std::to_string(axis.zpetc->previewSteps) + " samples; RMSE without " +
                            fixed(axis.rmseWithoutFf, 5) + " mm, with " +
                            fixed(axis.metrics.rmse, 5) + " mm (improvement " +
                            fixed(axis.improvementPct, 2) + " %)");
        return lines;
    }

    RobustnessProblem robustnessProblem(const Session& session, int axisIndex,
                                        const AxisEvaluation& nominal) const override {
        return rstRobustnessProblem(
            session, axisIndex, nominal, *nominal.pp, nominal.zpetc,
            session.axes.at(static_cast<std::size_t>(axisIndex)).pp.zpetcEnabled);
    }

    /// The analysis perturbs the normalized model (A/A(0), B/A(0)), which the settings then
    /// hold.
    AxisSettings withPlantParameters(
        AxisSettings settings,
        const std::function<double(const std::string&, double)>& value) const override {
        std::vector<double> a = settings.pp.a, b = settings.pp.b;
        const double a0 = a.empty() ? 0.0 : a[0];
        if (a0 == 0.0)
            throw InvalidInput("a", makeDiagnostic("analysis_a0_nonzero"));
        for (double& c : a)
            c /= a0;
        for (double& c : b)
            c /= a0;
        for (std::size_t i = 1; i < a.size(); ++i)
            a[i] = value("a" + std::to_string(i), a[i]);
        for (std::size_t i = 1; i < b.size(); ++i)
            b[i] = value("b" + std::to_string(i), b[i]);
        settings.pp.a = a;
        settings.pp.b = b;
        return settings;
    }
};

} // namespace

const DesignMethodModule& polePlacementMethod() {
    static const PolePlacementMethod module;
    return module;
}

} // namespace xyt
