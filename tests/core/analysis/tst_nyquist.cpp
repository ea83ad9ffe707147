// SPDX-License-Identifier: GPL-3.0-or-later
// Nyquist curve and encirclements: closed forms and the Nyquist criterion
// Z = N + P on random loops, with Z and P counted independently from the roots of D + N and D.
#include "core/analysis/nyquist.h"
#include "core/model/errors.h"
#include "tests/support/random_loops.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace xyt;

class TstNyquist : public QObject {
    Q_OBJECT
private slots:
    void closedForms();
    void criterionOnRandomLoops();
    void curveIsTheFrequencyResponse();
    void badOptionsThrow();
};

// Closed forms:
// - L = K/(s + 1): the curve is the circle through 0 and K, never around -1: N = 0.
// - L = 2/(s - 1): P = 1; L(j w) = -2 (1 + j w)/(1 + w^2) runs from -2 to 0 below the axis,
//   the full curve circles -1 once counterclockwise: N = -1, Z = 0 (closed loop s + 1).
// - L = K/(s (s + 1)(s + 2)): N = 0 for K < 6, N = 2 for K > 6 (two poles cross at s = j sqrt 2).
// - L = K/(z - 1) (discrete integrator, indentation at z = 1): Re L = -K/2 on the whole circle,
//   so -1 is encircled (N = 1, closed-loop pole 1 - K outside) exactly when K > 2.
void TstNyquist::closedForms() {
    struct Row {
        TransferFunction l;
        int n, p;
    };
    const std::vector<Row> rows = {
        {TransferFunction::fromDescending({3.0}, {1.0, 1.0}), 0, 0},
        {TransferFunction::fromDescending({2.0}, {1.0, -1.0}), -1, 1},
        {TransferFunction::fromDescending({5.0}, {1.0, 3.0, 2.0, 0.0}), 0, 0},
        {TransferFunction::fromDescending({7.0}, {1.0, 3.0, 2.0, 0.0}), 2, 0},
        {TransferFunction(Polynomial::constant(1.5), Polynomial::fromDescending({1.0, -1.0}), 0.1),
         0, 0},
        {TransferFunction(Polynomial::constant(3.0), Polynomial::fromDescending({1.0, -1.0}), 0.1),
         1, 0},
    };
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const NyquistCurve c = nyquistCurve(rows[i].l);
        QVERIFY2(c.warnings.empty(), qPrintable(QString::number(i)));
        QCOMPARE(c.clockwiseEncirclements, rows[i].n);
        QCOMPARE(c.openLoopUnstablePoles, rows[i].p);
        QCOMPARE(c.closedLoopUnstablePoles, rows[i].n + rows[i].p);
    }
    const NyquistCurve gt =
        nyquistCurve(TransferFunction::fromDescending({5.0}, {1.0, 3.0, 2.0, 0.0}));
    QCOMPARE(gt.indentations.size(), std::size_t(1));
    QCOMPARE(gt.indentations[0].order, 1);
}

// The Nyquist criterion on 240 random loops (fixed seed; continuous and discrete, up to two
// integrators, a quarter with an unstable open-loop pole): the encirclements counted on the
// curve plus the open-loop unstable poles equal the closed-loop unstable poles from the roots
// of D + N. Loops with a closed-loop pole within 1e-4 (relative) of the boundary are skipped:
// there the curve passes through -1 and N is not defined.
void TstNyquist::criterionOnRandomLoops() {
    std::mt19937 rng(2017);
    int tested = 0, unstableOpen = 0, unstableClosed = 0, withIntegrators = 0, discrete = 0;
    for (int draw = 0; draw < 400 && tested < 240; ++draw) {
        test::RandomLoopOptions o;
        o.discrete = draw % 2 == 1;
        o.unstablePoleChance = 0.3;
        const TransferFunction l = test::randomLoop(rng, o);
        const test::PoleCounts counts = test::poleCounts(l);
        if (counts.closedLoopBoundaryDistance < 1e-4)
            continue;
        const NyquistCurve c = nyquistCurve(l);
        const QByteArray where = "draw " + QByteArray::number(draw);
        QVERIFY2(c.warnings.empty(),
                 (where + " " + (c.warnings.empty() ? std::string() : c.warnings[0].text).c_str())
                     .constData());
        QVERIFY2(c.openLoopUnstablePoles == counts.openLoopUnstable, where.constData());
        if (c.clockwiseEncirclements + counts.openLoopUnstable != counts.closedLoopUnstable)
            QFAIL(qPrintable(QStringLiteral("%1: N %2 + P %3 != Z %4")
                                 .arg(QString::fromLatin1(where))
                                 .arg(c.clockwiseEncirclements)
                                 .arg(counts.openLoopUnstable)
                                 .arg(counts.closedLoopUnstable)));
        ++tested;
        unstableOpen += counts.openLoopUnstable > 0;
        unstableClosed += counts.closedLoopUnstable > 0;
        withIntegrators += !c.indentations.empty();
        discrete += l.isDiscrete();
    }
    QCOMPARE(tested, 240);
    // The draw covers every case the criterion has to handle.
    QVERIFY(unstableOpen >= 30);
    QVERIFY(unstableClosed >= 30);
    QVERIFY(withIntegrators >= 60);
    QVERIFY(discrete >= 100);
}

// Every point of the curve off the indentations is L at its frequency.
void TstNyquist::curveIsTheFrequencyResponse() {
    const TransferFunction l =
        TransferFunction::fromDescending({2.0, 1.0}, {1.0, 2.0, 3.0, 0.0, 0.0});
    const NyquistCurve c = nyquistCurve(l);
    QVERIFY(c.points.size() > 100);
    QCOMPARE(c.indentations.size(), std::size_t(1));
    QCOMPARE(c.indentations[0].order, 2);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (c.indentationIndex[i] >= 0 || std::isinf(c.omegaRadPerSec[i]))
            continue;
        const auto v = l.frequencyResponse(c.omegaRadPerSec[i]);
        QVERIFY(test::nearComplex(c.points[i], v, 1e-12));
    }
}

void TstNyquist::badOptionsThrow() {
    const TransferFunction l = TransferFunction::fromDescending({1.0}, {1.0, 1.0});
    NyquistOptions o;
    o.maxArgStepDeg = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, nyquistCurve(l, o));
    QVERIFY_THROWS_EXCEPTION(
        InvalidInput, nyquistCurve(TransferFunction::fromDescending({1.0, 0.0, 0.0}, {1.0, 1.0})));
}

QTEST_APPLESS_MAIN(TstNyquist)
#include "tst_nyquist.moc"
