// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/cross_coupled_run.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <cmath>

namespace xyt {

CouplingSignals runCrossCoupled(SteppedLoop& x, SteppedLoop& y,
                                const CouplingDirections& directions,
                                const CrossCoupling& coupling) {
    validateCrossCoupling(coupling, "cross_coupling");
    const double period = x.periodSeconds();
    if (std::abs(period - y.periodSeconds()) > 1e-9 * period)
        throw InvalidInput("cross_coupling",
                           makeDiagnostic("sim_coupling_periods_differ",
                                          {formatNumber(period), formatNumber(y.periodSeconds())}));
    const std::size_t n = x.samples();
    if (y.samples() != n || directions.thetaRad.size() != n ||
        directions.curvaturePerMm.size() != n ||
        (!directions.active.empty() && directions.active.size() != n) || x.index() != 0 ||
        y.index() != 0)
        throw InvalidInput("cross_coupling", makeDiagnostic("sim_coupling_samples_differ"));
    CouplingSignals out;
    out.estimate.resize(n);
    out.correction.resize(n);
    double integral = 0.0;
    const bool circular = coupling.estimate == ContourEstimateKind::Circular;
    const double cosCorner = std::cos(kCornerTurnRad);
    double previousCos = 0.0, previousSin = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double ex = x.reference() - x.output();
        const double ey = y.reference() - y.output();
        const double theta = directions.thetaRad[k];
        const double c = std::cos(theta), s = std::sin(theta);
        if (k > 0 && c * previousCos + s * previousSin < cosCorner)
            integral = 0.0; // a corner: what built up along the old normal means nothing now
        previousCos = c;
        previousSin = s;
        const ContourEstimate eps =
            contourEstimateAlong(ex, ey, c, s, directions.curvaturePerMm[k], circular);
        out.estimate[k] = eps.value;
        if (!directions.active.empty() && !directions.active[k]) {
            integral = 0.0;
            x.advance(0.0);
            y.advance(0.0);
            out.correction[k] = 0.0;
            continue;
        }
        const double next = integral + period * eps.value;
        const double uc = coupling.kp * eps.value + coupling.ki * next;
        const bool clipX = x.advance(eps.gainX * uc);
        const bool clipY = y.advance(eps.gainY * uc);
        if (!clipX && !clipY)
            integral = next;
        out.correction[k] = uc;
    }
    return out;
}

} // namespace xyt
