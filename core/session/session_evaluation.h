// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/pole_zero_map.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/session.h"
#include "core/simulation/contour_error.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/simulation/resample.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"
#include "core/study/specification.h"

#include <array>
#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// How long the session's runs last, and why (both axes share it).
struct RunDuration {
    double seconds = 0.0;   ///< the simulated duration
    bool automatic = false; ///< the session's duration is 0 (automatic)
    /// Automatic cubic: the run goes past tf by the settle estimate (settleTimeEstimateSeconds
    /// of the slowest-settling valid, stable axis, from its error at tf and its slowest
    /// closed-loop pole) times 1.5, plus a tenth of the move, so that the response is seen to
    /// stay in the window.
    bool includesSettle = false;
    double settleEstimateSeconds = 0.0; ///< that estimate, s after tf (infinity: never settles)
    bool capped = false;     ///< the wanted run was longer than the cap and was cut to it
    double capSeconds = 0.0; ///< TrajectorySettings::effectiveDurationSeconds()
    Diagnostic description;  ///< one sentence saying what was chosen and why
};

/**
 * The axis as the firmware runs it: the sampled-data loop with the session's
 * implementation settings (simulateSampledPi at controller_ts for a Guillemin-Truxal axis,
 * simulateSampledRst at the axis' Ts for pole placement), its tracking figures and its z-plane
 * poles (its move-and-settle figures: moveSettleMetrics of run.result, as the CLI prints them).
 */
struct DigitalEvaluation {
    double tsSeconds = 0.0;
    SampledDataRun run;
    TrackingMetrics metrics;
    /// Closed-loop poles of the linear digital loop (z-plane, delay included).
    std::vector<std::complex<double>> poles;
    /// The design's closed-loop poles in the same z-plane: the continuous ones mapped by
    /// z = e^(s Ts) (GT), or the RST loop's without the delay (pole placement).
    std::vector<std::complex<double>> designPoles;
    /// Minimum damping ratio of those poles and of the design they are compared with (the
    /// continuous loop for GT, the loop without delay for pole placement).
    double minDamping = 0.0;
    double designMinDamping = 0.0;
    /// A limit cycle at rest after a cubic move (only looked for with quantization on).
    std::optional<RestOscillation> limitCycle;
    /// Point-to-point (cubic) runs: the digital run's move-and-settle figures.
    std::optional<MoveSettleMetrics> moveSettle;
};

/// The design a registered method's module makes (DesignMethodModule::evaluate), held by the
/// evaluation for the module to read back: each module derives its own.
struct MethodDesign {
    virtual ~MethodDesign() = default;
};

/// Everything computed for one axis of a session: the design, the run and its figures.
/**
 * What an input shaper on the reference does to an axis' run: the shaper, the run without it,
 * and the residual vibration of the mode it is meant for, shaped and unshaped. The mode is the
 * axis' flexible mode, else the one the shaper is designed for; its deflection between table
 * and tool point is driven by the commanded acceleration (modeDeflection, the model shapers are
 * designed for), and the residual is the amplitude it rings with once a point-to-point move has
 * ended (tf, plus the shaper's duration when shaped), or its largest amplitude over a circle or
 * a program (the acceleration sampled at the run's step, linear between samples). After a move
 * the mode rings freely, so the shaped residual is the unshaped one times the shaper's
 * residualVibration at that mode (Singer and Seering's superposition).
 */
struct ShapingComparison {
    InputShaper shaper;
    SimulationResult unshapedRun;
    double modeHz = 0.0, modeDamping = 0.0; ///< the mode the residuals are of
    bool fromAxisMode = false;              ///< the axis' flexible mode (else the shaper's own)
    bool afterMove = false;                 ///< the residuals are after a point-to-point move
    double residualShapedMm = 0.0;
    double residualUnshapedMm = 0.0;
};

struct AxisEvaluation {
    bool ok = false;
    std::string errorField; ///< when !ok: the invalid setting, e.g. "axes[0].gt.kp"
    Diagnostic error;       ///< when !ok: the reason
    /// When !ok because the run itself was refused (its trajectory is invalid, it would not fit
    /// in memory or would hold a single sample): no figure of this session means anything, and
    /// a report or an export must refuse it, naming errorField (e.g. "trajectory.dt").
    bool runRefused = false;
    DesignMethod method = DesignMethod::GuilleminTruxal;
    std::optional<GtDesign> gt;
    /// Discrete designs: the pole-placement loop and its ZPETC feedforward.
    std::optional<PolePlacementDesign> pp;
    std::optional<ZpetcDesign> zpetc;
    /// The design of a method other than the built-in ones (its module's own type).
    std::shared_ptr<const MethodDesign> methodDesign;
    /// Discrete designs: the run of the feedback loop alone (Kf r), for comparison.
    SimulationResult feedbackOnlyRun;
    double rmseWithoutFf = 0.0;  ///< discrete designs: RMSE of the loop alone
    double improvementPct = 0.0; ///< 100 (1 - RMSE with ZPETC / RMSE without)
    /// The run shown: continuous designs simulate the loop with saturation; discrete designs the
    /// linear loop with ZPETC when enabled (else alone), sampled at Ts, with `clipped` marking
    /// samples where |u| exceeds umax (Patrick, Ishak and Adnan's loop has no limit, so it is
    /// flagged, not applied).
    SimulationResult run;
    TrackingMetrics metrics;
    /// Point-to-point (cubic) runs: the move-and-settle figures with the specification's
    /// in-position window (unset for the circle).
    std::optional<MoveSettleMetrics> moveSettle;
    /// The duration of this axis' run (the session's; see RunDuration).
    RunDuration duration;
    /// With an input shaper on the reference (TrajectorySettings::shaping): the same run
    /// unshaped, to show what the shaper does (the full evaluation only).
    std::shared_ptr<const ShapingComparison> shaping;
    /// The unit step of the system the axis runs: G_R (GT); the pole-placement loop Kf B / T
    /// alone, or with ZPETC enabled the step previewed through the feedforward and the loop
    /// (zpetcStepCharacteristics).
    StepCharacteristics step;
    /// The loop's stability margins (stability_margins.h, L of gtLoopTransferFunctions or
    /// rstLoopTransferFunctions); unset when the axis has no loop or the analysis refused it.
    std::optional<StabilityMargins> margins;
    /// Pass/fail of each criterion of the session's specification (the margins included when
    /// `margins` is set) for the design as it will run: each criterion passes only if it passes
    /// both on the design's run (designCheck) and on the digital implementation's
    /// (implementationCheck, when there is one). A design whose implementation saturates or
    /// loses the trajectory fails, whatever the linear design does.
    SpecificationCheck check;
    /// The specification judged on the design's run alone.
    SpecificationCheck designCheck;
    /// The specification judged on the digital implementation's run (its tracking and
    /// move-and-settle figures; the step and margins are the design's); unset without one.
    std::optional<SpecificationCheck> implementationCheck;
    /// What the user should know about this axis' result (coded: diagnostic_catalogue.h).
    std::vector<Diagnostic> warnings;
    /// The digital implementation of the axis; unset when the axis could not be designed.
    /// Shared (its runs hold megabytes at the default length, and evaluations are copied into
    /// every view on each slider step): set once by the evaluation, never changed.
    std::shared_ptr<const DigitalEvaluation> digital;

    /// The closed loop of the design (G_R for GT, Kf B / T for pole placement).
    TransferFunction closedLoop() const;
};

struct SessionEvaluation {
    std::array<AxisEvaluation, 2> axes;
    RunDuration duration;
    /// Radial error of the traced circle (circle trajectories with both axes valid).
    std::optional<ContourError> contour;
    /// G-code trajectories with both axes valid: the program run by both axes
    /// (runSessionProgram): the contour error along the path, the corners, and for one full
    /// circle the ISO 230-4 test. Shared, since evaluations are copied into the views.
    std::shared_ptr<const ContourRun> program;
    std::shared_ptr<const Path> programPath; ///< the programmed path of `program`
    Diagnostic programError; ///< why `program` is unset although both axes are valid
    /// With cross-coupling on and a trajectory that is not a program (which runs coupled in
    /// `program`), both axes valid: the trajectory run coupled beside the independent axes.
    std::shared_ptr<const CoupledTrajectoryRun> coupledTrajectory;
    /// Why the coupling could not run, or is unstable on a line of the path (its refusal or
    /// warning, for the coupling's editor); empty otherwise.
    Diagnostic couplingError;
};

/// The reference r(t) that axis @p axisIndex (0 = x, 1 = y) follows; with the trajectory's
/// input shaper (ReferenceShaping) r_s(t) = sum A_i r(t - t_i), before t0 the start position.
/// @throws InvalidInput naming the session path ("trajectory.cubic.xf", "trajectory.circle.radius")
///         for a non-finite value or a position beyond kMaxPositionMm, "trajectory.shaping.<field>"
///         for a shaper designInputShaper refuses or one that lasts longer than the point-to-point
///         move (tf - t0) or the program's run time.
std::function<double(double)> axisReference(const TrajectorySettings& trajectory, int axisIndex);

/// When the (shaped) point-to-point move ends: tf, plus the input shaper's duration when the
/// reference is shaped.
double shapedMoveEndSeconds(const TrajectorySettings& trajectory);

/**
 * The reference of axis @p axisIndex with its first three derivatives, as a feedforward reads
 * them from the trajectory generator: exact for the point-to-point move (CubicTrajectory::motion,
 * QuinticTrajectory::motion) and the circle (Sinusoid::motion); for a G-code program, whose feed
 * profile is given by its positions, central differences of the position with the step h =
 * trajectory.dt: r' = (r(t+h) - r(t-h))/2h, r'' = (r(t+h) - 2 r(t) + r(t-h))/h^2, r''' =
 * (r(t+2h) - 2 r(t+h) + 2 r(t-h) - r(t-2h))/2h^3 (second order in h). Shaped, each
 * derivative is shaped as the position is. Refusals as axisReference.
 */
std::function<MotionSample(double)> axisMotion(const TrajectorySettings& trajectory, int axisIndex);

/**
 * The duration of the session's runs: the set duration, one revolution plus the ramp-in for the
 * circle, or for an automatic cubic tf plus the settle (see RunDuration), which simulates both
 * axes up to tf once to estimate it.
 */
RunDuration chooseRunDuration(const Session& session);

/// Designs and simulates one axis over chooseRunDuration(session). Invalid settings give
/// ok = false with the field named (the GUI shows it at the field); an unstable design is ok,
/// with step.stable false.
AxisEvaluation evaluateAxis(const Session& session, int axisIndex);
SessionEvaluation evaluateSession(const Session& session);

/// The Guillemin-Truxal design of an axis, a refusal of wn, kp or the plant named by the session
/// path ("axes[0].gt.wn: 1e+308 rad/s is out of range: wn^4 = inf ... the reference model",
/// "axes[1].gt.plant.k0: plant gain k0 = 1e+308 is out of range with kp = 460.852 ...").
/// Made on the rigid plant, it is closed around the plant with the axis' flexible mode and with
/// its notch after the PI (withLoopElements) when the axis has either.
GtDesign sessionGtDesign(const GtAxisSettings& gt, int axisIndex);

/// The axis' table as every run and analysis sees it: the rigid plant k0 / (s (s^2 + a1 s +
/// a2)) times the flexible mode (FlexibleMode::transferFunction; the rigid plant itself, bit for
/// bit, without one). @throws InvalidInput naming "axes[i].gt.flexible_mode.<field>".
TransferFunction axisPlantTransferFunction(const GtAxisSettings& gt, int axisIndex);
/// The mode's factor alone, and the notch's N(s) (1 without one), refusals named as above
/// ("axes[i].gt.notch.<field>").
TransferFunction flexibleModeTransferFunction(const GtAxisSettings& gt, int axisIndex);
TransferFunction notchTransferFunction(const GtAxisSettings& gt, int axisIndex);

/// A discrete run sampled at @p t (k Ts) as a SimulationResult: r (the first t.size() samples
/// of @p r), y, e = r - y, u (zero-padded when the run has none), and `clipped` where
/// |u| > umax (the discrete loops are simulated without saturation: flagged, not applied).
SimulationResult discreteRun(const std::vector<double>& t, const std::vector<double>& r,
                             const DiscreteRun& run, double umaxVolts, double ts);

/// The z-plane sets of the digital implementation for the pole-zero map: "digital loop" (poles
/// of the digital closed loop) and "design at Ts" (DigitalEvaluation::designPoles); empty when
/// the axis has no digital evaluation.
std::vector<PoleZeroSet> digitalPoleZeroSets(const AxisEvaluation& axis);

/// The digital PI of a Guillemin-Truxal design as the session runs and exports it, with axis
/// @p axisIndex's notch discretized at controller_ts (discreteNotch) when it has one.
/// @throws InvalidInput "controller_ts", "implementation.tracking_time",
///         "axes[i].gt.notch.<field>" (a notch at or above the controller's Nyquist frequency).
DigitalPi sessionDigitalPi(const Session& session, const GtDesign& design, int axisIndex);

/// The sampled-data options of the session (umax and the implementation settings).
/// @throws InvalidInput "implementation.delay_samples", "implementation.encoder_resolution",
///         "implementation.dac_bits", "umax".
SampledDataOptions sessionSampledDataOptions(const Session& session);

} // namespace xyt
