// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/shaped_program.h"

#include "core/design/shaper_sensitivity.h"
#include "core/simulation/shaped_reference.h"

#include <algorithm>
#include <cmath>

namespace xyt {

FeedProfile shapedFeedProfile(const FeedProfile& profile, const InputShaper& shaper) {
    const double dt = profile.dtSeconds;
    const double run = profile.t.empty() ? 0.0 : profile.t.back() - profile.t.front();
    const ShapedPath shaped = shapePath(shaper, profile.x, profile.y, dt, run);
    FeedProfile out = profile;
    const std::size_t n = profile.t.size();
    const std::size_t total = shaped.x.size();
    const auto lag = static_cast<long long>(std::llround(shaperDelaySeconds(shaper) / dt));
    out.t.resize(total);
    out.s.resize(total);
    out.v.resize(total);
    out.a.resize(total);
    out.segment.resize(total);
    for (std::size_t k = 0; k < total; ++k) {
        out.t[k] = profile.t.front() + static_cast<double>(k) * dt;
        const long long from =
            std::clamp(static_cast<long long>(k) - lag, 0LL, static_cast<long long>(n) - 1);
        const auto j = static_cast<std::size_t>(from);
        out.s[k] = profile.s[j];
        out.v[k] = profile.v[j];
        out.a[k] = profile.a[j];
        out.segment[k] = profile.segment[j];
    }
    out.x = shaped.x;
    out.y = shaped.y;
    out.totalTimeSeconds = profile.totalTimeSeconds + static_cast<double>(shaped.addedSamples) * dt;
    return out;
}

} // namespace xyt
