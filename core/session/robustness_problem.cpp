// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/robustness_problem.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/design_method_module.h"
#include "core/session/program_trajectory.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/resample.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

/// The problem of axis @p axis from its evaluation @p nominal, as its method's module makes it.
RobustnessProblem problemOf(const Session& session, int axis, const AxisEvaluation& nominal) {
    if (!nominal.ok)
        throw InvalidInput(nominal.errorField, Diagnostic(nominal.error)); // its coded reason
    return designMethodModule(nominal.method).robustnessProblem(session, axis, nominal);
}

/// What every axis' problem holds: the specification with umax, the run's length and the move.
RobustnessProblem commonProblem(const Session& session, const AxisEvaluation& nominal) {
    RobustnessProblem p;
    p.spec = session.spec;
    p.spec.umaxVolts = session.umaxVolts;
    p.samples = nominal.run.t.size();
    if (session.trajectory.kind == TrajectoryKind::Cubic)
        p.move = PointToPointMove{session.trajectory.x0, session.trajectory.xf,
                                  session.trajectory.tfSeconds};
    return p;
}

/// Axis @p axis of a G-code session made to follow the program's feed profile as the contour
/// run does (runProgramContour): a continuous axis on the profile's samples from rest at its
/// start point, a discrete one on the profile resampled at its Ts (held at the end for the
/// ZPETC's preview).
void followProfile(RobustnessProblem& p, const FeedProfile& profile, int axis) {
    const std::vector<double>& r = axis == 0 ? profile.x : profile.y;
    if (p.controller) {
        p.reference = r;
        p.samples = r.size();
        p.dtSeconds = profile.dtSeconds;
        p.initialOutput = r.front();
        return;
    }
    const double ts = p.loop->tsSeconds;
    const std::size_t n = static_cast<std::size_t>(std::floor(profile.t.back() / ts + 1e-9)) + 1;
    const std::size_t preview = p.zpetc ? static_cast<std::size_t>(p.zpetc->previewSteps) : 0;
    std::vector<double> times(n + preview);
    for (std::size_t k = 0; k < times.size(); ++k)
        times[k] = static_cast<double>(k) * ts;
    p.reference = resampleLinear(profile.t, r, times);
    p.samples = n;
}

} // namespace

RobustnessProblem continuousRobustnessProblem(const Session& session, int axis,
                                              const AxisEvaluation& nominal,
                                              const TransferFunction& controller,
                                              double modelUnitsPerPositionUnit) {
    RobustnessProblem p = commonProblem(session, nominal);
    p.controller = controller;
    p.modelUnitsPerPositionUnit = modelUnitsPerPositionUnit;
    p.dtSeconds = nominal.run.dtSeconds;
    p.reference = nominal.run.r;
    const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axis));
    p.parameters = axisUncertainParameters(settings);
    p.flexibleMode = settings.gt.flexibleMode;
    if (settings.friction.active())
        p.table = settings.friction;
    // The nominal run's feedforward (a friction compensation, the PID's command feedforward):
    // fixed volts on the fixed trajectory, whatever plant is drawn.
    p.feedforwardVolts = nominal.run.uFeedforward;
    return p;
}

RobustnessProblem rstRobustnessProblem(const Session& session, int axis,
                                       const AxisEvaluation& nominal,
                                       const PolePlacementDesign& loop,
                                       const std::optional<ZpetcDesign>& zpetc, bool zpetcEnabled) {
    RobustnessProblem p = commonProblem(session, nominal);
    p.loop = loop;
    p.zpetc = zpetc;
    p.zpetcEnabled = zpetcEnabled;
    // The run's reference plus the preview the ZPETC reads beyond it, as the evaluation samples it.
    const auto r = axisReference(session.trajectory, axis);
    const std::size_t preview = p.zpetc ? static_cast<std::size_t>(p.zpetc->previewSteps) : 0;
    for (std::size_t k = 0; k < p.samples + preview; ++k)
        p.reference.push_back(r(static_cast<double>(k) * p.loop->tsSeconds));
    const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axis));
    p.parameters = axisUncertainParameters(settings);
    if (settings.friction.active())
        p.table = settings.friction; // the input dead zone of the ARX plant
    return p;
}

std::vector<UncertainParameter> thirdOrderPlantParameters(const ThirdOrderPlant& plant) {
    return {{"k0", plant.k0, 0.0}, {"a1", plant.a1, 0.0}, {"a2", plant.a2, 0.0}};
}

ThirdOrderPlant
withThirdOrderPlantParameters(ThirdOrderPlant plant,
                              const std::function<double(const std::string&, double)>& value) {
    plant.k0 = value("k0", plant.k0);
    plant.a1 = value("a1", plant.a1);
    plant.a2 = value("a2", plant.a2);
    return plant;
}

RobustnessProblem sessionRobustnessProblem(const Session& session, int axis) {
    if (axis < 0 || static_cast<std::size_t>(axis) >= session.axes.size())
        throw InvalidInput("axis", makeDiagnostic("session_no_axis", {std::to_string(axis)}));
    return problemOf(session, axis, evaluateAxis(session, axis));
}

ContourRobustnessProblem sessionContourRobustnessProblem(const Session& session) {
    ContourRobustnessProblem p;
    if (session.trajectory.kind == TrajectoryKind::Circle) {
        const AxisEvaluation x = evaluateAxis(session, 0); // (a circle's duration is fixed)
        const AxisEvaluation y = evaluateAxis(session, 1);
        p.x = problemOf(session, 0, x);
        p.y = problemOf(session, 1, y);
        p.geometry.circle = Circle{session.trajectory.radius, session.trajectory.omegaRadPerSec,
                                   0.0, 0.0, session.trajectory.rampInSeconds};
        p.geometry.t = x.run.t; // the evaluation's contour is judged on x's samples too
        if (session.crossCoupling.active())
            p.coupling = ContourCoupling{session.crossCoupling,
                                         referenceCouplingDirections(x.run.r, y.run.r)};
        return p;
    }
    if (session.trajectory.kind != TrajectoryKind::Gcode)
        throw InvalidInput("trajectory", makeDiagnostic("session_contour_needs_path"));
    const std::shared_ptr<const GcodeProgram> shared = sessionProgram(session.trajectory.gcode);
    const GcodeProgram& program = *shared;
    const ContourRunOptions run = programRunOptions(session.trajectory);
    const FeedProfile& profile = *sessionProgramProfile(session.trajectory);
    p.x = sessionRobustnessProblem(session, 0);
    p.y = sessionRobustnessProblem(session, 1);
    p.x.move.reset();
    p.y.move.reset();
    followProfile(p.x, profile, 0);
    followProfile(p.y, profile, 1);
    p.geometry.path = std::shared_ptr<const Path>(shared, &shared->path); // the shared program's
    p.geometry.pathOptions = programContourErrorOptions(program, run);
    p.geometry.t = profile.t;
    if (session.crossCoupling.active()) {
        // On the axes' grid: the profile's dt for continuous axes, Ts for discrete ones
        // (axes at two periods are refused by name).
        const double period = p.x.controller ? p.x.dtSeconds : p.x.loop->tsSeconds;
        const double periodY = p.y.controller ? p.y.dtSeconds : p.y.loop->tsSeconds;
        if (std::abs(period - periodY) > 1e-9 * period)
            throw InvalidInput("cross_coupling",
                               makeDiagnostic("sim_coupling_periods_differ",
                                              {formatNumber(period), formatNumber(periodY)}));
        const std::size_t n = p.x.controller ? p.x.reference.size() : p.x.samples;
        const std::vector<bool> rapid = programRapidSegments(program);
        p.coupling =
            ContourCoupling{session.crossCoupling,
                            pathCouplingDirections(program.path, profile, period, n, &rapid)};
    }
    return p;
}

void setIdentifiedUncertainty(RobustnessProblem& problem, const Session& session, int axis) {
    const std::string field = "axes[" + std::to_string(axis) + "].model_origin";
    const AxisSettings& settings = session.axes.at(static_cast<std::size_t>(axis));
    if (!settings.origin)
        throw InvalidInput(field, makeDiagnostic("session_model_not_identified"));
    const ModelOrigin& o = *settings.origin;
    const std::size_t d = o.parameterNames.size();
    if (o.covariance.size() != d * d || d == 0)
        throw InvalidInput(field,
                           makeDiagnostic("session_identified_no_covariance", {o.structure}));
    const bool continuous = o.parameterNames == std::vector<std::string>{"k0", "a1", "a2"};
    if (continuous != problem.controller.has_value())
        throw InvalidInput(field, makeDiagnostic("session_identified_wrong_method", {o.structure}));
    // The problem's index of each origin parameter (npos: not in the loop).
    std::vector<std::size_t> at(d, std::string::npos);
    std::vector<double> scale(d, 1.0);
    for (std::size_t i = 0; i < d; ++i) {
        std::string name = o.parameterNames[i];
        if (!continuous && !name.empty() && name[0] == 'f')
            name[0] = 'a'; // OE/BJ: the loop's A is F
        if (continuous && name == "k0")
            scale[i] = settings.gt.modelUnitsPerPositionUnit;
        for (std::size_t j = 0; j < problem.parameters.size(); ++j)
            if (problem.parameters[j].name == name)
                at[i] = j;
    }
    const Eigen::Index n = static_cast<Eigen::Index>(problem.parameters.size());
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t i = 0; i < d; ++i)
        for (std::size_t j = 0; j < d; ++j)
            if (at[i] != std::string::npos && at[j] != std::string::npos)
                c(static_cast<Eigen::Index>(at[i]), static_cast<Eigen::Index>(at[j])) =
                    o.covariance[i * d + j] * scale[i] * scale[j];
    for (Eigen::Index j = 0; j < n; ++j) {
        UncertainParameter& p = problem.parameters[static_cast<std::size_t>(j)];
        const double sigma = std::sqrt(std::max(c(j, j), 0.0));
        p.relative = p.nominal != 0.0 ? std::min(3.0 * sigma / std::abs(p.nominal), 0.99) : 0.0;
    }
    problem.covariance = c;
}

std::vector<UncertainParameter> axisUncertainParameters(const AxisSettings& axis) {
    return designMethodModule(axis.method).plantParameters(axis);
}

} // namespace xyt
