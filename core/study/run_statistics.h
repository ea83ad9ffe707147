// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <vector>

namespace xyt {

/// Order statistics of one figure over a set of runs (nearest-rank percentiles).
struct Distribution {
    int count = 0;
    double min = 0.0, p05 = 0.0, p50 = 0.0, p95 = 0.0, max = 0.0, mean = 0.0;
};

/// Pointwise order statistics of a signal over a set of runs, and the nominal run's value at
/// the same instants.
struct SignalEnvelope {
    std::vector<double> t, min, p05, p50, p95, max, nominal;
};

/// Nearest-rank percentile @p p (0..100) of the non-empty, ascending @p sorted: the value of
/// rank ceil(p N / 100), clamped to 1..N.
double nearestRankPercentile(const std::vector<double>& sorted, double p);

/// The distribution of @p values (count 0 when empty). The mean sums in sorted order, so it
/// does not depend on the order the runs finished in.
Distribution distributionOf(std::vector<double> values);

/// The sample indices an envelope keeps of an n-sample run: every stride-th with
/// stride = ceil(n / points), and the last. Empty for n = 0.
std::vector<std::size_t> envelopeIndices(std::size_t n, int points);

/**
 * The envelope over @p runs, each holding one value per kept index (idx.size() values), at the
 * times t[idx[j]], with @p nominal (a full run) read at the same indices. No runs: empty.
 */
SignalEnvelope envelopeOf(const std::vector<double>& t, const std::vector<std::size_t>& idx,
                          const std::vector<const std::vector<double>*>& runs,
                          const std::vector<double>& nominal);

} // namespace xyt
