// SPDX-License-Identifier: GPL-3.0-or-later
// The uncertainty of an identified model (the robustness analysis's uncertainty "from
// identification", taken from the model's origin). Sources: the sampling distribution of a sample
// covariance (the bounds are stated with their standard errors), the estimator's own covariance
// carried through the session (an invariant: the problem's covariance is the model's, reordered and
// scaled), and named errors.
#include "core/identification/experiment_data.h"
#include "core/identification/experiment_file.h"
#include "core/identification/identification.h"
#include "core/model/errors.h"
#include "core/session/identified_axis.h"
#include "core/session/robustness_problem.h"
#include "core/study/plant_uncertainty.h"
#include "core/study/robustness.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

using namespace xyt;

namespace {

/// Patrick, Ishak and Adnan's x axis identified as OE(3,2,1) from the committed synthetic PRBS log.
IdentifiedModel identifiedX(IoData& data) {
    const ExperimentTable table =
        readExperimentTable(XYT_SOURCE_DIR "/resources/examples/synthetic_x_axis_prbs_70ms.csv");
    ExperimentColumns c;
    c.input = "u";
    c.output = "y";
    c.time = "t";
    data = experimentData(table, c);
    IdentificationSpec spec;
    spec.structure = ModelStructure::Oe;
    spec.oe = {3, 2, 1};
    return identifyModel(data, nullptr, spec);
}

} // namespace

class TstIdentifiedUncertainty : public QObject {
    Q_OBJECT
private slots:
    void normalDrawsHaveTheCovariance();
    void semiDefiniteAndBadCovariances();
    void sessionCarriesTheModelsCovariance();
    void identifiedRobustnessRuns();
};

void TstIdentifiedUncertainty::normalDrawsHaveTheCovariance() {
    // Two strongly correlated parameters, as a1 and a2 of an ARX model are (rho = -0.9).
    const std::vector<UncertainParameter> p{{"a1", -1.658, 0.0}, {"a2", 0.6583, 0.0}};
    Eigen::Matrix2d c;
    c << 4e-4, -0.9 * 2e-2 * 1e-2, -0.9 * 2e-2 * 1e-2, 1e-4;
    const int n = 4000;
    const auto plants = drawPlantsNormal(p, c, n, 5);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& v : plants)
        mean += Eigen::Vector2d(v[0], v[1]);
    mean /= n;
    Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
    for (const auto& v : plants) {
        const Eigen::Vector2d d = Eigen::Vector2d(v[0], v[1]) - mean;
        s += d * d.transpose();
    }
    s /= n - 1;
    // Mean: standard error sigma / sqrt(n); 4.5 standard errors.
    QVERIFY(std::abs(mean(0) - p[0].nominal) <= 4.5 * 2e-2 / std::sqrt(n));
    QVERIFY(std::abs(mean(1) - p[1].nominal) <= 4.5 * 1e-2 / std::sqrt(n));
    // Variances: relative standard error sqrt(2 / (n - 1)) = 2.2 %; 4.5 of them.
    const double relSe = std::sqrt(2.0 / (n - 1));
    QVERIFY(std::abs(s(0, 0) / c(0, 0) - 1.0) <= 4.5 * relSe);
    QVERIFY(std::abs(s(1, 1) / c(1, 1) - 1.0) <= 4.5 * relSe);
    // Correlation: standard error (1 - rho^2) / sqrt(n) = 0.003; 4.5 of them.
    const double rho = s(0, 1) / std::sqrt(s(0, 0) * s(1, 1));
    QVERIFY2(std::abs(rho + 0.9) <= 4.5 * 0.19 / std::sqrt(n), qPrintable(QString::number(rho)));
    // Same seed, same plants (any machine: 53-bit uniforms, Box-Muller by hand).
    QCOMPARE(drawPlantsNormal(p, c, 3, 5),
             std::vector<std::vector<double>>(plants.begin(), plants.begin() + 3));
}

void TstIdentifiedUncertainty::semiDefiniteAndBadCovariances() {
    const std::vector<UncertainParameter> p{{"k0", 77.8, 0.0}, {"a1", 125.3, 0.0}};
    Eigen::Matrix2d exactA1;
    exactA1 << 1.0, 0.0, 0.0, 0.0; // a1 known exactly: semi-definite, allowed
    for (const auto& v : drawPlantsNormal(p, exactA1, 20, 1))
        QCOMPARE(v[1], 125.3);
    const auto field = [&](const Eigen::MatrixXd& c) {
        try {
            drawPlantsNormal(p, c, 2, 1);
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return std::string("(none)");
    };
    QCOMPARE(field(Eigen::Matrix3d::Identity()), std::string("covariance"));
    Eigen::Matrix2d negative;
    negative << 1.0, 0.0, 0.0, -1.0;
    QCOMPARE(field(negative), std::string("covariance"));
    Eigen::Matrix2d asymmetric;
    asymmetric << 1.0, 0.5, 0.0, 1.0;
    QCOMPARE(field(asymmetric), std::string("covariance"));
}

void TstIdentifiedUncertainty::sessionCarriesTheModelsCovariance() {
    IoData data;
    const IdentifiedModel m = identifiedX(data);
    QVERIFY(m.hasEstimate());
    Session s = Session::paperDefault();
    s.axes[0] = axisWithIdentifiedModel(s.axes[0], m, data);
    RobustnessProblem p = sessionRobustnessProblem(s, 0);
    setIdentifiedUncertainty(p, s, 0);
    QVERIFY(p.covariance.has_value());
    // The OE parameters b1 b2 b3 f1 f2 are the loop's b1 b2 b3 a1 a2.
    const auto index = [&](const std::vector<std::string>& names, const std::string& n) {
        return static_cast<Eigen::Index>(std::find(names.begin(), names.end(), n) - names.begin());
    };
    std::vector<std::string> problemNames;
    for (const UncertainParameter& q : p.parameters)
        problemNames.push_back(q.name);
    for (const auto& [model, loop] :
         {std::pair{"f1", "a1"}, {"f2", "a2"}, {"b1", "b1"}, {"b3", "b3"}})
        for (const auto& [model2, loop2] : {std::pair{"f1", "a1"}, {"b2", "b2"}})
            QCOMPARE((*p.covariance)(index(problemNames, loop), index(problemNames, loop2)),
                     m.covariance(index(m.parameterNames, model), index(m.parameterNames, model2)));
    // Ranges at 3 standard deviations for the corner search.
    const Eigen::Index a1 = index(problemNames, "a1");
    QVERIFY(test::near(p.parameters[static_cast<std::size_t>(a1)].relative,
                       3.0 * std::sqrt((*p.covariance)(a1, a1)) /
                           std::abs(p.parameters[static_cast<std::size_t>(a1)].nominal),
                       1e-12));
    // The other axis was typed by hand: named, not guessed.
    RobustnessProblem y = sessionRobustnessProblem(s, 1);
    try {
        setIdentifiedUncertainty(y, s, 1);
        QFAIL("an axis without an identified model was accepted");
    } catch (const InvalidInput& e) {
        QCOMPARE(e.field(), std::string("axes[1].model_origin"));
    }
}

void TstIdentifiedUncertainty::identifiedRobustnessRuns() {
    IoData data;
    const IdentifiedModel m = identifiedX(data);
    Session s = Session::paperDefault();
    s.axes[0] = axisWithIdentifiedModel(s.axes[0], m, data);
    s.trajectory.kind = TrajectoryKind::Circle;
    RobustnessProblem p = sessionRobustnessProblem(s, 0);
    setIdentifiedUncertainty(p, s, 0);
    RobustnessOptions o;
    o.samples = 40;
    o.corners = false;
    const RobustnessResult r = analyzeRobustness(p, o);
    QCOMPARE(r.runs.size(), std::size_t(40));
    // The plants are the normal draws of the problem's covariance, in order.
    const auto plants = drawPlantsNormal(p.parameters, *p.covariance, 40, o.seed);
    for (std::size_t i = 0; i < plants.size(); ++i)
        QCOMPARE(r.runs[i].values, plants[i]);
    QVERIFY(r.rmse.count + static_cast<int>(r.unstable.size()) == 40);
}

QTEST_APPLESS_MAIN(TstIdentifiedUncertainty)
#include "tst_identified_uncertainty.moc"
