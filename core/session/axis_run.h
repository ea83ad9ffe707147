// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/errors.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/loop_stepper.h"

#include <complex>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace xyt {

// What every design method's evaluation shares (core/session/design_method_module.h): the
// reference and the sample times an axis runs on, refused as refusals of the run, and the
// figures of its digital run.

/// A refusal of the run itself (AxisEvaluation::runRefused), not of one axis' design.
struct RunRefused : InvalidInput {
    using InvalidInput::InvalidInput;
};

/// axisReference, its refusals marked as refusals of the run.
std::function<double(double)> sessionReference(const TrajectorySettings& trajectory, int axisIndex);

/**
 * The sample times of one axis (step @p dt, named @p dtField in the session), refused naming
 * the session field when the run would not fit in memory or would hold a single sample (every
 * metric would read 0, which is not a result). The duration is blamed when the session sets it,
 * else the step.
 */
std::vector<double> axisSampleTimes(const TrajectorySettings& trajectory, double duration,
                                    double dt, const std::string& dtField);

/// "axes[i].field": a setting of axis @p axisIndex as the session file names it.
std::string axisFieldPath(int axisIndex, const std::string& field);

/**
 * A continuous controller @p controller on axis @p axisIndex's third-order plant (AxisSettings::gt:
 * the plant and its model unit) along @p reference sampled at @p dtSeconds, |u| <= umax, the
 * table at rest at the reference's first sample: a continuous axis' contour run. Throws
 * InvalidInput naming "axes[i].gt.plant" for a plant the loop cannot run.
 */
SimulationResult traceContinuousAxis(const AxisSettings& axis, int axisIndex,
                                     const TransferFunction& controller,
                                     const std::vector<double>& reference, double dtSeconds,
                                     double umaxVolts);

/// traceContinuousAxis' run as a loop advanced sample by sample (core/simulation/loop_stepper.h).
std::unique_ptr<SteppedLoop> steppedContinuousAxis(const AxisSettings& axis, int axisIndex,
                                                   const TransferFunction& controller,
                                                   const std::vector<double>& reference,
                                                   double dtSeconds, double umaxVolts);

/**
 * A program's reference (@p reference at the times @p t, from t = 0) at the times k
 * @p periodSeconds, k = 0 .. floor(t.back() / period) (+ @p lead samples beyond, the last value
 * held, for a ZPETC's preview): linear between the program's samples.
 * @throws InvalidInput @p field when the period is longer than the run or the run needs more
 *         samples than the machine holds.
 */
std::vector<double> programAtPeriod(const std::vector<double>& t,
                                    const std::vector<double>& reference, double periodSeconds,
                                    const std::string& field, std::size_t lead = 0);

/**
 * The table under @p axis for a loop's options (LoopSimulationOptions::table): null for the
 * linear table. @throws InvalidInput naming "axes[i].friction.<field>" for a value out of range
 * (validateTableFriction), and on a pole-placement axis, whose ARX model has no mass to put
 * friction on, for a static level above Coulomb, viscous friction, backlash or a compensation.
 */
const TableFriction* axisTable(const AxisSettings& axis, int axisIndex);

/**
 * What a pole-placement axis offers of a table: its Coulomb level plus the amplifier deadband as
 * a dead zone w of the ARX plant's input, u_plant = u - clamp(u, -w, w): the quasi-static form of
 * Coulomb friction at the input, exact while the axis moves the way it is pushed and ignoring
 * the flip of the friction at a reversal of the velocity against the command. 0 without one.
 * @throws InvalidInput as axisTable.
 */
double arxInputDeadzoneVolts(const AxisSettings& axis, int axisIndex);

/**
 * The friction compensation's feedforward (V) along @p reference (mm, step @p dtSeconds):
 * frictionCompensationVolts of the reference velocity, formed from the planned positions by
 * central differences (one-sided at the two ends), as firmware forms it from its trajectory
 * generator's positions. Empty when the axis has no compensation (percent 0).
 * @throws InvalidInput "axes[i].friction.compensation.<field>" (validateFrictionCompensation).
 */
std::vector<double> frictionFeedforward(const AxisSettings& axis, int axisIndex,
                                        const std::vector<double>& reference, double dtSeconds);

/// @p add added to @p into sample by sample (@p into empty: a copy of @p add).
void addFeedforward(std::vector<double>& into, const std::vector<double>& add);

/// The least damping ratio of continuous poles (1 without any).
double minContinuousDamping(const std::vector<std::complex<double>>& poles);
/// The least damping ratio of z-plane poles, those at the origin left out (1 without any).
double minDigitalDamping(const std::vector<std::complex<double>>& poles);

/// The figures, move-and-settle, damping and limit-cycle warnings of a digital run.
void finishDigital(const Session& session, DigitalEvaluation& d, AxisEvaluation& out);

} // namespace xyt
