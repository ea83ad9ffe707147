// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/diagnostic.h"
#include "core/model/flexible_mode.h"
#include "core/model/table_friction.h"
#include "core/model/transfer_function.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/metrics.h"
#include "core/simulation/move_settle.h"
#include "core/study/plant_uncertainty.h"
#include "core/study/run_statistics.h"
#include "core/study/specification.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * One axis as the robustness analysis perturbs it: the nominal controller stays as
 * designed while the plant it drives takes the perturbed parameters.
 *  - Continuous (Guillemin-Truxal): `controller` (the PI) drives k0 / (s^3 + a1 s^2 + a2 s) with
 *    the parameters "k0", "a1", "a2", simulated as simulateLoop does (saturation at umax) at dt.
 *  - Discrete (pole placement): the RST law of `loop` (F, G, Kf unchanged) drives the ARX model
 *    A = 1 + a1 z^-1 + ..., B = b1 z^-1 + ... with the perturbed coefficients, with the
 *    feedforward `zpetc` built from the NOMINAL model when zpetcEnabled (Patrick, Ishak and Adnan's
 * ZPETC sensitivity to mismatch); also the loop alone, for the RMSE without feedforward.
 */
struct RobustnessProblem {
    std::vector<UncertainParameter> parameters;
    /// A continuous axis' flexible mode, in series with each drawn plant; its frequency and
    /// damping are drawn as "mode_frequency" and "mode_damping" when parameters name them.
    FlexibleMode flexibleMode;
    /// The parameters' covariance (their order) of an identified model: the random plants are
    /// then drawn from N(nominal, covariance) (drawPlantsNormal) instead of the uniform ranges,
    /// which only give the box whose corners are searched (identifiedUncertainty sets them to
    /// +-3 standard deviations).
    std::optional<Eigen::MatrixXd> covariance;
    // Continuous axes
    std::optional<TransferFunction> controller;
    double modelUnitsPerPositionUnit = 1.0;
    double dtSeconds = 0.01;
    /// The controller's command feedforward in volts at the reference's samples (empty: none):
    /// fixed numbers on a fixed trajectory, so the same for every plant drawn.
    std::vector<double> feedforwardVolts;
    /**
     * Continuous axes: the table's friction, backlash and deadband (nominal), run as the
     * nonlinear plant of core/simulation/table_dynamics.h (discrete axes: its Coulomb level and
     * deadband as a dead zone of the ARX plant's input, simulateFeedbackLoop). The parameters
     * "coulomb", "static", "viscous" and "backlash", when listed, vary its levels; the plant's
     * poles must stay real over the box (validateRobustnessProblem). Costs the Runge-Kutta
     * integration per plant: a few times the linear run (xytune-bench robustness_friction).
     */
    std::optional<TableFriction> table;
    /// The table's position at rest at t = 0 (trajectory units; a G-code program starts there).
    double initialOutput = 0.0;
    // Discrete axes
    std::optional<PolePlacementDesign> loop;
    std::optional<ZpetcDesign> zpetc;
    bool zpetcEnabled = false;
    /// r(k dt) for the continuous loop; r(k Ts) for k = 0 .. samples - 1 + the ZPETC's preview
    /// for the discrete one (trajectory units).
    std::vector<double> reference;
    std::size_t samples = 0; ///< samples of each run (the reference's size for continuous axes)
    Specification spec;      ///< its umaxVolts is the actuator limit
    std::optional<PointToPointMove> move;
};

struct RobustnessOptions {
    int samples = 200; ///< random plants
    std::uint64_t seed = 1;
    bool corners = true;      ///< also the 2^p corners of the parameter box
    int threads = 0;          ///< 0: all cores; the result does not depend on it, bit for bit
    int envelopePoints = 400; ///< time points of the envelopes (every k-th sample, the last kept)
    /// As SweepOptions::progress: on the calling thread, fraction in [0, 1]; false cancels.
    std::function<bool(double fraction)> progress;
};

/// One plant of the analysis and how the unchanged controller does on it.
struct PlantRun {
    std::vector<double> values; ///< the parameters, in RobustnessProblem::parameters order
    bool corner = false;        ///< a corner of the box (else a random draw or the nominal)
    bool stable = false;        ///< the closed loop with the nominal controller
    bool finite = false;        ///< every sample of the run is finite (else it diverged)
    TrackingMetrics tracking;
    /// Axes with a feedforward (ZPETC, a PID's command feedforward): the RMSE of the feedback
    /// loop alone on this plant (NaN otherwise).
    double rmseWithoutFf = std::numeric_limits<double>::quiet_NaN();
    StepCharacteristics step;
    std::optional<MoveSettleMetrics> move;
    std::optional<LoopMarginFigures> margins;
    SpecificationCheck check;
    bool meetsSpec = false; ///< stable && finite && check.allPassed()
};

enum class RobustnessStatus { Completed, Cancelled };

struct RobustnessResult {
    RobustnessStatus status = RobustnessStatus::Completed;
    std::vector<std::string> parameterNames;
    PlantRun nominal;
    std::vector<PlantRun> runs; ///< the random plants, then the corners
    int computedCount = 0;
    SignalEnvelope output, error, command;
    Distribution rmse, maxAbsError, maxAbsU, rmseWithoutFf;
    /// The loop's margins over the stable runs where they are finite (no crossing: +infinity,
    /// left out of these).
    Distribution phaseMarginDeg, gainMarginDb;
    /// Over every computed run: an unstable or diverged plant counts as failing.
    double fractionMeetingSpec = 0.0;
    /// Runs whose closed loop is unstable or whose run diverged: listed, never in the statistics.
    std::vector<std::size_t> unstable;
    /// The stable run of largest RMSE (nullopt when none is stable).
    std::optional<std::size_t> worst;
    int threadsUsed = 0;
    std::vector<Diagnostic> warnings;
};

/**
 * Monte Carlo and corner analysis of one axis: options.samples random plants from the seed and
 * (options.corners) the box corners, each simulated with the unchanged controller on all cores;
 * figures as the session's evaluation computes them (tracking, step of the perturbed closed
 * loop, margins of the perturbed loop, move and settle) judged by the specification.
 * @throws InvalidInput "samples", "envelope_points", "threads", "problem" (neither or both
 *         loop kinds, a reference shorter than the run), "corners", and from the parameters.
 */
RobustnessResult analyzeRobustness(const RobustnessProblem& problem,
                                   const RobustnessOptions& options = {});

/**
 * Checks @p problem as analyzeRobustness does.
 * @throws InvalidInput "problem" (neither or both loop kinds, a reference shorter than the run,
 *         a continuous plant without k0, a1, a2), "range.<name>", and from the specification.
 */
void validateRobustnessProblem(const RobustnessProblem& problem);

/**
 * One plant of the analysis: @p values (in problem.parameters order) simulated with the nominal
 * controller into @p run (reused storage; the continuous loop on k dt, the discrete one on k Ts)
 * and judged as analyzeRobustness judges each run. The problem must be valid.
 */
PlantRun runPerturbedPlant(const RobustnessProblem& problem, const std::vector<double>& values,
                           SimulationResult& run);

/// Whether the nominal controller's closed loop on the plant @p values is stable (as
/// runPerturbedPlant's PlantRun::stable).
bool perturbedLoopStable(const RobustnessProblem& problem, const std::vector<double>& values);

/**
 * runPerturbedPlant's run on the plant @p values (with the feedforward, when the problem has
 * one) as a loop advanced sample by sample (core/simulation/loop_stepper.h), for the
 * cross-coupled contour of two axes (analyzeContourRobustness). The problem must be valid.
 */
std::unique_ptr<SteppedLoop> steppedPerturbedRun(const RobustnessProblem& problem,
                                                 const std::vector<double>& values);

/// Which figure of the runs a histogram shows.
enum class RobustnessFigure { Rmse, MaxAbsError, MaxAbsU };

/// The figure of every stable, finite run (the runs the statistics cover), in run order.
std::vector<double> figureValues(const RobustnessResult& result, RobustnessFigure figure);

/// Equal-width bins over [min, max] of @p values: edges (bins + 1) and counts (bins). All values
/// equal: one bin of width 1e-9 |v| (or 1e-9) centred on them. No values: no bins.
/// @throws InvalidInput "bins" unless 1 <= bins <= 10000.
struct Histogram {
    std::vector<double> edges;
    std::vector<int> counts;
};
Histogram histogram(const std::vector<double>& values, int bins);

/// One point of the ZPETC sensitivity curve: the runs at `scale` times the problem's ranges.
struct ZpetcSensitivityPoint {
    double scale = 0.0;
    Distribution rmseWithFf, rmseWithoutFf;
    /// 100 (1 - median RMSE with ZPETC / median RMSE without), over the stable runs.
    double medianImprovementPct = 0.0;
    int unstable = 0;
};

/**
 * Where the feedforward stops paying off: analyzeRobustness of a discrete axis with
 * ZPETC at each scale of its ranges (same seed for all, so the plants of a larger scale lie
 * farther out along the same directions), RMSE with and without the feedforward.
 * @throws InvalidInput "problem" unless the axis is discrete with ZPETC enabled, "scales" when
 *         empty or a scale makes a range >= 100 %, and as analyzeRobustness.
 */
std::vector<ZpetcSensitivityPoint> zpetcSensitivity(const RobustnessProblem& problem,
                                                    const std::vector<double>& scales,
                                                    const RobustnessOptions& options = {});

} // namespace xyt
