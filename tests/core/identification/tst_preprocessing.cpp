// SPDX-License-Identifier: GPL-3.0-or-later
// Preprocessing (core/identification/preprocessing.h): time ranges, means and trends, and
// decimation with its anti-alias filter. Sources: closed forms (index arithmetic, least squares
// of an exact line, the Chebyshev type I magnitude |H|^2 = (1 + eps^2) / (1 + eps^2 T_8^2(x)) with
// the bilinear warping x = tan(w/2) / tan(wc/2)).
#include "core/identification/preprocessing.h"
#include "core/model/errors.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTest>

#include <array>

#include <cmath>
#include <complex>
#include <numbers>

namespace {

constexpr double kPi = std::numbers::pi;

xyt::IoData record(std::size_t n, double ts, double (*u)(double), double (*y)(double)) {
    xyt::IoData d;
    d.tsSeconds = ts;
    for (std::size_t k = 0; k < n; ++k) {
        d.u.push_back(u(double(k) * ts));
        d.y.push_back(y(double(k) * ts));
    }
    return d;
}

double eps2() {
    return std::pow(10.0, xyt::kDecimationRippleDb / 10.0) - 1.0;
}

/// Closed-form |H(e^{jw})|^2 of the designed filter (unit DC gain).
double designMagnitudeSquared(double w, int factor) {
    const double wc = xyt::kDecimationEdge * kPi / factor;
    const double x = std::tan(w / 2.0) / std::tan(wc / 2.0);
    const double t8 = x <= 1.0 ? std::cos(8.0 * std::acos(x)) : std::cosh(8.0 * std::acosh(x));
    return (1.0 + eps2()) / (1.0 + eps2() * t8 * t8);
}

double magnitudeSquared(const std::vector<xyt::BiquadSection>& sections, double w) {
    const std::complex<double> z1 = std::polar(1.0, -w), z2 = z1 * z1;
    std::complex<double> h = 1.0;
    for (const auto& s : sections)
        h *= (s.b[0] + s.b[1] * z1 + s.b[2] * z2) / (s.a[0] + s.a[1] * z1 + s.a[2] * z2);
    return std::norm(h);
}

} // namespace

class TstPreprocessing : public QObject {
    Q_OBJECT
private slots:
    void preprocessIsTheStepsInOrder();
    void timeRangeKeepsTheSamplesInside();
    void meansAndTrendsAreRemoved();
    void filterMatchesTheChebyshevClosedForm_data();
    void filterMatchesTheChebyshevClosedForm();
    void decimateKeepsPassbandAndRejectsAliases();
    void tenMillisecondsBySevenIsSeventy();
    void badInput();
};

void TstPreprocessing::timeRangeKeepsTheSamplesInside() {
    xyt::IoData d = record(
        100, 0.01, [](double t) { return t; }, [](double t) { return 2.0 * t; });
    d.startSeconds = 1.0; // instants 1.00 .. 1.99
    const xyt::IoData r = xyt::selectTimeRange(d, 1.1, 1.2);
    // Samples k = 10 .. 20 (the bounds are instants, counted in): 11 samples.
    QCOMPARE(r.size(), std::size_t(11));
    QCOMPARE(r.u.front(), d.u[10]);
    QCOMPARE(r.y.back(), d.y[20]);
    XYT_COMPARE_NEAR(r.startSeconds, 1.1, 1e-15, 0.0); // 1 + 10 x 0.01 in one rounding
    // A range beyond the ends is cut to the record; one outside it is refused.
    QCOMPARE(xyt::selectTimeRange(d, 0.0, 5.0).size(), std::size_t(100));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::selectTimeRange(d, 3.0, 4.0); }),
             QString("range"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::selectTimeRange(d, 1.5, 1.2); }),
             QString("t1"));
}

void TstPreprocessing::meansAndTrendsAreRemoved() {
    // u = 3 + 0.5 k + (-1)^k, y = -2 - 0.25 k: the alternating term has zero mean over an even
    // count and is orthogonal to the trend only approximately, so check the exact line on y.
    xyt::IoData d;
    d.tsSeconds = 0.01;
    for (int k = 0; k < 10; ++k) {
        d.u.push_back(3.0 + (k % 2 ? -1.0 : 1.0));
        d.y.push_back(-2.0 - 0.25 * k);
    }
    const xyt::Detrended m = xyt::removeMeans(d);
    QCOMPARE(m.uOffset, 3.0);                        // mean of 5 x 4 and 5 x 2: exact
    XYT_COMPARE_NEAR(m.yOffset, -3.125, 1e-15, 0.0); // -2 - 0.25 x 4.5
    XYT_COMPARE_NEAR(m.data.u[0], 1.0, 1e-15, 0.0);
    const xyt::Detrended t = xyt::removeTrends(d);
    // An exact line is removed to round-off (values of order 1: 1e-14 absolute).
    XYT_COMPARE_NEAR(t.yOffset, -2.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(t.ySlopePerSample, -0.25, 1e-14, 0.0);
    for (double v : t.data.y)
        XYT_COMPARE_NEAR(v, 0.0, 0.0, 1e-14);
}

void TstPreprocessing::filterMatchesTheChebyshevClosedForm_data() {
    QTest::addColumn<int>("factor");
    QTest::newRow("2") << 2;
    QTest::newRow("7 (10 ms -> 70 ms)") << 7;
    QTest::newRow("50") << 50;
}

void TstPreprocessing::filterMatchesTheChebyshevClosedForm() {
    QFETCH(int, factor);
    const auto sections = xyt::decimationFilter(factor);
    QCOMPARE(int(sections.size()), xyt::kDecimationFilterOrder / 2);
    for (double f : {0.0, 0.1, 0.3, 0.5, 0.79, 0.8, 0.9, 1.0, 1.25, 1.5, 3.0}) {
        const double w = f * kPi / factor; // f = fraction of the new Nyquist frequency
        if (w >= kPi)
            continue;
        const double expected = designMagnitudeSquared(w, factor);
        // Products of 4 sections of well-conditioned biquads: 1e-9 relative (stopband values
        // down to 1e-10 are computed from pole positions near z = 1; for factor 50 the poles sit
        // within 0.05 of it, which costs about 6 digits of the stopband value).
        XYT_COMPARE_NEAR(magnitudeSquared(sections, w), expected, factor >= 50 ? 1e-5 : 1e-9,
                         1e-14);
    }
    XYT_COMPARE_NEAR(magnitudeSquared(sections, 0.0), 1.0, 1e-12, 0.0);
}

void TstPreprocessing::decimateKeepsPassbandAndRejectsAliases() {
    // 10 ms samples, factor 7: new Nyquist 1 / (2 x 0.07) = 7.142857 Hz.
    const int factor = 7;
    const double ts = 0.01, newNyquistHz = 0.5 / (ts * factor);
    const std::size_t n = 7000;
    for (const double fraction : {0.25, 1.5}) {
        const double hz = fraction * newNyquistHz;
        xyt::IoData d;
        d.tsSeconds = ts;
        for (std::size_t k = 0; k < n; ++k) {
            d.u.push_back(std::sin(2.0 * kPi * hz * double(k) * ts));
            d.y.push_back(d.u.back());
        }
        const xyt::IoData out = xyt::decimate(d, factor);
        QCOMPARE(out.size(), (n + factor - 1) / factor);
        // Forward and backward: the gain is |H|^2 with zero phase; interior samples only (the
        // first and last 100 of 1000, where the padding's transient could remain, are left out).
        const double gain = designMagnitudeSquared(2.0 * kPi * hz * ts, factor);
        double worst = 0.0, peak = 0.0;
        for (std::size_t j = 100; j + 100 < out.size(); ++j) {
            const double expected = gain * std::sin(2.0 * kPi * hz * double(j * factor) * ts);
            worst = std::max(worst, std::abs(out.u[j] - expected));
            peak = std::max(peak, std::abs(out.u[j]));
        }
        if (fraction < 1.0) {
            // Passband: the amplitude stays within the 2 x 0.05 dB ripple (1 <= gain <= 1.0116)
            // and the samples equal gain x the sine to 1e-6 (the filter's own round-off).
            QVERIFY(gain >= 1.0 && gain <= 1.0 + eps2() + 1e-12);
            QVERIFY2(worst <= 1e-6, qPrintable(QString::number(worst)));
        } else {
            // 1.5 x the new Nyquist frequency would alias to 0.5 x: the closed form gives
            // |H|^2 = 4.87e-7 (-63.1 dB, forward and backward); stated bound: attenuated by at
            // least 60 dB, and the samples follow the closed form to 1e-6 as in the passband.
            XYT_COMPARE_NEAR(gain, 4.869121475337362e-07, 1e-9, 0.0);
            QVERIFY2(20.0 * std::log10(peak) <= -60.0, qPrintable(QString::number(peak)));
            QVERIFY2(worst <= 1e-6, qPrintable(QString::number(worst)));
        }
    }
}

void TstPreprocessing::tenMillisecondsBySevenIsSeventy() {
    xyt::IoData d = record(
        700, 0.01, [](double) { return 1.0; }, [](double t) { return 5.0 + 0.0 * t; });
    d.startSeconds = 2.0;
    const xyt::IoData out = xyt::decimate(d, 7);
    XYT_COMPARE_NEAR(out.tsSeconds, 0.07, 1e-15, 0.0); // 7 x 0.01 in one rounding
    QCOMPARE(out.startSeconds, 2.0);
    QCOMPARE(out.size(), std::size_t(100));
    // A constant keeps its level (unit DC gain; padding by odd reflection of a constant is the
    // constant): round-off of 2 x 4 biquads on values of 5.
    for (double v : out.y)
        XYT_COMPARE_NEAR(v, 5.0, 1e-12, 0.0);
    QCOMPARE(xyt::decimate(d, 1).y, d.y);
}

void TstPreprocessing::badInput() {
    const xyt::IoData d = record(
        20, 0.01, [](double t) { return t; }, [](double t) { return t; });
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::decimate(d, 0); }), QString("factor"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::decimate(d, 2); }),
             QString("data")); // 20 <= 24
    xyt::IoData unequal = d;
    unequal.y.pop_back();
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::removeMeans(unequal); }), QString("data"));
    QCOMPARE(xyt::test::invalidInputField([&] { xyt::removeTrends(xyt::IoData{}); }),
             QString("data"));
}

void TstPreprocessing::preprocessIsTheStepsInOrder() {
    // Invariant: preprocess() is selectTimeRange, then removeTrends / removeMeans, then
    // decimate, bit for bit; no step leaves the record unchanged.
    const xyt::IoData d = record(
        2000, 0.01, [](double t) { return std::sin(3.0 * t) + 0.2 * t; },
        [](double t) { return std::cos(2.0 * t) + 1.5 + 0.1 * t; });
    QVERIFY(xyt::preprocess(d, {}).y == d.y);
    xyt::PreprocessingSteps steps;
    steps.rangeSeconds = std::array<double, 2>{2.0, 15.0};
    steps.offsets = xyt::OffsetRemoval::Trends;
    steps.decimateFactor = 3;
    const xyt::IoData expected =
        xyt::decimate(xyt::removeTrends(xyt::selectTimeRange(d, 2.0, 15.0)).data, 3);
    const xyt::IoData got = xyt::preprocess(d, steps);
    QVERIFY(got.u == expected.u && got.y == expected.y);
    QCOMPARE(got.tsSeconds, expected.tsSeconds);
    QCOMPARE(got.startSeconds, expected.startSeconds);
    steps.offsets = xyt::OffsetRemoval::Means;
    const xyt::IoData means = xyt::preprocess(d, steps);
    QVERIFY(means.y ==
            xyt::decimate(xyt::removeMeans(xyt::selectTimeRange(d, 2.0, 15.0)).data, 3).y);
    QVERIFY(means.y != got.y);
}

QTEST_APPLESS_MAIN(TstPreprocessing)
#include "tst_preprocessing.moc"
