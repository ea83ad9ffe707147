// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/input_shaper.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace xyt {

/**
 * A power spectrum: power[k] at frequencyHz[k] (increasing, >= 0). An accelerometer's PSD
 * ((mm/s^2)^2/Hz, as Klipper's calc_freq_response gives it), or |H(j 2 pi f)|^2 of a modelled
 * mode: the recommendation only uses ratios of the powers, so the unit does not matter.
 */
struct PowerSpectrum {
    std::vector<double> frequencyHz;
    std::vector<double> power;
};

/**
 * The settings of Klipper's shaper search (klippy/extras/shaper_calibrate.py, fit_shaper and
 * find_best_shaper), with Klipper's defaults except where said.
 */
struct ShaperRecommendationOptions {
    /// The tested shaper frequencies: Klipper's np.arange(min, max, step), i.e. min + i d with
    /// d = (min + step) - min, i = 0 .. ceil((max - min) / step) - 1 (max excluded). Klipper
    /// starts each shaper at its own min_freq (see useKlipperMinimumFrequencies) and ends at
    /// MAX_SHAPER_FREQ = 200 Hz with a 0.2 Hz step; here 10 Hz by default for every shaper.
    double minFrequencyHz = 10.0;
    double maxFrequencyHz = 200.0;
    double stepHz = 0.2;
    /// Start each of Klipper's shapers at Klipper's min_freq (shaper_defs.py: zv 21, mzv 23,
    /// zvd 29, ei 29, 2hump_ei 39, 3hump_ei 48 Hz, chosen there for a projected max_accel of
    /// about 1500 mm/s^2) instead of minFrequencyHz; ZVD-D, not in Klipper's set, keeps it.
    bool useKlipperMinimumFrequencies = false;
    /// The damping ratio the tested shapers are designed for (DEFAULT_DAMPING_RATIO).
    double dampingRatio = 0.1;
    /// The modes' damping is unknown: the remaining vibration is the worst over these
    /// (TEST_DAMPING_RATIOS).
    std::vector<double> testDampingRatios = {0.075, 0.1, 0.15};
    /// Square corner velocity (mm/s) of the smoothing estimate (Klipper's scv, default 5).
    double squareCornerVelocityMmPerS = 5.0;
    /// Spectrum bins above max(this, the highest tested frequency) are ignored (MAX_FREQ).
    double maxSpectrumFrequencyHz = 200.0;
    /// Klipper's max_smoothing and max_vibrations (both optional, off by default).
    std::optional<double> maxSmoothing;
    std::optional<double> maxVibrations;
    /// The shapers compared, in this order (the selection is sequential, so the order
    /// matters). Default: all seven, Klipper's INPUT_SHAPERS order (zv, mzv, zvd, ei, 2hump_ei,
    /// 3hump_ei) with zvdd after zvd. Klipper's own default is klipperAutotuneShapers().
    std::vector<ShaperType> shapers = {
        ShaperType::Zv, ShaperType::Mzv,       ShaperType::Zvd,        ShaperType::Zvdd,
        ShaperType::Ei, ShaperType::TwoHumpEi, ShaperType::ThreeHumpEi};
};

/// Klipper's AUTOTUNE_SHAPERS: zv, mzv, ei, 2hump_ei, 3hump_ei.
std::vector<ShaperType> klipperAutotuneShapers();

/// One tested frequency of one shaper (Klipper's CalibrationResult without vals).
struct ShaperCandidate {
    double frequencyHz = 0.0;
    double remainingVibrations = 0.0; ///< fraction, worst over the test damping ratios
    double smoothing = 0.0;           ///< mm, _get_shaper_smoothing at 5000 mm/s^2
    double score = 0.0;               ///< smoothing (v^1.5 + 0.2 v + 0.01)
};

/// The frequency chosen for one shaper type and its figures.
struct ShaperFit {
    InputShaper shaper; ///< designed at the chosen frequency and the options' damping ratio
    double remainingVibrations = 0.0;
    double smoothing = 0.0;
    double score = 0.0;
    double maxAccelMmPerS2 = 0.0; ///< find_shaper_max_accel (Klipper rounds it to 100 to print)
    /// The shaper's response at each spectrum bin used (the result's frequencyHz), the worst
    /// over the test damping ratios (Klipper's vals, before its resampling to 0.2 Hz).
    std::vector<double> response;
    /// Every frequency tested, increasing (a search stopped by maxSmoothing holds only the
    /// frequencies tested before it stopped).
    std::vector<ShaperCandidate> candidates;
};

struct ShaperRecommendation {
    std::vector<double> frequencyHz; ///< the spectrum bins used
    std::vector<ShaperFit> fits;     ///< one per options.shapers, in that order
    std::size_t recommended = 0;     ///< index into fits
    const ShaperFit& best() const { return fits[recommended]; }
};

/**
 * Klipper's automatic shaper choice (shaper_calibrate.py, find_best_shaper and fit_shaper):
 *  - for each shaper and each tested frequency, from the highest down: the smoothing; if it
 *    exceeds maxSmoothing once a best exists, the search of this shaper stops there (returning
 *    that best, without the selection below); the remaining vibration is the worst over the test
 *    damping ratios of klipperRemainingVibrations; score = smoothing (v^1.5 + 0.2 v + 0.01); the
 *    best is the frequency of least remaining vibration (the first, i.e. highest, on ties);
 *  - fit_shaper's selection: from the lowest tested frequency up, a candidate with
 *    v < 1.1 v_best + 0.0005 replaces the selection if its score is lower (or if v_best exceeds
 *    maxVibrations);
 *  - find_best_shaper, over the shapers in order: a shaper's fit becomes the best if its score
 *    times 1.2 is below the best's score, or its score times 1.05 is and its smoothing times 1.1
 *    is below the best's smoothing, or the best's vibration exceeds maxVibrations and this one's
 *    is lower; then any candidate of this shaper (lowest frequency first) with both less
 *    vibration and less smoothing than the best becomes the best and this shaper's fit;
 *  - at the end, if the best is ZV, the first other fit with 1.1 v < v_zv replaces it.
 * The spectrum is used as given: Klipper divides an accelerometer PSD by (f + 0.1) and damps
 * it below 10 Hz first (klipperNormalizeToFrequencies); a modelled |H|^2 needs neither.
 * @throws InvalidInput "spectrum.frequency" / "spectrum.power" (sizes, order, NaN, negative
 * power, no power in the bins used), or the option's name ("minFrequencyHz", "stepHz",
 * "dampingRatio", "testDampingRatios", ...).
 */
ShaperRecommendation recommendShaper(const PowerSpectrum& spectrum,
                                     const ShaperRecommendationOptions& options = {});

/**
 * Klipper's _estimate_shaper: the shaper's response to a mode at each of @p frequencyHz with
 * damping ratio @p testDampingRatio, omega = 2 pi f, omega_d = omega sqrt(1 - zeta^2):
 * sqrt((sum W_i sin(omega_d t_i))^2 + (sum W_i cos(omega_d t_i))^2) / sum A_i,
 * W_i = A_i exp(-zeta omega (t_n - t_i)) (residualVibration at each frequency).
 */
std::vector<double> klipperShaperResponse(const InputShaper& shaper, double testDampingRatio,
                                          const std::vector<double>& frequencyHz);

/**
 * Klipper's _estimate_remaining_vibrations: with the response v_k at each bin and the
 * threshold p_max / SHAPER_VIBRATION_REDUCTION (= p_max / 20: a shaper cannot reduce a
 * vibration more than 20 times, so whatever lies below is ignored),
 * sum_k max(v_k p_k - p_max/20, 0) / sum_k max(p_k - p_max/20, 0). Every bin of @p spectrum is
 * used (fit_shaper first drops those above its max_freq).
 */
double klipperRemainingVibrations(const InputShaper& shaper, double testDampingRatio,
                                  const PowerSpectrum& spectrum);

/**
 * Klipper's _get_shaper_smoothing (mm): with the shift ts = sum A_i t_i / sum A_i,
 * offset_90 = sqrt(2) sum_{t_i >= ts} A_i (scv + accel/2 (t_i - ts)) (t_i - ts) / sum A_i and
 * offset_180 = sum_i A_i accel/2 (t_i - ts)^2 / sum A_i, the larger of the two (the offset of a
 * 90 degree corner taken at the square corner velocity, and of a reversal). Klipper's defaults:
 * accel 5000 mm/s^2, scv 5 mm/s.
 */
double klipperShaperSmoothing(const InputShaper& shaper, double accelMmPerS2 = 5000.0,
                              double squareCornerVelocityMmPerS = 5.0);

/**
 * Klipper's find_shaper_max_accel: the largest acceleration whose smoothing stays within
 * TARGET_SMOOTHING = 0.12 mm, by Klipper's _bisect (0 if even 1e-9 mm/s^2 exceeds it; else
 * halving or doubling from 1 to bracket it, then bisection to a bracket of 1e-8 mm/s^2, the
 * lower end returned).
 */
double klipperMaxAccel(const InputShaper& shaper, double squareCornerVelocityMmPerS = 5.0);

/**
 * Klipper's CalibrationData.normalize_to_frequencies for an accelerometer PSD: each power
 * divided by (f + 0.1), and below 2 MIN_FREQ = 10 Hz multiplied by
 * exp(1 - (10 / (f + 0.1))^2) to remove low-frequency noise.
 */
PowerSpectrum klipperNormalizeToFrequencies(PowerSpectrum spectrum);

} // namespace xyt
