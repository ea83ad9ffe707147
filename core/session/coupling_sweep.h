// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/design/cross_coupling.h"
#include "core/model/diagnostic.h"
#include "core/session/contour_run.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/simulation.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * The gains of Koren's cross-coupled controller (CrossCoupling) tuned by the contour error: the
 * session's contour run once for every (kp, ki) of a small grid, the estimate the session's.
 * What is best depends on the program (on Braga et al.'s 25 mm circle at 90 mm/min, kp 0.1
 * V/mm with ki 1 V/(mm s) divides the independent axes' 0.52 mm by 400; on
 * resources/examples/circle_25mm.nc the same gains give 9.3 mm against 1.8 mm, and ki 0 gives
 * 0.25 mm), hence a sweep of the program itself rather than a rule.
 */

/// The values of kp (V/mm) and of ki (V/(mm s)) the sweep pairs, each list ascending.
struct CouplingSweepGrid {
    std::vector<double> kpVoltsPerMm;
    std::vector<double> kiVoltsPerMmSecond;
    friend bool operator==(const CouplingSweepGrid&, const CouplingSweepGrid&) = default;
};

/// At most this many (kp, ki) pairs: 400 runs of Braga et al.'s circle at dt 1 ms (100 000
/// samples, each run with its ISO 230-4 runs both ways) take about 80 s on two cores.
inline constexpr std::size_t kMaxCouplingSweepCells = 400;

/**
 * The grid a user gets without typing: kp in {0, 0.03, 0.1, 0.3, 1, 3} V/mm and ki in
 * {0, 0.1, 0.3, 1, 3} V/(mm s), 30 pairs about half a decade apart, from off to past the edges
 * of what helps. On the default session (Braga et al.'s PI axes, +-2.5 V) kp 0.03 already
 * halves the contour error of the paper's 25 mm circle; from kp 0.3 the axes reach their limit
 * on most example programs (resources/examples), and at kp 3 the coupled loop is unstable on the
 * straight lines of the square and the star; on the paper circle the error falls with ki up to
 * 3, past which (ki 10) the axes saturate (kp up to 0.3) or the loop frozen on the arc turns
 * unstable (kp 1). The best cells of the examples and of the paper circle all lie inside the
 * grid (kp 0 to 1, ki 0 to 3; xytune-cli contour --gcode FILE --ccc-sweep), the refused and
 * saturating cells around them showing where the edges are.
 */
CouplingSweepGrid defaultCouplingSweepGrid();

/**
 * The grid sorted ascending with repeated values dropped.
 * @throws InvalidInput "kp" or "ki" for an empty list or a value that is not finite or is
 *         negative; "grid" for more than kMaxCouplingSweepCells pairs.
 */
CouplingSweepGrid normalizedCouplingSweepGrid(CouplingSweepGrid grid);

/// What became of one cell of the sweep.
enum class CouplingCellStatus {
    NotRun,   ///< the sweep was cancelled before it
    Ok,       ///< the contour run ran: its figures are set
    Unstable, ///< refused: the coupled loop is unstable on a line of the path (message says which)
    Failed,   ///< another refusal of the run, or a run that diverged (message)
};

/// "not run", "ok", "unstable", "failed".
const char* couplingCellStatusName(CouplingCellStatus status);

/// One (kp, ki) of the sweep and its contour run.
struct CouplingSweepCell {
    CrossCoupling coupling; ///< the cell's gains with the session's estimate
    CouplingCellStatus status = CouplingCellStatus::NotRun;
    Diagnostic message; ///< Unstable and Failed: the run's refusal ("cross_coupling: ...")
    /// Ok: the contour error along the path (mm), G0 rapids left out (ContourErrorResult, or
    /// ContourDeviation for a session trajectory that is not a program).
    double maxAbsMm = std::numeric_limits<double>::quiet_NaN();
    double rmsMm = std::numeric_limits<double>::quiet_NaN();
    /// Ok with the coupling on: the coupled loop of the path's least stable line (frozen
    /// direction on arcs), CouplingStability::worst; NaN with the coupling off (no loop).
    double spectralRadius = std::numeric_limits<double>::quiet_NaN();
    double diskMargin = std::numeric_limits<double>::quiet_NaN();
    /// Ok: the coupled loop frozen on the arcs is unstable at some direction
    /// (CouplingStability::warning), or "".
    Diagnostic warning;
    /// Ok: an axis' command reached the actuator limit (a clipped sample of either axis' run).
    bool saturated = false;
};

/// Among which cells the best was chosen (kBestCouplingRule).
enum class CouplingBestBasis {
    Robust,      ///< inside the actuator limit, the coupled loop stable at every direction
    WithinLimit, ///< inside the limit, but every such cell's loop is unstable frozen on an arc
    Saturating,  ///< every cell that ran saturates
};

/// How the sweep runs: its threads and its progress.
struct CouplingSweepOptions {
    int threads = 0; ///< 0: the hardware's (parallelRuns)
    /// Called with the fraction of runs done (the independent axes' first); false cancels: the
    /// runs under way finish, the others stay NotRun and the result says cancelled.
    std::function<bool(double)> progress;
};

/**
 * The sweep's result. Every cell is computed by the same code into its own slot whatever
 * thread takes it: identical bit for bit for any thread count.
 *
 * The best cell (kBestCouplingRule): the smallest max contour error among the Ok cells whose
 * axes never reach their limit and whose coupled loop is stable at every direction it was
 * checked at (no warning: frozen on the arcs, CouplingStability::warning); failing any, among
 * the Ok cells inside the limit; failing any, among all Ok cells (bestBasis says which). Ties
 * go to the smaller RMS, then to the first in grid order. None when no cell is Ok.
 */
struct CouplingSweepResult {
    CouplingSweepGrid grid;
    ContourEstimateKind estimate = ContourEstimateKind::Circular;
    /// cells[i * grid.kiVoltsPerMmSecond.size() + j]: kp i and ki j (cellIndex).
    std::vector<CouplingSweepCell> cells;
    /// The same path with the coupling off (the (0, 0) run): the figure every cell is
    /// compared with. A (0, 0) cell of the grid holds the same figures.
    CouplingSweepCell independent;
    std::optional<std::size_t> best;
    CouplingBestBasis bestBasis = CouplingBestBasis::Robust;
    bool cancelled = false;
    std::size_t cellsRun = 0; ///< cells not NotRun
    int threadsUsed = 0;

    std::size_t cellIndex(std::size_t kpIndex, std::size_t kiIndex) const {
        return kpIndex * grid.kiVoltsPerMmSecond.size() + kiIndex;
    }
    const CouplingSweepCell& cell(std::size_t kpIndex, std::size_t kiIndex) const {
        return cells.at(cellIndex(kpIndex, kiIndex));
    }
};

/// The rule that picks CouplingSweepResult::best, in words (what a report or a view states).
inline constexpr const char* kBestCouplingRule =
    "the smallest max contour error among the gains whose runs keep both axes inside the "
    "actuator limit with the coupled loop stable at every direction of the path; failing "
    "those, inside the limit; failing those, among all that ran; ties: the smaller RMS error";

/// The index of the best cell of @p cells by kBestCouplingRule (none when no cell is Ok), and
/// in @p basis among which cells it was found.
std::optional<std::size_t> bestCouplingCell(const std::vector<CouplingSweepCell>& cells,
                                            CouplingBestBasis& basis);

/**
 * The sweep of @p program's contour run (runProgramContour with @p options, its independent
 * axes' comparison left out) with @p session's axes and estimate, once per pair of @p grid
 * (normalized first). @p plannedProfile: the program's profile planned with options.profile, as
 * runProgramContour takes it (planned once here otherwise).
 * @throws InvalidInput "kp", "ki", "grid" (normalizedCouplingSweepGrid); what runProgramContour
 *         throws for the run with the coupling off (the session's axes or the options).
 */
CouplingSweepResult sweepProgramCoupling(const Session& session, const GcodeProgram& program,
                                         const ContourRunOptions& options,
                                         const CouplingSweepGrid& grid,
                                         const CouplingSweepOptions& sweep = {},
                                         const FeedProfile* plannedProfile = nullptr);

/**
 * The sweep of a session trajectory that is not a program (the point-to-point move or the
 * circle): runCoupledTrajectory on the references of the axes' evaluated runs @p x and @p y for
 * each pair with the coupling on, and their independent axes (runIndependentTrajectory) for the
 * coupling off.
 * @throws InvalidInput as normalizedCouplingSweepGrid; as runIndependentTrajectory
 *         ("cross_coupling" when the axes run at different periods).
 */
CouplingSweepResult sweepTrajectoryCoupling(const Session& session, const SimulationResult& x,
                                            const SimulationResult& y,
                                            const CouplingSweepGrid& grid,
                                            const CouplingSweepOptions& sweep = {});

/**
 * The sweep of @p session's own contour as its evaluation runs it: a G-code trajectory's program
 * (sessionProgram, programRunOptions, its shared profile: runSessionProgram's run), else the
 * move or circle on the axes' runs of @p evaluation (evaluateSession(session)).
 * @throws InvalidInput as the two above, naming session paths ("trajectory.gcode.program",
 *         "trajectory.dt"); "axes[i]" with the axis' own refusal when an axis of @p evaluation
 *         is not ok.
 */
CouplingSweepResult sweepSessionCoupling(const Session& session,
                                         const SessionEvaluation& evaluation,
                                         const CouplingSweepGrid& grid,
                                         const CouplingSweepOptions& sweep = {});

/**
 * True when a sweep of @p a describes @p b: they differ in nothing but the coupling's two gains
 * (the sweep's own variables) and the stored snapshots. (The specification stays: its
 * in-position window sets the length of an automatic point-to-point run.)
 */
bool sameCouplingSweepInputs(const Session& a, const Session& b);

} // namespace xyt
