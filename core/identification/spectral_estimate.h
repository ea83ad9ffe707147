// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// The taper of each Welch segment.
enum class SpectralWindow {
    /// Periodic Hann, w[n] = 0.5 - 0.5 cos(2 pi n / M), n = 0..M-1 (scipy.signal.get_window
    /// ("hann", M), the default of scipy.signal.welch and csd).
    Hann,
    /// Symmetric Kaiser, w[n] = I0(beta sqrt(1 - (2n/(M-1) - 1)^2)) / I0(beta) (numpy.kaiser,
    /// the window of Klipper's shaper_calibrate.py with beta = 6).
    Kaiser,
};

/// How the record is cut and tapered. The overlap is always half a segment (floor(M/2)
/// samples, scipy's default noverlap and Klipper's), each segment's mean is removed before
/// the window (detrend="constant").
struct WelchOptions {
    /// Samples a segment (M, at least 4); 0: defaultWelchSegmentLength(samples).
    std::size_t segmentLength = 0;
    SpectralWindow window = SpectralWindow::Hann;
    double kaiserBeta = 6.0; ///< used by SpectralWindow::Kaiser only
};

/// The smallest segment length defaultWelchSegmentLength chooses, and the largest.
inline constexpr std::size_t kMinDefaultWelchSegment = 8;
inline constexpr std::size_t kMaxDefaultWelchSegment = 4096;

/**
 * The default segment length for @p samples samples: the largest power of two M in
 * [kMinDefaultWelchSegment, kMaxDefaultWelchSegment] that gives at least 8 half-overlapping
 * segments, K = floor((N - M) / (M/2)) + 1 >= 8, i.e. N >= 4.5 M; when even M = 8 gives fewer
 * (N < 36), M = 8 (estimates then refuse N < 12, two segments). 8 averages keep the normalized
 * random error of a PSD near 1/sqrt(8) = 35 % (Bendat and Piersol, Random Data, eq. 8.158)
 * while the cap keeps the bin width of a long 1 kHz log at 0.24 Hz.
 */
std::size_t defaultWelchSegmentLength(std::size_t samples);

/**
 * The number of segments and the equivalent number of independent averages of a Welch
 * estimate of @p samples samples with segments of @p segmentLength and half overlap.
 * K = floor((N - M) / S) + 1 with S = M - floor(M/2). Overlapping segments are correlated, so
 * they count for fewer than K independent averages: with rho(j) = sum_n w[n] w[n + jS] /
 * sum_n w[n]^2 the window's overlap correlation at lag j segments,
 *   n_d = K / (1 + 2 sum_{j=1}^{K-1} (1 - j/K) rho(j)^2)
 * (Welch 1967, eq. 10; Percival and Walden, Spectral Analysis for Physical Applications, 1993,
 * eq. 292b: the equivalent degrees of freedom are 2 n_d). For Hann at 50 % overlap rho(1) = 1/6
 * (for large M), so n_d ~ K / 1.056; only j = 1 is nonzero at half overlap.
 */
struct WelchSegments {
    std::size_t segmentLength = 0;
    std::size_t step = 0;
    std::size_t count = 0;           ///< K
    double equivalentAverages = 0.0; ///< n_d
};
WelchSegments welchSegments(std::size_t samples, const WelchOptions& options);

/// One-sided power spectral density of a signal.
struct WelchSpectrum {
    std::vector<double> frequencyHz; ///< k / (M ts), k = 0..floor(M/2)
    std::vector<double> psd;         ///< (unit)^2 / Hz
    double sampleTimeSeconds = 0.0;
    WelchSegments segments;
};

/**
 * Welch's averaged periodogram of @p x sampled every @p tsSeconds, one-sided, density scaling:
 *   P[k] = c_k / (fs sum_n w[n]^2) * (1/K) sum_i |X_i[k]|^2, X_i the FFT of segment i minus its
 * mean, times the window; c_k = 2 except at 0 Hz and (M even) at the Nyquist bin where c_k = 1.
 * Equal to scipy.signal.welch(x, fs, window, nperseg=M, noverlap=M//2, detrend="constant",
 * scaling="density") and, with SpectralWindow::Kaiser, to Klipper's shaper_calibrate.py _psd.
 * The integral of P over frequency is the variance of x (Parseval).
 * @throws InvalidInput naming "x" (non-finite sample, fewer samples than two segments, a PSD
 *         that overflows a double),
 *         "ts" (not positive and finite), "segment" (fewer than 4), "kaiser_beta".
 */
WelchSpectrum powerSpectralDensity(const std::vector<double>& x, double tsSeconds,
                                   const WelchOptions& options = {});

/**
 * The frequency-response estimate H1 of output y over input u (Bendat and Piersol, Random
 * Data, eq. 9.14), from Welch averages as in powerSpectralDensity:
 *   Puu[k], Pyy[k] the auto spectra, Puy[k] = (scale) (1/K) sum_i conj(U_i[k]) Y_i[k] (scipy's
 *   csd(u, y)); H1 = Puy / Puu; gamma^2 = |Puy|^2 / (Puu Pyy) (scipy.signal.coherence).
 * The normalized random error of the gain |H1| (Bendat and Piersol, Random Data, 4th ed.,
 * eq. 9.90 and Table 9.6):
 *   eps[k] = sqrt(1 - gamma^2) / (|gamma| sqrt(2 n_d)),
 * with n_d the equivalent independent averages of welchSegments (the formula assumes n_d
 * independent averages; with half overlap we count the correlated segments as n_d < K). The
 * band is |H1| (1 -+ bandSigmas eps), the low side clipped at 0: with bandSigmas = 2 it is an
 * approximately 95 % band where eps is small (the estimate is nearly normal there).
 */
struct FrequencyResponseEstimate {
    std::vector<double> frequencyHz;
    std::vector<double> magnitude;     ///< |H1|, (unit of y) / (unit of u)
    std::vector<double> phaseRad;      ///< arg H1, unwrapped from 0 Hz upwards (numpy.unwrap)
    std::vector<double> coherence;     ///< gamma^2 in [0, 1]; 0 where Puu or Pyy is 0
    std::vector<double> relativeError; ///< eps; +inf where gamma^2 = 0
    std::vector<double> magnitudeLow;  ///< max(0, |H1| (1 - bandSigmas eps))
    std::vector<double> magnitudeHigh; ///< |H1| (1 + bandSigmas eps)
    std::vector<double> inputPsd;      ///< Puu
    std::vector<double> outputPsd;     ///< Pyy
    double bandSigmas = 2.0;
    double sampleTimeSeconds = 0.0;
    WelchSegments segments;
};

/// @throws InvalidInput naming "u" or "y" (non-finite sample; fewer samples than two segments;
///         a spectrum that overflows a double),
///         "y" (a length other than u's), "ts", "segment", and "band_sigmas" (not > 0).
FrequencyResponseEstimate estimateFrequencyResponse(const std::vector<double>& u,
                                                    const std::vector<double>& y, double tsSeconds,
                                                    const WelchOptions& options = {},
                                                    double bandSigmas = 2.0);

/// What a resonance pick looks at: a gain |H| (half power at peak / sqrt 2) or a power
/// spectral density (half power at peak / 2).
enum class ResonanceQuantity { Magnitude, Power };

/// The band searched, Hz; unset ends: from the third bin (above 0 Hz and the lowest bin, where
/// a mean or drift leaks) to the last bin.
struct ResonanceBand {
    std::optional<double> lowHz;
    std::optional<double> highHz;
};

/**
 * The largest peak of @p values in the band, its frequency refined by the parabola through the
 * peak bin and its two neighbours (exact for a quadratic peak; for a sampled resonance the
 * error is O(df^3) in frequency), and the damping ratio by the half-power bandwidth:
 * the frequencies f1 < fn < f2 where the values cross the half-power level (peak / sqrt 2 for a
 * magnitude, peak / 2 for a power), linearly interpolated between bins, and
 *   zeta = (f2 - f1) / (2 fn)
 * (Bendat and Piersol, Random Data, eq. 2.28 / Ewins, Modal Testing, eq. 3.5). For a
 * second-order mode it is exact to O(zeta^2): for the gain of wn^2 / (s^2 + 2 zeta wn s + wn^2)
 * the half-power points satisfy (f/fn)^2 = 1 - 2 zeta^2 -+ 2 zeta sqrt(1 - zeta^2).
 * When a crossing is not found inside the band (the peak sits at its edge, or the response does
 * not fall to half power before the band ends), dampingRatio is unset and note says which side.
 */
struct ResonancePick {
    double frequencyHz = 0.0; ///< parabolic peak frequency
    double peakValue = 0.0;   ///< the parabola's maximum (at least the peak bin's value)
    std::size_t peakBin = 0;
    std::optional<double> lowHalfPowerHz;
    std::optional<double> highHalfPowerHz;
    std::optional<double> dampingRatio;
    Diagnostic note; ///< why dampingRatio is unset; empty otherwise (coded)
};

/// @throws InvalidInput naming "frequency" (sizes differ, fewer than 3 bins, not increasing,
///         non-finite), "values" (non-finite or negative), "band" (empty, reversed, outside
///         the frequencies, or fewer than 3 bins in it).
ResonancePick pickResonance(const std::vector<double>& frequencyHz,
                            const std::vector<double>& values, ResonanceQuantity quantity,
                            const ResonanceBand& band = {});

/// @throws InvalidInput naming @p field: "frequency above the log's Nyquist frequency of X Hz"
///         when @p frequencyHz > 1 / (2 ts), or a frequency that is not positive and finite.
void requireBelowNyquist(double frequencyHz, double tsSeconds, const std::string& field);

} // namespace xyt
