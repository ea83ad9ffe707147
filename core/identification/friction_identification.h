// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/**
 * The friction experiment's estimator. Under a closed-loop jog at constant velocity v (mm/s) the
 * plant k0 / (s (s^2 + a1 s + a2)) is in steady state, and the command u (V) that holds it there
 * balances the friction: the Stribeck curve
 * \f[ u(v) = \mathrm{sign}(v) \left( F_c + (F_s - F_c) e^{-(|v| / v_s)^2} \right) + b v \f]
 * with F_c the Coulomb level (V), F_s the static level (V), v_s the Stribeck velocity (mm/s) and
 * b the viscous slope (V per mm/s: the model's own a2 / k0 in mm plus any extra viscous
 * friction). It is TableFriction's curve (core/model/table_friction.h: Armstrong-Helouvry, Dupont
 * and Canudas de Wit 1994, Eq. 1), whose viscous slope is b less the model's own a2 / k0. One
 * jog segment gives one point (v, u) of the curve (steadyJogPoints), the points give the curve
 * (fitFrictionCurve). Experiment: jogReference (jog_experiment.h).
 */

/// One point of the curve: the steady part of one constant-velocity segment.
struct FrictionPoint {
    /// Slope of the least-squares line through the measured position over the steady part.
    double velocityMmPerS = 0;
    /// Mean command over the steady part.
    double volts = 0;
    /**
     * Standard deviation of that mean: s / sqrt(n) sqrt((1 + r) / (1 - r)), with s the sample
     * standard deviation of the command, n the samples and r its lag-1 autocorrelation
     * (clamped to >= 0): the variance of the mean of an AR(1) sequence, the first-order
     * correction for a command that the loop makes correlated from sample to sample. 0 for a
     * constant command.
     */
    double voltsStd = 0;
    std::size_t samples = 0; ///< n: the samples of the steady part
};

/// Settings of steadyJogPoints and fitFrictionCurve.
struct FrictionIdentificationOptions {
    /// Fraction of each constant-velocity segment (in time, in [0, 1)) left out at its start:
    /// the loop's transient after the ramp.
    double settleFraction = 0.5;
    /// Also try the Stribeck model (fitFrictionCurve), kept only where the data hold it.
    bool allowStribeck = true;
    /**
     * A segment is a run of the reference's first differences d[k] = r[k+1] - r[k] whose spread
     * max d - min d is at most this times |mean d| (and mean d != 0). 1e-3 holds a reference
     * logged in single precision (7 digits: 2e-6 mm at 20 mm) down to about 0.4 mm/s at 10 ms,
     * and tells a ramp (whose differences change by A Ts^2 per sample, relatively A Ts / v)
     * from a cruise unless A Ts / v < 1e-3 / 18 (18 changes in the shortest run): a ramp that
     * slow is taken as constant.
     */
    double referenceTolerance = 1e-3;
};

/// The fitted curve and the points it was fitted to.
struct FrictionEstimate {
    std::vector<FrictionPoint> points;
    /// F_c and b of the model selected: the Stribeck model's when hasStribeck, else the
    /// straight line's (u = F_c sign(v) + b v).
    double coulombVolts = 0;
    double coulombStd = 0;
    double viscousVoltsPerMmPerS = 0;
    double viscousStd = 0;
    /// The Stribeck model was fitted and kept (see fitFrictionCurve); the four fields below are
    /// 0 otherwise.
    bool hasStribeck = false;
    double staticVolts = 0;
    double staticStd = 0;
    double stribeckVelocityMmPerS = 0;
    double stribeckStd = 0;
    /// s = sqrt(RSS / (N - p)) of the selected model (V), p = 2 or 4.
    double residualStdVolts = 0;
    std::size_t degreesOfFreedom = 0; ///< N - p
    /// Why the Stribeck model was or was not kept, for the user: e.g. "F = 52.1 > F(2, 10;
    /// 0.99) = 7.56: Stribeck model kept" or "fewer than 3 distinct speeds per direction".
    Diagnostic modelSelection; ///< coded
};

/**
 * The points of the curve from a jog log (e.g. one run of jogReference): time t (s), reference
 * and measured position (mm), command (V), one row per sample.
 *
 * Segments are found from the reference alone: maximal runs of first differences within
 * options.referenceTolerance of their mean (see there), nonzero, at least 20 samples long
 * (19 differences), scanned from the start. Of each segment the part after the first
 * settleFraction of its duration is steady; a segment whose steady part has fewer than 10
 * samples is not used. For the steady part: velocity = the least-squares slope of position
 * against t (centred sums), volts = the mean command, voltsStd as in FrictionPoint. Points in
 * time order.
 * @throws InvalidInput "t" (fewer than 2 samples, not finite, not strictly increasing, or a
 *         step off the mean step by more than 1e-6 of it), "reference", "position", "command"
 *         (a length other than t's, a value not finite), "settle_fraction" (not in [0, 1)),
 *         "reference_tolerance" (not in (0, 0.1]), "reference" when fewer than 2 segments are
 *         found in either direction ("needs jogs in both directions at two or more speeds").
 */
std::vector<FrictionPoint> steadyJogPoints(const std::vector<double>& t,
                                           const std::vector<double>& reference,
                                           const std::vector<double>& position,
                                           const std::vector<double>& command,
                                           const FrictionIdentificationOptions& options = {});

/**
 * The Stribeck curve through @p points, all weighted equally (the spread about the curve, s^2,
 * pools the points' own noise and what the model misses).
 *
 * First the straight line u = F_c sign(v) + b v by linear least squares (linearLeastSquares in
 * least_squares.h: column-pivoting QR), standard deviations sqrt(diag(s^2 (J^T J)^-1)) with
 * s^2 = RSS / (N - 2).
 *
 * Then, with options.allowStribeck and at least 3 distinct speeds in each direction (speeds
 * within 1 % of each other count as one), the Stribeck model (header of this file) by Eigen's
 * Levenberg-Marquardt (MINPACK lmder, unsupported/Eigen/NonLinearOptimization) with the
 * analytic Jacobian in theta = (F_c, F_s, v_s, b), from the line's F_c and b, F_s = the mean
 * over both directions of sign(v) (u - b v) at the lowest speed, v_s = the lowest |v|. It is kept
 * when the search ends by one of MINPACK's convergence tests at finite values with v_s > 0
 * (the model holds v_s^2 only, so |v_s| is reported), F_s > F_c, J of full rank, and the F-test
 * of the nested models says the two extra parameters reduce the RSS significantly at the 1 %
 * level: F = ((RSS_line - RSS_S) / 2) / (RSS_S / (N - 4)) > F(2, N - 4; 0.99). For 2 numerator
 * degrees of freedom the F distribution's tail is closed form, P(F > x) = (1 + 2 x / nu)^(-nu/2)
 * (the regularized incomplete beta I_{nu / (nu + 2x)}(nu / 2, 1)), so the quantile is exact:
 * x = (nu / 2) (0.01^(-2 / nu) - 1). A line that fits to round-off (RMS residual below 1e-12
 * of the RMS command) is kept without the test. The kept model's standard deviations are
 * sqrt(diag(s^2 (J^T J)^-1)) at the optimum, s^2 = RSS / (N - 4): linearized, so with a dozen
 * points they can understate the spread of F_s and v_s (by 10 to 20 % for 14 points 5 mV off a
 * 0.2 V dip, over 200 seeds).
 * @throws InvalidInput "points": a value not finite, a velocity of 0, fewer than 2 points in
 *         either direction, or all speeds equal (F_c and b then cannot be told apart).
 */
FrictionEstimate fitFrictionCurve(const std::vector<FrictionPoint>& points,
                                  const FrictionIdentificationOptions& options = {});

/// fitFrictionCurve(steadyJogPoints(t, reference, position, command, options), options).
/// @throws InvalidInput as those two.
FrictionEstimate identifyFriction(const std::vector<double>& t,
                                  const std::vector<double>& reference,
                                  const std::vector<double>& position,
                                  const std::vector<double>& command,
                                  const FrictionIdentificationOptions& options = {});

} // namespace xyt
