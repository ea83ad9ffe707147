// SPDX-License-Identifier: GPL-3.0-or-later
// Welch spectra, the H1 frequency-response estimate with its coherence band, and the resonance
// pick. Sources: scipy.signal welch/csd/coherence on the same records
// (tests/data/gen_spectral_estimate.py -> spectral_estimate_scipy.json); the exact ZOH response
// of a lightly damped mode (c2dZoh) against its estimate from a seeded simulation, judged by
// Bendat and Piersol's normalized random error and binomial counts; the closed-form half-power
// points of a second-order gain; Parseval's theorem.
#include "core/identification/spectral_estimate.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"
#include "core/model/transfer_function.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>
#include <random>

using namespace xyt;

namespace {

constexpr double kPi = 3.14159265358979323846;

QJsonObject reference() {
    QFile f(QStringLiteral(XYT_SOURCE_DIR "/tests/data/spectral_estimate_scipy.json"));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read spectral_estimate_scipy.json");
    return QJsonDocument::fromJson(f.readAll()).object();
}

std::vector<double> doubles(const QJsonValue& v) {
    std::vector<double> out;
    for (const QJsonValue& e : v.toArray())
        out.push_back(e.toDouble());
    return out;
}

double largest(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
        m = std::max(m, std::abs(x));
    return m;
}

/// Each value within 1e-10 of its reference, relative, plus 1e-12 of the vector's largest
/// value: both sides are double-precision FFTs of at most 64 points (pocketfft and Eigen's
/// kissfft), whose round-off is a few 1e-16 of the largest bin; the floor covers bins some
/// 1e-4 below the largest, whose own relative round-off is larger.
void compareVectors(const std::vector<double>& actual, const std::vector<double>& expected,
                    const char* what) {
    QCOMPARE(actual.size(), expected.size());
    const double floor = 1e-12 * largest(expected);
    for (std::size_t k = 0; k < actual.size(); ++k)
        QVERIFY2(test::near(actual[k], expected[k], 1e-10, floor),
                 qPrintable(QString("%1[%2]: ").arg(what).arg(k) +
                            test::describe(actual[k], expected[k], 1e-10, floor)));
}

/// y = B(z^-1)/A(z^-1) u, A monic (ascending powers of z^-1), zero initial conditions.
std::vector<double> filtered(const std::vector<double>& b, const std::vector<double>& a,
                             const std::vector<double>& u) {
    std::vector<double> y(u.size(), 0.0);
    for (std::size_t k = 0; k < u.size(); ++k) {
        double v = 0.0;
        for (std::size_t i = 0; i < b.size() && i <= k; ++i)
            v += b[i] * u[k - i];
        for (std::size_t i = 1; i < a.size() && i <= k; ++i)
            v -= a[i] * y[k - i];
        y[k] = v / a[0];
    }
    return y;
}

/// The second-order gain wn^2 / (s^2 + 2 zeta wn s + wn^2) at f Hz.
double modeGain(double f, double fn, double zeta) {
    const double r = f / fn;
    return 1.0 / std::sqrt((1.0 - r * r) * (1.0 - r * r) + (2.0 * zeta * r) * (2.0 * zeta * r));
}

/// P(X > m) for X ~ Poisson(lambda): the binomial tail of rare events (n p small, n large).
double poissonTailAbove(double lambda, int m) {
    double term = std::exp(-lambda), cdf = term;
    for (int i = 1; i <= m; ++i) {
        term *= lambda / i;
        cdf += term;
    }
    return 1.0 - cdf;
}

void expectRefusal(const std::function<void()>& f, const std::string& field,
                   const std::string& part) {
    try {
        f();
        QFAIL(qPrintable(QString::fromStdString("no refusal naming " + field)));
    } catch (const InvalidInput& e) {
        QCOMPARE(QString::fromStdString(e.field()), QString::fromStdString(field));
        QVERIFY2(std::string(e.what()).find(part) != std::string::npos, e.what());
    }
}

} // namespace

class TstSpectralEstimate : public QObject {
    Q_OBJECT
private slots:
    void psdCsdCoherenceMatchScipy();
    void oddSegmentMatchesScipy();
    void defaultSegmentRule();
    void equivalentAveragesOfHannHalfOverlap();
    void estimateOfALightlyDampedModeLiesInItsBand();
    void resonancePickOfASecondOrderGain();
    void resonancePickWithoutACrossingInTheBand();
    void parsevalOnWhiteNoise();
    void refusals();
};

void TstSpectralEstimate::psdCsdCoherenceMatchScipy() {
    const QJsonObject h = reference()["hann"].toObject();
    const std::vector<double> u = doubles(h["u"]), y = doubles(h["y"]);
    const double ts = h["ts"].toDouble();
    WelchOptions o;
    o.segmentLength = static_cast<std::size_t>(h["segment"].toInt());
    const WelchSpectrum pu = powerSpectralDensity(u, ts, o);
    compareVectors(pu.frequencyHz, doubles(h["frequency"]), "frequency");
    compareVectors(pu.psd, doubles(h["puu"]), "welch(u)");
    const FrequencyResponseEstimate e = estimateFrequencyResponse(u, y, ts, o);
    compareVectors(e.inputPsd, doubles(h["puu"]), "Puu");
    compareVectors(e.outputPsd, doubles(h["pyy"]), "Pyy");
    compareVectors(e.magnitude, doubles(h["magnitude"]), "|H1|");
    // |Puy| = |H1| Puu, and the coherence and phase carry the CSD's argument.
    const std::vector<double> re = doubles(h["puy_re"]), im = doubles(h["puy_im"]);
    std::vector<double> csdAbs(re.size());
    for (std::size_t k = 0; k < re.size(); ++k)
        csdAbs[k] = std::hypot(re[k], im[k]);
    std::vector<double> ours(re.size());
    for (std::size_t k = 0; k < re.size(); ++k)
        ours[k] = e.magnitude[k] * e.inputPsd[k];
    compareVectors(ours, csdAbs, "|csd(u, y)|");
    // Coherence in [0, 1] and phase in rad: absolute 1e-10 (round-off as above).
    const std::vector<double> coh = doubles(h["coherence"]), phase = doubles(h["phase_rad"]);
    for (std::size_t k = 0; k < coh.size(); ++k) {
        XYT_COMPARE_NEAR(e.coherence[k], coh[k], 0.0, 1e-10);
        XYT_COMPARE_NEAR(e.phaseRad[k], phase[k], 0.0, 1e-10);
    }
    // scipy's segment count: (700 - 64) // 32 + 1.
    QCOMPARE(e.segments.count, std::size_t{20});
}

void TstSpectralEstimate::oddSegmentMatchesScipy() {
    const QJsonObject r = reference();
    const QJsonObject odd = r["odd"].toObject();
    WelchOptions o;
    o.segmentLength = static_cast<std::size_t>(odd["segment"].toInt());
    const WelchSpectrum p = powerSpectralDensity(doubles(r["hann"].toObject()["u"]),
                                                 r["hann"].toObject()["ts"].toDouble(), o);
    compareVectors(p.frequencyHz, doubles(odd["frequency"]), "frequency");
    compareVectors(p.psd, doubles(odd["psd"]), "welch(u, nperseg=45)");
}

void TstSpectralEstimate::defaultSegmentRule() {
    // The rule of defaultWelchSegmentLength: largest power of two in [8, 4096] with
    // N >= 4.5 M (8 half-overlapping segments).
    QCOMPARE(defaultWelchSegmentLength(100000), std::size_t{4096});
    QCOMPARE(defaultWelchSegmentLength(4608), std::size_t{1024}); // 4.5 * 1024: K = 8
    QCOMPARE(defaultWelchSegmentLength(4607), std::size_t{512});
    QCOMPARE(defaultWelchSegmentLength(20), std::size_t{8});
    for (std::size_t n : {36u, 100u, 4608u, 18432u, 50000u}) {
        const WelchSegments s = welchSegments(n, {});
        QVERIFY(s.count >= 8);
    }
}

void TstSpectralEstimate::equivalentAveragesOfHannHalfOverlap() {
    // Periodic Hann, M even, S = M/2: rho(1) = sum sin^2 cos^2 over half a period / sum sin^4
    // = (M/16) / (3M/8) = 1/6 exactly, so n_d = K / (1 + 2 (1 - 1/K) / 36) (Welch 1967).
    WelchOptions o;
    o.segmentLength = 64;
    const WelchSegments s = welchSegments((20 - 1) * 32 + 64, o);
    QCOMPARE(s.count, std::size_t{20});
    XYT_COMPARE_NEAR(s.equivalentAverages, 20.0 / (1.0 + 2.0 * (1.0 - 1.0 / 20.0) / 36.0), 1e-14,
                     0.0);
}

void TstSpectralEstimate::estimateOfALightlyDampedModeLiesInItsBand() {
    // A 50 Hz mode with zeta 0.05, discretized exactly (ZOH) at 1 kHz, driven by seeded unit
    // white noise, with seeded white output noise of standard deviation 0.5: the coherence is
    // |H|^2 / (|H|^2 + 0.25), above 0.9 where |H| > 1.5 (about 29 to 64 Hz).
    const double ts = 1e-3, fn = 50.0, zeta = 0.05, wn = 2.0 * kPi * fn;
    const TransferFunction g =
        c2dZoh(TransferFunction::fromDescending({wn * wn}, {1.0, 2.0 * zeta * wn, wn * wn}), ts);
    const std::vector<double> b = g.numZInverse().ascending(), a = g.denZInverse().ascending();
    const std::size_t warmup = 5000, n = 400000;
    std::mt19937_64 rng(20261126);
    std::normal_distribution<double> normal;
    std::vector<double> u(warmup + n);
    for (double& v : u)
        v = normal(rng);
    std::vector<double> y = filtered(b, a, u);
    // The first samples hold the filter's start from rest (it decays as e^{-zeta wn t}: below
    // 1e-6 after 5000 samples); drop them so the record is stationary.
    u.erase(u.begin(), u.begin() + warmup);
    y.erase(y.begin(), y.begin() + warmup);
    for (double& v : y)
        v += 0.5 * normal(rng);
    // M = 8192 (0.12 Hz bins): the Hann resolution bias at the peak, about (B_e / B_r)^2 / 3
    // with B_e = 1.5 df and B_r = 2 zeta fn (Bendat and Piersol, eq. 8.141), is 4e-4, a tenth of
    // the random error there; K = 96.
    WelchOptions o;
    o.segmentLength = 8192;
    const FrequencyResponseEstimate e = estimateFrequencyResponse(u, y, ts, o);
    int used = 0, outside3 = 0, inside1 = 0, phaseOutside3 = 0;
    for (std::size_t k = 1; k < e.frequencyHz.size(); ++k) {
        if (e.coherence[k] <= 0.9)
            continue;
        const std::complex<double> exact = g.frequencyResponse(2.0 * kPi * e.frequencyHz[k]);
        const double error = (e.magnitude[k] - std::abs(exact)) / std::abs(exact);
        const double eps = e.relativeError[k];
        ++used;
        outside3 += std::abs(error) > 3.0 * eps;
        inside1 += std::abs(error) <= eps;
        // The phase's standard deviation is eps rad (Bendat and Piersol, Table 9.6).
        const double phaseError = std::arg(std::polar(1.0, e.phaseRad[k]) / exact);
        phaseOutside3 += std::abs(phaseError) > 3.0 * eps;
        // The 2-sigma band of the estimate holds the band's definition.
        XYT_COMPARE_NEAR(e.magnitudeHigh[k], e.magnitude[k] * (1.0 + 2.0 * eps), 1e-15, 0.0);
    }
    qInfo("%d bins with coherence > 0.9: %d outside 3 eps, %d within 1 eps, %d phases outside "
          "3 eps",
          used, outside3, inside1, phaseOutside3);
    QVERIFY2(used > 200, qPrintable(QString("only %1 bins with coherence > 0.9").arg(used)));
    // Where eps is small the gain estimate is nearly normal with standard deviation eps |H|, so
    // a bin falls outside 3 eps with p = 0.0027. Neighbouring Hann bins are correlated (they
    // share about half their window energy), so outliers come at most in pairs: the number of
    // pairs outside is at most Poisson(n p) and m is twice the smallest count whose Poisson
    // tail is below 1e-3.
    const double lambda = used * 0.0027;
    int m = 0;
    while (poissonTailAbove(lambda, m) > 1e-3)
        ++m;
    QVERIFY2(outside3 <= 2 * m, qPrintable(QString("%1 of %2 bins outside 3 eps (at most %3)")
                                               .arg(outside3)
                                               .arg(used)
                                               .arg(2 * m)));
    QVERIFY2(phaseOutside3 <= 2 * m,
             qPrintable(QString("%1 of %2 phases outside 3 eps").arg(phaseOutside3).arg(used)));
    // Nor is the band too wide: 68.3 % within 1 eps; binomial sd sqrt(n p (1 - p)), times
    // sqrt(2) for the pairs, and 4.5 such sd either side (a band 2x too wide would hold 95 %,
    // one 2x too narrow 38 %).
    const double p1 = 0.6827, sd = std::sqrt(2.0 * used * p1 * (1.0 - p1));
    QVERIFY2(std::abs(inside1 - used * p1) <= 4.5 * sd,
             qPrintable(QString("%1 of %2 bins within 1 eps").arg(inside1).arg(used)));
    // The pick on the estimate: the peak of |H| sits at fn sqrt(1 - 2 zeta^2) (49.87 Hz) and
    // the half-power damping is zeta (1 + 2 zeta^2) = 0.0503 (resonancePickOfASecondOrderGain);
    // on the estimate the bins are 0.122 Hz apart and the peak is known to about its random
    // error, so within one bin and 10 %.
    const ResonancePick r = pickResonance(e.frequencyHz, e.magnitude, ResonanceQuantity::Magnitude);
    XYT_COMPARE_NEAR(r.frequencyHz, fn * std::sqrt(1.0 - 2.0 * zeta * zeta), 0.0,
                     1.0 / (o.segmentLength * ts));
    QVERIFY(r.dampingRatio.has_value());
    XYT_COMPARE_NEAR(*r.dampingRatio, zeta, 0.1, 0.0);
}

void TstSpectralEstimate::resonancePickOfASecondOrderGain() {
    // The exact gain of wn^2 / (s^2 + 2 zeta wn s + wn^2) sampled every fn / 1000: the peak is
    // at fn sqrt(1 - 2 zeta^2), the half-power points at fn sqrt(1 - 2 zeta^2 -+ 2 zeta
    // sqrt(1 - zeta^2)) (solving |H|^2 = |H|max^2 / 2), so the half-power estimate is
    // (f2 - f1) / (2 fpeak) = zeta (1 + 2 zeta^2 + O(zeta^4)).
    for (double zeta : {0.01, 0.05, 0.1}) {
        const double fn = 120.0, df = fn / 1000.0;
        std::vector<double> f, gain, power;
        for (int k = 0; k <= 2500; ++k) {
            f.push_back(k * df);
            gain.push_back(modeGain(k * df, fn, zeta));
            power.push_back(gain.back() * gain.back());
        }
        const double fPeak = fn * std::sqrt(1.0 - 2.0 * zeta * zeta);
        const double s = 2.0 * zeta * std::sqrt(1.0 - zeta * zeta);
        const double f1 = fn * std::sqrt(1.0 - 2.0 * zeta * zeta - s);
        const double f2 = fn * std::sqrt(1.0 - 2.0 * zeta * zeta + s);
        for (ResonanceQuantity q : {ResonanceQuantity::Magnitude, ResonanceQuantity::Power}) {
            const ResonancePick r =
                pickResonance(f, q == ResonanceQuantity::Magnitude ? gain : power, q);
            // The parabola's vertex error is of order df^3 / (zeta fn)^2 (the peak's cubic term
            // over its curvature): 1.7e-3 df at zeta 0.01; 0.01 df bounds it for every zeta.
            XYT_COMPARE_NEAR(r.frequencyHz, fPeak, 0.0, 0.01 * df);
            // Linear interpolation of the crossing: error ~ df^2 |H''| / (8 |H'|), with the
            // curvature scale the half-bandwidth zeta fn: df^2 / (8 zeta fn) <= 0.0125 df.
            XYT_COMPARE_NEAR(*r.lowHalfPowerHz, f1, 0.0, 0.02 * df);
            XYT_COMPARE_NEAR(*r.highHalfPowerHz, f2, 0.0, 0.02 * df);
            QVERIFY(r.dampingRatio.has_value());
            // Against zeta itself: the O(zeta^2) term 2 zeta^2 (5 % more for zeta 0.1), plus
            // the interpolation (0.04 df / (2 fn) = 2e-5).
            XYT_COMPARE_NEAR(*r.dampingRatio, zeta, 2.1 * zeta * zeta, 2e-5);
            QVERIFY(r.note.text.empty());
        }
    }
}

void TstSpectralEstimate::resonancePickWithoutACrossingInTheBand() {
    const double fn = 50.0, zeta = 0.05, df = 0.1;
    std::vector<double> f, gain;
    for (int k = 0; k <= 1000; ++k) {
        f.push_back(k * df);
        gain.push_back(modeGain(k * df, fn, zeta));
    }
    // The band starts above the lower half-power point (f1 = 47.4 Hz): no damping, and the
    // note names the side and the band.
    const ResonancePick r = pickResonance(f, gain, ResonanceQuantity::Magnitude, {48.5, 80.0});
    QVERIFY(!r.dampingRatio.has_value());
    QVERIFY(r.highHalfPowerHz.has_value());
    QVERIFY2(r.note.text.find("below the peak") != std::string::npos &&
                 r.note.text.find("[48.5, 80] Hz") != std::string::npos,
             r.note.text.c_str());
    // A band below the resonance: the largest value is at its upper edge, no damping.
    const ResonancePick edge = pickResonance(f, gain, ResonanceQuantity::Magnitude, {10.0, 30.0});
    XYT_COMPARE_NEAR(edge.frequencyHz, 30.0, 0.0, 1e-9);
    QVERIFY(!edge.dampingRatio.has_value());
    expectRefusal(
        [&] {
            pickResonance(f, gain, ResonanceQuantity::Magnitude, {30.0, 20.0});
        },
        "band", "empty or reversed");
    expectRefusal(
        [&] {
            pickResonance(f, gain, ResonanceQuantity::Magnitude, {200.0, 300.0});
        },
        "band", "fewer than 3 frequency bins");
}

void TstSpectralEstimate::parsevalOnWhiteNoise() {
    // Discrete Parseval: sum_k P[k] df = (1/K) sum_i sum_n ((x_n - mean_i) w_n)^2 / sum w^2,
    // exactly (the doubling of the one-sided bins restores the negative frequencies). And for
    // white noise of variance 4 its expectation is 4: the statistic is a weighted mean of x^2
    // whose relative standard deviation is sqrt(2 sum w^4 / (sum w^2)^2 / n_d) =
    // sqrt(2 * 35 / (18 M) / n_d) for Hann (sum w^2 = 3M/8, sum w^4 = 35M/128): 0.4 % here;
    // 5 of them bound it.
    const double ts = 1e-3, sigma = 2.0;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, sigma);
    std::vector<double> x(100000);
    for (double& v : x)
        v = normal(rng);
    const WelchSpectrum p = powerSpectralDensity(x, ts);
    const std::size_t m = p.segments.segmentLength;
    const double df = 1.0 / (m * ts);
    double integral = 0.0;
    for (double v : p.psd)
        integral += v * df;
    double direct = 0.0, w2 = 0.0;
    for (std::size_t n = 0; n < m; ++n) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * kPi * n / m);
        w2 += w * w;
    }
    for (std::size_t i = 0; i < p.segments.count; ++i) {
        double mean = 0.0;
        for (std::size_t n = 0; n < m; ++n)
            mean += x[i * p.segments.step + n] / m;
        for (std::size_t n = 0; n < m; ++n) {
            const double w = 0.5 - 0.5 * std::cos(2.0 * kPi * n / m);
            direct += std::pow((x[i * p.segments.step + n] - mean) * w, 2) / w2;
        }
    }
    direct /= p.segments.count;
    // Round-off of sums of 1e5 terms: 1e-12 relative.
    XYT_COMPARE_NEAR(integral, direct, 1e-12, 0.0);
    const double relSd = std::sqrt(2.0 * 35.0 / (18.0 * m) / p.segments.equivalentAverages);
    XYT_COMPARE_NEAR(integral, sigma * sigma, 5.0 * relSd, 0.0);
}

void TstSpectralEstimate::refusals() {
    std::vector<double> x(100, 1.0), y(100, 2.0);
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = std::sin(0.3 * i);
    expectRefusal([&] { powerSpectralDensity(x, 0.0); }, "ts", "positive");
    expectRefusal([&] { powerSpectralDensity(x, -1e-3); }, "ts", "positive");
    expectRefusal([&] { powerSpectralDensity(x, std::nan("")); }, "ts", "positive");
    std::vector<double> bad = x;
    bad[17] = std::numeric_limits<double>::infinity();
    expectRefusal([&] { powerSpectralDensity(bad, 1e-3); }, "x", "sample 18 is not finite");
    expectRefusal([&] { estimateFrequencyResponse(x, bad, 1e-3); }, "y", "sample 18");
    expectRefusal([&] { estimateFrequencyResponse(bad, y, 1e-3); }, "u", "sample 18");
    // Finite samples whose squares overflow: refused, never an infinite spectrum.
    std::vector<double> huge = x;
    huge[3] = 1e200;
    expectRefusal([&] { powerSpectralDensity(huge, 1e-3); }, "x", "overflows a double");
    expectRefusal([&] { estimateFrequencyResponse(x, huge, 1e-3); }, "y", "overflows a double");
    std::vector<double> shorter(99, 0.0);
    expectRefusal([&] { estimateFrequencyResponse(x, shorter, 1e-3); }, "y", "equally long");
    // Two half-overlapping segments of 64 need 96 samples: 95 are refused, 96 are accepted.
    WelchOptions o;
    o.segmentLength = 64;
    std::vector<double> x95(x.begin(), x.begin() + 95), x96(x.begin(), x.begin() + 96);
    expectRefusal([&] { powerSpectralDensity(x95, 1e-3, o); }, "x", "fewer than two");
    QCOMPARE(powerSpectralDensity(x96, 1e-3, o).segments.count, std::size_t{2});
    expectRefusal([&] { estimateFrequencyResponse(x95, x95, 1e-3, o); }, "u", "fewer than two");
    o.segmentLength = 3;
    expectRefusal([&] { powerSpectralDensity(x, 1e-3, o); }, "segment", "at least 4");
    expectRefusal([&] { estimateFrequencyResponse(x, y, 1e-3, {}, 0.0); }, "band_sigmas",
                  "positive");
    // Nyquist of a 1 kHz log: 500 Hz.
    requireBelowNyquist(500.0, 1e-3, "--mode-frequency");
    expectRefusal([&] { requireBelowNyquist(501.0, 1e-3, "--mode-frequency"); }, "--mode-frequency",
                  "frequency above the log's Nyquist frequency of 500 Hz");
    expectRefusal([&] { requireBelowNyquist(-1.0, 1e-3, "--mode-frequency"); }, "--mode-frequency",
                  "positive");
}

QTEST_APPLESS_MAIN(TstSpectralEstimate)
#include "tst_spectral_estimate.moc"
