// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/table_friction.h"
#include "core/model/transfer_function.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace xyt {

/**
 * The plant k0 / (s (s^2 + a1 s + a2)) of a Guillemin-Truxal axis taken apart so that friction
 * acts where it does, on the moving mass. With the two real poles pe and pm of s^2 + a1 s + a2
 * (pe + pm = a1, pe pm = a2; by default pe the faster, TableFriction::electricalPole), in model
 * units (metres for Braga et al.'s bases):
 *   electrical lag   z' = pe (u_a - z)               z: the drive's force in volts of input
 *   moving mass      v' = g (z - f(v)) - pm v,  g = k0 / pe
 *   motor position   x_m' = v
 *   table            y = play(x_m)                   backlash: |x_m - y| <= b / 2
 *   amplifier        u_a = u - clamp(u, -d, d)       deadband d
 * With f = 0, b = 0 and d = 0 this is the transfer function itself: Y/U = (pe / (s + pe))
 * (g / (s + pm)) / s = k0 / (s (s^2 + a1 s + a2)). In steady sliding u = (a2 / k0) v + f(v): the
 * friction is read in volts of equivalent input, as the jog experiment measures it.
 *
 * Sticking. The friction is the switched (hybrid) form of Karnopp's model with a stick band of
 * zero width: while sliding in direction s = +-1, f = s (Fc + (Fs - Fc) exp(-(v/vs)^2)) + bv v;
 * when v reaches 0 (an event located in time, below) the mass sticks if |z| <= Fs, else it slides
 * on the other way; while stuck v = 0 and x_m holds exactly (the friction takes whatever force
 * the drive applies, up to Fs), until |z| exceeds Fs (again a located event). So the table really
 * stops, holds without chattering and breaks away at Fs. Karnopp's band of finite width needs a
 * step small enough to land in it and LuGre a bristle stiffness whose dynamics are stiffer than
 * anything else in the loop; the located switch needs neither, and what LuGre would add (the
 * pre-sliding micro-displacement, micrometres) is below what the ballbar test resolves.
 *
 * Integration. Where every element is affine in its mode (Coulomb and viscous friction,
 * backlash, no Stribeck dip, no deadband) the closed loop takes exact steps between events
 * (simulateTableLoopInto). Otherwise, and at the samples holding an event, classical
 * fourth-order Runge-Kutta on sub-steps of each sample (h lambda <= 1/4,
 * lambda the largest rate in the loop: pe, pm, the linear closed loop's fastest pole, the
 * Stribeck and viscous slopes g df/dv), with the stick and slip events located inside a sub-step
 * by the Illinois variant of regula falsi on the Runge-Kutta solution to 1e-13 s, so between
 * events the order is four; the saturation, deadband and backlash corners are not located
 * (they bend the solution's derivative, not the state, and cost an O(h^2) local error at each).
 */
struct TableMechanics {
    double electricalPole = 0.0;   ///< pe (1/s), > 0
    double mechanicalPole = 0.0;   ///< pm (1/s), >= 0
    double forceGain = 0.0;        ///< g = k0 / pe (model units / s^2 per volt)
    double coulomb = 0.0;          ///< Fc (V)
    double breakaway = 0.0;        ///< Fs = max(Fs, Fc) (V); 0 for a table without dry friction
    double stribeckVelocity = 0.0; ///< vs (model units / s)
    double viscous = 0.0;          ///< bv (V per model unit / s)
    double backlash = 0.0;         ///< b (model units)
    double deadband = 0.0;         ///< d (V)
    bool dry() const { return breakaway > 0.0; }
};

/**
 * The split of @p plant with @p friction converted to model units (@p modelUnitsPerMm per mm).
 * @throws InvalidInput "plant" unless continuous of the form k0 / (s (s^2 + a1 s + a2)) with
 *         k0 > 0 and real poles pe > 0, pm >= 0 (complex poles have no electrical lag and mass to
 *         split), as validateTableFriction for the friction, "model_unit_scale" unless > 0.
 */
TableMechanics tableMechanics(const TransferFunction& plant, const TableFriction& friction,
                              double modelUnitsPerMm);

/// The table's state: the drive force z (V), the mass' velocity (model units/s), the motor and
/// table positions (model units) and whether the mass slides (+1 forward, -1 backward) or sticks
/// (0; a table without dry friction always reports +1).
struct TableState {
    double drive = 0.0, velocity = 0.0, motor = 0.0, table = 0.0;
    int sliding = 0;
};

/**
 * The table under a command held constant between the controller's samples (a sampled-data
 * loop's zero-order hold), integrated as TableMechanics says.
 */
class TablePlant {
public:
    /// At rest at @p initialModel (model units), the motor centred in the backlash gap.
    TablePlant(const TableMechanics& mechanics, double initialModel = 0.0);
    /// Applies @p volts for @p seconds (sub-steps: h pe, h pm and the friction slopes <= 1/4, at
    /// least @p minSubsteps of them).
    void hold(double volts, double seconds, int minSubsteps = 1);
    const TableState& state() const { return state_; }
    /// The number of stick/slip transitions so far.
    std::uint64_t transitions() const { return transitions_; }

private:
    TableMechanics m_;
    TableState state_;
    std::uint64_t transitions_ = 0;
};

struct LoopSimulationOptions;
struct SimulationResult;

/**
 * simulateLoopInto's run when its options carry an active table (LoopSimulationOptions::table):
 * the loop of simulateLoop with the controller realized (controllable canonical form) beside the
 * table, the reference and @p feedforwardVolts (or null) linear between samples, |u| <= umax at
 * every instant, the table at rest at initialOutput. Fills t, y, e, u, clipped and sliding of
 * @p out (sized by the caller). @throws InvalidInput as tableMechanics, "table_substeps".
 */
void simulateTableLoopInto(const TransferFunction& plant, const TransferFunction& controller,
                           const std::vector<double>& reference,
                           const LoopSimulationOptions& options, const double* feedforwardVolts,
                           SimulationResult& out);

class SteppedLoop;

/**
 * simulateTableLoopInto's loop as a SteppedLoop (core/simulation/loop_stepper.h), owning copies
 * of @p reference and @p feedforwardVolts: the extra voltage of each sample is a feedforward
 * offset held over the period. With every extra voltage 0 the run is simulateTableLoopInto's
 * bit for bit. @throws InvalidInput as simulateTableLoopInto.
 */
std::unique_ptr<SteppedLoop> steppedTableLoop(const TransferFunction& plant,
                                              const TransferFunction& controller,
                                              const std::vector<double>& reference,
                                              const LoopSimulationOptions& options,
                                              const double* feedforwardVolts);

} // namespace xyt
