// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/loop_responses.h"
#include "core/design/model_feedforward.h"
#include "core/design/servo_pid.h"
#include "core/model/diagnostic.h"
#include "core/session/design_method_module.h"
#include "core/simulation/sampled_data.h"

#include <string>
#include <vector>

namespace xyt {

/**
 * The position PID with command feedforward that CNC drives run (LinuxCNC's `pid` component,
 * core/design/servo_pid.h), on Braga et al.'s third-order plant (AxisSettings::gt: the plant and
 * its model unit). Its settings are numbers (AxisSettings::parameters, pidFeedforwardParameters),
 * in LinuxCNC's units with position in mm.
 *
 * - The digital implementation is the PID itself at the controller period
 *   (simulateSampledServoPid), the command's derivatives formed as the session says
 *   (`command_derivatives`: 0 backward differences as LinuxCNC, 1 the trajectory generator's).
 * - The continuous loop, which the analyses (margins, Bode, Nyquist, root locus, the step)
 *   and the design's run take, is
 *     C(s) = (P + I/s + D s / (Tf s + 1)) / unit   volts per model unit of error,
 *   with Tf the derivative filter, or, when the filter is 0 (LinuxCNC's unfiltered D), Tf = Ts/2:
 *   the backward difference (1 - z^-1)/Ts is a derivative delayed by half a sample,
 *   j w e^(-j w Ts/2) sinc(w Ts/2), whose phase a lag of Ts/2 matches to first order in w Ts.
 *   The feedforward enters that run as u_ff = bias + FF0 r + FF1 r' + FF2 r'' + FF3 r''' with
 *   the trajectory's exact derivatives (axisMotion), linear between the samples; with the
 *   derivative on the measurement it also takes off the D term's share of the reference,
 *   D Tf-filtered r'. The output is limited to max_output, or to umax when that is 0 or larger.
 */
const DesignMethodModule& pidFeedforwardMethod();

/// The method's parameters, in the order an editor lists them.
std::vector<MethodParameter> pidFeedforwardParameters();

/// The design the method makes for one axis (AxisEvaluation::methodDesign).
struct PidFeedforwardDesign : MethodDesign {
    ServoPidGains gains; ///< in mm units; maxOutput is the limit the loop applies (V)
    CommandDerivativeSource derivativeSource = CommandDerivativeSource::BackwardDifferences;
    double unit = 0.001;                ///< model units per mm
    double tsSeconds = 0.01;            ///< the controller period
    double continuousFilterSeconds = 0; ///< Tf of the continuous model (see above)
    ModelFeedforwardGains model;        ///< the plant's exact inverse as FF1..FF3
    TransferFunction plant;             ///< G(s), model units per volt
    TransferFunction controller;        ///< C(s), volts per model unit
    LoopTransferFunctions loop;         ///< of C and G
    /// r -> y with the feedforward: (C + F / unit) G / (1 + C G), F = FF0 + FF1 s + FF2 s^2 +
    /// FF3 s^3 (proper, since G has relative degree 3).
    TransferFunction trackingWithFeedforward;
    std::vector<std::complex<double>> closedLoopPoles;
    bool stable = false;
};

/// The design of an evaluated PID + feedforward axis. Throws InvalidInput "axis" without one.
const PidFeedforwardDesign& pidFeedforwardDesign(const AxisEvaluation& axis);

/**
 * The design of axis @p axisIndex's settings (no run): the gains read and checked from
 * AxisSettings::parameters (refusals name "axes[i].parameters.<name>"; a derivative filter
 * 0 < Tf < Ts/pi, whose corner lies beyond the Nyquist frequency, is refused), the plant and
 * the loops.
 */
PidFeedforwardDesign designPidFeedforward(const Session& session, int axisIndex);

/**
 * The closed-loop poles (z-plane) of the linear sampled-data PID loop (no limits, deadband or
 * quantization) on @p plant with @p delaySamples: the eigenvalues of its state matrix over
 * [x; errorI; previous feedback; filtered D; u[k-1] .. u[k-delay]].
 */
std::vector<std::complex<double>> sampledServoPidLoopPoles(const SampledPlant& plant,
                                                           const ServoPidGains& gains, double unit,
                                                           int delaySamples);

/**
 * Axis @p axisIndex with the plant's exact inverse as its feedforward (FF0 = 0, FF1..FF3 of
 * modelFeedforwardGains): a PID + feedforward axis keeps its feedback; a Guillemin-Truxal axis
 * becomes the same PI in LinuxCNC's units (P = kp u, I = ki u per mm, D = 0) on the PID +
 * feedforward method, Braga et al.'s PI plus the feedforward. Throws InvalidInput naming the
 * field: "axes[i].method" for a pole-placement axis (its model-inverse feedforward is ZPETC),
 * the plant's fields for a plant without a usable inverse, the GT design's fields.
 */
AxisSettings withModelFeedforward(const AxisSettings& axis, int axisIndex);

/// Feedback gains P, I, D (LinuxCNC units), or why a change cannot give any.
struct PidFeedbackGains {
    bool ok = false;
    Diagnostic reason; ///< when !ok
    double p = 0.0, i = 0.0, d = 0.0;
};

/**
 * The feedback gains whose controller has its zero @p from moved to @p to (a zero dragged on the
 * root locus; the design's continuous controller C(s), see pidFeedforwardMethod), the loop's
 * other zeros and the controller's high-frequency gain kept:
 *  - PI (D = 0): C = (P s + I)/(u s), one zero at -I/P: I' = -P Re(to) (a real zero; P kept);
 *  - PID: C's numerator n2 s^2 + n1 s + n0 with n2 = P Tf + D, n1 = P + I Tf, n0 = I (Tf the
 *    continuous filter): the zero moves (a complex pair moves together, a real zero keeps its
 *    partner; a real zero dragged off the axis takes its partner as the conjugate) and n2 is
 *    kept, so I' = n0', P' = n1' - I' Tf, D' = n2 - P' Tf.
 * Refused (ok = false) when a gain would be negative or not finite, or @p to is in the right
 * half plane.
 */
PidFeedbackGains pidGainsWithMovedZero(const PidFeedforwardDesign& design,
                                       std::complex<double> from, std::complex<double> to);

/**
 * The feedforward voltage along @p motion (bias + FF0 r + FF1 r' + FF2 r'' + FF3 r''').
 */
double feedforwardVolts(const ServoPidGains& gains, const MotionSample& motion);

} // namespace xyt
