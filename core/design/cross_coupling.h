// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace xyt {

/**
 * Estimates of the contour error from the two axis errors, as a cross-coupled controller forms
 * them at each sample (Koren 1980; the circular form after Koren and Lo 1991).
 *
 * Sign convention, stated once: each axis' error is e = r - y (reference minus output, mm), and
 * the estimate is eps = n . e with n = (-sin theta, cos theta) the unit normal LEFT of the
 * direction of travel theta. So eps > 0 when the table lies RIGHT of the path: eps is minus the
 * contour module's signed distance (Path::nearest, positive left of the direction of travel).
 *
 *  - linear (tangent) estimate: eps = -ex sin theta + ey cos theta, exact on a straight line;
 *  - circular estimate, with the path's signed curvature kappa (+1/R counter-clockwise) and the
 *    tangential error tau = ex cos theta + ey sin theta: eps = -ex sin theta + ey cos theta +
 *    kappa tau^2 / 2, the second-order expansion of the exact distance to the circle through the
 *    reference point, so its error is third order in |e| where the linear one's is second.
 */
struct ContourEstimate {
    double value = 0.0; ///< eps (mm)
    /// The coupling gains d eps / d ex and d eps / d ey: how a correction along eps is shared
    /// by the axes (Cx = -sin theta, Cy = cos theta, plus kappa tau (cos theta, sin theta) for
    /// the circular estimate).
    double gainX = 0.0, gainY = 0.0;
};

/**
 * The estimate along the unit tangent (@p cosTheta, @p sinTheta) of the direction of travel:
 * the circular one with @p curvaturePerMm when @p circular, else (or at zero curvature) the
 * linear one. linearContourEstimate and circularContourEstimate are this with the cosine and
 * sine of theta; the coupled run and the exported C step perform exactly its operations.
 */
ContourEstimate contourEstimateAlong(double ex, double ey, double cosTheta, double sinTheta,
                                     double curvaturePerMm, bool circular);

/// The linear estimate (see ContourEstimate).
ContourEstimate linearContourEstimate(double ex, double ey, double thetaRad);

/// The circular estimate with signed curvature @p curvaturePerMm (0: the linear one).
ContourEstimate circularContourEstimate(double ex, double ey, double thetaRad,
                                        double curvaturePerMm);

/**
 * The exact contour error in the estimates' sign, of the table at (x, y) against the circle of
 * signed curvature @p curvaturePerMm through the reference point (rx, ry) whose direction of
 * travel there is @p thetaRad (the line through it when the curvature is 0): minus the signed
 * distance, positive right of the direction of travel.
 */
double exactContourErrorNearReference(double rx, double ry, double thetaRad, double curvaturePerMm,
                                      double x, double y);

/// Which estimate of the contour error the coupling controls (core/contour/contour_estimate.h).
enum class ContourEstimateKind { Linear, Circular };

/**
 * Koren's cross-coupled controller: a PI on the estimated contour error eps (mm), sampled at
 * the coupling's period T, whose output u_c (V) is added to each axis' command before that
 * axis' limit, shared by the coupling gains (Cx, Cy) of the estimate: v_x = Cx u_c,
 * v_y = Cy u_c (Cx = -sin theta, Cy = cos theta on a line).
 *
 * The law at sample k, in this order (the simulation, the line-loop analysis and the exported C
 * perform exactly these operations):
 *   I_k+ = I_k + T eps_k,   u_c = kp eps_k + ki I_k+,
 * and I_k+ is kept only when neither axis' command is clipped at its limit at that sample
 * (conditional integration, the anti-windup); otherwise I stays I_k. Where the path's direction
 * turns by more than kCornerTurnRad from one sample to the next (a sharp corner, where the feed
 * profile stops: the tangents of two samples have a dot product below cos(kCornerTurnRad)),
 * I_k is first set to 0: what built up along the old normal means nothing along the new one.
 * kp = ki = 0 switches the coupling off: every run is then the uncoupled one, bit for bit.
 */
/// A turn of the direction of travel between two samples beyond which the coupling's integral
/// restarts (CrossCoupling): 0.1 rad, far more than an arc turns in one sample of a contour run.
inline constexpr double kCornerTurnRad = 0.1;

struct CrossCoupling {
    double kp = 0.0; ///< V/mm
    double ki = 0.0; ///< V/(mm s)
    ContourEstimateKind estimate = ContourEstimateKind::Circular;
    bool active() const { return kp != 0.0 || ki != 0.0; }
    friend bool operator==(const CrossCoupling&, const CrossCoupling&) = default;
};

/// @throws InvalidInput naming "<field>.kp" or "<field>.ki" for a gain that is not finite or is
///         negative.
void validateCrossCoupling(const CrossCoupling& coupling, const std::string& field);

/// The session file's name of an estimate ("linear", "circular"), and back (false: unknown).
const char* contourEstimateName(ContourEstimateKind kind);
bool contourEstimateFromName(const std::string& name, ContourEstimateKind& kind);

} // namespace xyt
