// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/coupled_trajectory.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/design_method_module.h"
#include "core/session/session.h"
#include "core/simulation/contour_error.h"

#include <cmath>
#include <memory>

namespace xyt {

namespace {

/// The contour error of the traced (tx, ty) against the reference (see CoupledTrajectoryRun).
ContourDeviation deviation(const Session& session, const std::vector<double>& t,
                           const std::vector<double>& rx, const std::vector<double>& ry,
                           const std::vector<double>& tx, const std::vector<double>& ty) {
    ContourDeviation out;
    const TrajectorySettings& traj = session.trajectory;
    if (traj.kind == TrajectoryKind::Circle) {
        const Circle circle{traj.radius, traj.omegaRadPerSec, 0.0, 0.0, traj.rampInSeconds};
        try {
            const ContourError e = circleContourError(t, tx, ty, circle);
            return {e.maxAbs, e.rms, e.samples};
        } catch (const InvalidInput&) {
            return out; // the run ends inside the ramp-in
        }
    }
    const double ax = rx.front(), ay = ry.front();
    const double lx = rx.back() - ax, ly = ry.back() - ay;
    const double length = std::hypot(lx, ly);
    if (!(length > 0.0))
        return out;
    double sum = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double d = std::abs((tx[k] - ax) * ly - (ty[k] - ay) * lx) / length;
        out.maxAbs = std::max(out.maxAbs, d);
        sum += d * d;
    }
    out.samples = t.size();
    out.rms = std::sqrt(sum / static_cast<double>(t.size()));
    return out;
}

void requireOnePeriod(const SimulationResult& x, const SimulationResult& y) {
    if (x.t.size() != y.t.size() || std::abs(x.dtSeconds - y.dtSeconds) > 1e-9 * x.dtSeconds)
        throw InvalidInput("cross_coupling",
                           makeDiagnostic("sim_coupling_periods_differ",
                                          {formatNumber(x.dtSeconds), formatNumber(y.dtSeconds)}));
}

} // namespace

IndependentTrajectoryRun runIndependentTrajectory(const Session& session, const SimulationResult& x,
                                                  const SimulationResult& y) {
    requireOnePeriod(x, y);
    IndependentTrajectoryRun out;
    for (int i = 0; i < 2; ++i) {
        const DesignMethodModule& m =
            designMethodModule(session.axes[static_cast<std::size_t>(i)].method);
        const SimulationResult& axis = i == 0 ? x : y;
        out.axes[static_cast<std::size_t>(i)] =
            m.tracePath(session, i, axis.t, axis.r, x.dtSeconds).run;
    }
    out.error = deviation(session, x.t, x.r, y.r, out.axes[0].y, out.axes[1].y);
    return out;
}

CouplingDirections referenceCouplingDirections(const std::vector<double>& x,
                                               const std::vector<double>& y) {
    const std::size_t n = x.size();
    CouplingDirections out;
    out.thetaRad.assign(n, 0.0);
    out.curvaturePerMm.assign(n, 0.0);
    std::vector<bool> moving(n, false);
    double scale = 0.0;
    for (std::size_t k = 0; k < n; ++k)
        scale = std::max({scale, std::abs(x[k]), std::abs(y[k])});
    const double still = 1e-12 * (1.0 + scale); // a step below round-off of the positions
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < n ? k + 1 : k;
        const double dx = x[b] - x[a], dy = y[b] - y[a];
        if (std::hypot(dx, dy) <= still)
            continue;
        moving[k] = true;
        out.thetaRad[k] = std::atan2(dy, dx);
        if (k > 0 && k + 1 < n) {
            // With the step h cancelling: kappa = (x' y'' - y' x'') / |r'|^3 on differences.
            const double ddx = x[k + 1] - 2.0 * x[k] + x[k - 1];
            const double ddy = y[k + 1] - 2.0 * y[k] + y[k - 1];
            const double cx = 0.5 * dx, cy = 0.5 * dy;
            out.curvaturePerMm[k] = (cx * ddy - cy * ddx) / std::pow(std::hypot(cx, cy), 3);
        }
    }
    // Standing samples: the last direction of travel, or the first before any.
    std::size_t first = 0;
    while (first < n && !moving[first])
        ++first;
    if (first == n)
        return out;
    for (std::size_t k = 0; k < n; ++k)
        if (!moving[k])
            out.thetaRad[k] = k < first ? out.thetaRad[first] : out.thetaRad[k - 1];
    return out;
}

CoupledTrajectoryRun runCoupledTrajectory(const Session& session, const SimulationResult& x,
                                          const SimulationResult& y) {
    if (!session.crossCoupling.active())
        throw InvalidInput("cross_coupling", makeDiagnostic("session_coupling_off"));
    validateCrossCoupling(session.crossCoupling, "cross_coupling");
    requireOnePeriod(x, y);
    CoupledTrajectoryRun out;
    const bool circle = session.trajectory.kind == TrajectoryKind::Circle;
    std::vector<CoupledLine> lines;
    if (!circle && !x.r.empty())
        lines.push_back({std::atan2(y.r.back() - y.r.front(), x.r.back() - x.r.front()),
                         makeDiagnostic("session_the_move")});
    out.stability = checkCouplingStability(session, x.dtSeconds, lines, circle);
    out.t = x.t;
    out.referenceX = x.r;
    out.referenceY = y.r;
    const double dt = x.dtSeconds;
    IndependentTrajectoryRun independent = runIndependentTrajectory(session, x, y);
    out.independent = std::move(independent.axes);
    out.independentError = independent.error;
    std::array<std::unique_ptr<SteppedLoop>, 2> loops;
    for (int i = 0; i < 2; ++i) {
        const DesignMethodModule& m =
            designMethodModule(session.axes[static_cast<std::size_t>(i)].method);
        const SimulationResult& axis = i == 0 ? x : y;
        loops[static_cast<std::size_t>(i)] = m.steppedPath(session, i, axis.t, axis.r, dt);
    }
    if (loops[0]->samples() != out.t.size() || loops[1]->samples() != out.t.size())
        throw InvalidInput("cross_coupling", makeDiagnostic("sim_coupling_samples_differ"));
    out.coupling = runCrossCoupled(*loops[0], *loops[1], referenceCouplingDirections(x.r, y.r),
                                   session.crossCoupling);
    for (std::size_t i = 0; i < 2; ++i)
        out.coupled[i] = loops[i]->takeResult();
    out.coupledError = deviation(session, out.t, x.r, y.r, out.coupled[0].y, out.coupled[1].y);
    return out;
}

} // namespace xyt
