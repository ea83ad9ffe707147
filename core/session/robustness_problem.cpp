// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/robustness_problem.h"

#include "core/model/errors.h"
#include "core/session/session_evaluation.h"

namespace xyt {

RobustnessProblem sessionRobustnessProblem(const Session& session, int axis) {
    if (axis < 0 || static_cast<std::size_t>(axis) >= session.axes.size())
        throw InvalidInput("axis", "there is no axis " + std::to_string(axis));
    const AxisEvaluation nominal = evaluateAxis(session, axis);
    if (!nominal.ok)
        throw InvalidInput(nominal.errorField, nominal.error);
    const AxisSettings& settings = session.axes[static_cast<std::size_t>(axis)];
    RobustnessProblem p;
    p.spec = session.spec;
    p.spec.umaxVolts = session.umaxVolts;
    p.samples = nominal.run.t.size();
    if (session.trajectory.kind == TrajectoryKind::Cubic)
        p.move = PointToPointMove{session.trajectory.x0, session.trajectory.xf, session.trajectory.tfSeconds};
    if (nominal.gt) {
        p.controller = nominal.gt->controller;
        p.modelUnitsPerPositionUnit = settings.gt.modelUnitsPerPositionUnit;
        p.dtSeconds = nominal.run.dtSeconds;
        p.reference = nominal.run.r;
        p.parameters = axisUncertainParameters(settings);
        return p;
    }
    p.loop = *nominal.pp;
    p.zpetc = nominal.zpetc;
    p.zpetcEnabled = settings.pp.zpetcEnabled;
    // The run's reference plus the preview the ZPETC reads beyond it, as the evaluation samples it.
    const auto r = axisReference(session.trajectory, axis);
    const std::size_t preview = p.zpetc ? static_cast<std::size_t>(p.zpetc->previewSteps) : 0;
    for (std::size_t k = 0; k < p.samples + preview; ++k)
        p.reference.push_back(r(static_cast<double>(k) * p.loop->tsSeconds));
    p.parameters = axisUncertainParameters(settings);
    return p;
}

std::vector<UncertainParameter> axisUncertainParameters(const AxisSettings& axis) {
    if (axis.method == DesignMethod::GuilleminTruxal) {
        const ThirdOrderPlant& g = axis.gt.plant;
        return {{"k0", g.k0, 0.0}, {"a1", g.a1, 0.0}, {"a2", g.a2, 0.0}};
    }
    // As designPolePlacement uses the model: A and B divided by A(0).
    const Polynomial a = Polynomial::fromAscending(axis.pp.a, "a");
    const Polynomial b = Polynomial::fromAscending(axis.pp.b, "b");
    const double a0 = a.coefficient(0);
    if (a0 == 0.0)
        throw InvalidInput("a", "A(0) must be nonzero");
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

} // namespace xyt
