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
        const ThirdOrderPlant& g = settings.gt.plant;
        p.parameters = {{"k0", g.k0, 0.0}, {"a1", g.a1, 0.0}, {"a2", g.a2, 0.0}};
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
    const auto& a = p.loop->a.ascending();
    for (std::size_t i = 1; i < a.size(); ++i)
        p.parameters.push_back({"a" + std::to_string(i), a[i], 0.0});
    const auto& b = p.loop->b.ascending();
    for (std::size_t i = 1; i < b.size(); ++i)
        if (b[i] != 0.0)
            p.parameters.push_back({"b" + std::to_string(i), b[i], 0.0});
    return p;
}

} // namespace xyt
