// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/resample.h"

namespace xyt {

std::vector<double> resampleLinear(const std::vector<double>& ts, const std::vector<double>& ys,
                                   const std::vector<double>& t) {
    std::vector<double> out(t.size());
    if (ts.empty())
        return out;
    std::size_t j = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        while (j + 1 < ts.size() && ts[j + 1] <= t[k])
            ++j;
        if (t[k] <= ts.front())
            out[k] = ys.front();
        else if (j + 1 >= ts.size())
            out[k] = ys.back();
        else {
            const double w = (t[k] - ts[j]) / (ts[j + 1] - ts[j]);
            out[k] = ys[j] + w * (ys[j + 1] - ys[j]);
        }
    }
    return out;
}

std::vector<std::size_t> heldSampleIndices(const std::vector<double>& ts,
                                           const std::vector<double>& t) {
    std::vector<std::size_t> out(t.size(), 0);
    if (ts.size() < 2)
        return out;
    const double slack = 1e-9 * (ts[1] - ts[0]);
    std::size_t j = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        while (j + 1 < ts.size() && ts[j + 1] <= t[k] + slack)
            ++j;
        out[k] = j;
    }
    return out;
}

} // namespace xyt
