// SPDX-License-Identifier: GPL-3.0-or-later
// The servo PID with feedforward against closed forms of LinuxCNC's pid semantics
// (core/design/servo_pid.h): P on an integrating plant, the integrator and its limit, the
// deadband, the output limit and its anti-windup, the command derivatives the feedforward
// reads, and the derivative filter.
#include "core/design/servo_pid.h"

#include <QTest>

#include <cmath>

using namespace xyt;

class TstServoPid : public QObject {
    Q_OBJECT
private slots:
    void proportionalOnAnIntegratorDecaysGeometrically();
    void integratorAccumulatesToItsLimit();
    void deadbandTakesItsWidthOff();
    void outputLimitFreezesTheIntegrator();
    void feedforwardReadsBackwardDifferences();
    void derivativeFilterIsAFirstOrderLag();
};

void TstServoPid::proportionalOnAnIntegratorDecaysGeometrically() {
    // y[k+1] = y[k] + Ts K u[k] (a velocity-commanded axis, K mm/s per V) with u = P (r - y):
    // e[k] = e0 (1 - Ts K P)^k exactly (closed form of the first-order recurrence).
    const double ts = 0.001, k = 50.0, p = 4.0, r = 10.0;
    ServoPidGains g;
    g.p = p;
    ServoPidState s = servoPidAtRest(0.0);
    double y = 0.0;
    for (int n = 0; n < 200; ++n) {
        const double expected = r * std::pow(1.0 - ts * k * p, n);
        // Tolerance: 200 steps of a contraction, each rounding once (1e-15 relative): 1e-12.
        QVERIFY(std::abs((r - y) - expected) <= 1e-12 * r);
        y += ts * k * stepServoPid(g, s, r, y, ts).output;
    }
}

void TstServoPid::integratorAccumulatesToItsLimit() {
    // A constant error e for n samples: errorI = n e Ts, until maxErrorI holds it.
    ServoPidGains g;
    g.i = 3.0;
    g.maxErrorI = 0.05;
    ServoPidState s = servoPidAtRest(0.0);
    const double e = 2.0, ts = 0.01;
    for (int n = 1; n <= 5; ++n) {
        const ServoPidTerms t = stepServoPid(g, s, e, 0.0, ts);
        const double expected = std::min(n * e * ts, g.maxErrorI);
        QVERIFY(std::abs(s.errorI - expected) <= 1e-15);
        // The first sample also sees the command's step as a derivative; I's part is 3 errorI.
        QVERIFY(std::abs(t.feedback - 3.0 * expected) <= 1e-14);
    }
    QCOMPARE(s.errorI, 0.05); // held at the limit from the third sample on
}

void TstServoPid::deadbandTakesItsWidthOff() {
    ServoPidGains g;
    g.p = 10.0;
    g.deadband = 0.01;
    for (const double e : {0.005, -0.01, 0.01}) {
        ServoPidState s = servoPidAtRest(0.0);
        QCOMPARE(stepServoPid(g, s, e, 0.0, 0.001).error, 0.0);
    }
    ServoPidState s = servoPidAtRest(0.0);
    QVERIFY(std::abs(stepServoPid(g, s, 0.03, 0.0, 0.001).output - 10.0 * 0.02) <= 1e-15);
    s = servoPidAtRest(0.0);
    QVERIFY(std::abs(stepServoPid(g, s, -0.03, 0.0, 0.001).output + 10.0 * 0.02) <= 1e-15);
}

void TstServoPid::outputLimitFreezesTheIntegrator() {
    // u = P e + I errorI beyond maxOutput: clipped, and from the next sample the integrator
    // holds while the error keeps its sign (LinuxCNC's limit_state); it integrates again once
    // the error turns.
    ServoPidGains g;
    g.p = 1.0;
    g.i = 1.0;
    g.maxOutput = 2.5;
    ServoPidState s = servoPidAtRest(0.0);
    const double ts = 0.1;
    ServoPidTerms t = stepServoPid(g, s, 5.0, 0.0, ts); // u = 5 + 0.5 > 2.5
    QCOMPARE(t.output, 2.5);
    QCOMPARE(s.limitState, 1.0);
    const double held = s.errorI; // 0.5
    QVERIFY(std::abs(held - 0.5) <= 1e-15);
    for (int n = 0; n < 3; ++n) {
        t = stepServoPid(g, s, 5.0, 0.0, ts);
        QCOMPARE(s.errorI, held);
        QCOMPARE(t.output, 2.5);
    }
    t = stepServoPid(g, s, -1.0, 0.0, ts); // the error turns: integrates, and leaves the limit
    QVERIFY(std::abs(s.errorI - (held - 0.1)) <= 1e-15);
    QVERIFY(std::abs(t.output - (-1.0 + held - 0.1)) <= 1e-15);
    QCOMPARE(s.limitState, 0.0);
    // Without a limit (maxOutput 0) the output is the whole sum.
    g.maxOutput = 0.0;
    s = servoPidAtRest(0.0);
    QVERIFY(std::abs(stepServoPid(g, s, 5.0, 0.0, ts).output - 5.5) <= 1e-15);
}

void TstServoPid::feedforwardReadsBackwardDifferences() {
    // A command c(t) = t^3 sampled at k Ts from rest: the backward differences are
    // cmd' = (c_k - c_{k-1})/Ts, cmd'' and cmd''' likewise; for k >= 3 the third difference of
    // a cubic is exactly 6 (times Ts^3 / Ts^3), the second 6 (k - 1) Ts, the first
    // (3k^2 - 3k + 1) Ts^2.
    ServoPidGains g;
    g.ff1 = 0.5;
    g.ff2 = 0.25;
    g.ff3 = 0.125;
    ServoPidState s = servoPidAtRest(0.0);
    const double ts = 0.5;
    for (int k = 1; k <= 6; ++k) {
        const double c = std::pow(k * ts, 3);
        const ServoPidTerms t = stepServoPid(g, s, c, c, ts); // feedback on the command: e = 0
        const double d1 = (3.0 * k * k - 3.0 * k + 1.0) * ts * ts;
        QVERIFY(std::abs(t.commandD - d1) <= 1e-12);
        if (k >= 2)
            QVERIFY(std::abs(t.commandDD - 6.0 * (k - 1) * ts) <= 1e-12);
        if (k >= 3) {
            QVERIFY(std::abs(t.commandDDD - 6.0) <= 1e-12);
            QVERIFY(std::abs(t.feedforward -
                             (0.5 * d1 + 0.25 * 6.0 * (k - 1) * ts + 0.125 * 6.0)) <= 1e-12);
        }
        QCOMPARE(t.feedback, 0.0);
        QCOMPARE(t.errorD, 0.0); // command and feedback move together
    }
}

void TstServoPid::derivativeFilterIsAFirstOrderLag() {
    // A feedback ramp of slope v from rest with D on the measurement: the unfiltered derivative
    // is -v from the first sample; through the filter, Df[k] = -v (1 - a^k), a = Tf/(Tf + Ts)
    // (the backward-Euler lag's step response). Tf = 0 is the unfiltered derivative (LinuxCNC).
    ServoPidGains g;
    g.d = 1.0;
    g.derivativeOnMeasurement = true;
    const double ts = 0.01, v = 3.0;
    for (const double tf : {0.0, 0.05}) {
        g.derivativeFilterSeconds = tf;
        ServoPidState s = servoPidAtRest(0.0);
        const double a = tf / (tf + ts);
        for (int k = 1; k <= 20; ++k) {
            const ServoPidTerms t = stepServoPid(g, s, 0.0, v * k * ts, ts);
            QVERIFY(std::abs(t.errorD - (-v * (1.0 - std::pow(a, k)))) <= 1e-12);
        }
    }
    // On the error instead, a command step gives the derivative kick the filter spreads.
    g.derivativeOnMeasurement = false;
    g.derivativeFilterSeconds = 0.0;
    ServoPidState s = servoPidAtRest(0.0);
    QVERIFY(std::abs(stepServoPid(g, s, 1.0, 0.0, ts).errorD - 1.0 / ts) <= 1e-9);
}

QTEST_MAIN(TstServoPid)
#include "tst_servo_pid.moc"
