// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/robustness.h"

#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/simulation.h"
#include "core/simulation/zpetc_step.h"
#include "core/study/parallel_runs.h"
#include "core/study/run_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

/// The value of parameter @p name among @p values, or @p fallback when it is not uncertain.
double valueOf(const RobustnessProblem& problem, const std::vector<double>& values,
               const std::string& name, double fallback) {
    for (std::size_t i = 0; i < problem.parameters.size(); ++i)
        if (problem.parameters[i].name == name)
            return values[i];
    return fallback;
}

/// The ARX polynomial with coefficients 1.. replaced by the parameters named prefix + index.
Polynomial perturbedArx(const RobustnessProblem& problem, const std::vector<double>& values,
                        const Polynomial& nominal, const std::string& prefix) {
    std::vector<double> c = nominal.ascending();
    for (std::size_t i = 1; i < c.size(); ++i)
        c[i] = valueOf(problem, values, prefix + std::to_string(i), c[i]);
    return Polynomial::fromAscending(c, prefix);
}

/// The signals of one run decimated onto the envelope's time points.
struct Decimated {
    std::vector<double> y, e, u;
};

/// A continuous axis' loop on the plant drawn: the plant, and the simulation's options with
/// this draw's table (the compensation keeps the nominal friction levels).
struct PerturbedContinuous {
    TransferFunction plant;
    LoopSimulationOptions options;
    std::optional<TableFriction> table;
    PerturbedContinuous(const PerturbedContinuous&) = delete;
    PerturbedContinuous(const RobustnessProblem& problem, const std::vector<double>& values) {
        ThirdOrderPlant p;
        p.k0 = valueOf(problem, values, "k0", kNaN);
        p.a1 = valueOf(problem, values, "a1", kNaN);
        p.a2 = valueOf(problem, values, "a2", kNaN);
        plant = p.transferFunction();
        if (problem.flexibleMode.present()) {
            FlexibleMode m = problem.flexibleMode;
            m.frequencyHz = valueOf(problem, values, "mode_frequency", m.frequencyHz);
            // A drawn damping stays a damping ratio (a relative range of +-100 % reaches 0).
            m.dampingRatio =
                std::clamp(valueOf(problem, values, "mode_damping", m.dampingRatio), 0.0, 0.999);
            if (m.twoMass())
                m.antiResonanceHz = std::min(m.antiResonanceHz, 0.999 * m.frequencyHz);
            plant = series(plant, m.transferFunction());
        }
        options.dtSeconds = problem.dtSeconds;
        options.umaxVolts = problem.spec.umaxVolts;
        options.modelUnitsPerPositionUnit = problem.modelUnitsPerPositionUnit;
        options.initialOutput = problem.initialOutput;
        table = problem.table;
        if (table) {
            table->coulombVolts = valueOf(problem, values, "coulomb", table->coulombVolts);
            table->viscousVoltsPerMmPerS =
                valueOf(problem, values, "viscous", table->viscousVoltsPerMmPerS);
            table->backlashMm = valueOf(problem, values, "backlash", table->backlashMm);
            if (table->staticVolts > 0.0)
                table->staticVolts = std::max(
                    valueOf(problem, values, "static", table->staticVolts), table->coulombVolts);
            options.table = &*table;
        }
    }
};

/// A discrete axis' RST loop on the ARX plant drawn.
PolePlacementDesign perturbedRst(const RobustnessProblem& problem,
                                 const std::vector<double>& values) {
    PolePlacementDesign loop = *problem.loop;
    loop.a = perturbedArx(problem, values, problem.loop->a, "a");
    loop.b = perturbedArx(problem, values, problem.loop->b, "b");
    loop.closedLoopNum = loop.kf * loop.b;
    loop.closedLoopDen = loop.a * loop.f + loop.b * loop.g;
    return loop;
}

/// An ARX axis' table: its Coulomb level and amplifier deadband as an input dead zone.
double rstDeadzone(const RobustnessProblem& problem) {
    return problem.table ? problem.table->coulombVolts + problem.table->amplifierDeadbandVolts
                         : 0.0;
}

} // namespace

bool perturbedLoopStable(const RobustnessProblem& problem, const std::vector<double>& values) {
    if (problem.controller) {
        const PerturbedContinuous loop(problem, values);
        return feedback(series(*problem.controller, loop.plant)).isStable();
    }
    return perturbedRst(problem, values).closedLoop().isStable();
}

std::unique_ptr<SteppedLoop> steppedPerturbedRun(const RobustnessProblem& problem,
                                                 const std::vector<double>& values) {
    if (problem.controller) {
        PerturbedContinuous loop(problem, values);
        if (!problem.feedforwardVolts.empty())
            loop.options.feedforwardVolts = &problem.feedforwardVolts;
        return steppedLoop(loop.plant, *problem.controller, problem.reference, loop.options);
    }
    const PolePlacementDesign loop = perturbedRst(problem, values);
    return steppedRstRun(loop, problem.zpetcEnabled ? &*problem.zpetc : nullptr, problem.reference,
                         problem.samples, problem.spec.umaxVolts, rstDeadzone(problem));
}

PlantRun runPerturbedPlant(const RobustnessProblem& problem, const std::vector<double>& values,
                           SimulationResult& run) {
    PlantRun out;
    out.values = values;
    std::optional<LoopMarginFigures> margins;
    if (problem.controller) {
        PerturbedContinuous perturbed(problem, values);
        const TransferFunction& g = perturbed.plant;
        const TransferFunction open = series(*problem.controller, g);
        const TransferFunction closed = feedback(open);
        out.stable = closed.isStable();
        LoopSimulationOptions& o = perturbed.options;
        if (!problem.feedforwardVolts.empty()) {
            // The feedback alone on this plant first: what the feedforward still gains here.
            simulateLoopInto(g, *problem.controller, problem.reference, o, run);
            out.rmseWithoutFf = rootMeanSquare(run.e);
            o.feedforwardVolts = &problem.feedforwardVolts;
        }
        simulateLoopInto(g, *problem.controller, problem.reference, o, run);
        if (out.stable)
            out.step = stepCharacteristics(closed);
        const StabilityMargins m = stabilityMargins(open);
        margins = LoopMarginFigures{m.phaseMarginDeg, m.gainMarginDb};
    } else {
        const PolePlacementDesign loop = perturbedRst(problem, values);
        out.stable = loop.closedLoop().isStable();
        const std::size_t n = problem.samples;
        const double deadzone = rstDeadzone(problem);
        const std::vector<double> rLoop(problem.reference.begin(),
                                        problem.reference.begin() + static_cast<std::ptrdiff_t>(n));
        const double umax = problem.spec.umaxVolts;
        if (problem.zpetcEnabled) {
            discreteResult(problem.reference,
                           simulateFeedbackLoop(loop, rLoop, StartCondition::AtReference, deadzone),
                           loop.tsSeconds, umax, n, run);
            out.rmseWithoutFf = rootMeanSquare(run.e);
            discreteResult(problem.reference,
                           simulateZpetcLoop(loop, *problem.zpetc, problem.reference, n,
                                             StartCondition::AtReference, deadzone),
                           loop.tsSeconds, umax, n, run);
        } else {
            discreteResult(problem.reference,
                           simulateFeedbackLoop(loop, rLoop, StartCondition::AtReference, deadzone),
                           loop.tsSeconds, umax, n, run);
        }
        if (out.stable)
            out.step = problem.zpetcEnabled ? zpetcStepCharacteristics(loop, *problem.zpetc)
                                            : loopStepCharacteristics(loop);
        const StabilityMargins m = stabilityMargins(rstLoopTransferFunctions(loop).openLoop);
        margins = LoopMarginFigures{m.phaseMarginDeg, m.gainMarginDb};
    }
    out.tracking = trackingMetrics(run);
    out.finite = !out.tracking.diverged && std::isfinite(out.tracking.rmse) &&
                 std::isfinite(out.tracking.itae);
    if (problem.move && out.finite)
        out.move = moveSettleMetrics(run, *problem.move, problem.spec.inPositionWindowMm);
    out.margins = margins;
    out.check = checkSpecification(problem.spec, out.tracking, out.step, out.move, out.margins);
    out.meetsSpec = out.stable && out.finite && out.check.allPassed();
    return out;
}

namespace {

void validateOptions(const RobustnessOptions& options) {
    if (options.samples < 0 || options.samples > 1'000'000)
        throw InvalidInput("samples", makeDiagnostic("study_from_to", {"0", "1000000"}));
    if (options.envelopePoints < 2 || options.envelopePoints > 100'000)
        throw InvalidInput("envelope_points", makeDiagnostic("study_from_to", {"2", "100000"}));
}

} // namespace

void validateRobustnessProblem(const RobustnessProblem& problem) {
    if (problem.controller.has_value() == problem.loop.has_value())
        throw InvalidInput("problem", makeDiagnostic("study_controller_or_loop"));
    if (problem.loop && problem.zpetcEnabled && !problem.zpetc)
        throw InvalidInput("problem", makeDiagnostic("study_zpetc_without_design"));
    const std::size_t preview = problem.loop && problem.zpetcEnabled
                                    ? static_cast<std::size_t>(problem.zpetc->previewSteps)
                                    : 0;
    if (problem.samples < 2 || problem.reference.size() < problem.samples + preview)
        throw InvalidInput("problem", makeDiagnostic("study_reference_too_short"));
    if (problem.controller)
        for (const char* name : {"k0", "a1", "a2"})
            if (std::none_of(problem.parameters.begin(), problem.parameters.end(),
                             [&](const UncertainParameter& p) { return p.name == name; }))
                throw InvalidInput("problem",
                                   makeDiagnostic("study_plant_needs_parameter", {name}));
    if (problem.controller && problem.reference.size() != problem.samples)
        throw InvalidInput("problem", makeDiagnostic("study_continuous_run_samples"));
    problem.spec.validate();
    for (const UncertainParameter& p : problem.parameters)
        if (!std::isfinite(p.relative) || p.relative < 0.0 || p.relative >= 1.0)
            throw InvalidInput("range." + p.name, makeDiagnostic("study_range_percent"));
    if (problem.controller && problem.table && problem.table->active()) {
        // The table splits the plant at the real poles of s^2 + a1 s + a2: the box's worst
        // corner (a1 at its least, a2 at its most) must keep a1^2 >= 4 a2.
        const auto bound = [&](const char* name, double sign) {
            for (const UncertainParameter& p : problem.parameters)
                if (p.name == name)
                    return p.nominal * (1.0 + sign * p.relative);
            return 0.0;
        };
        const double a1 = bound("a1", -1.0), a2 = bound("a2", 1.0);
        if (a1 * a1 < 4.0 * a2)
            throw InvalidInput("range.a2", makeDiagnostic("study_friction_real_poles"));
    }
}

RobustnessResult analyzeRobustness(const RobustnessProblem& problem,
                                   const RobustnessOptions& options) {
    validateRobustnessProblem(problem);
    validateOptions(options);
    RobustnessResult result;
    for (const UncertainParameter& p : problem.parameters)
        result.parameterNames.push_back(p.name);
    std::vector<std::vector<double>> plants =
        problem.covariance ? drawPlantsNormal(problem.parameters, *problem.covariance,
                                              options.samples, options.seed)
                           : drawPlants(problem.parameters, options.samples, options.seed);
    const std::size_t randomCount = plants.size();
    if (options.corners)
        for (auto& c : boxCorners(problem.parameters))
            plants.push_back(std::move(c));

    std::vector<double> nominalValues;
    for (const UncertainParameter& p : problem.parameters)
        nominalValues.push_back(p.nominal);
    SimulationResult nominalRun;
    result.nominal = runPerturbedPlant(problem, nominalValues, nominalRun);
    const std::vector<std::size_t> idx = envelopeIndices(problem.samples, options.envelopePoints);

    result.runs.resize(plants.size());
    std::vector<Decimated> signals(plants.size());
    std::vector<char> computed(plants.size(), 0);
    ParallelRunOptions parallel;
    parallel.threads = options.threads;
    parallel.progress = options.progress;
    const ParallelRunOutcome outcome =
        parallelRuns(plants.size(), parallel, [&](std::size_t first, std::size_t count) {
            SimulationResult run; // one per chunk; a chunk is one plant
            for (std::size_t i = first; i < first + count; ++i) {
                result.runs[i] = runPerturbedPlant(problem, plants[i], run);
                result.runs[i].corner = i >= randomCount;
                Decimated& d = signals[i];
                for (std::size_t k : idx) {
                    d.y.push_back(run.y[k]);
                    d.e.push_back(run.e[k]);
                    d.u.push_back(run.u[k]);
                }
                computed[i] = 1;
            }
        });
    result.threadsUsed = outcome.threadsUsed;
    if (outcome.cancelled) {
        result.status = RobustnessStatus::Cancelled;
        result.warnings.push_back(makeDiagnostic("study_cancelled_statistics"));
    }

    std::vector<double> rmse, maxE, maxU, rmseNoFf, phase, gain;
    std::vector<const std::vector<double>*> ys, es, us;
    int meeting = 0;
    double worstRmse = -1.0;
    for (std::size_t i = 0; i < plants.size(); ++i) {
        if (!computed[i])
            continue;
        ++result.computedCount;
        const PlantRun& r = result.runs[i];
        meeting += r.meetsSpec ? 1 : 0;
        if (!r.stable || !r.finite) {
            result.unstable.push_back(i);
            continue;
        }
        rmse.push_back(r.tracking.rmse);
        maxE.push_back(r.tracking.maxAbsError);
        maxU.push_back(r.tracking.maxAbsU);
        if (std::isfinite(r.rmseWithoutFf))
            rmseNoFf.push_back(r.rmseWithoutFf);
        if (r.margins && std::isfinite(r.margins->phaseMarginDeg))
            phase.push_back(r.margins->phaseMarginDeg);
        if (r.margins && std::isfinite(r.margins->gainMarginDb))
            gain.push_back(r.margins->gainMarginDb);
        ys.push_back(&signals[i].y);
        es.push_back(&signals[i].e);
        us.push_back(&signals[i].u);
        if (r.tracking.rmse > worstRmse) {
            worstRmse = r.tracking.rmse;
            result.worst = i;
        }
    }
    result.fractionMeetingSpec =
        result.computedCount > 0
            ? static_cast<double>(meeting) / static_cast<double>(result.computedCount)
            : 0.0;
    result.rmse = distributionOf(rmse);
    result.maxAbsError = distributionOf(maxE);
    result.maxAbsU = distributionOf(maxU);
    result.rmseWithoutFf = distributionOf(rmseNoFf);
    result.phaseMarginDeg = distributionOf(phase);
    result.gainMarginDb = distributionOf(gain);
    result.output = envelopeOf(nominalRun.t, idx, ys, nominalRun.y);
    result.error = envelopeOf(nominalRun.t, idx, es, nominalRun.e);
    result.command = envelopeOf(nominalRun.t, idx, us, nominalRun.u);
    if (!result.unstable.empty())
        result.warnings.push_back(
            makeDiagnostic("study_unstable_plants", {std::to_string(result.unstable.size())}));
    return result;
}

std::vector<double> figureValues(const RobustnessResult& result, RobustnessFigure figure) {
    std::vector<double> v;
    for (const PlantRun& r : result.runs) {
        if (!r.stable || !r.finite || r.values.empty())
            continue; // (a run of a cancelled analysis that was never computed has no values)
        v.push_back(figure == RobustnessFigure::Rmse          ? r.tracking.rmse
                    : figure == RobustnessFigure::MaxAbsError ? r.tracking.maxAbsError
                                                              : r.tracking.maxAbsU);
    }
    return v;
}

Histogram histogram(const std::vector<double>& values, int bins) {
    if (bins < 1 || bins > 10000)
        throw InvalidInput("bins", makeDiagnostic("study_from_to", {"1", "10000"}));
    Histogram h;
    if (values.empty())
        return h;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    double a = *lo, b = *hi;
    if (!(b > a)) {
        const double half = 0.5e-9 * std::max(std::abs(a), 1.0);
        a -= half;
        b += half;
        bins = 1;
    }
    for (int i = 0; i <= bins; ++i)
        h.edges.push_back(i == bins ? b : a + (b - a) * static_cast<double>(i) / bins);
    h.counts.assign(static_cast<std::size_t>(bins), 0);
    for (double v : values) {
        const int i = std::clamp(static_cast<int>((v - a) / (b - a) * bins), 0, bins - 1);
        ++h.counts[static_cast<std::size_t>(i)];
    }
    return h;
}

std::vector<ZpetcSensitivityPoint> zpetcSensitivity(const RobustnessProblem& problem,
                                                    const std::vector<double>& scales,
                                                    const RobustnessOptions& options) {
    if (!problem.loop || !problem.zpetcEnabled)
        throw InvalidInput("problem", makeDiagnostic("study_zpetc_sensitivity_needs_zpetc"));
    if (scales.empty())
        throw InvalidInput("scales", makeDiagnostic("study_no_scale"));
    std::vector<ZpetcSensitivityPoint> curve;
    for (double scale : scales) {
        RobustnessProblem scaled = problem;
        try {
            scaled.parameters = scaledRanges(problem.parameters, scale);
        } catch (const InvalidInput& e) {
            throw InvalidInput(
                "scales", makeDiagnostic(
                              "study_scale_reason",
                              {std::to_string(scale),
                               makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()})}));
        }
        const RobustnessResult r = analyzeRobustness(scaled, options);
        ZpetcSensitivityPoint point;
        point.scale = scale;
        point.rmseWithFf = r.rmse;
        point.rmseWithoutFf = r.rmseWithoutFf;
        point.unstable = static_cast<int>(r.unstable.size());
        point.medianImprovementPct = r.rmseWithoutFf.count > 0 && r.rmseWithoutFf.p50 > 0.0
                                         ? 100.0 * (1.0 - r.rmse.p50 / r.rmseWithoutFf.p50)
                                         : 0.0;
        curve.push_back(point);
        if (r.status == RobustnessStatus::Cancelled)
            break;
    }
    return curve;
}

} // namespace xyt
