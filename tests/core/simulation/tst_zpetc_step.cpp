// SPDX-License-Identifier: GPL-3.0-or-later
// The step figures of a pole-placement axis as it runs with its ZPETC: the paper's
// x axis must not look failed for the overshoot of its feedback loop alone.
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/errors.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/zpetc_step.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace xyt;

class TstZpetcStep : public QObject {
    Q_OBJECT
private slots:
    void equalsThePartialSumsOfTheZeroPhaseFir_data();
    void equalsThePartialSumsOfTheZeroPhaseFir();
    void badBandThrows();
    void sessionJudgesThePolePlacementAxisOnWhatItRuns();
};

void TstZpetcStep::equalsThePartialSumsOfTheZeroPhaseFir_data() {
    QTest::addColumn<QVector<double>>("a");
    QTest::addColumn<QVector<double>>("b");
    // Patrick, Ishak and Adnan Table 1 (x and y axes), T = 1 - 0.2 z^-1, Ts = 0.07 s.
    QTest::newRow("x axis of Patrick, Ishak and Adnan")
        << QVector<double>{1, -1.658, 0.6583} << QVector<double>{0, 0.0421, 0.0628, -0.0454};
    QTest::newRow("y axis of Patrick, Ishak and Adnan")
        << QVector<double>{1, -1.459, 0.4587} << QVector<double>{0, 0.0352, 0.0599, -0.0067};
}

void TstZpetcStep::equalsThePartialSumsOfTheZeroPhaseFir() {
    QFETCH(QVector<double>, a);
    QFETCH(QVector<double>, b);
    const PolePlacementDesign loop =
        designPolePlacement(Polynomial::fromAscending({a.begin(), a.end()}),
                            Polynomial::fromAscending({b.begin(), b.end()}),
                            Polynomial::fromAscending({1.0, -0.2}), 0.07);
    const ZpetcDesign z = designZpetc(loop);
    // With the feedforward ahead of it the loop's T and B+ cancel (Patrick, Ishak and Adnan Eq.
    // 11-13): the axis is the FIR h = B-(z^-1) B-(z) / [B-(1)]^2 applied to r(k + s), s = deg B-.
    // Its unit step is the partial sums of h: y(K - s + m) = h_0 + ... + h_m, m = 0 .. 2s.
    const int s = z.bMinus.degree();
    std::vector<double> partial;
    double sum = 0.0;
    for (int m = 0; m <= 2 * s; ++m)
        partial.push_back(sum += z.overallFir.ascending()[static_cast<std::size_t>(m)]);
    XYT_COMPARE_NEAR(sum, 1.0, 1e-12, 0.0); // DC gain 1 by construction
    const double peak = *std::max_element(partial.begin(), partial.end());
    int lastOutside = -1;
    for (int m = 0; m <= 2 * s; ++m)
        if (std::abs(partial[static_cast<std::size_t>(m)] - 1.0) > 0.02)
            lastOutside = m;
    const StepCharacteristics st = zpetcStepCharacteristics(loop, z);
    QVERIFY(st.stable);
    // Round-off: the loop runs some 10^2 samples of a difference equation with coefficients of
    // order 10, so 1e-10 absolute is far above it and far below any figure that matters.
    XYT_COMPARE_NEAR(st.finalValue, 1.0, 0.0, 1e-10);
    XYT_COMPARE_NEAR(st.overshootPct, std::max(0.0, (peak - 1.0) * 100.0), 0.0, 1e-8);
    // Settling counted from the step instant K; the FIR's sample m sits at K - s + m.
    const double expectedSettling = std::max(0, lastOutside + 1 - s) * 0.07;
    XYT_COMPARE_NEAR(st.settlingTimeSeconds, expectedSettling, 1e-12, 1e-12);
    // And the feedback loop alone (Kf B / T) overshoots more (52 % for the x axis): what the
    // panel used to judge.
    QVERIFY(st.overshootPct < 52.0);
}

void TstZpetcStep::badBandThrows() {
    const PolePlacementDesign loop =
        designPolePlacement(Polynomial::fromAscending({1, -1.658, 0.6583}),
                            Polynomial::fromAscending({0, 0.0421, 0.0628, -0.0454}),
                            Polynomial::fromAscending({1.0, -0.2}), 0.07);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, zpetcStepCharacteristics(loop, designZpetc(loop), 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, zpetcStepCharacteristics(loop, designZpetc(loop), 1.0));
}

void TstZpetcStep::sessionJudgesThePolePlacementAxisOnWhatItRuns() {
    // The x axis of Patrick, Ishak and Adnan was marked failed for "overshoot 52.363 %", the step
    // of its feedback loop alone; with ZPETC on, the session's step figures are the axis's own.
    Session s;
    s.axes[0].method = DesignMethod::PolePlacementZpetc;
    const AxisEvaluation with = evaluateSession(s).axes[0];
    QVERIFY(with.ok && with.pp && with.zpetc);
    const StepCharacteristics expected = zpetcStepCharacteristics(*with.pp, *with.zpetc);
    QCOMPARE(with.step.overshootPct, expected.overshootPct);
    QCOMPARE(with.step.settlingTimeSeconds, expected.settlingTimeSeconds);
    s.axes[0].pp.zpetcEnabled = false;
    const AxisEvaluation without = evaluateSession(s).axes[0];
    QVERIFY(without.step.overshootPct > 50.0); // Kf B / T alone: the NMP zero's 52 %
    QVERIFY(with.step.overshootPct < without.step.overshootPct);
}

QTEST_APPLESS_MAIN(TstZpetcStep)
#include "tst_zpetc_step.moc"
