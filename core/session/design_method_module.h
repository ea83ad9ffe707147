// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/coupled_line_loop.h"
#include "core/analysis/loop_responses.h"
#include "core/analysis/pole_zero_map.h"
#include "core/model/translatable_text.h"
#include "core/session/export_text.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/sampled_data.h"
#include "core/study/plant_uncertainty.h"
#include "core/study/robustness.h"

#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace xyt {

/**
 * One design method as a module: everything that differs between methods is behind this
 * interface, and the evaluation, the analyses and the views ask the module of an axis' method
 * (designMethodModule) instead of branching on the method themselves.
 *
 * A module turns an axis' settings and the session into its evaluated design (evaluate): the
 * design itself, the run the axis makes (with its feedforward, if the method has one), the step
 * figures and the warnings, and, when asked, the digital implementation at the controller
 * period. From an evaluated design it gives the loop every analysis takes (margins, Bode,
 * Nyquist, root locus), the closed loop, the pole-zero sets a map draws and the slowest decay
 * (for the automatic run duration).
 *
 * Adding a method: its module (a DesignMethodModule with a DesignMethod value of its own), and
 * one registration: a line in the registry of built-in methods (design_method_module.cpp), or
 * registerDesignMethodModule at start-up. A method whose settings are numbers declares them
 * (parameters()): the session holds them in AxisSettings::parameters, the session file writes
 * them, and the workbench's parameter editor edits them, so such a method needs no other change
 * (tests/ui/tst_registered_method.cpp registers a proportional controller and runs the whole
 * workbench, the exports and the report with it).
 */
/// One axis' run along a path (the contour run of a G-code program).
struct AxisTrace {
    SimulationResult run;             ///< on the method's own sample times
    std::vector<double> outputOnPath; ///< the output at the path's sample times
};

/// One axis' lines of the Octave/MATLAB script, and the time vector its response y_<id> is on.
struct OctaveLines {
    std::string text;
    std::string timeVector;
};

/**
 * One number of a method's settings, held in AxisSettings::parameters under its name. The session
 * file writes it at "axes[i].parameters.<name>", and a refusal names that path.
 */
struct MethodParameter {
    std::string name;  ///< the key: lower-case letters, digits and '_' ("kp")
    std::string label; ///< what an editor shows ("Proportional gain kp")
    std::string unit;  ///< "V/mm"
    double defaultValue = 0.0;
    double minimum = 0.0; ///< the smallest value allowed (inclusive)
    double maximum = 0.0; ///< the largest value allowed (inclusive)
};

/// One coefficient of an evaluated design as panels, reports and exports list it.
struct DesignCoefficient {
    std::string name; ///< "kp", "ωn"
    double value = 0.0;
    std::string unit; ///< "rad/s"; empty for a number without unit
};

class DesignMethodModule {
public:
    virtual ~DesignMethodModule() = default;

    virtual DesignMethod method() const = 0;
    /// The method's name as the session file writes it ("guillemin-truxal").
    virtual std::string_view id() const = 0;
    /// The method's name as the workbench shows it within a sentence ("Guillemin-Truxal PI",
    /// "pole placement + ZPETC").
    virtual std::string_view displayName() const = 0;
    /// The numbers of the method's settings held in AxisSettings::parameters (none for the
    /// built-in methods, whose settings are typed: AxisSettings::gt, AxisSettings::pp).
    virtual std::vector<MethodParameter> parameters() const { return {}; }

    /**
     * Designs axis @p axisIndex of @p session and runs it for @p durationSeconds, filling the
     * method's part of @p out: the design, run, metrics, step, warnings and (when
     * @p withDigital) the digital implementation. Throws InvalidInput naming the session field
     * of a setting that allows no design, and RunRefused (axis_run.h) for a run that cannot be
     * made.
     */
    virtual void evaluate(const Session& session, int axisIndex, double durationSeconds,
                          bool withDigital, AxisEvaluation& out) const = 0;

    /**
     * Runs axis @p axisIndex on @p reference, sampled at the times @p t (step @p dtSeconds), the
     * table at rest at its first sample: the contour run of a program. Throws InvalidInput
     * naming the session field ("axes[1].pp.ts").
     */
    virtual AxisTrace tracePath(const Session& session, int axisIndex, const std::vector<double>& t,
                                const std::vector<double>& reference, double dtSeconds) const = 0;

    /**
     * tracePath's run as a loop advanced one sample at a time (core/simulation/loop_stepper.h),
     * for the cross-coupled contour run (core/simulation/cross_coupled_run.h): the same design,
     * limit, feedforward, table and refusals, on the method's own samples (a continuous axis at
     * @p dtSeconds on @p t, a discrete one at its controller period from t = 0); the extra
     * voltage of each sample is the coupling's, added to the axis' command before its limit.
     * By default throws InvalidInput "cross_coupling": a method whose loop takes no coupling.
     */
    virtual std::unique_ptr<SteppedLoop> steppedPath(const Session& session, int axisIndex,
                                                     const std::vector<double>& t,
                                                     const std::vector<double>& reference,
                                                     double dtSeconds) const;

    /**
     * Axis @p axisIndex's loop as the cross-coupled controller of period @p periodSeconds sees
     * it on a straight line (core/analysis/coupled_line_loop.h): linear, from the coupling's
     * voltage to the output in mm. By default throws InvalidInput "cross_coupling", as
     * steppedPath. Throws InvalidInput naming the session field of a setting that allows no
     * design.
     */
    virtual SampledAxisModel couplingModel(const Session& session, int axisIndex,
                                           double periodSeconds) const;

    /**
     * The digital implementation of axis @p axisIndex (what cController exports: its controller
     * at its period, the encoder, DAC, delay and limit of the session's implementation) along a
     * program's reference @p reference sampled at @p t, resampled at the controller's period
     * from t = 0 and run from rest as the axis' digital evaluation runs (a pole-placement axis
     * at rest at the reference's first sample, a continuous plant at 0), one sample at a time:
     * the cross-coupled digital run the exported coupled step is checked against. By default
     * throws InvalidInput "cross_coupling", as steppedPath.
     */
    virtual std::unique_ptr<SampledLoopStepper>
    steppedDigitalPath(const Session& session, int axisIndex, const std::vector<double>& t,
                       const std::vector<double>& reference) const;

    /**
     * The C function the exported cross-coupled step (exportCHeader with the coupling on) calls
     * for this axis: `xyt_<id>_coupled(state, reference, measured, ff, extra, given)` forming
     * the axis' command with the feedforward @c ff and the coupling's @c extra volts added
     * before the limit, the operations of steppedDigitalPath's advance in their order
     * (@c reference is what the axis' own step takes: r(k + preview) for a ZPETC axis; @c given
     * the trajectory generator's derivatives or null, for a PID that reads them). By default
     * throws InvalidInput "cross_coupling".
     */
    virtual std::string cCoupledAxis(const Session& session, const AxisEvaluation& axis,
                                     int axisIndex) const;

    /// The plant's parameters with their nominal values, as the robustness study varies them
    /// (relative ranges 0). Throws InvalidInput for a plant that has none.
    virtual std::vector<UncertainParameter> plantParameters(const AxisSettings& settings) const = 0;

    /**
     * The controller of evaluated axis @p axisIndex as C for firmware, its block of
     * exportCHeader: a comment saying what it runs, its coefficients, and its state, init and
     * step functions (with the saturation and the anti-windup) performing the operations of
     * the sampled-data simulation in the same order. Written with core/session/c_export.h;
     * throws InvalidInput naming the field of a number C cannot hold.
     */
    virtual std::string cController(const Session& session, const AxisEvaluation& axis,
                                    int axisIndex, const ExportOptions& options) const = 0;

    /**
     * The axis' part of exportOctaveScript: plant_<id>, controller_<id>, closed_loop_<id>, the
     * reference r_<id> (octaveTrajectoryLines) and the linear response y_<id> over a run of
     * @p durationSeconds.
     */
    virtual OctaveLines octaveController(const Session& session, const AxisEvaluation& axis,
                                         int axisIndex, const ExportOptions& options,
                                         double durationSeconds) const = 0;

    /// The loop of an evaluated design (L, S, T and u/r); unset without a design.
    virtual std::optional<LoopTransferFunctions> loop(const AxisEvaluation& axis) const = 0;
    /// Reference to output of the loop the design closes. Throws without a design.
    virtual TransferFunction closedLoop(const AxisEvaluation& axis) const = 0;
    /// The pole-zero sets of an evaluated design, in the order a map lists them; empty without
    /// a design.
    virtual std::vector<PoleZeroSet> poleZeroSets(const AxisEvaluation& axis,
                                                  const AxisSettings& settings) const = 0;
    /// The slowest decay rate of the closed loop (1/s); 0 or less when not asymptotically
    /// stable or without a design.
    virtual double slowestDecayPerSecond(const AxisEvaluation& axis) const = 0;

    /// The coefficients of an evaluated design, as the snapshot comparison, the coefficient file
    /// and the teaching panel list them; empty without a design.
    virtual std::vector<DesignCoefficient> coefficients(const AxisEvaluation& axis) const = 0;
    /**
     * The design in words, one line each, as the session report prints it under the axis (the
     * coefficients and what the method adds, such as a feedforward's figures). By default, the
     * coefficients as "name = value unit".
     */
    virtual std::vector<std::string> reportLines(const AxisSettings& settings,
                                                 const AxisEvaluation& axis) const;
    /**
     * The design's equations as the teaching panel shows them, one plain-text line each (Unicode
     * for symbols: "u = kp e"): a line of symbols and numbers as text, a line with words coded
     * (makeDiagnostic) so that the workbench translates it. By default, the coefficients as
     * "name = value unit". (The built-in methods' panels are typeset by the workbench.)
     */
    virtual std::vector<Diagnostic> equations(const AxisSettings& settings,
                                              const AxisEvaluation& axis) const;
    /**
     * The tracking response r -> y of an evaluated design on @p omegaRadPerSec, without and with
     * its feedforward, when the method has one (pole placement's ZPETC, a PID's command
     * feedforward); unset otherwise. Throws InvalidInput "omega" as frequencyResponse.
     */
    virtual std::optional<TrackingFrequencyResponses>
    trackingResponses(const AxisEvaluation& /*axis*/,
                      const std::vector<double>& /*omegaRadPerSec*/) const {
        return std::nullopt;
    }
    /**
     * @p settings without the method's command feedforward (pole placement's ZPETC, a PID's
     * FF0..FF3; a friction compensation stays), for the contour views' comparison of the
     * feedback alone; unset when the method has none or it is off already.
     */
    virtual std::optional<AxisSettings> withoutFeedforward(const AxisSettings& /*settings*/) const {
        return std::nullopt;
    }
    /// The method's feedforward as the views name it ("ZPETC", "feedforward").
    virtual std::string_view feedforwardName() const {
        return XYT_TRANSLATE_NOOP("xyt::CoreText", "feedforward");
    }
    /// What the design's run is (AxisEvaluation::run), as the report labels it.
    virtual std::string designRunDescription() const { return "the continuous loop, |u| limited"; }

    /**
     * The robustness problem of evaluated axis @p axisIndex (@p nominal, ok): the nominal
     * controller with the run the evaluation made, and every plant parameter with a zero range
     * (robustness_problem.h builds it: continuousRobustnessProblem, rstRobustnessProblem).
     */
    virtual RobustnessProblem robustnessProblem(const Session& session, int axisIndex,
                                                const AxisEvaluation& nominal) const = 0;
    /**
     * @p settings with its plant's parameters (those of plantParameters) replaced by
     * @p value(name, current value): a plant the robustness study drew, loaded into the session.
     */
    virtual AxisSettings
    withPlantParameters(AxisSettings settings,
                        const std::function<double(const std::string&, double)>& value) const = 0;
};

/// The module of @p method. Throws InvalidInput "method" when none is registered for it.
const DesignMethodModule& designMethodModule(DesignMethod method);

/// The module whose id() is @p id, or null.
const DesignMethodModule* findDesignMethodModule(std::string_view id);

/// Every registered module, in the order the workbench offers them: the built-in ones, then
/// those registered by registerDesignMethodModule in their order.
const std::vector<const DesignMethodModule*>& designMethodModules();

/**
 * Adds @p module to the registry, for the life of the program. Call it at start-up, before any
 * session is evaluated (the registry is not guarded against concurrent use). Throws InvalidInput
 * "method" when its DesignMethod value or its id is taken, or its id or a parameter name is not
 * lower-case letters, digits, '-' or '_'.
 */
void registerDesignMethodModule(std::unique_ptr<const DesignMethodModule> module);

/// Whether @p name can name a method's parameter: 1 to 32 lower-case letters, digits or '_'.
bool isMethodParameterName(std::string_view name);

/**
 * The value of @p parameter of axis @p axisIndex: AxisSettings::parameters' entry, or the
 * parameter's default when the session has none. Throws InvalidInput naming
 * "axes[i].parameters.<name>" for a value that is not finite or out of its range.
 */
double methodParameterValue(const AxisSettings& settings, int axisIndex,
                            const MethodParameter& parameter);

/**
 * The loop of an evaluated axis, whatever its design method (its DesignMethodModule says):
 * margins, frequency responses, the root locus and the views read the loop from here and never
 * ask which method made it.
 *
 * Guillemin-Truxal: gtLoopTransferFunctions (continuous, unity feedback). Pole placement:
 * rstLoopTransferFunctions (the loop broken at the plant input, L = B G/(A F), in z with the
 * design's Ts). Unset when the axis has no design (invalid settings).
 */
std::optional<LoopTransferFunctions> axisLoop(const AxisEvaluation& axis);

/**
 * The pole-zero sets of an evaluated axis with @p settings, in the order a map lists them.
 * Guillemin-Truxal: gtPoleZeroSets. Pole placement: "plant B/A", "feedback G/F", "closed loop
 * Kf B/T" and, when the feedforward runs, "ZPETC feedforward". Empty without a design.
 */
std::vector<PoleZeroSet> axisPoleZeroSets(const AxisEvaluation& axis, const AxisSettings& settings);

} // namespace xyt
