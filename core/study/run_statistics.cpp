// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/run_statistics.h"

#include <algorithm>
#include <cmath>

namespace xyt {

double nearestRankPercentile(const std::vector<double>& sorted, double p) {
    const double rank = std::ceil(p / 100.0 * static_cast<double>(sorted.size()));
    const std::size_t i =
        static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(sorted.size())));
    return sorted[i - 1];
}

Distribution distributionOf(std::vector<double> v) {
    Distribution d;
    d.count = static_cast<int>(v.size());
    if (v.empty())
        return d;
    std::sort(v.begin(), v.end());
    d.min = v.front();
    d.max = v.back();
    d.p05 = nearestRankPercentile(v, 5.0);
    d.p50 = nearestRankPercentile(v, 50.0);
    d.p95 = nearestRankPercentile(v, 95.0);
    double sum = 0.0;
    for (double x : v) // in sorted order: the same sum whatever the thread count
        sum += x;
    d.mean = sum / static_cast<double>(v.size());
    return d;
}

std::vector<std::size_t> envelopeIndices(std::size_t n, int points) {
    std::vector<std::size_t> idx;
    if (n == 0)
        return idx;
    const std::size_t stride = std::max<std::size_t>(1, (n + static_cast<std::size_t>(points) - 1) /
                                                            static_cast<std::size_t>(points));
    for (std::size_t k = 0; k < n; k += stride)
        idx.push_back(k);
    if (idx.back() != n - 1)
        idx.push_back(n - 1);
    return idx;
}

SignalEnvelope envelopeOf(const std::vector<double>& t, const std::vector<std::size_t>& idx,
                          const std::vector<const std::vector<double>*>& runs,
                          const std::vector<double>& nominal) {
    SignalEnvelope env;
    if (runs.empty())
        return env;
    for (std::size_t k : idx)
        env.nominal.push_back(nominal[k]);
    std::vector<double> column(runs.size());
    for (std::size_t j = 0; j < idx.size(); ++j) {
        for (std::size_t i = 0; i < runs.size(); ++i)
            column[i] = (*runs[i])[j];
        std::sort(column.begin(), column.end());
        env.t.push_back(t[idx[j]]);
        env.min.push_back(column.front());
        env.p05.push_back(nearestRankPercentile(column, 5.0));
        env.p50.push_back(nearestRankPercentile(column, 50.0));
        env.p95.push_back(nearestRankPercentile(column, 95.0));
        env.max.push_back(column.back());
    }
    return env;
}

} // namespace xyt
