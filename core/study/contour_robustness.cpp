// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/contour_robustness.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/simulation/resample.h"
#include "core/study/parallel_runs.h"
#include "core/study/plant_uncertainty.h"
#include "core/study/run_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

/// The contour one pair of runs traced: e per sample of the time base, and its figures.
struct ContourTraceError {
    std::vector<double> e;
    double maxAbs = 0.0, rms = 0.0;
};

/// A run's output on the time base (taken as it is when the run is on that grid already).
std::vector<double> outputOn(const SimulationResult& run, const std::vector<double>& t) {
    if (run.t == t)
        return run.y;
    return resampleLinear(run.t, run.y, t);
}

/// Which samples of the time base a circle judges: those after the ramp-in, for every run. (A
/// path judges the samples nearest a measured segment, which each trace decides for itself.)
std::vector<char> circleMeasured(const ContourGeometry& g) {
    std::vector<char> m(g.t.size());
    for (std::size_t k = 0; k < g.t.size(); ++k)
        m[k] = g.t[k] >= g.circle->rampInSeconds ? 1 : 0;
    return m;
}

/// e of the traced points (x, y) on the time base; figures over the measured samples: for a
/// circle those of @p measured, for a path those the trace itself is nearest a measured segment
/// at (as contourError judges it: a pair whose trace strays near a rapid is not judged on the
/// nominal trace's samples).
ContourTraceError judge(const ContourGeometry& g, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<char>& measured) {
    ContourTraceError out;
    if (!g.circle) {
        ContourErrorResult c = contourError(*g.path, g.t, x, y, g.pathOptions);
        out.e = std::move(c.error);
        const double none = std::numeric_limits<double>::quiet_NaN(); // not judged: not finite
        out.maxAbs = c.measuredSamples > 0 ? c.maxAbs : none;
        out.rms = c.measuredSamples > 0 ? c.rms : none;
        return out;
    }
    out.e.resize(g.t.size());
    const Circle& c = *g.circle;
    for (std::size_t k = 0; k < g.t.size(); ++k) // as circleContourError measures it
        out.e[k] = std::hypot(x[k] - c.centreX, y[k] - c.centreY) - c.radius;
    double sumSquares = 0.0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < g.t.size(); ++k) {
        if (!measured[k])
            continue;
        out.maxAbs = std::max(out.maxAbs, std::abs(out.e[k]));
        sumSquares += out.e[k] * out.e[k];
        ++n;
    }
    out.rms = std::sqrt(sumSquares / static_cast<double>(n));
    return out;
}

std::string prefixed(const std::string& field, const char* axis) {
    return std::string(axis) + "." + field;
}

void validate(const ContourRobustnessProblem& p) {
    for (const auto& [axis, name] : {std::pair{&p.x, "x"}, std::pair{&p.y, "y"}}) {
        try {
            validateRobustnessProblem(*axis);
        } catch (const InvalidInput& e) {
            throw InvalidInput(prefixed(e.field(), name), e.reasonDiagnostic());
        }
    }
    const ContourGeometry& g = p.geometry;
    if (g.circle.has_value() == (g.path != nullptr))
        throw InvalidInput("geometry", makeDiagnostic("study_circle_or_path"));
    if (g.t.empty())
        throw InvalidInput("geometry", makeDiagnostic("study_time_base_empty"));
    for (std::size_t k = 0; k < g.t.size(); ++k)
        if (!std::isfinite(g.t[k]) || (k > 0 && !(g.t[k] > g.t[k - 1])))
            throw InvalidInput(
                "geometry", makeDiagnostic("study_time_base_not_increasing", {std::to_string(k)}));
    if (p.coupling) {
        validateCrossCoupling(p.coupling->gains, "cross_coupling");
        // One grid for both axes: the continuous loop runs on k dt over its reference, the
        // discrete one on k Ts over its samples.
        const auto grid = [](const RobustnessProblem& a) {
            return a.controller ? std::pair{a.dtSeconds, a.reference.size()}
                                : std::pair{a.loop->tsSeconds, a.samples};
        };
        const auto [tx, nx] = grid(p.x);
        const auto [ty, ny] = grid(p.y);
        const CouplingDirections& d = p.coupling->directions;
        if (std::abs(tx - ty) > 1e-9 * tx || nx != ny || d.thetaRad.size() != nx ||
            d.curvaturePerMm.size() != nx || (!d.active.empty() && d.active.size() != nx))
            throw InvalidInput("cross_coupling", makeDiagnostic("study_coupling_one_grid"));
    }
}

/// Runs the pair @p values (x's parameters then y's) into the reused runs.
JointPlantRun runPair(const ContourRobustnessProblem& p, const std::vector<double>& values,
                      SimulationResult& runX, SimulationResult& runY) {
    const auto split = values.begin() + static_cast<std::ptrdiff_t>(p.x.parameters.size());
    const std::vector<double> valuesX(values.begin(), split), valuesY(split, values.end());
    JointPlantRun out;
    out.values = values;
    if (p.coupling) {
        // Both axes in lockstep with the coupling; a diverging pair ends with non-finite
        // samples, which the figures leave out as any unstable run.
        const std::unique_ptr<SteppedLoop> lx = steppedPerturbedRun(p.x, valuesX);
        const std::unique_ptr<SteppedLoop> ly = steppedPerturbedRun(p.y, valuesY);
        runCrossCoupled(*lx, *ly, p.coupling->directions, p.coupling->gains);
        runX = lx->takeResult();
        runY = ly->takeResult();
        out.stable = perturbedLoopStable(p.x, valuesX) && perturbedLoopStable(p.y, valuesY);
        const auto finite = [](const SimulationResult& r) {
            return std::all_of(r.y.begin(), r.y.end(), [](double v) { return std::isfinite(v); });
        };
        out.finite = finite(runX) && finite(runY);
        return out;
    }
    const PlantRun x = runPerturbedPlant(p.x, valuesX, runX);
    const PlantRun y = runPerturbedPlant(p.y, valuesY, runY);
    out.stable = x.stable && y.stable;
    out.finite = x.finite && y.finite;
    return out;
}

} // namespace

ContourRobustnessResult analyzeContourRobustness(const ContourRobustnessProblem& problem,
                                                 const RobustnessOptions& options) {
    validate(problem);
    if (options.envelopePoints < 2 || options.envelopePoints > 100'000)
        throw InvalidInput("envelope_points", makeDiagnostic("study_from_to", {"2", "100000"}));
    const ContourGeometry& g = problem.geometry;

    ContourRobustnessResult result;
    std::vector<UncertainParameter> joint;
    for (const auto& [axis, name] : {std::pair{&problem.x, "x"}, std::pair{&problem.y, "y"}})
        for (const UncertainParameter& q : axis->parameters) {
            joint.push_back(q);
            result.parameterNames.push_back(prefixed(q.name, name));
        }
    // With an identified axis, the pairs are drawn from the block-diagonal covariance of both
    // axes (an axis without one stays at its nominal plant in the draws).
    std::vector<std::vector<double>> pairs;
    if (problem.x.covariance || problem.y.covariance) {
        const Eigen::Index nx = static_cast<Eigen::Index>(problem.x.parameters.size());
        const Eigen::Index ny = static_cast<Eigen::Index>(problem.y.parameters.size());
        Eigen::MatrixXd c = Eigen::MatrixXd::Zero(nx + ny, nx + ny);
        if (problem.x.covariance)
            c.topLeftCorner(nx, nx) = *problem.x.covariance;
        if (problem.y.covariance)
            c.bottomRightCorner(ny, ny) = *problem.y.covariance;
        pairs = drawPlantsNormal(joint, c, options.samples, options.seed);
    } else {
        pairs = drawPlants(joint, options.samples, options.seed);
    }
    const std::size_t randomCount = pairs.size();
    if (options.corners)
        for (auto& c : boxCorners(joint))
            pairs.push_back(std::move(c));

    // The nominal pair decides at which instants the error band is sampled and where the XY
    // band is drawn (the samples it judges); each pair's figures are over its own judged samples.
    std::vector<double> nominalValues;
    for (const UncertainParameter& q : joint)
        nominalValues.push_back(q.nominal);
    SimulationResult nominalX, nominalY;
    result.nominal = runPair(problem, nominalValues, nominalX, nominalY);
    if (!result.nominal.finite)
        throw InvalidInput("nominal", makeDiagnostic("study_nominal_not_finite"));
    const std::vector<double> nx = outputOn(nominalX, g.t);
    const std::vector<double> ny = outputOn(nominalY, g.t);
    std::vector<char> measured;
    if (g.circle) {
        measured = circleMeasured(g);
    } else {
        const ContourErrorResult c = contourError(*g.path, g.t, nx, ny, g.pathOptions);
        measured.assign(c.measured.begin(), c.measured.end());
    }
    std::vector<std::size_t> judged;
    for (std::size_t k = 0; k < measured.size(); ++k)
        if (measured[k])
            judged.push_back(k);
    if (judged.empty())
        throw InvalidInput("geometry", makeDiagnostic(g.circle ? "sim_no_sample_after_ramp_in"
                                                               : "study_no_sample_on_segment"));
    // The envelope's instants: every stride-th judged sample and the last.
    std::vector<std::size_t> idx;
    for (std::size_t j : envelopeIndices(judged.size(), options.envelopePoints))
        idx.push_back(judged[j]);

    const ContourTraceError nominalError = judge(g, nx, ny, measured);
    result.nominal.maxAbsContourError = nominalError.maxAbs;
    result.nominal.rmsContourError = nominalError.rms;
    std::size_t hint = 0;
    for (std::size_t k : idx) {
        if (g.circle) {
            const double dx = nx[k] - g.circle->centreX, dy = ny[k] - g.circle->centreY;
            const double rho = std::hypot(dx, dy);
            const Point2 u = rho > 0.0 ? Point2{dx / rho, dy / rho} : Point2{1.0, 0.0};
            result.normal.push_back(u);
            result.base.push_back({g.circle->centreX + g.circle->radius * u.x,
                                   g.circle->centreY + g.circle->radius * u.y});
        } else {
            const PathProjection q = g.path->nearest({nx[k], ny[k]}, hint);
            hint = q.segment;
            result.base.push_back(q.point);
            result.normal.push_back({-q.tangent.y, q.tangent.x}); // left of travel
        }
    }

    result.runs.resize(pairs.size());
    std::vector<std::vector<double>> errors(pairs.size());
    std::vector<char> computed(pairs.size(), 0);
    ParallelRunOptions parallel;
    parallel.threads = options.threads;
    parallel.progress = options.progress;
    const ParallelRunOutcome outcome =
        parallelRuns(pairs.size(), parallel, [&](std::size_t first, std::size_t count) {
            SimulationResult runX, runY;
            for (std::size_t i = first; i < first + count; ++i) {
                JointPlantRun& r = result.runs[i];
                r = runPair(problem, pairs[i], runX, runY);
                r.corner = i >= randomCount;
                if (r.finite) {
                    const ContourTraceError c =
                        judge(g, outputOn(runX, g.t), outputOn(runY, g.t), measured);
                    r.maxAbsContourError = c.maxAbs;
                    r.rmsContourError = c.rms;
                    r.finite = std::isfinite(c.maxAbs) && std::isfinite(c.rms);
                    for (std::size_t k : idx)
                        errors[i].push_back(c.e[k]);
                }
                computed[i] = 1;
            }
        });
    result.threadsUsed = outcome.threadsUsed;
    if (outcome.cancelled) {
        result.status = RobustnessStatus::Cancelled;
        result.warnings.push_back(makeDiagnostic("study_cancelled_statistics"));
    }

    std::vector<double> maxAbs, rms;
    std::vector<const std::vector<double>*> es;
    double worst = -1.0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (!computed[i])
            continue;
        ++result.computedCount;
        const JointPlantRun& r = result.runs[i];
        if (!r.stable || !r.finite) {
            result.unstable.push_back(i);
            continue;
        }
        maxAbs.push_back(r.maxAbsContourError);
        rms.push_back(r.rmsContourError);
        es.push_back(&errors[i]);
        if (r.maxAbsContourError > worst) {
            worst = r.maxAbsContourError;
            result.worst = i;
        }
    }
    result.maxAbsContourError = distributionOf(maxAbs);
    result.rmsContourError = distributionOf(rms);
    result.error = envelopeOf(g.t, idx, es, nominalError.e);
    if (!result.unstable.empty())
        result.warnings.push_back(
            makeDiagnostic("study_unstable_plant_pairs", {std::to_string(result.unstable.size())}));
    return result;
}

std::vector<double> contourFigureValues(const ContourRobustnessResult& result) {
    std::vector<double> v;
    for (const JointPlantRun& r : result.runs)
        if (r.stable && r.finite && !r.values.empty())
            v.push_back(r.maxAbsContourError);
    return v;
}

} // namespace xyt
