// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/table_friction.h"
#include "core/model/transfer_function.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <vector>

namespace xyt {

struct LoopSimulationOptions {
    double dtSeconds = 0.01;
    /// Actuator limit |u| <= umax (2.5 V in Braga et al.); infinity for none.
    double umaxVolts = std::numeric_limits<double>::infinity();
    /// The plant starts at rest at this output. Nonzero values need a plant with a pole at s = 0.
    double initialOutput = 0.0;
    /**
     * Plant output units per reference unit. The identified models of Braga et al. map volts to
     * metres (their velocity gain k0/a2 is 0.021 m/s per volt) while trajectories are typed in
     * millimetres, so the presets use 0.001: the reference is multiplied by this before it
     * enters the loop, and y and e are divided by it on the way out (u is unchanged).
     * initialOutput is in reference units.
     */
    double modelUnitsPerPositionUnit = 1.0;
    /**
     * A feedforward added to the controller's output before the limit, in volts at the
     * reference's samples and linear between them (as the reference is): u = sat(C e + uff).
     * Null or empty for none (then the run is the feedback loop's, bit for bit). It must have
     * the reference's length.
     */
    const std::vector<double>* feedforwardVolts = nullptr;
    /**
     * The table's friction, backlash and amplifier deadband (core/simulation/table_dynamics.h).
     * Null or inactive (TableFriction::active): the linear plant, and the run is the linear one
     * bit for bit. Active: the plant must be k0 / (s (s^2 + a1 s + a2)) with real poles.
     */
    const TableFriction* table = nullptr;
    /// Runge-Kutta sub-steps per sample of a run with a table; 0: automatic (h lambda <= 1/4).
    int tableSubsteps = 0;
};

/// Sampled signals of one run: t, reference r, output y, error e = r - y, actuator command u
/// (after saturation) and whether u was clipped at each sample.
struct SimulationResult {
    std::vector<double> t, r, y, e, u;
    std::vector<bool> clipped;
    /// The feedforward part of u before the limit (V), when the run has one (else empty): the
    /// feedback part is u - uFeedforward while u is not clipped.
    std::vector<double> uFeedforward;
    /// With a table that has dry friction: whether the mass slides (+1 forward, -1 backward) or
    /// sticks (0) at each sample; empty otherwise.
    std::vector<std::int8_t> sliding;
    double dtSeconds = 0.0;
    double umaxVolts = std::numeric_limits<double>::infinity();
};

/**
 * The two linear modes of the loop of simulateLoop, in the state x = [x_p; x_c] (plant states
 * first, then controller states, both in the controllable canonical form of realize()):
 *   inside the limits  x' = A_lin x + B_lin r,       u = C_c x_c + D_c (r - C_p x_p),
 *   clipped            x' = A_sat x + B_sat [r; u],  u = +-umax held,
 * with A_lin = [A_p - D_c B_p C_p, B_p C_c; -B_c C_p, A_c], B_lin = [D_c B_p; B_c],
 * A_sat = [A_p, 0; -B_c C_p, A_c], B_sat = [0, B_p; B_c, 0]. The plant output is y = C_p x_p.
 * Shared by simulateLoop and the fast tracking kernel of the design sweep, so both integrate
 * the very same equations.
 * @throws InvalidInput "plant" unless strictly proper and continuous, "controller" unless
 *         proper and continuous.
 */
struct LoopModes {
    Eigen::MatrixXd aLinear, bLinear;   ///< n x n, n x 1
    Eigen::MatrixXd aClipped, bClipped; ///< n x n, n x 2 (inputs r, u)
    Eigen::MatrixXd plantA;             ///< A_p, for initial conditions
    Eigen::RowVectorXd plantC;          ///< C_p
    Eigen::RowVectorXd controllerC;     ///< C_c
    double controllerD = 0.0;           ///< D_c
    Eigen::Index plantStates = 0;
    Eigen::Index controllerStates = 0;
};
LoopModes loopModes(const TransferFunction& plant, const TransferFunction& controller);

/**
 * Time simulation of the unity-feedback loop r -> e = r - y -> controller -> sat(. + uff, umax)
 * -> continuous plant -> y, with the reference (and the feedforward uff, when given) linear
 * between its samples (first-order hold).
 *
 * The loop is piecewise linear: while the controller output v is inside the limits, the closed
 * loop x' = A_cl x + B_cl r is linear; while it is clipped, the plant sees a constant u = +-umax
 * and the controller still integrates e. Both modes are discretized exactly (matrix exponential,
 * first-order hold on r), and the mode is chosen from v at the start of each step. So with no
 * saturation the result equals the linear closed loop at the samples to round-off, and the only
 * approximation is that a switch between modes happens at the sample instant (error O(dt) at
 * switches, as in a real digital loop).
 *
 * @param reference r(k dt) for k = 0..n-1
 * @throws InvalidInput "plant" unless strictly proper and continuous, "controller" unless proper
 *         and continuous, "reference" when empty or not finite, "dt", "umax" (must be > 0),
 *         "initial_output".
 */
SimulationResult simulateLoop(const TransferFunction& plant, const TransferFunction& controller,
                              const std::vector<double>& reference,
                              const LoopSimulationOptions& options);

/**
 * simulateLoop into @p out, whose buffers are reused: the sample loop allocates nothing, and a
 * caller that keeps one SimulationResult for repeated runs of at most as many samples (a live
 * view, a benchmark) causes no heap traffic for the signals either (the setup still builds the
 * loop's few small matrices). The results are those of simulateLoop, bit for bit.
 * @throws InvalidInput as simulateLoop; @p out is then unspecified.
 */
void simulateLoopInto(const TransferFunction& plant, const TransferFunction& controller,
                      const std::vector<double>& reference, const LoopSimulationOptions& options,
                      SimulationResult& out);

/**
 * Output of a continuous linear system from zero initial state driven by an input that is linear
 * between its samples u(k dt): exact at the samples (first-order-hold discretization).
 * @throws InvalidInput "system" unless proper and continuous, "input", "dt".
 */
std::vector<double> simulateLinear(const TransferFunction& system, const std::vector<double>& input,
                                   double dtSeconds);

} // namespace xyt
