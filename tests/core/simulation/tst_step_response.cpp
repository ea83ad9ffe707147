// SPDX-License-Identifier: GPL-3.0-or-later
// The unit-step curves the step view draws, against closed forms and difference
// equations; their rise time; the specification envelope over them; and the view's horizon.
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/errors.h"
#include "core/simulation/step_envelope.h"
#include "core/simulation/step_response.h"
#include "core/simulation/step_view.h"
#include "core/simulation/zpetc_step.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace xyt;

class TstStepResponse : public QObject {
    Q_OBJECT
private slots:
    void firstOrderIsTheClosedForm();
    void underdampedSecondOrderIsTheClosedForm();
    void discreteLoopFollowsItsDifferenceEquation();
    void zpetcStepReachesOne();
    void riseTimeInterpolatesBetweenSamples();
    void riseTimeRefusesBadInput();
    void envelopeFlagsOvershootAndLateExcursions();
    void horizonShowsTheTransient();
    void viewOfAContinuousLoop();
    void viewOfAPolePlacementAxis();
    void unstableLoopHasNoView();
};

void TstStepResponse::firstOrderIsTheClosedForm() {
    // 1 / (tau s + 1): y(t) = 1 - e^{-t/tau}, rise time (10 % -> 90 %) tau ln 9.
    const double tau = 2.0;
    const StepResponseCurve c =
        stepResponseCurve(TransferFunction::fromDescending({1.0}, {tau, 1.0}), 20.0, 2000);
    QCOMPARE(c.t.size(), std::size_t{2001});
    QCOMPARE(c.stepAtSeconds, 0.0);
    for (std::size_t k = 0; k < c.t.size(); ++k)
        // The discretization is exact for a constant input: only round-off of a 2000-step
        // recursion (about 2000 * 1.1e-16) remains; 1e-12 is above it.
        XYT_COMPARE_NEAR(c.y[k], 1.0 - std::exp(-c.t[k] / tau), 0.0, 1e-12);
    XYT_COMPARE_NEAR(c.t.back(), 20.0, 1e-14, 0.0);
    const RiseTime r = riseTime(c, 1.0);
    QVERIFY(r.reached);
    // Linear interpolation errs by at most dt^2/8 |y''| / |y'| = dt^2 / (8 tau) = 6.25e-6 s per
    // crossing (dt = 0.01 s); two crossings: 1.25e-5 s.
    XYT_COMPARE_NEAR(r.lowCrossingSeconds, -tau * std::log(0.9), 0.0, 6.25e-6);
    XYT_COMPARE_NEAR(r.highCrossingSeconds, tau * std::log(10.0), 0.0, 6.25e-6);
    XYT_COMPARE_NEAR(r.seconds, tau * std::log(9.0), 0.0, 1.25e-5);
}

void TstStepResponse::underdampedSecondOrderIsTheClosedForm() {
    // wn^2 / (s^2 + 2 zeta wn s + wn^2): y = 1 - e^{-zeta wn t} (cos wd t + zeta/sqrt(1-zeta^2) sin
    // wd t).
    const double wn = 2.0, zeta = 0.3, wd = wn * std::sqrt(1.0 - zeta * zeta);
    const StepResponseCurve c = stepResponseCurve(
        TransferFunction::fromDescending({wn * wn}, {1.0, 2.0 * zeta * wn, wn * wn}), 15.0, 3000);
    for (std::size_t k = 0; k < c.t.size(); ++k) {
        const double t = c.t[k];
        const double y =
            1.0 - std::exp(-zeta * wn * t) *
                      (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
        XYT_COMPARE_NEAR(c.y[k], y, 0.0, 1e-12); // round-off only, as above
    }
    // Its peak is the closed form too: 1 + exp(-pi zeta / sqrt(1 - zeta^2)) at pi / wd; the
    // largest sample is within one step (5 ms) of it, where y' = 0 keeps y within
    // |y''| dt^2 / 2 <= wn^2 dt^2 = 1e-4 of the peak.
    double peak = 0.0;
    for (double y : c.y)
        peak = std::max(peak, y);
    XYT_COMPARE_NEAR(peak, 1.0 + std::exp(-M_PI * zeta / std::sqrt(1.0 - zeta * zeta)), 0.0, 1e-4);
}

void TstStepResponse::discreteLoopFollowsItsDifferenceEquation() {
    // y(k) = 1.2 y(k-1) - 0.5 y(k-2) + 0.1 u(k-1) + 0.05 u(k-2), u = 1 from k = 0, Ts = 0.05 s.
    const double ts = 0.05;
    const TransferFunction g =
        TransferFunction::fromZInverse(Polynomial::fromAscending({0.0, 0.1, 0.05}),
                                       Polynomial::fromAscending({1.0, -1.2, 0.5}), ts);
    const StepResponseCurve c = stepResponseCurve(g, 3.0);
    QCOMPARE(c.t.size(), std::size_t{61}); // ceil(3 / 0.05) + 1 samples, at the loop's own Ts
    double y1 = 0.0, y2 = 0.0;
    for (std::size_t k = 0; k < c.t.size(); ++k) {
        const double u1 = k >= 1 ? 1.0 : 0.0, u2 = k >= 2 ? 1.0 : 0.0;
        const double y = 1.2 * y1 - 0.5 * y2 + 0.1 * u1 + 0.05 * u2;
        XYT_COMPARE_NEAR(c.t[k], static_cast<double>(k) * ts, 1e-15, 0.0);
        XYT_COMPARE_NEAR(c.y[k], y, 0.0, 1e-13); // the same recursion, up to the order of the sums
        y2 = y1;
        y1 = y;
    }
}

void TstStepResponse::zpetcStepReachesOne() {
    // Patrick, Ishak and Adnan, x axis, T = 1 - 0.2 z^-1, Ts = 0.07 s: the axis with ZPETC has DC
    // gain 1.
    const PolePlacementDesign loop =
        designPolePlacement(Polynomial::fromAscending({1, -1.658, 0.6583}),
                            Polynomial::fromAscending({0, 0.0421, 0.0628, -0.0454}),
                            Polynomial::fromAscending({1.0, -0.2}), 0.07);
    const ZpetcDesign z = designZpetc(loop);
    const StepResponseCurve c = zpetcStepResponseCurve(loop, z, 2.0);
    QVERIFY(c.stepAtSeconds > 0.0);
    QVERIFY(c.t.back() - c.stepAtSeconds >= 2.0 - 1e-12);
    QCOMPARE(c.y.front(), 0.0); // at rest before the preview acts
    // 1e-10: round-off of ~10^2 samples of the loop's recursion (as tst_zpetc_step).
    XYT_COMPARE_NEAR(c.y.back(), 1.0, 0.0, 1e-10);
    // The figures the panel quotes are those of this very run.
    const StepCharacteristics st = zpetcStepCharacteristics(loop, z);
    double peak = 0.0;
    for (double y : c.y)
        peak = std::max(peak, y);
    XYT_COMPARE_NEAR(std::max(0.0, (peak - st.finalValue) / st.finalValue * 100.0), st.overshootPct,
                     0.0, 1e-8);
}

void TstStepResponse::riseTimeInterpolatesBetweenSamples() {
    // A ramp 0, 0.25, 0.5, 0.75, 1 at t = 0..4 with final value 1: 10 % at 0.4 s, 90 % at 3.6 s
    // (exact: the curve is linear between its samples).
    StepResponseCurve c;
    c.t = {0, 1, 2, 3, 4};
    c.y = {0, 0.25, 0.5, 0.75, 1.0};
    RiseTime r = riseTime(c, 1.0);
    QVERIFY(r.reached);
    XYT_COMPARE_NEAR(r.lowCrossingSeconds, 0.4, 1e-15, 0.0);
    XYT_COMPARE_NEAR(r.highCrossingSeconds, 3.6, 1e-15, 0.0);
    XYT_COMPARE_NEAR(r.seconds, 3.2, 1e-15, 0.0);
    // A negative final value rises "down" the same way.
    for (double& y : c.y)
        y = -y;
    r = riseTime(c, -1.0);
    XYT_COMPARE_NEAR(r.seconds, 3.2, 1e-15, 0.0);
    // Never reaching 90 %: not reached, NaN, never a made-up figure.
    c.y = {0, 0.2, 0.4, 0.5, 0.6};
    r = riseTime(c, 1.0);
    QVERIFY(!r.reached);
    QVERIFY(std::isnan(r.seconds));
}

void TstStepResponse::riseTimeRefusesBadInput() {
    StepResponseCurve c;
    c.t = {0, 1};
    c.y = {0, 1};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, riseTime(c, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, riseTime(c, NAN));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, riseTime(c, 1.0, 0.9, 0.1));
    c.y = {0};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, riseTime(c, 1.0));
}

void TstStepResponse::envelopeFlagsOvershootAndLateExcursions() {
    StepResponseCurve c;
    c.stepAtSeconds = 1.0;
    c.t = {0, 1, 2, 3, 4, 5, 6};
    c.y = {0, 0.5, 1.15, 0.97, 1.01, 0.975, NAN};
    StepEnvelope e;
    e.maxOvershootPct = 10.0;    // bound 1.1
    e.settlingTimeSeconds = 3.0; // from t = 4 on: |y - 1| <= 0.02
    QCOMPARE(e.overshootBound(), 1.1);
    const std::vector<bool> v = envelopeViolations(c, e);
    QCOMPARE(v, (std::vector<bool>{false, false, true, false, false, true, true}));
    // No limits: nothing but the non-finite sample.
    QCOMPARE(envelopeViolations(c, StepEnvelope{}),
             (std::vector<bool>{false, false, false, false, false, false, true}));
    StepEnvelope bad;
    bad.band = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, envelopeViolations(c, bad));
}

void TstStepResponse::horizonShowsTheTransient() {
    StepCharacteristics st;
    st.stable = true;
    st.settlingTimeSeconds = 4.0;
    st.overshootPct = 1.0;
    st.peakTimeSeconds = 150.0; // a slow pole-zero pair's late peak: quoted, not drawn
    QCOMPARE(stepViewHorizonSeconds(st), 6.0);
    st.peakTimeSeconds = 5.0; // a peak within the transient is drawn
    QCOMPARE(stepViewHorizonSeconds(st), 7.5);
    QCOMPARE(stepViewHorizonSeconds(st, 0.0, 100.0), 7.5); // far limit: beyond the edge
    XYT_COMPARE_NEAR(stepViewHorizonSeconds(st, 0.0, 10.0), 11.5, 1e-15, 0.0); // near: in view
    QCOMPARE(stepViewHorizonSeconds(st, 20.0), 20.0); // a discrete loop's floor
    st.stable = false;
    QCOMPARE(stepViewHorizonSeconds(st), 1.0);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, stepViewHorizonSeconds(st, -1.0));
}

void TstStepResponse::viewOfAContinuousLoop() {
    // omega_n^2 / (s^2 + 2 zeta omega_n s + omega_n^2), zeta = 0.5, omega_n = 2: the view is the
    // curve stepResponseCurve draws over the horizon the figures ask for, its rise the curve's,
    // and the envelope flags exactly the samples above the overshoot bound (16.3 % > 10 %).
    const TransferFunction g(Polynomial::fromDescending({4.0}),
                             Polynomial::fromDescending({1.0, 2.0, 4.0}));
    const StepCharacteristics st = stepCharacteristics(g);
    StepEnvelope limits;
    limits.maxOvershootPct = 10.0;
    const StepView v = stepView(g, st, limits);
    QVERIFY(v.stable);
    QCOMPARE(v.sampleTimeSeconds, 0.0);
    QCOMPARE(v.curves.size(), std::size_t{1});
    QCOMPARE(v.curves[0].kind, StepCurveKind::ClosedLoop);
    QCOMPARE(v.horizonSeconds, stepViewHorizonSeconds(st, 0.0, limits.settlingTimeSeconds));
    const StepResponseCurve direct = stepResponseCurve(g, v.horizonSeconds);
    QCOMPARE(v.curves[0].curve.y, direct.y);
    QCOMPARE(v.envelope.finalValue, st.finalValue);
    const RiseTime r = riseTime(direct, st.finalValue);
    QCOMPARE(v.rise.seconds, r.seconds);
    QCOMPARE(v.violations, envelopeViolations(direct, v.envelope));
    // Closed form: Mp = exp(-pi zeta / sqrt(1 - zeta^2)) = 16.3 %, above the 10 % bound.
    QVERIFY(std::count(v.violations.begin(), v.violations.end(), true) > 0);
    for (std::size_t k = 0; k < direct.y.size(); ++k)
        QCOMPARE(static_cast<bool>(v.violations[k]), direct.y[k] > 1.1 * st.finalValue);
}

void TstStepResponse::viewOfAPolePlacementAxis() {
    // Patrick, Ishak and Adnan's x axis: both curves, the one the axis runs first, drawn at the
    // loop's Ts.
    const PolePlacementDesign loop =
        designPolePlacement(Polynomial::fromAscending({1, -1.658, 0.6583}),
                            Polynomial::fromAscending({0, 0.0421, 0.0628, -0.0454}),
                            Polynomial::fromAscending({1.0, -0.2}), 0.07);
    const ZpetcDesign z = designZpetc(loop);
    const StepCharacteristics with = zpetcStepCharacteristics(loop, z);
    const StepView on = stepView(loop.closedLoop(), with, StepEnvelope{}, &loop, &z, true);
    QCOMPARE(on.sampleTimeSeconds, 0.07);
    QCOMPARE(on.curves.size(), std::size_t{2});
    QCOMPARE(on.curves[0].kind, StepCurveKind::WithZpetc);
    QCOMPARE(on.curves[1].kind, StepCurveKind::LoopAlone);
    QVERIFY(on.horizonSeconds >= 20 * 0.07); // a discrete loop's floor of 20 samples
    QCOMPARE(on.curves[0].curve.y, zpetcStepResponseCurve(loop, z, on.horizonSeconds).y);
    QCOMPARE(on.curves[1].curve.y, stepResponseCurve(loop.closedLoop(), on.horizonSeconds).y);
    // ZPETC off: the loop alone leads (the figures passed only set the horizon and final value).
    const StepView off = stepView(loop.closedLoop(), with, StepEnvelope{}, &loop, &z, false);
    QCOMPARE(off.curves[0].kind, StepCurveKind::LoopAlone);
    QCOMPARE(off.curves[1].kind, StepCurveKind::WithZpetc);
    // Without a limit nothing is a violation (a finite response, the default band from +inf).
    QCOMPARE(std::count(off.violations.begin(), off.violations.end(), true), 0);
}

void TstStepResponse::unstableLoopHasNoView() {
    // 1 / (s - 1): no step response to draw, and no figures to mark.
    const TransferFunction g(Polynomial::fromDescending({1.0}),
                             Polynomial::fromDescending({1.0, -1.0}));
    const StepView v = stepView(g, stepCharacteristics(g), StepEnvelope{});
    QVERIFY(!v.stable);
    QVERIFY(v.curves.empty());
    QVERIFY(v.violations.empty());
}

QTEST_APPLESS_MAIN(TstStepResponse)
#include "tst_step_response.moc"
