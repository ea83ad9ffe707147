// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/cross_coupling.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>

namespace xyt {

ContourEstimate contourEstimateAlong(double ex, double ey, double cosTheta, double sinTheta,
                                     double curvaturePerMm, bool circular) {
    const double c = cosTheta, s = sinTheta;
    if (!circular || curvaturePerMm == 0.0)
        return {-ex * s + ey * c, -s, c};
    const double tau = ex * c + ey * s;
    const double k = curvaturePerMm;
    return {-ex * s + ey * c + 0.5 * k * tau * tau, -s + k * tau * c, c + k * tau * s};
}

ContourEstimate linearContourEstimate(double ex, double ey, double thetaRad) {
    return contourEstimateAlong(ex, ey, std::cos(thetaRad), std::sin(thetaRad), 0.0, false);
}

ContourEstimate circularContourEstimate(double ex, double ey, double thetaRad,
                                        double curvaturePerMm) {
    return contourEstimateAlong(ex, ey, std::cos(thetaRad), std::sin(thetaRad), curvaturePerMm,
                                true);
}

double exactContourErrorNearReference(double rx, double ry, double thetaRad, double curvaturePerMm,
                                      double x, double y) {
    const double s = std::sin(thetaRad), c = std::cos(thetaRad);
    // n = (-s, c), the normal left of travel.
    if (curvaturePerMm == 0.0)
        return -(-(x - rx) * s + (y - ry) * c);
    // The centre lies at r + n / kappa (left for kappa > 0, right for kappa < 0).
    const double radius = 1.0 / std::abs(curvaturePerMm);
    const double cx = rx - s / curvaturePerMm, cy = ry + c / curvaturePerMm;
    const double rho = std::hypot(x - cx, y - cy);
    // Left of a counter-clockwise circle is inside; left of a clockwise one outside.
    const double signedLeft = curvaturePerMm > 0.0 ? radius - rho : rho - radius;
    return -signedLeft;
}

void validateCrossCoupling(const CrossCoupling& coupling, const std::string& field) {
    for (const auto& [name, value] :
         {std::pair<const char*, double>{"kp", coupling.kp}, {"ki", coupling.ki}}) {
        requireFinite(value, field + "." + name);
        if (value < 0.0)
            throw InvalidInput(field + "." + name, makeDiagnostic("design_coupling_not_negative"));
    }
}

const char* contourEstimateName(ContourEstimateKind kind) {
    return kind == ContourEstimateKind::Linear ? "linear" : "circular";
}

bool contourEstimateFromName(const std::string& name, ContourEstimateKind& kind) {
    if (name == "linear")
        kind = ContourEstimateKind::Linear;
    else if (name == "circular")
        kind = ContourEstimateKind::Circular;
    else
        return false;
    return true;
}

} // namespace xyt
