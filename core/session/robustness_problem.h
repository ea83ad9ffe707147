// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/study/contour_robustness.h"
#include "core/study/robustness.h"

#include <functional>
#include <string>
#include <vector>

namespace xyt {

/**
 * The robustness problem of axis @p axis of @p session: its nominal design (the
 * session's PI, or its pole-placement loop and ZPETC), the run the session evaluates (the same
 * reference, duration and step), the session's specification with umax, and every plant
 * parameter with a zero range ("k0", "a1", "a2"; or "a1".."an", "b1".."bm" of the ARX model,
 * B's leading zeros of the delay left out): set the ranges with setRelativeRange.
 * @throws InvalidInput "axis" when out of range, and naming the session field when the axis
 *         cannot be evaluated (as evaluateAxis reports it).
 */
RobustnessProblem sessionRobustnessProblem(const Session& session, int axis);

/**
 * The problem of a continuous controller @p controller (volts per model unit of error) on the
 * axis' third-order plant, as a module builds it for its robustnessProblem: the run of
 * @p nominal (its reference and step), the session's specification with umax, the move of a
 * cubic, and the axis' plant parameters with zero ranges.
 */
RobustnessProblem continuousRobustnessProblem(const Session& session, int axis,
                                              const AxisEvaluation& nominal,
                                              const TransferFunction& controller,
                                              double modelUnitsPerPositionUnit);

/// The problem of a discrete RST loop @p loop with its ZPETC feedforward @p zpetc (run when
/// @p zpetcEnabled): the reference sampled at the loop's Ts, with the feedforward's preview.
RobustnessProblem rstRobustnessProblem(const Session& session, int axis,
                                       const AxisEvaluation& nominal,
                                       const PolePlacementDesign& loop,
                                       const std::optional<ZpetcDesign>& zpetc, bool zpetcEnabled);

/// The parameters of a third-order plant k0/(s^3 + a1 s^2 + a2 s) with zero ranges: "k0", "a1",
/// "a2".
std::vector<UncertainParameter> thirdOrderPlantParameters(const ThirdOrderPlant& plant);

/// @p plant with k0, a1 and a2 replaced by @p value(name, current value).
ThirdOrderPlant
withThirdOrderPlantParameters(ThirdOrderPlant plant,
                              const std::function<double(const std::string&, double)>& value);

/**
 * The joint XY problem of @p session: both axes' problems as sessionRobustnessProblem
 * gives them, judged on the session's contour. A circle: the runs the evaluation makes, judged
 * on x's samples as SessionEvaluation::contour is (so the nominal figures are those). A G-code
 * program: both axes follow the program's feed profile as runSessionProgram runs them, judged
 * along the programmed path with the rapids left out (so the nominal figures are those of
 * SessionEvaluation::program).
 * @throws InvalidInput "trajectory" for a cubic, and as sessionRobustnessProblem and the
 *         program's reader ("trajectory.gcode.program").
 */
ContourRobustnessProblem sessionContourRobustnessProblem(const Session& session);

/**
 * The uncertainty of axis @p axis from its identified model ("from identification";
 * the model's origin): problem.covariance is the estimate's covariance over the
 * problem's parameters (random plants then come from N(nominal, covariance)), and each range is
 * set to 3 standard deviations (at most 99 %) so that the box's corners are the +-3 sigma
 * worst-case search. Names map as the models do: a Guillemin-Truxal axis takes k0, a1, a2 of a
 * continuous fit (k0's row and column scaled from mm to the axis' model unit); a pole-placement
 * axis takes a_i, b_i of an ARX model, or f_i (as a_i) and b_i of an OE or BJ model (the noise
 * model's c_i, d_i do not enter the loop). A parameter the origin does not name stays exact.
 * @throws InvalidInput "axes[i].model_origin" when the axis has no identified model, the model
 *         has no covariance, or was identified for the other design method.
 */
void setIdentifiedUncertainty(RobustnessProblem& problem, const Session& session, int axis);

/**
 * The uncertain parameters of an axis, with zero ranges, from its settings alone (nothing is
 * designed or simulated, so a view may call it on every slider step): those of
 * sessionRobustnessProblem. ARX coefficients are those of the normalized model (A(0) = 1).
 * @throws InvalidInput naming the coefficient list when A or B cannot be read.
 */
std::vector<UncertainParameter> axisUncertainParameters(const AxisSettings& axis);

} // namespace xyt
