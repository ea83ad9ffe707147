// SPDX-License-Identifier: GPL-3.0-or-later
// Klipper's input shaper auto-tuning (klippy/extras/shaper_calibrate.py by Dmitry Butyugin):
// each function below names the Klipper function it reproduces. The search evaluates a shaper's
// response at every spectrum bin for about a thousand frequencies per shaper and three damping
// ratios; the inner loop (recommendationResponseInto) runs over the bins as Eigen arrays, with one
// exp and one sin/cos pair per bin for shapers with evenly spaced impulses (all seven).
#include "core/design/shaper_recommendation.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace xyt {

namespace {

/// SHAPER_VIBRATION_REDUCTION of Klipper's shaper_defs.py.
constexpr double kRecommendationVibrationReduction = 20.0;
/// find_shaper_max_accel's TARGET_SMOOTHING (mm).
constexpr double kRecommendationTargetSmoothing = 0.12;
/// _get_shaper_smoothing's default acceleration (mm/s^2) for the reported smoothing.
constexpr double kRecommendationSmoothingAccel = 5000.0;

/// Klipper's min_freq per shaper (shaper_defs.py INPUT_SHAPERS); 0 when Klipper has none.
double recommendationKlipperMinFrequency(ShaperType type) {
    switch (type) {
    case ShaperType::Zv:
        return 21.0;
    case ShaperType::Mzv:
        return 23.0;
    case ShaperType::Zvd:
    case ShaperType::Ei:
        return 29.0;
    case ShaperType::TwoHumpEi:
        return 39.0;
    case ShaperType::ThreeHumpEi:
        return 48.0;
    case ShaperType::Zvdd:
        break;
    }
    return 0.0;
}

/// One test damping ratio's per-bin constants.
struct RecommendationDamping {
    double ratio = 0.0;
    Eigen::ArrayXd decay;  ///< zeta omega
    Eigen::ArrayXd omegaD; ///< omega sqrt(1 - zeta^2)
};

RecommendationDamping recommendationDamping(double ratio, const Eigen::ArrayXd& omega) {
    return {ratio, ratio * omega, omega * std::sqrt(1.0 - ratio * ratio)};
}

/// Scratch arrays of the inner loop, sized once.
struct RecommendationScratch {
    Eigen::ArrayXd q, c, s, pRe, pIm, next, accRe, accIm;
    explicit RecommendationScratch(Eigen::Index n)
        : q(n), c(n), s(n), pRe(n), pIm(n), next(n), accRe(n), accIm(n) {}
};

/// True when t_i = i t_1 (to 1e-12 of the duration): then exp(-zeta omega (t_n - t_i)) and
/// exp(j omega_d t_i) are powers of one exp and one sin/cos pair per bin.
bool recommendationEvenlySpaced(const InputShaper& s) {
    const std::size_t n = s.times.size();
    if (n < 2)
        return false;
    const double step = s.times[1];
    for (std::size_t i = 0; i < n; ++i)
        if (std::abs(s.times[i] - static_cast<double>(i) * step) > 1e-12 * s.times.back())
            return false;
    return true;
}

/// _estimate_shaper into @p out: |sum_i A_i exp(-zeta omega (t_n - t_i)) e^{j omega_d t_i}| /
/// sum A_i at every bin. Evenly spaced impulses, t_i = i h: with q = exp(-zeta omega h) and
/// p = e^{j omega_d h}, the sum is sum_i A_i q^(n-1-i) p^i, evaluated by Horner's rule
/// (acc <- acc q + A_i p^i), which agrees with Klipper's term-by-term sum to a few ulps per
/// impulse; otherwise term by term as Klipper does.
void recommendationResponseInto(const InputShaper& shaper, const RecommendationDamping& d,
                                RecommendationScratch& w, Eigen::ArrayXd& out) {
    const std::vector<double>& a = shaper.amplitudes;
    const std::vector<double>& t = shaper.times;
    double sumA = 0.0;
    for (double ai : a)
        sumA += ai;
    const double invD = 1.0 / sumA;
    const Eigen::Index bins = d.omegaD.size();
    if (recommendationEvenlySpaced(shaper)) {
        const double h = t[1];
        w.q = (-h * d.decay).exp(); // Eigen's vectorized exp
        for (Eigen::Index k = 0; k < bins; ++k) {
            const double phase = d.omegaD[k] * h;
            w.c[k] = std::cos(phase);
            w.s[k] = std::sin(phase);
        }
        w.accRe.setConstant(a[0]);
        w.accIm.setZero();
        w.pRe.setOnes();
        w.pIm.setZero();
        for (std::size_t i = 1; i < a.size(); ++i) {
            // p <- p e^{j omega_d h}; acc <- acc q + A_i p (vectorized over the bins)
            w.next = w.pRe * w.c - w.pIm * w.s;
            w.pIm = w.pRe * w.s + w.pIm * w.c;
            w.pRe.swap(w.next);
            w.accRe = w.accRe * w.q + a[i] * w.pRe;
            w.accIm = w.accIm * w.q + a[i] * w.pIm;
        }
        out = (w.accRe.square() + w.accIm.square()).sqrt() * invD;
        return;
    }
    w.accRe.setZero();
    w.accIm.setZero();
    const double tn = t.back();
    for (std::size_t i = 0; i < a.size(); ++i) {
        w.q = a[i] * (-(tn - t[i]) * d.decay).exp();
        w.accIm += w.q * (d.omegaD * t[i]).sin();
        w.accRe += w.q * (d.omegaD * t[i]).cos();
    }
    out = (w.accRe.square() + w.accIm.square()).sqrt() * invD;
}

/// The spectrum checked: sizes, increasing finite frequencies >= 0, finite powers >= 0.
void requireRecommendationSpectrum(const PowerSpectrum& p) {
    if (p.frequencyHz.size() != p.power.size())
        throw InvalidInput(
            "spectrum.power",
            makeDiagnostic("design_spectrum_sizes_differ",
                           {std::to_string(p.power.size()), std::to_string(p.frequencyHz.size())}));
    if (p.frequencyHz.empty())
        throw InvalidInput("spectrum.frequency", makeDiagnostic("is_empty"));
    for (std::size_t k = 0; k < p.frequencyHz.size(); ++k) {
        const double f = p.frequencyHz[k];
        if (!std::isfinite(f) || f < 0.0 || (k > 0 && !(f > p.frequencyHz[k - 1])))
            throw InvalidInput(
                "spectrum.frequency",
                makeDiagnostic("design_spectrum_frequency_order", {std::to_string(k + 1)}));
        if (!std::isfinite(p.power[k]) || p.power[k] < 0.0)
            throw InvalidInput("spectrum.power", makeDiagnostic("design_spectrum_power_negative",
                                                                {std::to_string(k + 1)}));
    }
}

void requireRecommendationDamping(double zeta, const std::string& field) {
    if (!(zeta >= 0.0 && zeta < 1.0))
        throw InvalidInput(field, makeDiagnostic("in_zero_one_open_right"));
}

/// The vibration threshold and the denominator of _estimate_remaining_vibrations.
struct RecommendationPsd {
    Eigen::ArrayXd power;
    double threshold = 0.0;
    double allVibrations = 0.0;
};

RecommendationPsd recommendationPsd(const Eigen::ArrayXd& power) {
    RecommendationPsd p;
    p.power = power;
    p.threshold = power.maxCoeff() / kRecommendationVibrationReduction;
    p.allVibrations = (power - p.threshold).max(0.0).sum();
    if (!(p.allVibrations > 0.0))
        throw InvalidInput("spectrum.power", makeDiagnostic("design_spectrum_power_zero"));
    return p;
}

double recommendationRemaining(const Eigen::ArrayXd& response, const RecommendationPsd& p) {
    return (response * p.power - p.threshold).max(0.0).sum() / p.allVibrations;
}

/// Klipper's np.arange(start, stop, step): ceil((stop - start) / step) values start + i d with
/// d = (start + step) - start (NumPy fills the array from its first two values).
std::vector<double> recommendationArange(double start, double stop, double step) {
    const double n = std::ceil((stop - start) / step);
    std::vector<double> out;
    if (!(n > 0.0))
        return out;
    const double delta = (start + step) - start;
    out.reserve(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
        out.push_back(start + static_cast<double>(i) * delta);
    return out;
}

/// One shaper's search: Klipper's results list (highest frequency first) and its choice.
struct RecommendationSearch {
    ShaperType type = ShaperType::Zv;
    std::vector<ShaperCandidate> results; ///< Klipper's order: decreasing frequency
    std::size_t chosen = 0;
};

} // namespace

std::vector<ShaperType> klipperAutotuneShapers() {
    return {ShaperType::Zv, ShaperType::Mzv, ShaperType::Ei, ShaperType::TwoHumpEi,
            ShaperType::ThreeHumpEi};
}

std::vector<double> klipperShaperResponse(const InputShaper& shaper, double testDampingRatio,
                                          const std::vector<double>& frequencyHz) {
    requireRecommendationDamping(testDampingRatio, "testDampingRatio");
    const Eigen::ArrayXd omega =
        2.0 * std::numbers::pi *
        Eigen::Map<const Eigen::ArrayXd>(frequencyHz.data(),
                                         static_cast<Eigen::Index>(frequencyHz.size()));
    RecommendationScratch scratch(omega.size());
    Eigen::ArrayXd out(omega.size());
    recommendationResponseInto(shaper, recommendationDamping(testDampingRatio, omega), scratch,
                               out);
    return {out.begin(), out.end()};
}

double klipperRemainingVibrations(const InputShaper& shaper, double testDampingRatio,
                                  const PowerSpectrum& spectrum) {
    requireRecommendationSpectrum(spectrum);
    const std::vector<double> response =
        klipperShaperResponse(shaper, testDampingRatio, spectrum.frequencyHz);
    const RecommendationPsd psd = recommendationPsd(Eigen::Map<const Eigen::ArrayXd>(
        spectrum.power.data(), static_cast<Eigen::Index>(spectrum.power.size())));
    return recommendationRemaining(
        Eigen::Map<const Eigen::ArrayXd>(response.data(), psd.power.size()), psd);
}

double klipperShaperSmoothing(const InputShaper& shaper, double accelMmPerS2,
                              double squareCornerVelocityMmPerS) {
    const std::vector<double>& a = shaper.amplitudes;
    const std::vector<double>& t = shaper.times;
    const double halfAccel = accelMmPerS2 * 0.5;
    double sumA = 0.0;
    for (double ai : a)
        sumA += ai;
    const double invD = 1.0 / sumA;
    double ts = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        ts += a[i] * t[i];
    ts *= invD;
    double offset90 = 0.0, offset180 = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (t[i] >= ts)
            offset90 += a[i] * (squareCornerVelocityMmPerS + halfAccel * (t[i] - ts)) * (t[i] - ts);
        offset180 += a[i] * halfAccel * (t[i] - ts) * (t[i] - ts);
    }
    offset90 *= invD * std::sqrt(2.0);
    offset180 *= invD;
    return std::max(offset90, offset180);
}

double klipperMaxAccel(const InputShaper& shaper, double squareCornerVelocityMmPerS) {
    const auto within = [&](double accel) {
        return klipperShaperSmoothing(shaper, accel, squareCornerVelocityMmPerS) <=
               kRecommendationTargetSmoothing;
    };
    // Klipper's _bisect, step by step.
    double left = 1.0, right = 1.0;
    if (!within(1e-9))
        return 0.0;
    while (!within(left)) {
        right = left;
        left *= 0.5;
    }
    if (right == left)
        while (within(right))
            right *= 2.0;
    while (right - left > 1e-8) {
        const double middle = (left + right) * 0.5;
        if (within(middle))
            left = middle;
        else
            right = middle;
    }
    return left;
}

PowerSpectrum klipperNormalizeToFrequencies(PowerSpectrum spectrum) {
    requireRecommendationSpectrum(spectrum);
    constexpr double kMinFreq = 5.0; // shaper_calibrate.py's MIN_FREQ
    for (std::size_t k = 0; k < spectrum.power.size(); ++k) {
        const double f = spectrum.frequencyHz[k];
        spectrum.power[k] /= f + 0.1;
        if (f < 2.0 * kMinFreq) {
            const double r = 2.0 * kMinFreq / (f + 0.1);
            spectrum.power[k] *= std::exp(-r * r + 1.0);
        }
    }
    return spectrum;
}

ShaperRecommendation recommendShaper(const PowerSpectrum& spectrum,
                                     const ShaperRecommendationOptions& o) {
    requireRecommendationSpectrum(spectrum);
    requirePositive(o.minFrequencyHz, "minFrequencyHz");
    requirePositive(o.maxFrequencyHz, "maxFrequencyHz");
    requirePositive(o.stepHz, "stepHz");
    if (!(o.maxFrequencyHz > o.minFrequencyHz))
        throw InvalidInput("maxFrequencyHz", makeDiagnostic("design_above_min_frequency"));
    requireRecommendationDamping(o.dampingRatio, "dampingRatio");
    if (o.testDampingRatios.empty())
        throw InvalidInput("testDampingRatios", makeDiagnostic("is_empty"));
    for (double zeta : o.testDampingRatios)
        requireRecommendationDamping(zeta, "testDampingRatios");
    requireFinite(o.squareCornerVelocityMmPerS, "squareCornerVelocityMmPerS");
    if (o.squareCornerVelocityMmPerS < 0.0)
        throw InvalidInput("squareCornerVelocityMmPerS", makeDiagnostic("not_negative"));
    requirePositive(o.maxSpectrumFrequencyHz, "maxSpectrumFrequencyHz");
    if (o.maxSmoothing)
        requirePositive(*o.maxSmoothing, "maxSmoothing");
    if (o.maxVibrations) {
        requireFinite(*o.maxVibrations, "maxVibrations");
        if (*o.maxVibrations < 0.0)
            throw InvalidInput("maxVibrations", makeDiagnostic("not_negative"));
    }
    if (o.shapers.empty())
        throw InvalidInput("shapers", makeDiagnostic("is_empty"));

    // The tested frequencies of each shaper, and the spectrum bins used (fit_shaper's max_freq
    // = max(MAX_FREQ, the highest tested frequency)).
    std::vector<std::vector<double>> testFrequencies;
    double highestTested = 0.0;
    for (ShaperType type : o.shapers) {
        double start = o.minFrequencyHz;
        if (o.useKlipperMinimumFrequencies && recommendationKlipperMinFrequency(type) > 0.0)
            start = std::min(recommendationKlipperMinFrequency(type), o.maxFrequencyHz - 1e-7);
        testFrequencies.push_back(recommendationArange(start, o.maxFrequencyHz, o.stepHz));
        if (testFrequencies.back().empty())
            throw InvalidInput("stepHz", makeDiagnostic("design_no_frequency_to_test"));
        highestTested = std::max(highestTested, testFrequencies.back().back());
    }
    const double maxBin = std::max(o.maxSpectrumFrequencyHz, highestTested);
    ShaperRecommendation out;
    std::vector<double> power;
    for (std::size_t k = 0; k < spectrum.frequencyHz.size(); ++k)
        if (spectrum.frequencyHz[k] <= maxBin) {
            out.frequencyHz.push_back(spectrum.frequencyHz[k]);
            power.push_back(spectrum.power[k]);
        }
    if (out.frequencyHz.empty())
        throw InvalidInput("spectrum.frequency", makeDiagnostic("design_spectrum_no_frequency",
                                                                {std::to_string(maxBin)}));
    const Eigen::Index bins = static_cast<Eigen::Index>(power.size());
    const RecommendationPsd psd =
        recommendationPsd(Eigen::Map<const Eigen::ArrayXd>(power.data(), bins));
    const Eigen::ArrayXd omega =
        2.0 * std::numbers::pi * Eigen::Map<const Eigen::ArrayXd>(out.frequencyHz.data(), bins);
    std::vector<RecommendationDamping> dampings;
    for (double zeta : o.testDampingRatios)
        dampings.push_back(recommendationDamping(zeta, omega));
    RecommendationScratch scratch(bins);
    Eigen::ArrayXd response(bins);
    const double scv = o.squareCornerVelocityMmPerS;

    // fit_shaper for each shaper.
    std::vector<RecommendationSearch> searches;
    for (std::size_t s = 0; s < o.shapers.size(); ++s) {
        RecommendationSearch search;
        search.type = o.shapers[s];
        const std::vector<double>& freqs = testFrequencies[s];
        std::optional<std::size_t> best;
        bool stoppedBySmoothing = false;
        for (auto it = freqs.rbegin(); it != freqs.rend(); ++it) {
            const InputShaper shaper = designInputShaper(search.type, *it, o.dampingRatio);
            const double smoothing =
                klipperShaperSmoothing(shaper, kRecommendationSmoothingAccel, scv);
            if (o.maxSmoothing && smoothing > *o.maxSmoothing && best) {
                stoppedBySmoothing = true;
                break;
            }
            double vibrations = 0.0;
            for (const RecommendationDamping& d : dampings) {
                recommendationResponseInto(shaper, d, scratch, response);
                vibrations = std::max(vibrations, recommendationRemaining(response, psd));
            }
            const double score = smoothing * (std::pow(vibrations, 1.5) + vibrations * 0.2 + 0.01);
            search.results.push_back({*it, vibrations, smoothing, score});
            if (!best || search.results[*best].remainingVibrations > vibrations)
                best = search.results.size() - 1;
        }
        // The search can only end without a best if no frequency was tested (excluded above).
        std::size_t selected = *best;
        if (!stoppedBySmoothing) {
            // fit_shaper: "the one that is not much worse than the 'best' one, but gives much
            // less smoothing", scanning from the lowest frequency up.
            const ShaperCandidate& b = search.results[*best];
            for (std::size_t k = search.results.size(); k-- > 0;) {
                const ShaperCandidate& r = search.results[k];
                if (r.remainingVibrations < b.remainingVibrations * 1.1 + 0.0005 &&
                    (r.score < search.results[selected].score ||
                     (o.maxVibrations && b.remainingVibrations > *o.maxVibrations)))
                    selected = k;
            }
        }
        search.chosen = selected;
        searches.push_back(std::move(search));
    }

    // find_best_shaper.
    std::optional<std::size_t> bestShaper;
    const auto chosen = [&](std::size_t s) -> const ShaperCandidate& {
        return searches[s].results[searches[s].chosen];
    };
    for (std::size_t s = 0; s < searches.size(); ++s) {
        const ShaperCandidate& c = chosen(s);
        if (!bestShaper || c.score * 1.2 < chosen(*bestShaper).score ||
            (c.score * 1.05 < chosen(*bestShaper).score &&
             c.smoothing * 1.1 < chosen(*bestShaper).smoothing) ||
            (o.maxVibrations && chosen(*bestShaper).remainingVibrations > *o.maxVibrations &&
             c.remainingVibrations < chosen(*bestShaper).remainingVibrations))
            bestShaper = s;
        // Any frequency of this shaper with both less vibration and less smoothing than the
        // best becomes the best, and this shaper's reported fit (from the lowest frequency up).
        for (std::size_t k = searches[s].results.size(); k-- > 0;) {
            const ShaperCandidate& r = searches[s].results[k];
            const ShaperCandidate& b = chosen(*bestShaper);
            if (r.remainingVibrations < b.remainingVibrations && r.smoothing < b.smoothing) {
                searches[s].chosen = k;
                bestShaper = s;
            }
        }
    }
    if (searches[*bestShaper].type == ShaperType::Zv)
        for (std::size_t s = 0; s < searches.size(); ++s)
            if (searches[s].type != ShaperType::Zv &&
                chosen(s).remainingVibrations * 1.1 < chosen(*bestShaper).remainingVibrations) {
                bestShaper = s;
                break;
            }
    out.recommended = *bestShaper;

    // The reported figures: max_accel and the response only for the chosen frequencies.
    for (const RecommendationSearch& search : searches) {
        ShaperFit fit;
        const ShaperCandidate& c = search.results[search.chosen];
        fit.shaper = designInputShaper(search.type, c.frequencyHz, o.dampingRatio);
        fit.remainingVibrations = c.remainingVibrations;
        fit.smoothing = c.smoothing;
        fit.score = c.score;
        fit.maxAccelMmPerS2 = klipperMaxAccel(fit.shaper, scv);
        Eigen::ArrayXd worst = Eigen::ArrayXd::Zero(bins);
        for (const RecommendationDamping& d : dampings) {
            recommendationResponseInto(fit.shaper, d, scratch, response);
            worst = worst.max(response);
        }
        fit.response.assign(worst.begin(), worst.end());
        fit.candidates.assign(search.results.rbegin(), search.results.rend());
        out.fits.push_back(std::move(fit));
    }
    return out;
}

} // namespace xyt
