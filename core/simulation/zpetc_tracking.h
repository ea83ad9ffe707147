// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/simulation/contour_error.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/trajectory.h"

#include <vector>

namespace xyt {

/// One axis tracking a reference with the pole-placement loop alone and with the ZPETC.
struct ZpetcTrackingRun {
    std::vector<double> t;       ///< k Ts, k = 0 .. n-1 (s)
    std::vector<double> r;       ///< reference (position units, e.g. mm)
    DiscreteRun feedbackOnly;    ///< structure (1)
    DiscreteRun withZpetc;       ///< structure (2)
    DiscreteRun trajectoryZpetc; ///< structure (3)
    double rmseWithoutFf = 0.0;  ///< sqrt(mean (r - y1)^2)
    double rmseWithFf = 0.0;     ///< sqrt(mean (r - y2)^2)
    double improvementPct =
        0.0; ///< 100 (1 - rmseWithFf / rmseWithoutFf), Patrick, Ishak and Adnan Table 1
    double maxAbsErrorWithoutFf = 0.0;
    double maxAbsErrorWithFf = 0.0;
};

/**
 * Samples @p reference at k Ts for k = 0 .. n-1 (n = floor(duration/Ts) + 1, plus the preview
 * samples the ZPETC reads beyond the end) and runs the three structures of discrete_simulation.h.
 * @throws InvalidInput "duration" unless duration >= 0 and the run fits in memory (see
 *         sampleTimes), when it holds a single sample, and when the last sample time (preview
 *         included) or omega times it overflows a double; "amplitude"/"offset" beyond
 *         kMaxPositionMm (Sinusoid::validate).
 */
ZpetcTrackingRun runZpetcTracking(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                                  const Sinusoid& reference, double durationSeconds,
                                  StartCondition start = StartCondition::AtReference);

/// Both axes on a circle (x = circle.xAxis(), y = circle.yAxis()) and the radial contour error.
struct ZpetcCircleRun {
    ZpetcTrackingRun x;
    ZpetcTrackingRun y;
    ContourError contourWithoutFf;
    ContourError contourWithFf;
};

/// @throws InvalidInput "ts" when the two axes have different sample times.
ZpetcCircleRun runZpetcCircle(const PolePlacementDesign& xLoop, const ZpetcDesign& xZpetc,
                              const PolePlacementDesign& yLoop, const ZpetcDesign& yZpetc,
                              const Circle& circle, double durationSeconds,
                              StartCondition start = StartCondition::AtReference);

} // namespace xyt
