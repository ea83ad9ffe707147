// SPDX-License-Identifier: GPL-3.0-or-later
// Stability margins: closed forms, the root locus as an independent computation of
// the gain margins, GNU Octave's margin and norm(., Inf) on random loops, dense-grid bounds.
#include "core/analysis/frequency_response.h"
#include "core/analysis/root_locus.h"
#include "core/analysis/stability_margins.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/model/errors.h"
#include "tests/support/random_loops.h"
#include "tests/support/reference_data.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace xyt;
Q_DECLARE_METATYPE(xyt::TransferFunction)

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

TransferFunction gtOpenLoop(const char* preset) {
    const GtPreset p = *findGtPreset(preset);
    return designGuilleminTruxal(p.plant, p.omegaNRadPerSec, p.kp).openLoop;
}

/// Patrick, Ishak and Adnan's x axis (Eq. 1) with T = 1 - 0.2 z^-1, Ts = 0.07: the RST loop L = B
/// G/(A F).
TransferFunction paperXAxisLoop() {
    const PolePlacementDesign d =
        designPolePlacement(Polynomial::fromAscending({1.0, -1.658, 0.6583}),
                            Polynomial::fromAscending({0.0, 0.0421, 0.0628, -0.0454}),
                            Polynomial::fromAscending({1.0, -0.2}), 0.07);
    return TransferFunction::fromZInverse(d.b * d.g, d.a * d.f, d.tsSeconds);
}

Polynomial descendingCell(const QString& cell) {
    std::vector<double> c;
    for (const QString& v : cell.split(' ', Qt::SkipEmptyParts))
        c.push_back(v.toDouble());
    return Polynomial::fromDescending(c);
}

/// Max of |top/(D + N)| over a dense log grid (400 000 points), then over 20 000 points within
/// two grid steps of the best one: a lower bound of the exact peak, close to it.
double densePeak(const TransferFunction& l, bool sensitivity) {
    const double ts = l.tsSeconds();
    const double hi = ts > 0.0 ? kPi / ts : 1e8;
    auto value = [&](double w) {
        const auto x = boundaryPoint(w, ts);
        const auto top = sensitivity ? l.den()(x) : l.num()(x);
        return std::abs(top / (l.den()(x) + l.num()(x)));
    };
    const std::vector<double> grid = logFrequencyGrid(ts > 0.0 ? 1e-4 : 1e-6, hi, 400000);
    std::size_t bestIndex = 0;
    double best = value(0.0); // the peak may sit at omega = 0
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (value(grid[i]) > best) {
            best = value(grid[i]);
            bestIndex = i;
        }
    const double a = grid[bestIndex > 1 ? bestIndex - 2 : 0];
    const double b = grid[std::min(bestIndex + 2, grid.size() - 1)];
    for (int i = 0; i <= 20000; ++i)
        best = std::max(best, value(a + (b - a) * i / 20000.0));
    return best;
}

} // namespace

class TstStabilityMargins : public QObject {
    Q_OBJECT
private slots:
    void thirdOrderTypeOneClosedForm_data();
    void thirdOrderTypeOneClosedForm();
    void secondOrderTypeOneClosedForm();
    void discreteIntegratorClosedForms();
    void unstableOpenLoopLowerGainMargin();
    void firstOrderBandwidth();
    void gainMarginEqualsRootLocusCrossing_data();
    void gainMarginEqualsRootLocusCrossing();
    void randomLoopsGainMarginEqualsRootLocus();
    void octaveReference();
    void peaksBoundDenseGrid();
    void improperLoopThrows();
};

// Closed form: L = K/(s(s+1)(s+2)), L(j w) = K/(-3 w^2 + j w (2 - w^2)): real where w^2 = 2,
// L = -K/6 there, so GM = 6/K at w = sqrt 2 (every K, also K > 6 where the loop is unstable).
void TstStabilityMargins::thirdOrderTypeOneClosedForm_data() {
    QTest::addColumn<double>("k");
    QTest::newRow("K=1") << 1.0;
    QTest::newRow("K=2") << 2.0;
    QTest::newRow("K=10 (unstable closed loop)") << 10.0;
}

void TstStabilityMargins::thirdOrderTypeOneClosedForm() {
    QFETCH(double, k);
    const StabilityMargins m =
        stabilityMargins(TransferFunction::fromDescending({k}, {1.0, 3.0, 2.0, 0.0}));
    QCOMPARE(m.gainMargins.size(), std::size_t(1));
    // 1e-12: the root of a cubic in u, refined by Newton on log|L|, is exact to a few ulps.
    XYT_COMPARE_NEAR(m.gainMarginOmegaRadPerSec, std::sqrt(2.0), 1e-12, 0.0);
    XYT_COMPARE_NEAR(m.gainMarginFactor, 6.0 / k, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m.gainMarginDb, 20.0 * std::log10(6.0 / k), 1e-12, 1e-12);
    QCOMPARE(m.closedLoopStable, k < 6.0);
    QCOMPARE(m.phaseMargins.size(), std::size_t(1));
}

// Closed form: L = K/(s(s+1)): |L(j w)| = 1 <=> w^4 + w^2 - K^2 = 0, so
// wc^2 = (sqrt(1 + 4K^2) - 1)/2, PM = 90 - atan(wc) degrees; no phase crossover (GM = inf).
// T = K/(s^2 + s + K) is the standard second order with wn = sqrt K, zeta = 1/(2 sqrt K):
// Mt = 1/(2 zeta sqrt(1 - zeta^2)) at wn sqrt(1 - 2 zeta^2), and the -3 dB bandwidth
// wn sqrt(1 - 2 zeta^2 + sqrt(4 zeta^4 - 4 zeta^2 + 2)) (textbook formulas, e.g. Ogata 7-3).
void TstStabilityMargins::secondOrderTypeOneClosedForm() {
    for (const double k : {0.3, 1.0, 4.0, 25.0}) {
        const StabilityMargins m =
            stabilityMargins(TransferFunction::fromDescending({k}, {1.0, 1.0, 0.0}));
        const double wc = std::sqrt((std::sqrt(1.0 + 4.0 * k * k) - 1.0) / 2.0);
        const double pm = 90.0 - std::atan(wc) * kDeg;
        QVERIFY(m.gainMargins.empty());
        QVERIFY(std::isinf(m.gainMarginFactor) && std::isinf(m.gainMarginDb));
        QVERIFY(std::isnan(m.gainMarginOmegaRadPerSec));
        QCOMPARE(m.phaseMargins.size(), std::size_t(1));
        XYT_COMPARE_NEAR(m.phaseMarginOmegaRadPerSec, wc, 1e-12, 0.0);
        XYT_COMPARE_NEAR(m.phaseMarginDeg, pm, 1e-12, 0.0);
        XYT_COMPARE_NEAR(m.delayMarginSeconds, pm / kDeg / wc, 1e-12, 0.0);
        QVERIFY(std::isnan(m.delayMarginSamples));
        const double wn = std::sqrt(k), zeta = 1.0 / (2.0 * wn);
        if (zeta < 1.0 / std::sqrt(2.0)) {
            XYT_COMPARE_NEAR(m.peakComplementarySensitivity,
                             1.0 / (2.0 * zeta * std::sqrt(1.0 - zeta * zeta)), 1e-12, 0.0);
            // The peak frequency is a stationary point: found from a polynomial root, exact to
            // about sqrt(eps) relative only where the peak is flat; 1e-7.
            XYT_COMPARE_NEAR(m.peakComplementarySensitivityOmegaRadPerSec,
                             wn * std::sqrt(1.0 - 2.0 * zeta * zeta), 1e-7, 0.0);
        } else {
            XYT_COMPARE_NEAR(m.peakComplementarySensitivity, 1.0, 1e-12, 0.0); // at w = 0
        }
        const double z2 = zeta * zeta;
        XYT_COMPARE_NEAR(m.bandwidthRadPerSec,
                         wn * std::sqrt(1.0 - 2.0 * z2 + std::sqrt(4.0 * z2 * z2 - 4.0 * z2 + 2.0)),
                         1e-12, 0.0);
        QVERIFY(m.closedLoopStable);
    }
}

// Closed forms derived here, theta = w Ts:
// L1 = K z^-1/(1 - z^-1) = K/(z - 1): L1(e^{j theta}) = K e^{-j theta/2}/(2 j sin(theta/2)),
//   |L1| = K/(2 sin(theta/2)), arg L1 = -90 - theta/2 degrees. Phase crossover only at z = -1
//   (theta = pi): L1 = -K/2, GM = 2/K at w = pi/Ts (the closed-loop pole 1 - K leaves at K = 2).
//   Gain crossover: theta_c = 2 asin(K/2), PM = 90 deg - asin(K/2), delay margin
//   PM / theta_c samples.
// L2 = K/(z (z - 1)) (one more sample of delay): arg L2 = -90 - 3 theta/2 degrees, -180 at
//   theta = pi/3 where |L2| = K/(2 sin(pi/6)) = K: GM = 1/K at w = pi/(3 Ts) (z^2 - z + K has
//   |z|^2 = K); theta_c = 2 asin(K/2) as above, PM = 90 deg - 3 asin(K/2).
// Octave's margin agrees on L1 with K = 0.5, Ts = 0.1: GM 4 at 31.416, PM 75.522 at 5.0536.
void TstStabilityMargins::discreteIntegratorClosedForms() {
    const double ts = 0.1;
    for (const double k : {0.1, 0.5, 0.9}) {
        const double thetaC = 2.0 * std::asin(k / 2.0);
        {
            const StabilityMargins m = stabilityMargins(TransferFunction(
                Polynomial::constant(k), Polynomial::fromDescending({1.0, -1.0}), ts));
            QCOMPARE(m.gainMargins.size(), std::size_t(1));
            XYT_COMPARE_NEAR(m.gainMarginOmegaRadPerSec, kPi / ts, 1e-14, 0.0);
            XYT_COMPARE_NEAR(m.gainMarginFactor, 2.0 / k, 1e-12, 0.0);
            QCOMPARE(m.phaseMargins.size(), std::size_t(1));
            XYT_COMPARE_NEAR(m.phaseMarginOmegaRadPerSec, thetaC / ts, 1e-12, 0.0);
            const double pm = 90.0 - std::asin(k / 2.0) * kDeg;
            XYT_COMPARE_NEAR(m.phaseMarginDeg, pm, 1e-12, 0.0);
            XYT_COMPARE_NEAR(m.delayMarginSamples, pm / kDeg / thetaC, 1e-12, 0.0);
            XYT_COMPARE_NEAR(m.delayMarginSeconds, pm / kDeg / thetaC * ts, 1e-12, 0.0);
        }
        {
            const StabilityMargins m = stabilityMargins(TransferFunction(
                Polynomial::constant(k), Polynomial::fromDescending({1.0, -1.0, 0.0}), ts));
            QCOMPARE(m.gainMargins.size(), std::size_t(1));
            XYT_COMPARE_NEAR(m.gainMarginOmegaRadPerSec, kPi / (3.0 * ts), 1e-12, 0.0);
            XYT_COMPARE_NEAR(m.gainMarginFactor, 1.0 / k, 1e-12, 0.0);
            XYT_COMPARE_NEAR(m.phaseMarginOmegaRadPerSec, thetaC / ts, 1e-12, 0.0);
            XYT_COMPARE_NEAR(m.phaseMarginDeg, 90.0 - 3.0 * std::asin(k / 2.0) * kDeg, 1e-12, 0.0);
        }
    }
}

// Closed form: L = 2 (s + 1)/(s (s - 1)), one unstable open-loop pole. The closed loop of g L,
// s^2 + (2g - 1) s + 2g, is stable for g > 1/2 only: the loop tolerates any gain increase but
// a decrease by 1/2, where the poles cross at s = +-j (L(j) = -2).
void TstStabilityMargins::unstableOpenLoopLowerGainMargin() {
    const StabilityMargins m =
        stabilityMargins(TransferFunction::fromDescending({2.0, 2.0}, {1.0, -1.0, 0.0}));
    QVERIFY(m.closedLoopStable);
    QCOMPARE(m.gainMargins.size(), std::size_t(1));
    XYT_COMPARE_NEAR(m.gainMarginFactor, 0.5, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m.gainMarginOmegaRadPerSec, 1.0, 1e-12, 0.0);
    XYT_COMPARE_NEAR(m.lowerGainMarginFactor, 0.5, 1e-12, 0.0);
    QVERIFY(std::isinf(m.upperGainMarginFactor));
    QVERIFY(m.gainMarginDb < 0.0);
}

// Closed form: L = 1/s gives T = 1/(s + 1) (bandwidth exactly 1 rad/s, Mt = 1 at w = 0) and
// S = s/(s + 1) (|S| rises to 1 as w -> inf: Ms = 1 at the end of the axis).
void TstStabilityMargins::firstOrderBandwidth() {
    const StabilityMargins m =
        stabilityMargins(TransferFunction::fromDescending({1.0}, {1.0, 0.0}));
    XYT_COMPARE_NEAR(m.bandwidthRadPerSec, 1.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(m.peakComplementarySensitivity, 1.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(m.peakSensitivity, 1.0, 1e-14, 0.0);
    QVERIFY(std::isinf(m.peakSensitivityOmegaRadPerSec));
    XYT_COMPARE_NEAR(m.phaseMarginDeg, 90.0, 1e-12, 0.0);
}

// Cross-feature invariant: a phase crossover at w with gain factor k is a gain k at which a
// closed-loop pole of 1 + k L sits on the boundary (at j w or e^{j w Ts}); locusCrossings finds
// those gains from its own boundary polynomial. The two sets must agree, and the upper gain
// margin is the smallest crossing gain above 1.
void TstStabilityMargins::gainMarginEqualsRootLocusCrossing_data() {
    QTest::addColumn<TransferFunction>("loop");
    QTest::newRow("Braga et al.'s lower base, wn 2, kp 30 (GT, double integrator)")
        << gtOpenLoop("lower-base");
    QTest::newRow("Braga et al.'s upper base, wn 1, kp 30") << gtOpenLoop("upper-base");
    QTest::newRow("Patrick, Ishak and Adnan's x axis RST loop B G/(A F), Ts 0.07")
        << paperXAxisLoop();
}

namespace {
/// Distinct crossing gains of the root locus (conjugate pairs listed once).
std::vector<double> locusGains(const TransferFunction& l) {
    std::vector<double> k;
    for (const LocusFeature& f : locusCrossings(l.num(), l.den(), l.tsSeconds()))
        k.push_back(f.gain);
    std::sort(k.begin(), k.end());
    k.erase(std::unique(k.begin(), k.end(),
                        [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; }),
            k.end());
    return k;
}

void compareWithLocus(const TransferFunction& l) {
    const StabilityMargins m = stabilityMargins(l);
    std::vector<double> ours;
    for (const auto& c : m.gainMargins)
        ours.push_back(c.gainFactor);
    std::sort(ours.begin(), ours.end());
    const std::vector<double> locus = locusGains(l);
    if (ours.size() != locus.size())
        qDebug() << "num" << l.num().descending() << "den" << l.den().descending() << "ts"
                 << l.tsSeconds();
    QCOMPARE(ours.size(), locus.size());
    // 1e-8: both are roots refined in double precision, but the locus gain K = -D/N at a
    // boundary root is taken after its own polynomial solve (relative error about 1e-10 on the
    // 4th-order GT loops whose coefficients span 1e-3 .. 1e5).
    for (std::size_t i = 0; i < ours.size(); ++i)
        XYT_COMPARE_NEAR(ours[i], locus[i], 1e-8, 0.0);
    double upper = std::numeric_limits<double>::infinity();
    for (double k : locus)
        if (k > 1.0)
            upper = std::min(upper, k);
    XYT_COMPARE_NEAR(m.upperGainMarginFactor, upper, 1e-8, 0.0);
}
} // namespace

void TstStabilityMargins::gainMarginEqualsRootLocusCrossing() {
    QFETCH(TransferFunction, loop);
    QVERIFY(stabilityMargins(loop).closedLoopStable);
    compareWithLocus(loop);
}

void TstStabilityMargins::randomLoopsGainMarginEqualsRootLocus() {
    std::mt19937 rng(1717);
    int tested = 0;
    for (int draw = 0; draw < 1000 && tested < 50; ++draw) {
        test::RandomLoopOptions o;
        o.discrete = draw % 2 == 1;
        const TransferFunction l = test::randomLoop(rng, o);
        const test::PoleCounts c = test::poleCounts(l);
        if (c.closedLoopUnstable > 0 || c.closedLoopBoundaryDistance < 1e-6)
            continue; // the invariant is stated for stable loops
        compareWithLocus(l);
        if (QTest::currentTestFailed())
            QFAIL(qPrintable(QStringLiteral("draw %1").arg(draw)));
        ++tested;
    }
    QCOMPARE(tested, 50);
}

// GNU Octave 7.3, control 3.4.0 (tests/data/gen_margins_octave.m): margin's selection rules
// applied to our list of crossings must give Octave's numbers. Octave's rules (margin.m,
// gm_filter/pm_filter): GM = the smallest factor >= 1 (Re L in [-1, 0)), else the largest below
// 1, Inf/NaN when none, crossings at w = 0 not considered; PM = min over gain crossovers of
// 180 + arg L in (0, 360] (ours + 360 when ours <= 0), 180/NaN when none.
void TstStabilityMargins::octaveReference() {
    const test::CsvTable t = test::readCsv(QStringLiteral("margins_octave.csv"));
    QVERIFY2(t.rows.size() >= 20, "tests/data/margins_octave.csv missing or short");
    for (std::size_t row = 0; row < t.rows.size(); ++row) {
        const double ts = t.number(row, "ts");
        const TransferFunction l(descendingCell(t.rows[row][t.column("num")]),
                                 descendingCell(t.rows[row][t.column("den")]), ts);
        const StabilityMargins m = stabilityMargins(l);
        const QByteArray where = QByteArray("row ") + QByteArray::number(int(row) + 1);

        double gm = std::numeric_limits<double>::infinity(), wgm = std::nan("");
        bool above = false;
        for (const auto& c : m.gainMargins) {
            if (c.omegaRadPerSec <= 0.0)
                continue;
            if (c.gainFactor >= 1.0 && (!above || c.gainFactor < gm)) {
                gm = c.gainFactor;
                wgm = c.omegaRadPerSec;
                above = true;
            } else if (!above && c.gainFactor < 1.0 && (std::isinf(gm) || c.gainFactor > gm)) {
                gm = c.gainFactor;
                wgm = c.omegaRadPerSec;
            }
        }
        double pm = 180.0, wpm = std::nan("");
        bool anyPm = false;
        for (const auto& c : m.phaseMargins) {
            const double octavePm =
                c.phaseMarginDeg <= 0.0 ? c.phaseMarginDeg + 360.0 : c.phaseMarginDeg;
            if (!anyPm || octavePm < pm) {
                pm = octavePm;
                wpm = c.omegaRadPerSec;
                anyPm = true;
            }
        }
        // Octave takes unpolished roots of the same polynomials (no refinement, roots() of
        // the unscaled polynomial): agreement to 1e-7 relative is what its root accuracy
        // allows on these loops (observed differences are below 1e-9).
        if (!QTest::qVerify(test::near(gm, t.number(row, "gm"), 1e-7), "gm", where.constData(),
                            __FILE__, __LINE__))
            qDebug() << where << "gm ours" << gm << "octave" << t.number(row, "gm");
        QVERIFY2(test::near(wgm, t.number(row, "wgm"), 1e-7) ||
                     (std::isnan(wgm) && std::isnan(t.number(row, "wgm"))),
                 where.constData());
        XYT_COMPARE_NEAR(pm, t.number(row, "pm"), 1e-7, 1e-9);
        QVERIFY2(test::near(wpm, t.number(row, "wpm"), 1e-7) ||
                     (std::isnan(wpm) && std::isnan(t.number(row, "wpm"))),
                 where.constData());
        // norm(., Inf, 1e-10) (SLICOT AB13DD with relative tolerance 1e-10; it returned values
        // up to 3.4e-9 below the peak, which our dense-grid check confirms is exact): 1e-8.
        // The frequencies of flat peaks are not compared.
        XYT_COMPARE_NEAR(m.peakSensitivity, t.number(row, "ms"), 1e-8, 0.0);
        XYT_COMPARE_NEAR(m.peakComplementarySensitivity, t.number(row, "mt"), 1e-8, 0.0);
        QVERIFY(m.closedLoopStable);
    }
}

// Invariant: the peaks are exact maxima, so a dense grid never exceeds them and comes within its
// sampling error: after the local refinement the step is below 1e-8 of the peak's half-width
// even for the sharpest peak drawn (a closed-loop pole at |z| = 0.987), so 1e-9 relative.
void TstStabilityMargins::peaksBoundDenseGrid() {
    std::mt19937 rng(4242);
    for (int i = 0; i < 12; ++i) {
        test::RandomLoopOptions o;
        o.discrete = i % 2 == 1;
        o.maxIntegrators = 1;
        const TransferFunction l = test::randomLoop(rng, o);
        if (test::poleCounts(l).closedLoopBoundaryDistance < 1e-3)
            continue;
        const StabilityMargins m = stabilityMargins(l);
        for (const bool sensitivity : {true, false}) {
            const double exact = sensitivity ? m.peakSensitivity : m.peakComplementarySensitivity;
            const double grid = densePeak(l, sensitivity);
            QVERIFY2(grid <= exact * (1.0 + 1e-12), qPrintable(test::describe(grid, exact, 0, 0)));
            XYT_COMPARE_NEAR(grid, exact, 1e-9, 0.0);
        }
    }
}

void TstStabilityMargins::improperLoopThrows() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             stabilityMargins(TransferFunction::fromDescending({1, 0, 0}, {1, 1})));
}

QTEST_APPLESS_MAIN(TstStabilityMargins)
#include "tst_stability_margins.moc"
