// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/io_data.h"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace xyt {

/**
 * The samples of @p data whose instants t_k = startSeconds + k Ts lie in [t0, t1] (s; an
 * instant within 1e-9 Ts of a bound counts as inside). startSeconds becomes the first kept
 * instant.
 * @throws InvalidInput "t0"/"t1" (not finite, t1 < t0), "range" (no sample inside), "data" (Ts
 *         not > 0, u and y of unequal length).
 */
IoData selectTimeRange(const IoData& data, double t0Seconds, double t1Seconds);

/// What was removed from each signal: x_k - (offset + slope k), k = 0..n-1 (slope 0 for means).
struct Detrended {
    IoData data;
    double uOffset = 0.0, uSlopePerSample = 0.0; ///< V, V per sample
    double yOffset = 0.0, ySlopePerSample = 0.0; ///< mm, mm per sample
};

/// u - mean(u), y - mean(y). @throws InvalidInput "data" (empty, unequal lengths).
Detrended removeMeans(const IoData& data);
/**
 * The least-squares straight line of each signal removed: x_k - (a + b k) with b =
 * sum (k - kbar)(x_k - xbar) / sum (k - kbar)^2, a = xbar - b kbar (what MATLAB detrend does).
 * @throws InvalidInput "data" (fewer than 2 samples, unequal lengths).
 */
Detrended removeTrends(const IoData& data);

/**
 * The anti-alias filter of decimate(): a Chebyshev type I lowpass of order 8 with 0.05 dB
 * passband ripple and its ripple edge at 0.8 x the new Nyquist frequency (0.8 / factor of the old
 * one), the filter MATLAB's decimate uses, as 4 second-order sections from the analogue
 * prototype by the bilinear transform with prewarping, scaled to unit gain at DC:
 *   |H(e^{jw})|^2 = (1 + eps^2) / (1 + eps^2 T_8^2(tan(w/2) / tan(wc/2))), eps^2 = 10^(0.05/10) -
 * 1, wc = 0.8 pi / factor (rad/sample), T_8 the Chebyshev polynomial; so 1 <= |H| <= 1.0058
 *   (+0.05 dB) below wc. (MATLAB's cheby1 has DC at the bottom of the ripple, |H(1)| = 0.9943;
 *   here a step keeps its level.)
 * Each section: (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2), coefficients ascending.
 */
struct BiquadSection {
    std::array<double, 3> b{};
    std::array<double, 3> a{}; ///< a[0] = 1
};
std::vector<BiquadSection> decimationFilter(int factor);

/// Order and ripple of the filter (stated where they are used and tested).
inline constexpr int kDecimationFilterOrder = 8;
inline constexpr double kDecimationRippleDb = 0.05;
inline constexpr double kDecimationEdge = 0.8; ///< fraction of the new Nyquist frequency

/**
 * Keeps every @p factor-th sample (k = 0, factor, 2 factor, ...) of u and y after filtering both
 * with decimationFilter(factor) forward and then backward (zero phase, magnitude squared:
 * passband gain from 0 to +0.1 dB). As MATLAB's filtfilt, the ends are padded with the odd
 * reflection of 3 x 8 = 24 samples and every section starts in its steady state for the first
 * padded value, so a record does not start with the filter's transient. Ts becomes factor Ts,
 * startSeconds is kept. factor 1 returns the data unchanged.
 * @throws InvalidInput "factor" (< 1 or > 1000), "data" (for factor > 1 fewer than 25 samples,
 *         too short to pad, as MATLAB's filtfilt requires; unequal lengths; Ts not > 0).
 */
IoData decimate(const IoData& data, int factor);

/// What to remove from u and y before identification.
enum class OffsetRemoval { None, Means, Trends };

/// The preprocessing a user chooses for a record, applied in this order by preprocess().
struct PreprocessingSteps {
    std::optional<std::array<double, 2>> rangeSeconds; ///< [t0, t1] for selectTimeRange
    OffsetRemoval offsets = OffsetRemoval::None;
    int decimateFactor = 1; ///< 1: keep every sample
};

/**
 * The time range (selectTimeRange), then the offsets (removeMeans / removeTrends), then the
 * decimation (decimate): what `xytune-cli identify` and the identification window do with
 * their range, detrend and decimate options. @throws as those functions.
 */
IoData preprocess(const IoData& data, const PreprocessingSteps& steps);

/// One signal filtered by the sections forward and backward, ends padded as decimate() does.
std::vector<double> zeroPhaseFilter(const std::vector<BiquadSection>& sections,
                                    const std::vector<double>& x);

} // namespace xyt
