// SPDX-License-Identifier: GPL-3.0-or-later
// Model validation (core/identification/validation.h): fit %, simulation and k-step prediction,
// FPE and AIC, the ARX order table, the residual tests with their false-alarm rate, and the
// poles and zeros with the non-minimum-phase flag.
#include "core/design/digital_controller.h"
#include "core/design/guillemin_truxal.h"
#include "core/identification/arx.h"
#include "core/identification/validation.h"
#include "core/model/errors.h"
#include "tests/support/identification_data.h"
#include "tests/support/reference_data.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <complex>

using namespace xyt;
using namespace xyt::test;

namespace {

// The classic test plant of Soderstrom & Stoica (1989), Example 2.3.
const std::vector<double> kB{0.0, 1.0, 0.5};
const std::vector<double> kF{1.0, -1.5, 0.7};
// Patrick, Ishak and Adnan Eq. 1 (x axis, ARX(2,3,1), 70 ms).
const std::vector<double> kPaperA{1.0, -1.6580, 0.6583};
const std::vector<double> kPaperB{0.0, 0.0421, 0.0628, -0.0454};

PolynomialModel bjModel(std::vector<double> c, std::vector<double> d) {
    PolynomialModel m;
    m.b = kB;
    m.f = kF;
    m.c = std::move(c);
    m.d = std::move(d);
    m.tsSeconds = 0.01;
    return m;
}

/// y = B/F u + C/D e for @p m (A = 1), with the innovations e returned too.
IoData bjData(const PolynomialModel& m, std::size_t n, double sigma, std::uint64_t seed,
              std::vector<double>& e) {
    const std::vector<double> u = randomBinary(n, 1.0, seed);
    e = gaussianNoise(n, sigma, seed + 1);
    return ioData(
        u, plus(filterDifferenceEquation(m.b, m.f, u), filterDifferenceEquation(m.c, m.d, e)),
        m.tsSeconds);
}

double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        m = std::max(m, std::abs(a[k] - b[k]));
    return m;
}

bool hasRoot(const std::vector<std::complex<double>>& roots, std::complex<double> r, double tol) {
    for (const auto& x : roots)
        if (std::abs(x - r) <= tol * std::max(1.0, std::abs(r)))
            return true;
    return false;
}

} // namespace

class TstValidation : public QObject {
    Q_OBJECT

private slots:
    // Closed form of the definition: yhat = y gives 100, yhat = mean(y) gives 0, and
    // yhat = y - c (y - mean) gives 100 (1 - |c|). Round-off: 1e-12.
    void fitPercentClosedForm() {
        const std::vector<double> y = gaussianNoise(100, 1.0, 1);
        double mean = 0.0;
        for (double v : y)
            mean += v / 100.0;
        std::vector<double> half(y.size()), flat(y.size(), mean);
        for (std::size_t k = 0; k < y.size(); ++k)
            half[k] = y[k] - 0.5 * (y[k] - mean);
        XYT_COMPARE_NEAR(fitPercent(y, y), 100.0, 0.0, 1e-12);
        XYT_COMPARE_NEAR(fitPercent(y, flat), 0.0, 0.0, 1e-12);
        XYT_COMPARE_NEAR(fitPercent(y, half), 50.0, 0.0, 1e-12);
        QVERIFY(std::isnan(fitPercent(std::vector<double>(5, 1.0), std::vector<double>(5, 0.0))));
        QVERIFY_THROWS_EXCEPTION(InvalidInput, fitPercent(y, std::vector<double>(99, 0.0)));
    }

    // Invariant: the true model on noise-free data fits 100 % in simulation and at every
    // horizon (1e-9: the recursion's round-off relative to the output's spread).
    void trueModelOnNoiseFreeDataFits100() {
        std::vector<double> e;
        const PolynomialModel m = bjModel({1.0, -0.3}, {1.0, -0.7});
        const IoData d = bjData(m, 500, 0.0, 2, e);
        XYT_COMPARE_NEAR(simulationFit(m, d).fitPercent, 100.0, 0.0, 1e-9);
        for (int k : {1, 5, 1000})
            XYT_COMPARE_NEAR(predictionFit(m, d, k).fitPercent, 100.0, 0.0, 1e-9);
        const FitReport r = fitReport(m, d, &d, 3);
        QVERIFY(r.validationPrediction && r.validationSimulation);
        QCOMPARE(r.estimationPrediction.horizon, 3);
        QCOMPARE(r.estimationSimulation.horizon, 0);
    }

    // Invariant (Ljung Sec. 3.2): the one-step prediction errors of the true model are its
    // innovations e (from rest, as the data were made). BJ with C and D: 1e-12 of sigma.
    void oneStepErrorsOfTrueModelAreTheInnovations() {
        std::vector<double> e;
        const PolynomialModel m = bjModel({1.0, -0.3}, {1.0, -0.7});
        const IoData d = bjData(m, 500, 0.5, 3, e);
        QVERIFY(maxAbsDiff(predictionErrors(m, d), e) <= 1e-12);
        // ... and for ARX (A != 1): Patrick, Ishak and Adnan's model with equation noise.
        PolynomialModel arx;
        arx.a = kPaperA;
        arx.b = kPaperB;
        arx.tsSeconds = 0.07;
        const std::vector<double> u = randomBinary(300, 1.0, 4);
        const std::vector<double> w = gaussianNoise(300, 0.01, 5);
        const IoData da = ioData(u,
                                 plus(filterDifferenceEquation(kPaperB, kPaperA, u),
                                      filterDifferenceEquation({1.0}, kPaperA, w)),
                                 0.07);
        QVERIFY(maxAbsDiff(predictionErrors(arx, da), w) <= 1e-12);
    }

    // Closed form of the k-step predictor for AR(1) noise v = e / (1 - 0.8 q^-1):
    // yhat(t|t-k) = G u(t) + 0.8^k (y(t-k) - G u(t-k)) (Ljung Example 3.2). 1e-12.
    void kStepPredictorClosedForm() {
        std::vector<double> e;
        const PolynomialModel m = bjModel({1.0}, {1.0, -0.8});
        const IoData d = bjData(m, 400, 0.5, 6, e);
        const std::vector<double> w = filterDifferenceEquation(kB, kF, d.u);
        for (int k : {1, 2, 7}) {
            const std::vector<double> yhat = predictModel(m, d, k);
            std::vector<double> expected(w);
            for (std::size_t t = static_cast<std::size_t>(k); t < expected.size(); ++t)
                expected[t] += std::pow(0.8, k) * (d.y[t - static_cast<std::size_t>(k)] -
                                                   w[t - static_cast<std::size_t>(k)]);
            QVERIFY2(maxAbsDiff(yhat, expected) <= 1e-12, qPrintable(QString::number(k)));
        }
        // A horizon of N or more is the simulation.
        QVERIFY(maxAbsDiff(predictModel(m, d, 400), w) <= 1e-12);
        QVERIFY_THROWS_EXCEPTION(InvalidInput, predictModel(m, d, 0));
    }

    // Closed forms: FPE = V (1 + d/N) / (1 - d/N), AIC = N ln V + 2 d.
    void informationCriteriaClosedForm() {
        const InformationCriteria c = informationCriteria(2.0, 100, 4);
        XYT_COMPARE_NEAR(c.fpe, 2.0 * 1.04 / 0.96, 1e-15, 0.0);
        XYT_COMPARE_NEAR(c.aic, 100.0 * std::log(2.0) + 8.0, 1e-15, 0.0);
        QVERIFY_THROWS_EXCEPTION(InvalidInput, informationCriteria(0.0, 100, 4));
        QVERIFY_THROWS_EXCEPTION(InvalidInput, informationCriteria(1.0, 4, 4));
    }

    // The order table on ARX(2,3,1) data (Patrick, Ishak and Adnan's model, fixed seed): 9 rows,
    // losses over the common samples 3 .. N-1, the (2,3,1) row's loss equal to that estimate's own
    // loss (same rows), and AIC picks ARX(2,3,1) (the under-fitted orders have far larger losses,
    // the over-fitted ones pay 2 per parameter for a loss drop of about 1 per parameter).
    void arxOrderTable() {
        const std::vector<double> u = randomBinary(600, 1.0, 7);
        const std::vector<double> w = gaussianNoise(600, 0.01, 8);
        const IoData d = ioData(u,
                                plus(filterDifferenceEquation(kPaperB, kPaperA, u),
                                     filterDifferenceEquation({1.0}, kPaperA, w)),
                                0.07);
        const std::vector<double> u2 = randomBinary(600, 1.0, 9);
        const std::vector<double> w2 = gaussianNoise(600, 0.01, 10);
        const IoData v = ioData(u2,
                                plus(filterDifferenceEquation(kPaperB, kPaperA, u2),
                                     filterDifferenceEquation({1.0}, kPaperA, w2)),
                                0.07);
        int calls = 0;
        const ArxOrderTable t = xyt::arxOrderTable(d, &v, {1, 3}, {1, 3}, {1, 1}, [&](double) {
            ++calls;
            return true;
        });
        QCOMPARE(t.rows.size(), std::size_t{9});
        QCOMPARE(t.commonFirstRow, std::size_t{3});
        QVERIFY(calls >= 9);
        QVERIFY(t.bestAic.has_value() && t.bestValidation.has_value());
        const ArxOrderRow& best = t.rows[*t.bestAic];
        QVERIFY(best.orders.na >= 2 && best.orders.nb >= 3);
        const ArxResult r = estimateArx(d, ArxOrders{2, 3, 1});
        const ArxOrderRow& truthRow = t.rows[5]; // (na - 1) * 3 + (nb - 1): na outer, nb inner
        QCOMPARE(truthRow.orders.na, 2);
        QCOMPARE(truthRow.orders.nb, 3);
        XYT_COMPARE_NEAR(truthRow.loss, r.loss, 1e-12, 0.0);
        XYT_COMPARE_NEAR(truthRow.aic, 597.0 * std::log(r.loss) + 10.0, 1e-12, 0.0);
        QVERIFY(t.rows[0].loss > 10.0 * truthRow.loss); // ARX(1,1,1)
        const ArxOrderRow& bestV = t.rows[*t.bestValidation];
        QVERIFY(bestV.orders.na >= 2 && bestV.orders.nb >= 3);
        // Cancel: the rows so far are kept.
        const ArxOrderTable c = xyt::arxOrderTable(d, nullptr, {1, 3}, {1, 3}, {1, 1},
                                                   [](double f) { return f < 0.3; });
        QVERIFY(c.cancelled);
        QVERIFY(!c.rows.empty() && c.rows.size() < 9);
        QVERIFY_THROWS_EXCEPTION(InvalidInput,
                                 xyt::arxOrderTable(d, nullptr, {3, 1}, {1, 3}, {1, 1}));
    }

    // White residuals independent of u pass (fixed seed), residuals coloured by
    // 1 / (1 - 0.5 q^-1) fail whiteness at lag 1 (r(1) = 0.5 against a bound of 0.08), and
    // residuals containing 0.3 u(t-2) fail independence at lag +2.
    void residualTestsPassAndFail() {
        const std::size_t n = 1000;
        const std::vector<double> u = randomBinary(n, 1.0, 11);
        const std::vector<double> white = gaussianNoise(n, 1.0, 12);
        const ResidualAnalysis ok = residualAnalysis(white, u);
        XYT_COMPARE_NEAR(ok.autocorrelation.bound, 2.576 / std::sqrt(1000.0), 1e-15, 0.0);
        QCOMPARE(ok.autocorrelation.lags.size(), std::size_t{25});
        QCOMPARE(ok.crossCorrelation.lags.size(), std::size_t{51});
        QCOMPARE(ok.crossCorrelation.lags.front(), -25);
        QVERIFY(ok.passed());
        const ResidualAnalysis coloured =
            residualAnalysis(filterDifferenceEquation({1.0}, {1.0, -0.5}, white), u);
        QVERIFY(!coloured.autocorrelation.passed);
        QCOMPARE(coloured.autocorrelation.worstLag, 1);
        XYT_COMPARE_NEAR(coloured.autocorrelation.worstValue, 0.5, 0.0, 4.0 / std::sqrt(1000.0));
        std::vector<double> leak = white;
        for (std::size_t t = 2; t < n; ++t)
            leak[t] += 0.3 * u[t - 2];
        const ResidualAnalysis dyn = residualAnalysis(leak, u);
        QVERIFY(!dyn.crossCorrelation.passed);
        QCOMPARE(dyn.crossCorrelation.worstLag, 2);
        QVERIFY(dyn.autocorrelation.passed || dyn.autocorrelation.worstValue < 0.2);
    }

    // The false-alarm rate the 99 % bound implies, measured over 400 seeds of white residuals
    // (N = 1000): 1 % per lag (10 000 autocorrelation lags: 100 expected, binomial SD 10, so
    // 60..140 is 4 SD), and 1 - 0.99^25 = 22 % for the whole whiteness test (400 tests: 89
    // expected, SD 8.3, so 22 % +- 8.3 points is 4 SD).
    void falseAlarmRateOfThe99PercentBound() {
        int outside = 0, failedTests = 0;
        for (std::uint64_t seed = 0; seed < 400; ++seed) {
            const std::vector<double> u = randomBinary(1000, 1.0, 20000 + seed);
            const std::vector<double> e = gaussianNoise(1000, 1.0, 30000 + seed);
            const ResidualAnalysis r = residualAnalysis(e, u);
            outside += r.autocorrelation.outsideCount;
            failedTests += r.autocorrelation.passed ? 0 : 1;
        }
        QVERIFY2(outside >= 60 && outside <= 140, qPrintable(QString::number(outside)));
        const double rate = failedTests / 400.0;
        const double expected = 1.0 - std::pow(0.99, 25);
        QVERIFY2(std::abs(rate - expected) <= 4.0 * std::sqrt(expected * (1 - expected) / 400.0),
                 qPrintable(QString::number(rate)));
    }

    // A constructed zero at z = 2.5 (B = q^-1 - 2.5 q^-2) is flagged non-minimum-phase with the
    // ZPETC note; B = q^-1 + 0.5 q^-2 (zero at -0.5) is not.
    void nonMinimumPhaseZeroIsFlagged() {
        PolynomialModel m;
        m.b = {0.0, 1.0, -2.5};
        m.f = kF;
        m.tsSeconds = 0.01;
        const ModelRoots r = modelRoots(m);
        QCOMPARE(r.zeros.size(), std::size_t{1});
        QVERIFY(std::abs(r.zeros[0] - 2.5) <= 1e-12);
        QVERIFY(r.nonMinimumPhase);
        QVERIFY(r.stable);
        QCOMPARE(r.notes.size(), std::size_t{1});
        QVERIFY(r.notes[0].text.find("ZPETC") != std::string::npos);
        m.b = kB;
        const ModelRoots mp = modelRoots(m);
        QVERIFY(!mp.nonMinimumPhase);
        QVERIFY(hasRoot(mp.zeros, -0.5, 1e-12));
        // Poles of F: 0.75 +- i sqrt(0.7 - 0.5625) (closed form of z^2 - 1.5 z + 0.7).
        QVERIFY(hasRoot(mp.poles, {0.75, std::sqrt(0.7 - 0.5625)}, 1e-12));
        QVERIFY(hasRoot(mp.poles, {0.75, -std::sqrt(0.7 - 0.5625)}, 1e-12));
    }

    // Patrick, Ishak and Adnan's x-axis model: B = 0.0421 z^2 + 0.0628 z - 0.0454 has the zero
    // (-0.0628 - sqrt(0.0628^2 + 4 0.0421 0.0454)) / (2 0.0421) = -2.02 outside the unit circle:
    // the reason the paper uses ZPETC.
    void paperModelIsNonMinimumPhase() {
        PolynomialModel m;
        m.a = kPaperA;
        m.b = kPaperB;
        m.tsSeconds = 0.07;
        const ModelRoots r = modelRoots(m);
        const double z =
            (-0.0628 - std::sqrt(0.0628 * 0.0628 + 4 * 0.0421 * 0.0454)) / (2 * 0.0421);
        QVERIFY(hasRoot(r.zeros, z, 1e-12));
        QVERIFY(r.nonMinimumPhase);
    }

    // Braga et al.'s lower base at 10 ms: continuous poles 0 and (-125.3 +- sqrt(125.3^2 -
    // 4 3665)) / 2, z-poles e^{p Ts} (1e-9), and the ZOH sampling zeros of relative degree 3
    // (Astrom, Hagander & Sternby 1984: -3.73 and -0.27 as Ts -> 0; -2.76 and -0.19 at 10 ms),
    // here the quadratic formula on GNU Octave's c2d numerator (tests/data/gt_zoh.csv), 1e-9.
    // The zero outside the unit circle is flagged.
    void thirdOrderPlantRootsOfThePaper() {
        const ModelRoots r = thirdOrderPlantRoots(findGtPreset("lower-base")->plant, 0.01);
        const double disc = std::sqrt(125.3 * 125.3 - 4 * 3665.0);
        const std::vector<double> p{0.0, (-125.3 + disc) / 2, (-125.3 - disc) / 2};
        QCOMPARE(r.continuousPoles.size(), std::size_t{3});
        for (double s : p) {
            QVERIFY(hasRoot(r.continuousPoles, s, 1e-9));
            QVERIFY(hasRoot(r.poles, std::exp(s * 0.01), 1e-9));
        }
        QVERIFY(r.continuousZeros.empty());
        QCOMPARE(r.zeros.size(), std::size_t{2});
        QVERIFY(r.nonMinimumPhase);
        QVERIFY(!r.stable);     // the integrator: a pole at z = 1
        QVERIFY(r.integrating); // ... and nothing else outside: integrating, not unstable
        // A pole just outside beside the integrator is unstable (1 + 1e-3 is 1000 times the
        // tolerance away from 1), and so is a pole at -1.
        PolynomialModel m;
        m.b = {0.0, 1.0};
        m.tsSeconds = 0.01;
        m.a = {1.0, -2.001, 1.001}; // (1 - z^-1)(1 - 1.001 z^-1)
        QVERIFY(!modelRoots(m).stable && !modelRoots(m).integrating);
        m.a = {1.0, -1.5, 0.5}; // (1 - z^-1)(1 - 0.5 z^-1)
        QVERIFY(!modelRoots(m).stable && modelRoots(m).integrating);
        m.a = {1.0, 0.0, -1.0}; // poles at +1 and -1
        QVERIFY(!modelRoots(m).integrating);
        const CsvTable zoh = readCsv(QStringLiteral("gt_zoh.csv"));
        std::size_t row = 0;
        while (row < zoh.rows.size() && !(zoh.rows[row][0] == QStringLiteral("lower-base plant") &&
                                          zoh.number(row, QStringLiteral("ts")) == 0.01 &&
                                          zoh.rows[row][2] == QStringLiteral("num")))
            ++row;
        QVERIFY(row < zoh.rows.size());
        const double a = zoh.number(row, QStringLiteral("c2"));
        const double b = zoh.number(row, QStringLiteral("c3"));
        const double c = zoh.number(row, QStringLiteral("c4"));
        const double root = std::sqrt(b * b - 4 * a * c);
        QVERIFY(hasRoot(r.zeros, (-b - root) / (2 * a), 1e-9));
        QVERIFY(hasRoot(r.zeros, (-b + root) / (2 * a), 1e-9));
        QVERIFY(std::abs(r.zeros[0]) > 1.0);
    }
};

QTEST_APPLESS_MAIN(TstValidation)
#include "tst_validation.moc"
