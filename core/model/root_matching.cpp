// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/root_matching.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace xyt {

namespace {

/// Every assignment cost is clamped to this finite bound. An infinite or NaN cost (the squared
/// norm overflows for roots beyond about 1e154; a root finder can return NaN for an extreme
/// polynomial) makes every comparison in the augmenting-path search false, so it never found a
/// column and looped forever (found by fuzz_design, regression input
/// tests/fuzz/corpus/fuzz_design/hang-root-matching-overflow). With n <= 64 roots, sums of a
/// few such costs stay far below the largest double.
constexpr double kMaxMatchingCost = 1e300;

double matchingCost(std::complex<double> a, std::complex<double> b) {
    // sqrt(norm) in the common case: std::abs's hypot is several times slower, and this is the
    // inner loop of every locus step.
    const double fast = std::sqrt(std::norm(a - b));
    if (fast <= kMaxMatchingCost) // false for NaN and infinity
        return fast;
    const double exact = std::abs(a - b); // hypot: no overflow of the square
    return exact <= kMaxMatchingCost ? exact : kMaxMatchingCost;
}

} // namespace

std::vector<std::size_t> matchRoots(const std::vector<std::complex<double>>& previous,
                                    const std::vector<std::complex<double>>& next) {
    const std::size_t n = previous.size();
    if (next.size() != n)
        throw InvalidInput("next", makeDiagnostic("model_root_count", {std::to_string(next.size()),
                                                                       std::to_string(n)}));
    if (n <= 1)
        return std::vector<std::size_t>(n, 0);
    // Hungarian method with potentials (rows = previous roots, columns = next roots), 1-based
    // with a dummy column 0, as in Kuhn-Munkres / Jonker-Volgenant shortest augmenting paths.
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0), minv(n + 1);
    std::vector<std::size_t> p(n + 1, 0), way(n + 1, 0);
    std::vector<char> used(n + 1);
    for (std::size_t i = 1; i <= n; ++i) {
        p[0] = i;
        std::size_t j0 = 0;
        std::fill(minv.begin(), minv.end(), inf);
        std::fill(used.begin(), used.end(), 0);
        do {
            used[j0] = 1;
            const std::size_t i0 = p[j0];
            double delta = inf;
            std::size_t j1 = 0;
            for (std::size_t j = 1; j <= n; ++j) {
                if (used[j])
                    continue;
                const double cur = matchingCost(previous[i0 - 1], next[j - 1]) - u[i0] - v[j];
                if (cur < minv[j]) {
                    minv[j] = cur;
                    way[j] = j0;
                }
                if (minv[j] < delta) {
                    delta = minv[j];
                    j1 = j;
                }
            }
            for (std::size_t j = 0; j <= n; ++j) {
                if (used[j]) {
                    u[p[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
        } while (p[j0] != 0);
        do {
            const std::size_t j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
        } while (j0 != 0);
    }
    std::vector<std::size_t> order(n);
    for (std::size_t j = 1; j <= n; ++j)
        order[p[j] - 1] = j - 1;
    return order;
}

std::vector<std::complex<double>>
continueBranches(const std::vector<std::complex<double>>& previous,
                 const std::vector<std::complex<double>>& next) {
    const std::vector<std::size_t> order = matchRoots(previous, next);
    std::vector<std::complex<double>> result(order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        result[i] = next[order[i]];
    return result;
}

} // namespace xyt
