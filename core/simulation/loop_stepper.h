// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/simulation/simulation.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace xyt {

/**
 * One axis' loop advanced one sample at a time, so that two axes can run in lockstep with a
 * controller between them that reads both outputs at each sample (the cross-coupled contouring
 * controller, core/design/cross_coupling.h). At sample k the loop shows its output y_k, and
 * advance(v) forms the command of sample k with v (V) added before the limit, records sample k
 * and moves the plant to sample k + 1 with v held over the period.
 */
class SteppedLoop {
public:
    virtual ~SteppedLoop() = default;
    /// The number of samples of the run.
    virtual std::size_t samples() const = 0;
    /// The period between samples (s).
    virtual double periodSeconds() const = 0;
    /// The index of the current sample (samples() once every sample is recorded).
    virtual std::size_t index() const = 0;
    /// The output y_k at the current sample, in the reference's units.
    virtual double output() const = 0;
    /// The reference r_k at the current sample.
    virtual double reference() const = 0;
    /// Records sample k with @p extraVolts added to the command before the limit and advances;
    /// returns whether the command was clipped at the limit at sample k.
    virtual bool advance(double extraVolts) = 0;
    /// The run, complete once index() == samples() (a continuous loop fills it as it goes, a
    /// discrete one when its last sample is recorded).
    virtual const SimulationResult& result() const = 0;
    virtual SimulationResult takeResult() = 0;
};

/**
 * simulateLoop's loop as a SteppedLoop: the same plant, controller, limit, feedforward (copied),
 * initial output and table (LoopSimulationOptions; the table's TableFriction is copied too).
 * The extra voltage enters as a feedforward held over the period. With every extra voltage 0
 * the run equals simulateLoop's to round-off (a linear table: the same exact modes, with the
 * feedforward's input column always present).
 * @throws InvalidInput as simulateLoop.
 */
std::unique_ptr<SteppedLoop> steppedLoop(const TransferFunction& plant,
                                         const TransferFunction& controller,
                                         const std::vector<double>& reference,
                                         const LoopSimulationOptions& options);

} // namespace xyt
