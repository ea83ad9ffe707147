// SPDX-License-Identifier: GPL-3.0-or-later
// The robustness analysis and the design space on a table with friction: the nominal plant of
// the robustness problem runs exactly the session's run (the same simulateLoop call), the
// friction levels are uncertain parameters that change the run, a parameter box whose corner
// would make the plant's poles complex is refused by name, and the design space's point at the
// session's design equals simulateLoop with the table on the study's reference.
#include "core/model/errors.h"
#include "core/session/design_study.h"
#include "core/session/robustness_problem.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/metrics.h"
#include "core/study/design_sweep.h"
#include "core/study/robustness.h"
#include "tests/support/core_checks.h"

#include <QTest>

#include <algorithm>

using namespace xyt;

namespace {

Session frictionSession() {
    Session s = Session::paperDefault();
    s.trajectory.xf = 50.0;
    s.trajectory.tfSeconds = 10.0;
    s.trajectory.durationSeconds = 20.0;
    s.axes[0].friction.coulombVolts = 0.05;
    s.axes[0].friction.backlashMm = 0.01;
    return s;
}

std::vector<double> nominalValues(const RobustnessProblem& p) {
    std::vector<double> v;
    for (const UncertainParameter& u : p.parameters)
        v.push_back(u.nominal);
    return v;
}

} // namespace

class TstFrictionStudies : public QObject {
    Q_OBJECT

private slots:
    void robustnessRunsTheTableAndVariesItsLevels() {
        const Session s = frictionSession();
        RobustnessProblem p = sessionRobustnessProblem(s, 0);
        QVERIFY(p.table.has_value());
        const auto has = [&](const char* name) {
            return std::any_of(p.parameters.begin(), p.parameters.end(),
                               [&](const UncertainParameter& u) { return u.name == name; });
        };
        QVERIFY(has("coulomb") && has("backlash"));
        QVERIFY(!has("static") && !has("viscous")); // zero levels have no relative range
        // The nominal plant is the session's run, sample for sample (the same call).
        SimulationResult run;
        runPerturbedPlant(p, nominalValues(p), run);
        const AxisEvaluation nominal = evaluateAxis(s, 0);
        QCOMPARE(run.y, nominal.run.y);
        QCOMPARE(run.sliding, nominal.run.sliding);
        // A Coulomb level 50 % higher changes the run (the parameter reaches the table).
        std::vector<double> higher = nominalValues(p);
        for (std::size_t i = 0; i < p.parameters.size(); ++i)
            if (p.parameters[i].name == "coulomb")
                higher[i] *= 1.5;
        SimulationResult other;
        const PlantRun r = runPerturbedPlant(p, higher, other);
        QVERIFY(r.finite);
        QVERIFY(other.y != run.y);
        // a2 +10 % and a1 -10 %: a1^2 = 12717 < 4 a2 = 16126, complex poles at that corner.
        setRelativeRange(p.parameters, "a2", 0.1);
        setRelativeRange(p.parameters, "a1", 0.1);
        QCOMPARE(test::invalidInputField([&] { validateRobustnessProblem(p); }),
                 QStringLiteral("range.a2"));
        // 1 % each keeps them real (a1^2 = 15387 >= 4 a2 = 14807).
        setRelativeRange(p.parameters, "a2", 0.01);
        setRelativeRange(p.parameters, "a1", 0.01);
        validateRobustnessProblem(p);
    }

    void theDesignSpaceRunsTheTable() {
        const Session s = frictionSession();
        const DesignProblem problem = sessionDesignProblem(s, 0);
        QVERIFY(problem.table.has_value());
        const DesignEvaluator evaluator(problem);
        const GtAxisSettings& gt = s.axes[0].gt;
        const DesignPoint point = evaluator.evaluate(gt.omegaNRadPerSec, gt.kp);
        // The same loop by simulateLoop on the study's reference, step and limit.
        const GtDesign d = designGuilleminTruxal(gt.plant, gt.omegaNRadPerSec, gt.kp);
        LoopSimulationOptions o;
        o.dtSeconds = problem.dtSeconds;
        o.umaxVolts = problem.spec.umaxVolts;
        o.modelUnitsPerPositionUnit = gt.modelUnitsPerPositionUnit;
        o.table = &*problem.table;
        const SimulationResult run =
            simulateLoop(gt.plant.transferFunction(), d.controller, problem.reference, o);
        QCOMPARE(point.tracking.rmse, trackingMetrics(run).rmse);
        QCOMPARE(point.tracking.maxAbsError, trackingMetrics(run).maxAbsError);
        // And not the linear table's figure.
        DesignProblem linear = problem;
        linear.table.reset();
        QVERIFY(DesignEvaluator(linear).evaluate(gt.omegaNRadPerSec, gt.kp).tracking.rmse !=
                point.tracking.rmse);
    }
};

QTEST_APPLESS_MAIN(TstFrictionStudies)
#include "tst_friction_studies.moc"
