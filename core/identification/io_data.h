// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace xyt {

/**
 * One input/output record of an experiment on an axis, uniformly sampled: u[k] is the command
 * (volts) applied over [k Ts, (k+1) Ts) and y[k] the measured position at k Ts (mm after the
 * reader's output scale). The readers (core/identification: delimited, lvm, mat) and the
 * preprocessing produce it; the estimators (ARX, OE, BJ, the continuous third-order fit) and the
 * validation consume it.
 */
struct IoData {
    std::vector<double> u;     ///< input samples (V)
    std::vector<double> y;     ///< output samples (mm)
    double tsSeconds = 0.0;    ///< sample time (s)
    double startSeconds = 0.0; ///< time of sample 0 (for plots and ranges)
    std::string source;        ///< where the data came from, e.g. "run3.lvm: u=Command, y=X"

    std::size_t size() const { return y.size(); }
};

} // namespace xyt
