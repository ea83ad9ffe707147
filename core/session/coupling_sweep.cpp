// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/coupling_sweep.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/program_trajectory.h"
#include "core/study/parallel_runs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace xyt {

CouplingSweepGrid defaultCouplingSweepGrid() {
    return {{0.0, 0.03, 0.1, 0.3, 1.0, 3.0}, {0.0, 0.1, 0.3, 1.0, 3.0}};
}

CouplingSweepGrid normalizedCouplingSweepGrid(CouplingSweepGrid grid) {
    for (auto* list : {&grid.kpVoltsPerMm, &grid.kiVoltsPerMmSecond}) {
        const std::string field = list == &grid.kpVoltsPerMm ? "kp" : "ki";
        if (list->empty())
            throw InvalidInput(field, makeDiagnostic("session_needs_one_value"));
        for (double v : *list)
            if (!std::isfinite(v) || v < 0.0)
                throw InvalidInput(field,
                                   makeDiagnostic("session_not_a_finite_gain", {formatNumber(v)}));
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    const std::size_t pairs = grid.kpVoltsPerMm.size() * grid.kiVoltsPerMmSecond.size();
    if (pairs > kMaxCouplingSweepCells)
        throw InvalidInput("grid", makeDiagnostic("session_too_many_pairs",
                                                  {std::to_string(grid.kpVoltsPerMm.size()),
                                                   std::to_string(grid.kiVoltsPerMmSecond.size()),
                                                   std::to_string(pairs),
                                                   std::to_string(kMaxCouplingSweepCells)}));
    return grid;
}

const char* couplingCellStatusName(CouplingCellStatus status) {
    switch (status) {
    case CouplingCellStatus::NotRun:
        return "not run";
    case CouplingCellStatus::Ok:
        return "ok";
    case CouplingCellStatus::Unstable:
        return "unstable";
    case CouplingCellStatus::Failed:
        return "failed";
    }
    return "";
}

std::optional<std::size_t> bestCouplingCell(const std::vector<CouplingSweepCell>& cells,
                                            CouplingBestBasis& basis) {
    const auto pick = [&](CouplingBestBasis among) {
        std::optional<std::size_t> best;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const CouplingSweepCell& c = cells[i];
            if (c.status != CouplingCellStatus::Ok ||
                (c.saturated && among != CouplingBestBasis::Saturating) ||
                (!c.warning.text.empty() && among == CouplingBestBasis::Robust))
                continue;
            if (!best || c.maxAbsMm < cells[*best].maxAbsMm ||
                (c.maxAbsMm == cells[*best].maxAbsMm && c.rmsMm < cells[*best].rmsMm))
                best = i; // strict comparisons: the first in grid order keeps a tie
        }
        return best;
    };
    for (const CouplingBestBasis among :
         {CouplingBestBasis::Robust, CouplingBestBasis::WithinLimit, CouplingBestBasis::Saturating})
        if (const auto best = pick(among)) {
            basis = among;
            return best;
        }
    basis = CouplingBestBasis::Robust;
    return std::nullopt;
}

namespace {

/// Runs one cell: the figures of a contour run with @p coupling, or its refusal.
using CouplingCellRun = std::function<CouplingSweepCell(const CrossCoupling& coupling)>;

bool sweepCellClipped(const SimulationResult& run) {
    return std::find(run.clipped.begin(), run.clipped.end(), true) != run.clipped.end();
}

/// A run's refusal as a cell's status: the stability check's refusal of a line is Unstable.
CouplingSweepCell sweepCellRefused(const CrossCoupling& coupling, const InvalidInput& e) {
    CouplingSweepCell cell;
    cell.coupling = coupling;
    const bool unstable = e.field() == "cross_coupling" &&
                          e.reasonDiagnostic().code == "session_coupled_loop_unstable";
    cell.status = unstable ? CouplingCellStatus::Unstable : CouplingCellStatus::Failed;
    // A traced point that is not finite: the coupled loop diverged along the path.
    cell.message =
        e.field() == "traced"
            ? makeDiagnostic("session_coupled_run_diverged_because", {e.reasonDiagnostic()})
            : makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()});
    return cell;
}

/// Figures that are not finite (a run that diverged without a refusal) fail the cell.
void sweepCellRequireFinite(CouplingSweepCell& cell) {
    if (std::isfinite(cell.maxAbsMm) && std::isfinite(cell.rmsMm))
        return;
    cell.status = CouplingCellStatus::Failed;
    cell.message = makeDiagnostic("session_coupled_run_diverged");
    cell.maxAbsMm = cell.rmsMm = std::numeric_limits<double>::quiet_NaN();
}

/**
 * The sweep over @p grid (normalized) with @p runCell: the independent axes first on the calling
 * thread (their refusal is the sweep's), then the cells in parallel, each into its own slot; a
 * (0, 0) cell takes the independent figures, which are its run.
 */
CouplingSweepResult runCouplingSweep(const CouplingSweepGrid& grid, ContourEstimateKind estimate,
                                     const CouplingCellRun& runCell,
                                     const CouplingSweepOptions& options) {
    CouplingSweepResult out;
    out.grid = normalizedCouplingSweepGrid(grid);
    out.estimate = estimate;
    const std::size_t nKi = out.grid.kiVoltsPerMmSecond.size();
    out.cells.resize(out.grid.kpVoltsPerMm.size() * nKi);
    for (std::size_t i = 0; i < out.cells.size(); ++i) {
        out.cells[i].coupling.kp = out.grid.kpVoltsPerMm[i / nKi];
        out.cells[i].coupling.ki = out.grid.kiVoltsPerMmSecond[i % nKi];
        out.cells[i].coupling.estimate = estimate;
    }
    CrossCoupling off;
    off.estimate = estimate;
    out.independent = runCell(off); // a run that diverged is Failed, and said so

    // The cells to run: every one but (0, 0), which is the independent run itself.
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < out.cells.size(); ++i) {
        if (out.cells[i].coupling.active())
            pending.push_back(i);
        else
            out.cells[i] = out.independent;
    }
    const double total = static_cast<double>(pending.size() + 1);
    bool cancelled = options.progress && !options.progress(1.0 / total);
    if (!cancelled && !pending.empty()) {
        ParallelRunOptions parallel;
        parallel.threads = options.threads;
        if (options.progress)
            parallel.progress = [&](double fraction) {
                return options.progress((1.0 + fraction * static_cast<double>(pending.size())) /
                                        total);
            };
        const ParallelRunOutcome outcome =
            parallelRuns(pending.size(), parallel, [&](std::size_t first, std::size_t count) {
                for (std::size_t k = first; k < first + count; ++k) {
                    CouplingSweepCell& cell = out.cells[pending[k]];
                    cell = runCell(cell.coupling);
                }
            });
        cancelled = outcome.cancelled;
        out.threadsUsed = outcome.threadsUsed;
    }
    out.cancelled = cancelled;
    out.cellsRun = static_cast<std::size_t>(
        std::count_if(out.cells.begin(), out.cells.end(), [](const CouplingSweepCell& c) {
            return c.status != CouplingCellStatus::NotRun;
        }));
    out.best = bestCouplingCell(out.cells, out.bestBasis);
    return out;
}

} // namespace

CouplingSweepResult sweepProgramCoupling(const Session& session, const GcodeProgram& program,
                                         const ContourRunOptions& options,
                                         const CouplingSweepGrid& grid,
                                         const CouplingSweepOptions& sweep,
                                         const FeedProfile* plannedProfile) {
    normalizedCouplingSweepGrid(grid); // refused before anything runs
    ContourRunOptions runOptions = options;
    runOptions.compareIndependentAxes = false; // the sweep runs the independent axes once
    // Planned once for every cell (as runProgramContour would plan it: the same profile).
    std::optional<FeedProfile> planned;
    if (!plannedProfile) {
        FeedProfileOptions profileOptions = runOptions.profile;
        profileOptions.maxSamples = std::min(profileOptions.maxSamples, sampleLimit());
        planned = planFeedProfile(program.path, programFeeds(program, profileOptions.feedScale),
                                  profileOptions);
        plannedProfile = &*planned;
    }
    const CouplingCellRun runCell = [&](const CrossCoupling& coupling) {
        Session cellSession = session;
        cellSession.crossCoupling = coupling;
        CouplingSweepCell cell;
        cell.coupling = coupling;
        ContourRun run;
        try {
            run = runProgramContour(cellSession, program, runOptions, plannedProfile);
        } catch (const InvalidInput& e) {
            // The independent axes' refusal of their settings is the sweep's; a divergence
            // (a traced point that is not finite) is the cell's.
            if (!coupling.active() && e.field() != "traced")
                throw;
            return sweepCellRefused(coupling, e);
        }
        cell.status = CouplingCellStatus::Ok;
        cell.maxAbsMm = run.contour.maxAbs;
        cell.rmsMm = run.contour.rms;
        if (run.couplingStability) {
            cell.spectralRadius = run.couplingStability->worst.spectralRadius;
            cell.diskMargin = run.couplingStability->worst.diskMargin;
            cell.warning = run.couplingStability->warning;
        }
        cell.saturated = sweepCellClipped(run.trace.axes[0]) || sweepCellClipped(run.trace.axes[1]);
        sweepCellRequireFinite(cell);
        return cell;
    };
    return runCouplingSweep(grid, session.crossCoupling.estimate, runCell, sweep);
}

CouplingSweepResult sweepTrajectoryCoupling(const Session& session, const SimulationResult& x,
                                            const SimulationResult& y,
                                            const CouplingSweepGrid& grid,
                                            const CouplingSweepOptions& sweep) {
    normalizedCouplingSweepGrid(grid);
    const CouplingCellRun runCell = [&](const CrossCoupling& coupling) {
        CouplingSweepCell cell;
        cell.coupling = coupling;
        if (!coupling.active()) {
            // runCoupledTrajectory refuses the coupling off: its independent half is that run.
            const IndependentTrajectoryRun run = runIndependentTrajectory(session, x, y);
            cell.status = CouplingCellStatus::Ok;
            cell.maxAbsMm = run.error.maxAbs;
            cell.rmsMm = run.error.rms;
            cell.saturated = sweepCellClipped(run.axes[0]) || sweepCellClipped(run.axes[1]);
            sweepCellRequireFinite(cell);
            return cell;
        }
        Session cellSession = session;
        cellSession.crossCoupling = coupling;
        CoupledTrajectoryRun run;
        try {
            run = runCoupledTrajectory(cellSession, x, y);
        } catch (const InvalidInput& e) {
            return sweepCellRefused(coupling, e);
        }
        cell.status = CouplingCellStatus::Ok;
        cell.maxAbsMm = run.coupledError.maxAbs;
        cell.rmsMm = run.coupledError.rms;
        cell.spectralRadius = run.stability.worst.spectralRadius;
        cell.diskMargin = run.stability.worst.diskMargin;
        cell.warning = run.stability.warning;
        cell.saturated = sweepCellClipped(run.coupled[0]) || sweepCellClipped(run.coupled[1]);
        // The traced path must be finite to mean anything (ContourDeviation does not check it).
        for (const SimulationResult& axis : run.coupled)
            for (double v : axis.y)
                if (!std::isfinite(v)) {
                    cell.maxAbsMm = std::numeric_limits<double>::infinity();
                    break;
                }
        sweepCellRequireFinite(cell);
        return cell;
    };
    return runCouplingSweep(grid, session.crossCoupling.estimate, runCell, sweep);
}

CouplingSweepResult sweepSessionCoupling(const Session& session,
                                         const SessionEvaluation& evaluation,
                                         const CouplingSweepGrid& grid,
                                         const CouplingSweepOptions& sweep) {
    normalizedCouplingSweepGrid(grid);
    for (std::size_t i = 0; i < 2; ++i)
        if (!evaluation.axes[i].ok)
            throw InvalidInput("axes[" + std::to_string(i) + "]",
                               makeDiagnostic("session_cannot_run", {evaluation.axes[i].errorField,
                                                                     evaluation.axes[i].error}));
    if (session.trajectory.kind != TrajectoryKind::Gcode)
        return sweepTrajectoryCoupling(session, evaluation.axes[0].run, evaluation.axes[1].run,
                                       grid, sweep);
    // As runSessionProgram runs the session's own program: its shared profile, its options.
    const std::shared_ptr<const GcodeProgram> program = sessionProgram(session.trajectory.gcode);
    const std::shared_ptr<const FeedProfile> profile = sessionProgramProfile(session.trajectory);
    return sweepProgramCoupling(session, *program, programRunOptions(session.trajectory), grid,
                                sweep, profile.get());
}

bool sameCouplingSweepInputs(const Session& a, const Session& b) {
    const auto runInputs = [](Session s) {
        s.crossCoupling.kp = s.crossCoupling.ki = 0.0;
        s.snapshots.clear();
        return s;
    };
    return runInputs(a) == runInputs(b);
}

} // namespace xyt
