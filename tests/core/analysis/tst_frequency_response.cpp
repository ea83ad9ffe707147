// SPDX-License-Identifier: GPL-3.0-or-later
// Frequency response and unwrapped phase: closed forms, grid independence of the
// unwrapping, the adaptive grid on a sharp resonance.
#include "core/analysis/frequency_response.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace xyt;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;
} // namespace

class TstFrequencyResponse : public QObject {
    Q_OBJECT
private slots:
    void firstOrderClosedForm();
    void integratorsStartAtMinus90k();
    void unwrappingDoesNotDependOnTheGrid();
    void unstableAndNegativeGain();
    void discreteClosedForms();
    void adaptiveGridFollowsResonance();
    void badInputThrows();
};

// Closed form: 1/(s + 1) at w: |G| = 1/sqrt(1 + w^2), arg = -atan w.
void TstFrequencyResponse::firstOrderClosedForm() {
    const FrequencyResponse r = frequencyResponse(
        TransferFunction::fromDescending({1.0}, {1.0, 1.0}), {0.0, 0.5, 1.0, 100.0});
    for (std::size_t i = 0; i < r.omegaRadPerSec.size(); ++i) {
        const double w = r.omegaRadPerSec[i];
        // 1e-13: a Horner evaluation and a log10, a few ulps.
        XYT_COMPARE_NEAR(r.magnitudeDb[i], -10.0 * std::log10(1.0 + w * w), 1e-13, 1e-14);
        XYT_COMPARE_NEAR(r.phaseDeg[i], -std::atan(w) * kDeg, 1e-13, 1e-14);
    }
    QCOMPARE(r.lowFrequencyIntegrators, 0);
}

// Closed form: K/(s^k (s + 1)) has phase -90 k - atan w (the low-frequency asymptote -90 k,
// not a wrapped value); the GT loop (double integrator, the PI zero at psi1 = wn^4/(kp k0) =
// 0.00686 rad/s) starts at -180 and ends at -270 (relative degree 3).
void TstFrequencyResponse::integratorsStartAtMinus90k() {
    for (int k = 0; k <= 4; ++k) {
        std::vector<double> den = {1.0, 1.0};
        for (int i = 0; i < k; ++i)
            den.push_back(0.0);
        const FrequencyResponse r =
            frequencyResponse(TransferFunction::fromDescending({2.0}, den), {1e-6, 0.3, 3.0, 1e5});
        QCOMPARE(r.lowFrequencyIntegrators, k);
        for (std::size_t i = 0; i < r.omegaRadPerSec.size(); ++i)
            XYT_COMPARE_NEAR(r.phaseDeg[i], -90.0 * k - std::atan(r.omegaRadPerSec[i]) * kDeg,
                             1e-12, 1e-12);
    }
    // (kp s + ki)/s * k0/(s^3 + a1 s^2 + a2 s), Braga et al.'s lower base wn 2, kp 30.
    const double k0 = 77.8, a1 = 125.3, a2 = 3665.0, kp = 30.0, ki = kp * 16.0 / (kp * k0);
    const TransferFunction gt(Polynomial::fromDescending({k0 * kp, k0 * ki}),
                              Polynomial::fromDescending({1.0, a1, a2, 0.0, 0.0}));
    const FrequencyResponse r = frequencyResponse(gt, {1e-9, 1e6});
    // At 1e-9 rad/s the zero leads by atan(1e-9/0.00686) = 8e-6 degrees; at 1e6 the poles
    // (sum of real parts -a1 = -125.3) lag by about 125.3/1e6 rad = 0.007 degrees.
    XYT_COMPARE_NEAR(r.phaseDeg[0], -180.0, 0.0, 1e-4);
    XYT_COMPARE_NEAR(r.phaseDeg[1], -270.0, 0.0, 1e-2);
}

// 1/(s + 1)^6 on 3 points and on 2000 points: the same phase at the shared frequencies, and
// -6 atan w at each (reaching -540 degrees), though 3 points cannot be unwrapped by
// differences.
void TstFrequencyResponse::unwrappingDoesNotDependOnTheGrid() {
    const TransferFunction g(Polynomial::constant(1.0),
                             Polynomial::fromRoots({-1.0, -1.0, -1.0, -1.0, -1.0, -1.0}));
    const FrequencyResponse coarse = frequencyResponse(g, {0.01, 10.0, 1000.0});
    for (std::size_t i = 0; i < 3; ++i)
        XYT_COMPARE_NEAR(coarse.phaseDeg[i], -6.0 * std::atan(coarse.omegaRadPerSec[i]) * kDeg,
                         1e-9, 1e-9);
    const FrequencyResponse fine = frequencyResponse(g, logFrequencyGrid(0.01, 1000.0, 2000));
    XYT_COMPARE_NEAR(fine.phaseDeg.back(), coarse.phaseDeg.back(), 1e-12, 0.0);
    for (std::size_t i = 1; i < fine.phaseDeg.size(); ++i)
        QVERIFY(fine.phaseDeg[i] < fine.phaseDeg[i - 1]);
}

// Closed forms: 1/(s - 1) = -(1 + j w)/(1 + w^2): phase -180 + atan w (from -180 to -90);
// -1/(s + 1): c < 0, phase -180 - atan w; 5/(s^2 - 2 s + 5) (poles 1 +- 2j, DC gain 1) goes
// continuously from 0 to +180: each unstable pole turns the phase by +90 as w goes to inf.
void TstFrequencyResponse::unstableAndNegativeGain() {
    const std::vector<double> w = {1e-3, 0.5, 2.0, 50.0};
    const FrequencyResponse u =
        frequencyResponse(TransferFunction::fromDescending({1.0}, {1.0, -1.0}), w);
    const FrequencyResponse n =
        frequencyResponse(TransferFunction::fromDescending({-1.0}, {1.0, 1.0}), w);
    for (std::size_t i = 0; i < w.size(); ++i) {
        XYT_COMPARE_NEAR(u.phaseDeg[i], -180.0 + std::atan(w[i]) * kDeg, 1e-12, 1e-12);
        XYT_COMPARE_NEAR(n.phaseDeg[i], -180.0 - std::atan(w[i]) * kDeg, 1e-12, 1e-12);
    }
    const TransferFunction pair = TransferFunction::fromDescending({5.0}, {1.0, -2.0, 5.0});
    const FrequencyResponse p = frequencyResponse(pair, logFrequencyGrid(1e-5, 1e5, 5000));
    // The asymptotes to within 2 Re(p)/w rad: 0.0011 degrees at both ends.
    XYT_COMPARE_NEAR(p.phaseDeg.front(), 0.0, 0.0, 0.01);
    XYT_COMPARE_NEAR(p.phaseDeg.back(), 180.0, 0.0, 0.01); // two RHP poles: +90 each
    for (std::size_t i = 1; i < p.phaseDeg.size(); ++i)
        QVERIFY(std::abs(p.phaseDeg[i] - p.phaseDeg[i - 1]) < 5.0);
}

// Closed forms (theta = w Ts): the discrete integrator Ts/(z - 1) has |G| = Ts/(2 sin(theta/2))
// and phase -90 - theta/2 degrees; a pure delay z^-3 has phase -3 theta (-540 at Nyquist).
void TstFrequencyResponse::discreteClosedForms() {
    const double ts = 0.05;
    const std::vector<double> w = logFrequencyGrid(0.01, kPi / ts, 50);
    const FrequencyResponse r = frequencyResponse(
        TransferFunction(Polynomial::constant(ts), Polynomial::fromDescending({1.0, -1.0}), ts), w);
    QCOMPARE(r.lowFrequencyIntegrators, 1);
    const FrequencyResponse d = frequencyResponse(
        TransferFunction(Polynomial::constant(1.0), Polynomial::fromDescending({1.0, 0, 0, 0}), ts),
        w);
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double theta = w[i] * ts;
        XYT_COMPARE_NEAR(r.magnitudeDb[i], 20.0 * std::log10(ts / (2.0 * std::sin(theta / 2.0))),
                         1e-11, 1e-11);
        XYT_COMPARE_NEAR(r.phaseDeg[i], -90.0 - theta / 2.0 * kDeg, 1e-12, 1e-10);
        XYT_COMPARE_NEAR(d.phaseDeg[i], -3.0 * theta * kDeg, 1e-12, 1e-10);
    }
}

// A resonance with zeta = 0.001 at 10 rad/s (peak 54 dB, half-power width 0.02 rad/s) between
// grid points of a 10-per-decade start: the adaptive grid puts points at the peak and bounds
// every step by the options (except where the frequency ratio floor stops the halving).
void TstFrequencyResponse::adaptiveGridFollowsResonance() {
    const double zeta = 0.001, wn = 10.0;
    const TransferFunction g =
        TransferFunction::fromDescending({wn * wn}, {1.0, 2 * zeta * wn, wn * wn});
    FrequencyGridOptions o;
    const FrequencyResponse r = adaptiveFrequencyResponse(g, o);
    double peak = -1e300;
    for (std::size_t i = 0; i < r.magnitudeDb.size(); ++i)
        peak = std::max(peak, r.magnitudeDb[i]);
    const double exactPeak = -20.0 * std::log10(2 * zeta * std::sqrt(1 - zeta * zeta));
    XYT_COMPARE_NEAR(peak, exactPeak, 0.0, o.maxMagnitudeStepDb);
    for (std::size_t i = 1; i < r.omegaRadPerSec.size(); ++i) {
        QVERIFY(r.omegaRadPerSec[i] > r.omegaRadPerSec[i - 1]);
        QVERIFY(std::abs(r.magnitudeDb[i] - r.magnitudeDb[i - 1]) <= o.maxMagnitudeStepDb);
        QVERIFY(std::abs(r.phaseDeg[i] - r.phaseDeg[i - 1]) <= o.maxPhaseStepDeg);
    }
    QVERIFY(r.omegaRadPerSec.front() <= 1.0 && r.omegaRadPerSec.back() >= 100.0);
    QVERIFY(static_cast<int>(r.omegaRadPerSec.size()) < o.maxPoints);
    XYT_COMPARE_NEAR(r.phaseDeg.back(), -180.0, 0.0, 1.0);
    // A discrete loop ends exactly at the Nyquist frequency.
    const FrequencyResponse d = adaptiveFrequencyResponse(
        TransferFunction(Polynomial::constant(0.1), Polynomial::fromDescending({1.0, -0.9}), 0.1));
    XYT_COMPARE_NEAR(d.omegaRadPerSec.back(), kPi / 0.1, 1e-15, 0.0);
}

void TstFrequencyResponse::badInputThrows() {
    const TransferFunction g = TransferFunction::fromDescending({1.0}, {1.0, 1.0});
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frequencyResponse(g, {-1.0}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frequencyResponse(g, {std::nan("")}));
    const TransferFunction d(Polynomial::constant(1.0), Polynomial::fromDescending({1.0, -0.5}),
                             0.1);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frequencyResponse(d, {40.0}));
    FrequencyGridOptions o;
    o.maxPoints = 1;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, adaptiveFrequencyResponse(g, o));
}

QTEST_APPLESS_MAIN(TstFrequencyResponse)
#include "tst_frequency_response.moc"
