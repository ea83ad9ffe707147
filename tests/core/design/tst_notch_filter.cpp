// SPDX-License-Identifier: GPL-3.0-or-later
// The flexible mode and the notch against their closed forms: the resonant pair's gain
// 1 / (2 zeta) at its frequency, the two-mass model's zero at the anti-resonance, the notch's
// depth and zero phase at its centre; the prewarped bilinear notch equal to the continuous one
// at the warped frequency K tan(w Ts / 2) (Franklin, Powell and Workman, section 6.3.2), so
// exactly at the centre; and the refusals that name the field.
#include "core/design/notch_filter.h"
#include "core/model/errors.h"
#include "core/model/flexible_mode.h"
#include "core/model/math_constants.h"

#include <QTest>

#include <cmath>
#include <complex>
#include <numbers>

using namespace xyt;
using Complex = std::complex<double>;

namespace {

/// The field InvalidInput names when @p f throws, or "" when it does not.
template <class F> std::string refusedField(F f) {
    try {
        f();
    } catch (const InvalidInput& e) {
        return e.field();
    }
    return {};
}

/// H(e^{j w Ts}) of the biquad, from its coefficients.
Complex biquadResponse(const Biquad& b, double w, double ts) {
    const Complex z1 = std::exp(Complex(0.0, -w * ts));
    return (b.b0 + b.b1 * z1 + b.b2 * z1 * z1) / (1.0 + b.a1 * z1 + b.a2 * z1 * z1);
}

} // namespace

class TstNotchFilter : public QObject {
    Q_OBJECT

private slots:
    /// Unit static gain; at wr the pair's gain is 1 / (2 zr) with phase -90 degrees (closed form
    /// of wr^2 / (s^2 + 2 zr wr s + wr^2) at s = j wr). Round-off of a handful of operations on
    /// numbers near wr^2 ~ 1e5: 1e-12 relative.
    void theResonantPairPeaksAtOneOverTwoZeta() {
        const FlexibleMode m{45.0, 0.03, 0.0, 0.02};
        const TransferFunction g = m.transferFunction();
        QVERIFY(std::abs(g.frequencyResponse(0.0) - 1.0) < 1e-12);
        const Complex h = g.frequencyResponse(2.0 * kPi * 45.0);
        QVERIFY(std::abs(std::abs(h) - 1.0 / (2.0 * 0.03)) < 1e-12 / 0.06);
        QVERIFY(std::abs(std::arg(h) + kPi / 2.0) < 1e-12);
        QCOMPARE(FlexibleMode{}.transferFunction().frequencyResponse(3.0), Complex(1.0, 0.0));
    }

    /// The two-mass model: static gain 1, and at wa the closed form
    /// (wr/wa)^2 (2 j za wa^2) / (wr^2 - wa^2 + 2 j zr wr wa).
    void theTwoMassModelHasItsAntiResonance() {
        const FlexibleMode m{60.0, 0.05, 35.0, 0.04};
        const TransferFunction g = m.transferFunction();
        QVERIFY(std::abs(g.frequencyResponse(0.0) - 1.0) < 1e-12);
        const double wr = 2.0 * kPi * 60.0, wa = 2.0 * kPi * 35.0;
        const Complex expected = (wr * wr) / (wa * wa) * Complex(0.0, 2.0 * 0.04 * wa * wa) /
                                 Complex(wr * wr - wa * wa, 2.0 * 0.05 * wr * wa);
        QVERIFY(std::abs(g.frequencyResponse(wa) - expected) < 1e-12 * std::abs(expected) + 1e-15);
    }

    /// |N(j w0)| = 10^(-depth/20) with zero phase; 1 at DC and far above.
    void theNotchHasItsDepthAtItsCentre() {
        const NotchFilter n{80.0, 20.0, 26.0};
        const TransferFunction tf = n.transferFunction();
        const Complex h = tf.frequencyResponse(2.0 * kPi * 80.0);
        QVERIFY(std::abs(h.real() - std::pow(10.0, -26.0 / 20.0)) < 1e-12);
        QVERIFY(std::abs(h.imag()) < 1e-12);
        QVERIFY(std::abs(tf.frequencyResponse(0.0) - 1.0) < 1e-12);
        // Far above: N -> 1 as 1 - O((w0 / w)); at 1e4 w0 within 1e-3.
        QVERIFY(std::abs(std::abs(tf.frequencyResponse(2.0 * kPi * 8e5)) - 1.0) < 1e-3);
    }

    /// The bilinear transform maps z = e^{j w Ts} to s = j K tan(w Ts / 2); prewarped, K =
    /// w0 / tan(w0 Ts / 2), so the discrete notch equals the continuous one at the warped
    /// frequency for every w, and at the centre itself. Both sides are sums of a few terms of
    /// size up to K^2 ~ 1e6, normalized: 1e-11.
    void thePrewarpedBiquadMatchesTheContinuousNotch() {
        const NotchFilter n{120.0, 30.0, 20.0};
        const double ts = 0.001;
        const Biquad b = discreteNotch(n, ts);
        const TransferFunction tf = n.transferFunction();
        const double w0 = 2.0 * kPi * 120.0;
        const double k = w0 / std::tan(w0 * ts / 2.0);
        const Complex atCentre = biquadResponse(b, w0, ts);
        QVERIFY(std::abs(atCentre - tf.frequencyResponse(w0)) < 1e-11);
        for (const double f : {1.0, 30.0, 100.0, 140.0, 400.0, 499.0}) {
            const double w = 2.0 * kPi * f;
            const Complex warped = tf.frequencyResponse(k * std::tan(w * ts / 2.0));
            QVERIFY2(std::abs(biquadResponse(b, w, ts) - warped) < 1e-11,
                     qPrintable(QString::number(f)));
        }
        // Unit static gain: b0 + b1 + b2 = 1 + a1 + a2.
        QVERIFY(std::abs((b.b0 + b.b1 + b.b2) - (1.0 + b.a1 + b.a2)) < 1e-15);
        // The transfer function agrees with the sums stepBiquad does: its impulse response.
        BiquadState s;
        const TransferFunction d = b.transferFunction(ts);
        QVERIFY(std::abs(d.frequencyResponse(w0) - atCentre) < 1e-11);
        QCOMPARE(stepBiquad(b, s, 1.0), b.b0);
        QCOMPARE(stepBiquad(b, s, 0.0), b.b1 - b.a1 * b.b0);
    }

    /// Designed from a mode: centred on it, as deep as its peak (1/(2 zeta), held to 6..40 dB),
    /// four half-power bandwidths wide (at least f/10).
    void theNotchForAModeFollowsItsPeak() {
        const NotchFilter n = notchForMode(FlexibleMode{50.0, 0.02, 0.0, 0.02});
        QCOMPARE(n.centreHz, 50.0);
        QCOMPARE(n.depthDb, std::round(20.0 * std::log10(25.0) * 100.0) / 100.0); // 27.96 dB
        QVERIFY(std::abs(n.widthHz - 8.0) < 1e-12);
        const NotchFilter light = notchForMode(FlexibleMode{50.0, 0.001, 0.0, 0.02});
        QCOMPARE(light.depthDb, 40.0);
        QCOMPARE(light.widthHz, 5.0);
        // The notch cancels the peak it was designed for: |N G| at wr = 25 10^(-depth/20), 1 to
        // the depth's rounding (0.005 dB: 6e-4).
        const FlexibleMode m{50.0, 0.02, 0.0, 0.02};
        const TransferFunction ng = series(n.transferFunction(), m.transferFunction());
        QVERIFY(std::abs(std::abs(ng.frequencyResponse(2.0 * kPi * 50.0)) - 1.0) < 6e-4);
    }

    void badValuesAreRefusedNamingTheField() {
        QCOMPARE(refusedField([] {
                     validateFlexibleMode({40.0, 1.0, 0.0, 0.02}, "m.");
                 }),
                 std::string("m.damping"));
        QCOMPARE(refusedField([] {
                     validateFlexibleMode({40.0, -0.1, 0.0, 0.02});
                 }),
                 std::string("damping"));
        QCOMPARE(refusedField([] {
                     validateFlexibleMode({40.0, 0.1, 50.0, 0.02});
                 }),
                 std::string("anti_resonance"));
        QCOMPARE(refusedField([] {
                     validateFlexibleMode({std::nan(""), 0.1, 0.0, 0.02});
                 }),
                 std::string("frequency"));
        QCOMPARE(refusedField([] {
                     discreteNotch({600.0, 50.0, 20.0}, 0.001, "gt.notch.");
                 }),
                 std::string("gt.notch.centre"));
        QCOMPARE(refusedField([] {
                     validateNotchFilter({100.0, 250.0, 20.0});
                 }),
                 std::string("width"));
        QCOMPARE(refusedField([] {
                     validateNotchFilter({100.0, 10.0, 0.0});
                 }),
                 std::string("depth"));
        QCOMPARE(refusedField([] { notchForMode({}); }), std::string("frequency"));
        QCOMPARE(refusedField([] { validateNotchFilter({}); }), std::string());
    }
};

QTEST_APPLESS_MAIN(TstNotchFilter)
#include "tst_notch_filter.moc"
