// SPDX-License-Identifier: GPL-3.0-or-later
// Klipper's shaper auto-tuning against an independent NumPy re-implementation of its formulas
// (tests/data/gen_input_shapers.py -> input_shapers_klipper.json: Klipper's shaper_defs.py
// closed forms and shaper_calibrate.py's _estimate_shaper, _estimate_remaining_vibrations,
// _get_shaper_smoothing, find_shaper_max_accel, fit_shaper and find_best_shaper), on Klipper's
// frequency bins of a 3200 Hz log and a fixed two-peak spectrum; and the response against the
// residual vibration formula of Singer and Seering.
#include "core/design/input_shaper.h"
#include "core/design/shaper_recommendation.h"
#include "core/model/errors.h"
#include "tests/support/tolerance.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>
#include <vector>

using namespace xyt;

namespace {

QJsonObject referenceData() {
    QFile file(QStringLiteral(XYT_TEST_DATA_DIR "/input_shapers_klipper.json"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

std::vector<double> toVector(const QJsonArray& a) {
    std::vector<double> v;
    for (const QJsonValue& x : a)
        v.push_back(x.toDouble());
    return v;
}

PowerSpectrum referenceSpectrum(const QJsonObject& data) {
    const QJsonObject s = data["spectrum"].toObject();
    return {toVector(s["frequency"].toArray()), toVector(s["power"].toArray())};
}

/// The spectrum cut at 200 Hz, as fit_shaper uses it.
PowerSpectrum cutAt200(const PowerSpectrum& p) {
    PowerSpectrum out;
    for (std::size_t k = 0; k < p.frequencyHz.size(); ++k)
        if (p.frequencyHz[k] <= 200.0) {
            out.frequencyHz.push_back(p.frequencyHz[k]);
            out.power.push_back(p.power[k]);
        }
    return out;
}

ShaperType typeOf(const QString& name) {
    ShaperType t = ShaperType::Zv;
    if (!shaperFromName(name.toStdString(), t))
        qFatal("unknown shaper %s", qPrintable(name));
    return t;
}

} // namespace

class TstShaperRecommendation : public QObject {
    Q_OBJECT

private slots:
    void shapersMatchKlippersDefinitions();
    void smoothingMaxAccelAndRemainingVibration();
    void responseIsTheResidualVibration();
    void normalizationMatchesKlipper();
    void recommendation_data();
    void recommendation();
    void badInputNamesTheField();
};

/// ZV .. 3-hump EI at 40 Hz, zeta 0.1: the same closed forms evaluated by both; the 2-hump EI
/// takes a cube root (cbrt here, ** (1/3) in Python), which may differ by an ulp; 1e-13
/// relative covers that after normalization.
void TstShaperRecommendation::shapersMatchKlippersDefinitions() {
    const QJsonObject data = referenceData();
    QVERIFY(!data.isEmpty());
    const QJsonObject shapers = data["shapers_40hz_zeta_0p1"].toObject();
    QCOMPARE(shapers.size(), 7);
    for (auto it = shapers.begin(); it != shapers.end(); ++it) {
        const QJsonObject o = it.value().toObject();
        const InputShaper s = designInputShaper(typeOf(it.key()), 40.0, 0.1);
        const std::vector<double> a = toVector(o["amplitudes"].toArray());
        const std::vector<double> t = toVector(o["times"].toArray());
        QCOMPARE(s.amplitudes.size(), a.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            XYT_COMPARE_NEAR(s.amplitudes[i], a[i], 1e-13, 0.0);
            XYT_COMPARE_NEAR(s.times[i], t[i], 1e-14, 0.0);
        }
    }
}

/// Smoothing: the same dozen operations, 1e-12 relative. Max accel: both run Klipper's
/// bisection to a bracket of 1e-8 mm/s^2; a decision flipped by round-off could move the result
/// by at most that bracket, hence 1e-8 absolute. Remaining vibration over zeta 0 .. 0.2: the
/// sums are taken in another order (Horner's rule over evenly spaced impulses here, term by
/// term and NumPy's pairwise sums there), round-off ~1e-15 of the sums; 1e-9 relative with
/// 1e-14 absolute for the exact zeros (MZV cancels every bin above the threshold).
void TstShaperRecommendation::smoothingMaxAccelAndRemainingVibration() {
    const QJsonObject data = referenceData();
    const PowerSpectrum spectrum = cutAt200(referenceSpectrum(data));
    QCOMPARE(spectrum.frequencyHz.size(), std::size_t(129)); // 0 .. 200 Hz every 1.5625 Hz
    const QJsonObject shapers = data["shapers_40hz_zeta_0p1"].toObject();
    for (auto it = shapers.begin(); it != shapers.end(); ++it) {
        const QJsonObject o = it.value().toObject();
        const InputShaper s = designInputShaper(typeOf(it.key()), 40.0, 0.1);
        XYT_COMPARE_NEAR(klipperShaperSmoothing(s), o["smoothing"].toDouble(), 1e-12, 0.0);
        XYT_COMPARE_NEAR(klipperShaperSmoothing(s, 3000.0, 8.0),
                         o["smoothing_accel_3000_scv_8"].toDouble(), 1e-12, 0.0);
        XYT_COMPARE_NEAR(klipperMaxAccel(s), o["max_accel"].toDouble(), 0.0, 1e-8);
        XYT_COMPARE_NEAR(klipperMaxAccel(s, 8.0), o["max_accel_scv_8"].toDouble(), 0.0, 1e-8);
        const std::vector<double> drs = toVector(o["test_damping_ratios"].toArray());
        const std::vector<double> expected = toVector(o["remaining_vibrations"].toArray());
        for (std::size_t i = 0; i < drs.size(); ++i)
            XYT_COMPARE_NEAR(klipperRemainingVibrations(s, drs[i], spectrum), expected[i], 1e-9,
                             1e-14);
    }
}

/// _estimate_shaper is Singer and Seering's residual vibration at each frequency: for every
/// shaper (evenly spaced impulses: the Horner path) and for a shaper with uneven times (the
/// term-by-term path), 1e-13 absolute (values <= 1, a handful of terms).
void TstShaperRecommendation::responseIsTheResidualVibration() {
    std::vector<double> f;
    for (double x = 0.5; x < 400.0; x += 0.7)
        f.push_back(x);
    InputShaper uneven;
    uneven.frequencyHz = 50.0;
    uneven.amplitudes = {0.3, 0.45, 0.25};
    uneven.times = {0.0, 0.0071, 0.0188};
    std::vector<InputShaper> shapers = {uneven};
    for (ShaperType t : ShaperRecommendationOptions().shapers)
        shapers.push_back(designInputShaper(t, 47.0, 0.08));
    for (const InputShaper& s : shapers)
        for (double zeta : {0.0, 0.075, 0.15}) {
            const std::vector<double> v = klipperShaperResponse(s, zeta, f);
            for (std::size_t k = 0; k < f.size(); ++k)
                XYT_COMPARE_NEAR(v[k], residualVibration(s, f[k], zeta), 0.0, 1e-13);
        }
}

/// normalize_to_frequencies: one division and one exp per bin, 1e-14 relative.
void TstShaperRecommendation::normalizationMatchesKlipper() {
    const QJsonObject data = referenceData();
    const PowerSpectrum n = klipperNormalizeToFrequencies(referenceSpectrum(data));
    const std::vector<double> expected = toVector(data["normalized_power"].toArray());
    QCOMPARE(n.power.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k)
        XYT_COMPARE_NEAR(n.power[k], expected[k], 1e-14, 0.0);
}

void TstShaperRecommendation::recommendation_data() {
    QTest::addColumn<QString>("scenario");
    QTest::addColumn<bool>("klipperSet");
    QTest::addColumn<double>("maxSmoothing");
    QTest::addColumn<double>("maxVibrations");
    // All seven from 10 Hz; Klipper's default search (its five autotune shapers from their
    // min_freq) with max_smoothing 0.1, which stops every search early; max_vibrations 0.01.
    QTest::newRow("default") << "recommendation_default" << false << 0.0 << -1.0;
    QTest::newRow("klipper_max_smoothing") << "recommendation_klipper" << true << 0.1 << -1.0;
    QTest::newRow("max_vibrations") << "recommendation_max_vibrations" << false << 0.0 << 0.01;
}

/// Every shaper's chosen frequency (the same grid point: both build NumPy's arange), its
/// remaining vibration and score (1e-9 relative, as above), smoothing (1e-12), max accel
/// (1e-8 absolute, the bisection's bracket), the number of frequencies tested, and the
/// recommended shaper.
void TstShaperRecommendation::recommendation() {
    QFETCH(QString, scenario);
    QFETCH(bool, klipperSet);
    QFETCH(double, maxSmoothing);
    QFETCH(double, maxVibrations);
    const QJsonObject data = referenceData();
    const QJsonObject ref = data[scenario].toObject();
    QVERIFY(!ref.isEmpty());
    ShaperRecommendationOptions o;
    if (klipperSet) {
        o.shapers = klipperAutotuneShapers();
        o.useKlipperMinimumFrequencies = true;
    }
    if (maxSmoothing > 0.0)
        o.maxSmoothing = maxSmoothing;
    if (maxVibrations >= 0.0)
        o.maxVibrations = maxVibrations;
    const ShaperRecommendation r = recommendShaper(referenceSpectrum(data), o);
    QCOMPARE(r.frequencyHz.size(), std::size_t(129));
    const QJsonArray fits = ref["fits"].toArray();
    QCOMPARE(r.fits.size(), std::size_t(fits.size()));
    for (std::size_t i = 0; i < r.fits.size(); ++i) {
        const QJsonObject e = fits[static_cast<int>(i)].toObject();
        const ShaperFit& f = r.fits[i];
        QCOMPARE(QString(shaperName(f.shaper.type)), e["name"].toString());
        XYT_COMPARE_NEAR(f.shaper.frequencyHz, e["freq"].toDouble(), 1e-12, 0.0);
        XYT_COMPARE_NEAR(f.remainingVibrations, e["vibrs"].toDouble(), 1e-9, 1e-14);
        XYT_COMPARE_NEAR(f.score, e["score"].toDouble(), 1e-9, 1e-14);
        XYT_COMPARE_NEAR(f.smoothing, e["smoothing"].toDouble(), 1e-12, 0.0);
        XYT_COMPARE_NEAR(f.maxAccelMmPerS2, e["max_accel"].toDouble(), 0.0, 1e-8);
        QCOMPARE(static_cast<int>(f.candidates.size()), e["candidates"].toInt());
        QCOMPARE(f.response.size(), r.frequencyHz.size());
        // Invariants: candidates increasing in frequency, the reported one among them.
        for (std::size_t k = 1; k < f.candidates.size(); ++k)
            QVERIFY(f.candidates[k].frequencyHz > f.candidates[k - 1].frequencyHz);
    }
    QCOMPARE(QString(shaperName(r.best().shaper.type)), ref["recommended"].toString());
}

void TstShaperRecommendation::badInputNamesTheField() {
    const auto field = [](auto&& call) -> std::string {
        try {
            call();
        } catch (const InvalidInput& e) {
            return e.field();
        }
        return "no exception";
    };
    const PowerSpectrum good{{0.0, 10.0, 20.0}, {0.0, 1.0, 0.5}};
    QCOMPARE(field([&] { recommendShaper({{0.0, 10.0}, {1.0}}); }), std::string("spectrum.power"));
    QCOMPARE(field([&] {
                 recommendShaper({{10.0, 5.0}, {1.0, 1.0}});
             }),
             std::string("spectrum.frequency"));
    QCOMPARE(field([&] {
                 recommendShaper({{0.0, 10.0}, {0.0, 0.0}});
             }),
             std::string("spectrum.power"));
    QCOMPARE(field([&] {
                 recommendShaper({{0.0, 10.0}, {1.0, std::nan("")}});
             }),
             std::string("spectrum.power"));
    ShaperRecommendationOptions o;
    o.dampingRatio = 1.0;
    QCOMPARE(field([&] { recommendShaper(good, o); }), std::string("dampingRatio"));
    o = {};
    o.stepHz = 0.0;
    QCOMPARE(field([&] { recommendShaper(good, o); }), std::string("stepHz"));
    o = {};
    o.testDampingRatios = {0.1, -0.1};
    QCOMPARE(field([&] { recommendShaper(good, o); }), std::string("testDampingRatios"));
    o = {};
    o.maxFrequencyHz = 5.0;
    QCOMPARE(field([&] { recommendShaper(good, o); }), std::string("maxFrequencyHz"));
}

QTEST_APPLESS_MAIN(TstShaperRecommendation)
#include "tst_shaper_recommendation.moc"
