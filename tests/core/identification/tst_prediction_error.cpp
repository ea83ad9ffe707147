// SPDX-License-Identifier: GPL-3.0-or-later
// OE and BJ by prediction-error minimization (core/identification/prediction_error.h): exact
// recovery, reported standard deviations against the truth and against the spread over 200
// seeds, the textbook bias of ARX under output-error noise, stability of F during the search,
// cancel and iteration limit, invalid input.
//
// The plant is the classic second-order test system of Soderstrom & Stoica, System
// Identification (1989), Example 2.3 and of MATLAB's identification demos:
//   B = q^-1 + 0.5 q^-2,  F (or A) = 1 - 1.5 q^-1 + 0.7 q^-2  (poles 0.75 +- 0.37i).
// The BJ noise model is C = 1 - 0.3 q^-1, D = 1 - 0.7 q^-1.
#include "core/design/digital_controller.h"
#include "core/identification/arx.h"
#include "core/identification/least_squares.h"
#include "core/identification/prediction_error.h"
#include "core/identification/validation.h"
#include "core/model/errors.h"
#include "tests/support/identification_data.h"
#include "tests/support/tolerance.h"

#include <Eigen/Cholesky>
#include <QTest>

#include <cmath>

using namespace xyt;
using namespace xyt::test;

namespace {

const std::vector<double> kB{0.0, 1.0, 0.5};
const std::vector<double> kF{1.0, -1.5, 0.7};
const std::vector<double> kC{1.0, -0.3};
const std::vector<double> kD{1.0, -0.7};
constexpr double kTs = 0.01;

/// y = B/F u + C/D e (noiseFilter false: y = B/F u + e, output-error noise).
IoData data(std::size_t n, double sigma, std::uint64_t seed, bool colouredNoise) {
    const std::vector<double> u = randomBinary(n, 1.0, seed);
    std::vector<double> y = filterDifferenceEquation(kB, kF, u);
    if (sigma > 0.0) {
        const std::vector<double> e = gaussianNoise(n, sigma, seed + 5000);
        y = plus(y, colouredNoise ? filterDifferenceEquation(kC, kD, e) : e);
    }
    return ioData(u, y, kTs);
}

std::vector<double> oeTruth() {
    return {kB[1], kB[2], kF[1], kF[2]};
}
std::vector<double> bjTruth() {
    return {kB[1], kB[2], kC[1], kD[1], kF[1], kF[2]};
}

void requireWithinThreeSigma(const PemResult& r, const std::vector<double>& truth) {
    QCOMPARE(r.status, EstimationStatus::Converged);
    QCOMPARE(r.parameters.size(), truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i)
        QVERIFY2(std::abs(r.parameters[i] - truth[i]) <= 3.0 * r.standardDeviations[i],
                 qPrintable(QStringLiteral("%1 %2: %3 vs %4 +- %5")
                                .arg(QString::fromStdString(r.structure))
                                .arg(QString::fromStdString(r.parameterNames[i]))
                                .arg(r.parameters[i])
                                .arg(truth[i])
                                .arg(r.standardDeviations[i])));
}

/// The 200-seed check (spreadMismatch) of one structure on N = 400 samples.
template <typename Estimate>
void requireSpreadMatchesReportedSd(Estimate estimate, const std::vector<double>& truth) {
    std::vector<std::vector<double>> est, sd;
    bool allConverged = true;
    collectOverSeeds(
        200, truth.size(),
        [&](std::size_t seed, std::vector<double>& p, std::vector<double>& s) {
            const PemResult r = estimate(seed);
            allConverged = allConverged && r.status == EstimationStatus::Converged;
            p = r.parameters;
            s = r.standardDeviations;
        },
        est, sd);
    QVERIFY(allConverged);
    const QString mismatch = spreadMismatch(est, sd, truth);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

} // namespace

class TstPredictionError : public QObject {
    Q_OBJECT

private slots:
    // Invariant: noise-free OE data are reproduced exactly by the true B/F, the global minimum
    // (V = 0). 1e-9 relative: round-off of a 300-step recursion with poles of modulus 0.84.
    void noiseFreeOeRecoversTheModel() {
        const PemResult r = estimateOe(data(300, 0.0, 1, false), OeOrders{2, 2, 1});
        QCOMPARE(r.status, EstimationStatus::Converged);
        QCOMPARE(r.model.b.size(), std::size_t{3});
        QCOMPARE(r.model.b[0], 0.0);
        for (std::size_t i = 1; i < 3; ++i) {
            XYT_COMPARE_NEAR(r.model.b[i], kB[i], 1e-9, 0.0);
            XYT_COMPARE_NEAR(r.model.f[i], kF[i], 1e-9, 0.0);
        }
        QCOMPARE(r.parameterNames, (std::vector<std::string>{"b1", "b2", "f1", "f2"}));
        QCOMPARE(r.structure, std::string("OE(2,2,1)"));
    }

    // The same for BJ: B and F are exact; C and D cannot be identified from noise-free data
    // (the residuals are zero for any C, D), which the result reports as a warning.
    void noiseFreeBjRecoversBAndF() {
        const PemResult r = estimateBj(data(300, 0.0, 2, false), BjOrders{2, 1, 1, 2, 1});
        QVERIFY2(r.status == EstimationStatus::Converged,
                 (estimationStatusName(r.status) + ": " + r.message.text).c_str());
        for (std::size_t i = 1; i < 3; ++i) {
            XYT_COMPARE_NEAR(r.model.b[i], kB[i], 1e-9, 0.0);
            XYT_COMPARE_NEAR(r.model.f[i], kF[i], 1e-9, 0.0);
        }
        QCOMPARE(r.parameterNames, (std::vector<std::string>{"b1", "b2", "c1", "d1", "f1", "f2"}));
        QVERIFY(r.loss < 1e-20);
    }

    // The analytic gradients by filtering (b, c, d and f alike), checked through the reported
    // covariance: sigma^2 (J^T J)^-1 with J built in the test by central differences of the
    // one-step prediction errors (validation.h predictionErrors, an independent path) with a
    // relative step of 1e-6. Agreement to 1e-5 relative: the difference quotient's error is
    // ~h^2 + eps/h ~ 1e-10, amplified by the condition number of J^T J (~1e4).
    void covarianceMatchesFiniteDifferenceJacobian() {
        const IoData d = data(400, 0.3, 10, true);
        const PemResult r = estimateBj(d, BjOrders{2, 1, 1, 2, 1});
        QCOMPARE(r.status, EstimationStatus::Converged);
        const std::size_t np = r.parameters.size();
        const auto modelOf = [&](const std::vector<double>& theta) {
            PolynomialModel m = r.model;
            m.b = {0.0, theta[0], theta[1]};
            m.c = {1.0, theta[2]};
            m.d = {1.0, theta[3]};
            m.f = {1.0, theta[4], theta[5]};
            return m;
        };
        Eigen::MatrixXd jac(static_cast<Eigen::Index>(d.size()), static_cast<Eigen::Index>(np));
        for (std::size_t j = 0; j < np; ++j) {
            std::vector<double> plusTheta = r.parameters, minusTheta = r.parameters;
            const double h = 1e-6 * std::abs(r.parameters[j]);
            plusTheta[j] += h;
            minusTheta[j] -= h;
            const std::vector<double> ep = predictionErrors(modelOf(plusTheta), d);
            const std::vector<double> em = predictionErrors(modelOf(minusTheta), d);
            for (std::size_t t = 0; t < d.size(); ++t)
                jac(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(j)) =
                    (ep[t] - em[t]) / (plusTheta[j] - minusTheta[j]);
        }
        const Eigen::MatrixXd cov =
            r.noiseVariance * (jac.transpose() * jac)
                                  .ldlt()
                                  .solve(Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(np),
                                                                   static_cast<Eigen::Index>(np)));
        for (std::size_t j = 0; j < np; ++j)
            XYT_COMPARE_NEAR(
                r.standardDeviations[j],
                std::sqrt(cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j))), 1e-5,
                0.0);
        // The residuals are the one-step prediction errors of the estimated model.
        const std::vector<double> e = predictionErrors(r.model, d);
        for (std::size_t t = 0; t < e.size(); ++t)
            XYT_COMPARE_NEAR(r.residuals[t], e[t], 0.0, 1e-12);
    }

    // Statistics (Ljung Eq. 9.29: the PEM estimate is asymptotically Gaussian with covariance
    // sigma^2 (sum psi psi^T)^-1): fixed seeds, each parameter within 3 reported SDs.
    void noisyOeWithinThreeSigma() {
        requireWithinThreeSigma(estimateOe(data(500, 0.3, 3, false), OeOrders{2, 2, 1}), oeTruth());
    }
    void noisyBjWithinThreeSigma() {
        requireWithinThreeSigma(estimateBj(data(500, 0.3, 4, true), BjOrders{2, 1, 1, 2, 1}),
                                bjTruth());
    }

    // Over 200 seeds the sample SD agrees with the mean reported SD within 25 %
    // (spreadMismatch in tests/support/identification_data.h).
    void oeSpreadOverSeedsMatchesReportedSd() {
        requireSpreadMatchesReportedSd(
            [](std::size_t seed) {
                return estimateOe(data(400, 0.3, 1000 + seed, false), OeOrders{2, 2, 1});
            },
            oeTruth());
    }
    void bjSpreadOverSeedsMatchesReportedSd() {
        requireSpreadMatchesReportedSd(
            [](std::size_t seed) {
                return estimateBj(data(400, 0.3, 2000 + seed, true), BjOrders{2, 1, 1, 2, 1});
            },
            bjTruth());
    }

    // The textbook case (Ljung Sec. 8.3, Soderstrom & Stoica Example 2.3): with white noise on
    // the OUTPUT the ARX equation error is coloured, so least squares is biased: ARX's a1 lies
    // beyond 3 of its own standard deviations from f1, while OE (the right structure) and BJ
    // with an AR(1) noise model (true d1 = 0) recover B and F within 3 sigma.
    void outputErrorNoiseBiasesArxNotOeOrBj() {
        const IoData d = data(2000, 1.0, 5, false);
        const ArxResult arx = estimateArx(d, ArxOrders{2, 2, 1});
        QCOMPARE(arx.status, EstimationStatus::Converged);
        QVERIFY2(std::abs(arx.parameters[0] - kF[1]) > 3.0 * arx.standardDeviations[0],
                 qPrintable(QStringLiteral("ARX a1 %1 +- %2")
                                .arg(arx.parameters[0])
                                .arg(arx.standardDeviations[0])));
        QVERIFY(std::abs(arx.parameters[1] - kF[2]) > 3.0 * arx.standardDeviations[1]);
        requireWithinThreeSigma(estimateOe(d, OeOrders{2, 2, 1}), oeTruth());
        const PemResult bj = estimateBj(d, BjOrders{2, 0, 1, 2, 1});
        requireWithinThreeSigma(bj, {kB[1], kB[2], 0.0, kF[1], kF[2]});
    }

    // Stability of F during the search: started from an unstable F (roots 1.25 and 1.2), the
    // roots are reflected into the unit circle and the search still reaches the truth.
    void unstableStartIsReflected() {
        PemOptions o;
        PolynomialModel start;
        start.b = {0.0, 0.5, 0.5};
        start.f = {1.0, -2.45, 1.5}; // (1 - 1.25 q^-1)(1 - 1.2 q^-1)
        o.initial = start;
        const PemResult r = estimateOe(data(400, 0.0, 6, false), OeOrders{2, 2, 1}, o);
        QCOMPARE(r.initialization, std::string("given"));
        QVERIFY(maxRootMagnitude(r.model.f) < 1.0);
        for (std::size_t i = 1; i < 3; ++i)
            XYT_COMPARE_NEAR(r.model.f[i], kF[i], 1e-9, 0.0);
    }

    // Progress and cancel, the SweepOptions::progress contract: fractions in [0, 1],
    // non-decreasing, the last exactly 1; false cancels with status Cancelled.
    void progressAndCancel() {
        std::vector<double> seen;
        PemOptions o;
        o.search.progress = [&](double f) {
            seen.push_back(f);
            return true;
        };
        estimateBj(data(400, 0.3, 7, true), BjOrders{2, 1, 1, 2, 1}, o);
        QVERIFY(seen.size() >= 2);
        QCOMPARE(seen.back(), 1.0);
        for (std::size_t i = 1; i < seen.size(); ++i)
            QVERIFY(seen[i] >= seen[i - 1] && seen[i] <= 1.0);
        o.search.progress = [](double) { return false; };
        const PemResult c = estimateOe(data(400, 0.3, 7, false), OeOrders{2, 2, 1}, o);
        QCOMPARE(c.status, EstimationStatus::Cancelled);
        QCOMPARE(c.iterations, 0);
    }

    void iterationLimit() {
        PemOptions o;
        o.search.maxIterations = 1;
        PolynomialModel start;
        start.b = {0.0, 0.1, 0.1};
        start.f = {1.0, 0.0, 0.0};
        o.initial = start;
        const PemResult r = estimateOe(data(400, 0.3, 8, false), OeOrders{2, 2, 1}, o);
        QCOMPARE(r.status, EstimationStatus::IterationLimit);
        QCOMPARE(r.iterations, 1);
        QCOMPARE(r.lossHistory.size(), std::size_t{2});
        QVERIFY(r.lossHistory[1] < r.lossHistory[0]);
    }

    void invalidInputThrows() {
        try {
            estimateOe(data(6, 0.1, 9, false), OeOrders{2, 2, 1}); // needs n0 + d + 1 = 7
            QFAIL("no exception");
        } catch (const InvalidInput& e) {
            QCOMPARE(e.field(), std::string("data"));
            QVERIFY(std::string(e.what()).find("OE(2,2,1)") != std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 estimateOe(data(100, 0.1, 9, false), OeOrders{0, 2, 1}));
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 estimateBj(data(100, 0.1, 9, false), BjOrders{2, -1, 1, 2, 1}));
        PemOptions o;
        PolynomialModel wrong;
        wrong.b = {0.0, 1.0};
        wrong.f = {1.0, -1.5, 0.7};
        o.initial = wrong;
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 estimateOe(data(100, 0.1, 9, false), OeOrders{2, 2, 1}, o));
        o = PemOptions{};
        o.search.maxIterations = 0;
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 estimateOe(data(100, 0.1, 9, false), OeOrders{2, 2, 1}, o));
    }

    // A constant input cannot excite nb = 2: the ARX start reports it, the search does not run.
    void notPersistentlyExciting() {
        const std::vector<double> step(200, 1.0);
        const PemResult r = estimateOe(ioData(step, filterDifferenceEquation(kB, kF, step), kTs),
                                       OeOrders{2, 2, 1});
        QCOMPARE(r.status, EstimationStatus::NotPersistentlyExciting);
        QVERIFY2(r.message.text.find("nb = 2") != std::string::npos, r.message.text.c_str());
    }
};

QTEST_APPLESS_MAIN(TstPredictionError)
#include "tst_prediction_error.moc"
