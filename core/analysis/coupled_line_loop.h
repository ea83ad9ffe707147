// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/stability_margins.h"
#include "core/design/cross_coupling.h"
#include "core/design/pole_placement.h"
#include "core/model/transfer_function.h"

#include <Eigen/Core>

#include <complex>
#include <optional>
#include <vector>

namespace xyt {

/**
 * One closed axis loop seen by a cross-coupled controller of period T: the coupling's voltage v
 * (V, held over each period, added to the axis' command before its limit) to the axis' output y
 * in mm, linear (inside the limit), with the reference at rest:
 *   \f$ x(k+1) = \Phi x(k) + \gamma v(k), \qquad y(k) = c\, x(k) \f$
 * (no direct feedthrough: y(k) depends on the past inputs only). Sizes: phi n x n, gamma and c
 * of length n, n >= 1.
 */
struct SampledAxisModel {
    Eigen::MatrixXd phi;
    Eigen::VectorXd gamma;
    Eigen::RowVectorXd c;
    double periodSeconds = 0.0;
};

/**
 * A continuous axis (a continuous controller on a continuous plant, unity feedback, as
 * simulateLoop runs it). With realize()'s plant (A_p, B_p, C_p) and controller
 * (A_c, B_c, C_c, D_c), in the state [x_p; x_c]:
 *   \f$ A = [A_p - D_c B_p C_p, B_p C_c; -B_c C_p, A_c], \quad B_v = [B_p; 0] \f$
 * (the linear mode of loopModes with v entering where u does), discretized exactly with a
 * zero-order hold at @p periodSeconds (discretizeZoh); c = [C_p, 0] / @p modelUnitsPerMm (plant
 * output units per mm, as LoopSimulationOptions::modelUnitsPerPositionUnit).
 * @throws InvalidInput "plant" unless continuous and strictly proper, "controller" unless
 *         continuous and proper (as loopModes), "period" unless finite and > 0 (or when the
 *         exponential overflows), "model_unit_scale" unless finite and > 0.
 */
SampledAxisModel continuousAxisModel(const TransferFunction& plant,
                                     const TransferFunction& controller, double modelUnitsPerMm,
                                     double periodSeconds);

/**
 * A pole-placement axis run as runRstLoop runs it, at rest (w = 0), the dead zone left out:
 *   \f$ A(z^{-1}) y = B(z^{-1}) u_a, \quad F(z^{-1}) u = -G(z^{-1}) y, \quad u_a = u + v \f$
 * (the RST law's own output u and the coupling's v added at the plant input; y in the design's
 * position unit, mm). The state is the histories runRstLoop keeps:
 * x(k) = [y(k-1) .. y(k-n_y); u(k-1) .. u(k-n_f); u_a(k-1) .. u_a(k-n_b)] with
 * n_y = max(deg A, deg G), n_f = deg F, n_b = deg B; y(k) comes from the past only because
 * B(0) = 0. The eigenvalues of phi are the roots of the closed-loop polynomial
 * A F + B G = T (in z) and poles at z = 0 (the redundant histories). Period loop.tsSeconds.
 * A(0) is 1 for a design of designPolePlacement; any other nonzero A(0) is divided out.
 * @throws InvalidInput "ts" unless loop.tsSeconds is finite and > 0, "a" when A(0) = 0, "b"
 *         when B(0) != 0, "f" when F(0) = 0.
 */
SampledAxisModel rstAxisModel(const PolePlacementDesign& loop);

/// The coupled loop broken at one axis' input (CoupledLineLoop::brokenAtX).
struct AxisBrokenLoop {
    TransferFunction loop;
    /**
     * Its gain and phase margins (negative feedback) from the state-space models on the unit
     * circle: the crossings of |L| = 1 and arg L = 180 degrees found on a log grid of omega T
     * (300 points a decade from min(1e-4, 0.1 |1 - p|) over the poles to pi, plus the poles'
     * arguments) and refined by bisection to 1e-13 relative; the margin closest to 0 of each,
     * +inf without a crossing. (stabilityMargins on `loop` would do the same from polynomials,
     * which lose the low frequencies when poles cluster near z = 1.)
     */
    double gainMarginDb = 0.0;
    double phaseMarginDeg = 0.0;
    double gainCrossoverRadPerSec = 0.0;  ///< where the gain margin is read (phase 180 degrees)
    double phaseCrossoverRadPerSec = 0.0; ///< where the phase margin is read (|L| = 1)
};

/**
 * The coupled loop of two axes on a straight line at angle @p thetaRad: linear and
 * time-invariant (CrossCoupling's law with Cx = -sin theta, Cy = cos theta, no clipping, the
 * reference at rest so that eps_k = -(Cx y_x(k) + Cy y_y(k))).
 *
 * The closed loop, in the state [x_x; x_y; I] with kc = kp + ki T:
 *   u_c(k) = kc eps_k + ki I_k,  x_x+ = Phi_x x_x + gamma_x Cx u_c,  x_y+ = Phi_y x_y +
 *   gamma_y Cy u_c,  I+ = I + T eps_k.
 * The integral state is kept only when ki > 0: with ki = 0 it feeds nothing back and would
 * only add an (unobservable) pole at z = 1.
 */
struct CoupledLineLoop {
    /// The eigenvalues (z-plane, Eigen::EigenSolver) of the closed coupled loop: both axes'
    /// states and the coupling's integral (when ki > 0), by increasing modulus (ties by
    /// argument). With the coupling off (kp = ki = 0): both axes' own eigenvalues.
    std::vector<std::complex<double>> poles;
    double spectralRadius = 0.0; ///< the largest |pole|
    /// spectralRadius < 1 - 1e-12: a pole within 1e-12 of the unit circle (far below any
    /// physical decay rate, far above the eigenvalue round-off of ~1e-15) counts as on it.
    bool stable = false;
    /**
     * The coupling's integral beside axes that reject a constant voltage (a PI on a plant with
     * an integrator: each axis' v -> y is 0 at z = 1): one pole stays at z = 1 whatever the
     * gains, the mode of the coupling's integral and the axes' integrators sharing a constant
     * voltage. It never shows in the contour error. Set when the largest pole is within 1e-9
     * of z = 1, the others are inside the circle (as `stable`), and the pole's eigenvector v
     * gives |eps| <= 1e-9 |v|.
     */
    bool hiddenIntegralMode = false;
    /// stable, or stable but for the hidden integral mode: nothing the coupling sees grows or
    /// persists. What a run needs.
    bool bounded = false;
    /**
     * The loop broken at the coupling's output u_c (negative feedback, discrete, period T):
     *   \f$ L(z) = C(z) (C_x^2 G_x(z) + C_y^2 G_y(z)), \quad C(z) = k_p + k_i T z / (z - 1) \f$
     * with G = c (zI - Phi)^{-1} gamma each axis' v -> y: denominator det(zI - Phi), numerator
     * det(zI - Phi + gamma c) - det(zI - Phi) (as c2dZoh), both from eigenvalues, so not
     * minimal (the RST histories' poles at z = 0 stay). Bookkeeping: when the two axes'
     * denominators agree (relative 1e-12: identical axes, or RST designs with the same T) the
     * sum is taken over the one denominator; an axis whose |C| <= 1e-12 (theta a multiple of
     * pi/2 up to the round-off of sin and cos) is left out. The roots of L's closed-loop
     * polynomial D + N are therefore the coupled poles less those an equal denominator or a
     * left-out axis keeps out of the loop. The zero gain (with the period) when the coupling
     * is off.
     * Accuracy: the polynomial form itself is ill conditioned near z = 1 when poles cluster
     * there (a Guillemin-Truxal axis' slow PI pole sits at 1 - 1e-5 with T = 10 ms): evaluated
     * at omega T < 0.05 it can be off by 1e-6 relative and more, and by orders of magnitude
     * where an integral coupling meets PI axes (G(1) = 0 against C's pole at 1). The disk
     * margin is evaluated from the state-space models for that reason.
     */
    TransferFunction couplingLoop;
    /// stabilityMargins(couplingLoop); left default (not computed) when the coupling is off.
    StabilityMargins margins;
    /**
     * The 2 x 2 loop broken at each axis' input in turn (where the coupling's voltage joins
     * that axis' command), the other axis and the coupling closed: L_x = C Cx^2 Gx /
     * (1 + C Cy^2 Gy), L_y alike, with their margins; 1 + L_x has the coupled loop's
     * characteristic polynomial (up to the bookkeeping of couplingLoop). Unset for an axis the
     * coupling does not reach at this direction (|C| <= 1e-12), and without margins
     * (withMargins false).
     */
    std::optional<AxisBrokenLoop> brokenAtX, brokenAtY;
    /**
     * The symmetric disk margin of couplingLoop: alpha = 1 / max_omega |(1 - L) / (2 (1 + L))|
     * over 0 <= omega <= pi/T; the loop tolerates any simultaneous gain and phase change of the
     * disk with gain in [(1 - alpha/2)/(1 + alpha/2), (1 + alpha/2)/(1 - alpha/2)] and phase
     * +-2 atan(alpha/2). The maximum is taken on a log grid of omega T from
     * min(1e-4, 0.1 |1 - p|) (p over the poles of the coupled loop and of both axes) to pi, 300
     * points a decade, plus omega = 0 and the arguments of all those poles (so a resonance is
     * never stepped over), each of the five largest local maxima then refined by golden-section
     * search between its grid neighbours to 1e-12 relative in omega: alpha is exact to ~1e-10
     * relative when the peak is bracketed, which the pole arguments ensure for resonances.
     * L is evaluated from the state-space models (not from couplingLoop's polynomials).
     * 0 when the coupled loop is not bounded, and when the coupling is off (no loop).
     */
    double diskMargin = 0.0;
    /// 20 log10 (1 + alpha/2)/(1 - alpha/2) (inf for alpha >= 2); 0 when diskMargin is 0.
    double diskGainMarginDb = 0.0;
    double diskPhaseMarginDeg = 0.0; ///< 2 atan(alpha/2) in degrees; 0 when diskMargin is 0
};

/**
 * @throws InvalidInput "cross_coupling.kp" / "cross_coupling.ki" when a gain is negative or not
 *         finite (validateCrossCoupling, checked first); "x_axis" / "y_axis" when a model's
 *         sizes disagree, it has no state or a coefficient is not finite; "period" when a
 *         period is not finite and > 0 or the two differ (relative 1e-12); "theta" unless
 *         finite. @p withMargins false: the poles only (couplingLoop, margins and the disk
 *         margin left default), what a check of many directions needs.
 */
CoupledLineLoop coupledLineLoop(const SampledAxisModel& x, const SampledAxisModel& y,
                                double thetaRad, const CrossCoupling& coupling,
                                bool withMargins = true);

} // namespace xyt
