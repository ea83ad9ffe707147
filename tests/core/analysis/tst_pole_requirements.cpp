// SPDX-License-Identifier: GPL-3.0-or-later
// The specification as a region of the s- and z-plane (the root-locus overlay).
#include "core/analysis/pole_requirements.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>

using namespace xyt;

class TstPoleRequirements : public QObject {
    Q_OBJECT
private slots:
    void dampingInvertsTheOvershootFormula();
    void settlingLineAndCircle();
    void polesAreJudged();
};

void TstPoleRequirements::dampingInvertsTheOvershootFormula() {
    // Closed form: Mp = exp(-pi zeta / sqrt(1 - zeta^2)); the inverse must round-trip to
    // round-off (1e-12: a log, a sqrt and an exp).
    for (double zeta : {0.1, 0.3, 0.5, 1.0 / std::sqrt(2.0), 0.9}) {
        const double mpPct = 100.0 * std::exp(-M_PI * zeta / std::sqrt(1.0 - zeta * zeta));
        XYT_COMPARE_NEAR(dampingForOvershoot(mpPct), zeta, 1e-12, 0.0);
    }
    QCOMPARE(dampingForOvershoot(0.0), 1.0); // no overshoot: only the negative real axis
    QCOMPARE(dampingForOvershoot(100.0), 0.0);
    QCOMPARE(dampingForOvershoot(250.0), 0.0);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, dampingForOvershoot(-1.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, dampingForOvershoot(NAN));
}

void TstPoleRequirements::settlingLineAndCircle() {
    const PoleRequirements r = poleRequirements(10.0, 100.0);
    QCOMPARE(r.maxRealPartPerSec, -0.04);
    XYT_COMPARE_NEAR(settlingRadius(r, 0.07), std::exp(-4.0 * 0.07 / 100.0), 1e-15, 0.0);
    QVERIFY(std::isinf(poleRequirements(10.0, INFINITY).maxRealPartPerSec));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, poleRequirements(10.0, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, settlingRadius(r, 0.0));
}

void TstPoleRequirements::polesAreJudged() {
    const PoleRequirements r = poleRequirements(4.32, 4.0); // zeta >= 0.707, Re s <= -1
    QVERIFY(!checkPole({-2.0, 1.0}, r).any());
    QVERIFY(checkPole({-2.0, 3.0}, r).damping);  // zeta 0.55
    QVERIFY(checkPole({-0.5, 0.0}, r).settling); // too slow
    QVERIFY(!checkPole({-0.5, 0.0}, r).damping);
    QVERIFY(checkPole({0.0, 0.0}, r).settling); // an integrator never settles
    // zeta = 1: a real pole with a round-off imaginary part passes, a complex one fails.
    const PoleRequirements none = poleRequirements(0.0, 100.0);
    QVERIFY(!checkPole({-1.0, 1e-9}, none).damping);
    QVERIFY(checkPole({-1.0, 1e-3}, none).damping);
    // Discrete: through s = ln(z) / Ts; |z| above exp(-4 Ts / ts) is too slow.
    const double ts = 0.07, radius = settlingRadius(r, ts);
    QVERIFY(checkPole({radius * 1.001, 0.0}, r, ts).settling);
    QVERIFY(!checkPole({radius * 0.999, 0.0}, r, ts).settling);
    QVERIFY(checkPole({-0.2, 0.0}, r, ts).damping); // a negative real z oscillates at Nyquist
}

QTEST_APPLESS_MAIN(TstPoleRequirements)
#include "tst_pole_requirements.moc"
