// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/coupling_stability.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/design_method_module.h"
#include "core/session/session.h"

#include <cmath>
#include <numbers>

namespace xyt {

namespace {

/// @p theta folded into [0, pi): the coupled line loop depends on the direction modulo pi.
double foldedDirection(double theta) {
    double t = std::fmod(theta, std::numbers::pi);
    if (t < 0.0)
        t += std::numbers::pi;
    return t;
}

std::string degrees(double theta) {
    return formatNumber(theta * 180.0 / std::numbers::pi, 4) + " deg";
}

} // namespace

CouplingStability checkCouplingStability(const Session& session, double periodSeconds,
                                         const std::vector<CoupledLine>& lines, bool hasArcs) {
    validateCrossCoupling(session.crossCoupling, "cross_coupling");
    std::array<SampledAxisModel, 2> models;
    for (int i = 0; i < 2; ++i)
        models[static_cast<std::size_t>(i)] =
            designMethodModule(session.axes[static_cast<std::size_t>(i)].method)
                .couplingModel(session, i, periodSeconds);
    const double tx = models[0].periodSeconds, ty = models[1].periodSeconds;
    if (std::abs(tx - ty) > 1e-9 * std::max(tx, ty))
        throw InvalidInput("cross_coupling", makeDiagnostic("session_coupling_one_period_why",
                                                            {formatNumber(tx), formatNumber(ty)}));
    models[1].periodSeconds = tx; // equal to round-off: one period for the analysis
    CouplingStability out;
    out.periodSeconds = tx;
    const auto loopAt = [&](double theta, bool margins) {
        return coupledLineLoop(models[0], models[1], theta, session.crossCoupling, margins);
    };
    bool any = false;
    std::vector<double> seen;
    for (const CoupledLine& line : lines) {
        const double theta = foldedDirection(line.thetaRad);
        bool repeated = false;
        for (double s : seen)
            repeated = repeated || std::abs(s - theta) <= 1e-9;
        if (repeated)
            continue;
        seen.push_back(theta);
        const CoupledLineLoop loop = loopAt(theta, false);
        if (!loop.bounded)
            throw InvalidInput("cross_coupling",
                               makeDiagnostic("session_coupled_loop_unstable",
                                              {line.where, degrees(line.thetaRad),
                                               formatNumber(loop.spectralRadius, 6),
                                               formatNumber(session.crossCoupling.kp),
                                               formatNumber(session.crossCoupling.ki)}));
        if (!any || loop.spectralRadius > out.worst.spectralRadius) {
            out.worst = loop;
            out.worstThetaRad = theta;
            any = true;
        }
    }
    out.linesChecked = seen.size();
    if (hasArcs) {
        constexpr std::size_t kDirections = 180;
        out.frozenDirections = kDirections;
        double worstFrozen = -1.0, worstFrozenTheta = 0.0;
        for (std::size_t i = 0; i < kDirections; ++i) {
            const double theta = std::numbers::pi * static_cast<double>(i) / kDirections;
            const CoupledLineLoop loop = loopAt(theta, false);
            if (!loop.bounded)
                ++out.unboundedFrozenDirections;
            if (loop.spectralRadius > worstFrozen) {
                worstFrozen = loop.spectralRadius;
                worstFrozenTheta = theta;
            }
        }
        if (!any || worstFrozen > out.worst.spectralRadius) {
            out.worstThetaRad = worstFrozenTheta;
            out.worst.spectralRadius = worstFrozen;
            any = true;
        }
        if (out.unboundedFrozenDirections > 0)
            out.warning = makeDiagnostic("session_coupling_frozen_unstable",
                                         {std::to_string(out.unboundedFrozenDirections),
                                          std::to_string(kDirections), formatNumber(worstFrozen, 6),
                                          degrees(worstFrozenTheta)});
    }
    if (any) // the margins of the worst direction
        out.worst = loopAt(out.worstThetaRad, true);
    return out;
}

} // namespace xyt
