// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"

#include <cstddef>

namespace xyt::bench {

/**
 * The reference loops, against which xytune-bench states its simulation and sweep
 * figures as ratios (so that they survive a loaded machine): the recurrence of simulateLoop for
 * a third-order plant under a PI controller (4 states; the same exact FOH steps, the same mode
 * choice from v at the start of each step) written as straightforward scalar C++ over fixed
 * arrays, allocation-free, as a firmware engineer would write it. Not used by the tool.
 */
struct ReferenceLoop {
    double phiLinear[4][4], g0Linear[4], g1Linear[4];
    double phiClipped[4][4], g0Clipped[4][2], g1Clipped[4];
    double cp[3], cc, dc;
};

/// The step matrices of the loop @p plant (3rd order) under @p controller (PI) at @p dt.
ReferenceLoop referenceLoop(const TransferFunction& plant, const TransferFunction& controller,
                            double dt);

/// One run storing t, y, e, u and the clipped flags into arrays of @p count samples.
void referenceRun(const ReferenceLoop& m, const double* reference, std::size_t count, double dt,
                  double umax, double unit, double* t, double* y, double* e, double* u,
                  bool* clipped);

/// Tracking figures only (the design sweep's kernel): RMSE, max |e|, max |u|, ITAE.
struct ReferenceFigures {
    double rmse = 0.0, maxAbsError = 0.0, maxAbsU = 0.0, itae = 0.0;
};
ReferenceFigures referenceFigures(const ReferenceLoop& m, const double* reference,
                                  std::size_t count, double dt, double umax, double unit);

} // namespace xyt::bench
