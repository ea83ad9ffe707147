// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/simulation.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace xyt {

/**
 * The state before k = 0. Signals before k = 0 are those of a reference extended backwards:
 * r(j) = r(0) for j < 0 (AtReference) or r(j) = 0 with every state zero (AtOrigin).
 *  - AtReference (default): the table rests at r(0) with every signal in the steady state of
 *    the constant reference r(0), as if it had been there forever. The same extended reference
 *    drives all three structures, so with a perfect model they agree to round-off.
 *  - AtOrigin: zero state (table at 0), to show the start-up transient of a reference that does
 *    not start at 0 (y = 30 cos(0.1 t) starts at 30 mm).
 * With a preview of p samples the feedforward already reads r(0 .. p-1) at k = -p .. -1, so the
 * table may leave its rest position up to deg B- - 1 samples before k = 0 (inherent to a
 * zero-phase, non-causal overall response); the runs report k >= 0 only.
 */
enum class StartCondition { AtReference, AtOrigin };

/// Output and control samples k = 0 .. n-1 of one discrete run (u empty when there is no loop).
struct DiscreteRun {
    std::vector<double> y;
    std::vector<double> u;
};

/**
 * Runs the difference equation D(z^-1) y = N(z^-1) x (ascending powers of z^-1, D(0) != 0) on
 * x(0 .. n-1), with x(j) = pastInput and y(j) = pastOutput for j < 0.
 * @throws InvalidInput "den" when D(0) = 0.
 */
std::vector<double> filterZInverse(const Polynomial& num, const Polynomial& den,
                                   const std::vector<double>& x, double pastInput = 0.0,
                                   double pastOutput = 0.0);

/**
 * The RST loop F u = Kf w - G y, A y = B (u + v) one sample at a time, on the loop input
 * w(0 .. n-1), every history at the steady state of w = rest: at sample k, output() is y(k)
 * (from the past only, B(0) = 0) and advance(v) forms u(k), adds v (V, the cross-coupled
 * controller's voltage) and passes u + v, less the input dead zone, to the plant. Advanced with
 * v = 0 throughout it is simulateFeedbackLoop's (and the ZPETC loop's) run bit for bit.
 */
class RstLoopStepper {
public:
    RstLoopStepper(const PolePlacementDesign& design, std::vector<double> loopInput, double rest,
                   double inputDeadzoneVolts = 0.0);
    std::size_t samples() const { return v_.size(); }
    std::size_t index() const { return k_; }
    double output() const { return y_[history_ + k_]; }
    /// Records sample k with @p extraVolts added at the plant input; returns the plant's
    /// command u(k) + v (before the dead zone).
    double advance(double extraVolts);
    /// y and the plant's command u + v of samples from .. index()-1.
    DiscreteRun run(std::size_t from = 0) const;

private:
    double dead(double x) const;
    double plantOutput(std::size_t k) const;

    PolePlacementDesign d_;
    std::vector<double> v_;
    double deadzone_;
    std::size_t history_;
    std::vector<double> y_, u_, ua_, command_;
    std::size_t k_ = 0;
};

/**
 * The first @p n samples of a discrete run on t = k @p ts as a SimulationResult in @p out (its
 * buffers reused): r from @p r, e = r - y, u zero-padded when the run has none, and `clipped`
 * where |u| > @p umax (the discrete loops are linear: flagged, not applied).
 */
void discreteResult(const std::vector<double>& r, const DiscreteRun& run, double ts, double umax,
                    std::size_t n, SimulationResult& out);

/**
 * The pole-placement loop (with @p zpetc: its ZPETC ahead) on @p r (r(0 .. samples + p - 1),
 * p its preview), at rest at r(0), as a SteppedLoop (core/simulation/loop_stepper.h): the
 * preview's samples before k = 0 run at construction without extra voltage, as
 * simulateZpetcLoop has them; the extra voltage joins the plant's input (RstLoopStepper). Its
 * result is on t = k Ts, the loop linear with |u| > @p umaxVolts flagged, not applied; with
 * every extra voltage 0 it is simulateZpetcLoop's (simulateFeedbackLoop's) run bit for bit.
 * @throws InvalidInput "reference" as simulateZpetcLoop.
 */
std::unique_ptr<SteppedLoop> steppedRstRun(const PolePlacementDesign& loop,
                                           const ZpetcDesign* zpetc, const std::vector<double>& r,
                                           std::size_t samples, double umaxVolts,
                                           double inputDeadzoneVolts = 0.0);

/**
 * Structure (1): the pole-placement loop alone (paper Fig. 9), F u = Kf r - G y, A y = B u,
 * driven by r(0 .. n-1). Returns y and u for k = 0 .. n-1. With @p inputDeadzoneVolts > 0 the
 * plant receives u - clamp(u, -w, w) (an ARX axis' Coulomb friction and amplifier deadband as a
 * dead zone of its input, AxisSettings::friction); 0 is the linear loop bit for bit.
 * @throws InvalidInput "reference" when empty.
 */
DiscreteRun simulateFeedbackLoop(const PolePlacementDesign& loop, const std::vector<double>& r,
                                 StartCondition start = StartCondition::AtReference,
                                 double inputDeadzoneVolts = 0.0);

/**
 * Structure (2): the ZPETC (paper Fig. 6) ahead of the pole-placement loop (Fig. 9): the loop's
 * reference input is u_ff(k) = N_ff/D_ff r(k + p). @p r holds r(0 .. samples + p - 1).
 * Returns y and the plant input u for k = 0 .. samples-1.
 * @throws InvalidInput "reference" when r is shorter than samples + p or samples is 0.
 */
DiscreteRun simulateZpetcLoop(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                              const std::vector<double>& r, std::size_t samples,
                              StartCondition start = StartCondition::AtReference,
                              double inputDeadzoneVolts = 0.0);

/**
 * The loop input of simulateZpetcLoop: the ZPETC's output u_ff(k) = N_ff/D_ff r(k + p) for
 * k = -p .. samples-1 (samples + p values), its histories at @p rest.
 * @throws InvalidInput as simulateZpetcLoop.
 */
std::vector<double> zpetcLoopInput(const ZpetcDesign& zpetc, const std::vector<double>& r,
                                   std::size_t samples, double rest);

/**
 * Structure (3), the trajectory ZPETC of paper Fig. 8: y = B-(z^-1) B-(z) / [B-(1)]^2 r, i.e.
 * y(k) = sum_j h_j r(k + s - j), s = deg B-. @p r holds r(0 .. samples + s - 1) at least.
 * Returns y for k = 0 .. samples-1 (u empty).
 * @throws InvalidInput "reference" when r is too short or samples is 0.
 */
DiscreteRun simulateTrajectoryZpetc(const ZpetcDesign& zpetc, const std::vector<double>& r,
                                    std::size_t samples,
                                    StartCondition start = StartCondition::AtReference);

} // namespace xyt
