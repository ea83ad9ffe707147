// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/digital_controller.h"
#include "core/design/pole_placement.h"
#include "core/design/servo_pid.h"
#include "core/design/zpetc.h"
#include "core/model/diagnostic.h"
#include "core/model/transfer_function.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"

#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/**
 * What the hardware around the digital controller does: the controller reads a
 * quantized encoder, computes every Ts, writes a quantized DAC value, clipped at +-umax, possibly
 * one or more samples late.
 */
struct SampledDataOptions {
    /// Computation delay: the command computed at sample k is applied from sample k + delay.
    int delaySamples = 0;
    /// Encoder resolution in position units (mm) per count; 0: ideal (no quantization).
    /// The measured position is res * floor(y / res + 1/2) (encoderReading).
    double encoderResolution = 0.0;
    /// DAC resolution over +-umax; 0: ideal (dacOutput).
    int dacBits = 0;
    /// Actuator limit (V); infinity: none (then dacBits must be 0).
    double umaxVolts = std::numeric_limits<double>::infinity();
    /// Pole-placement axes: None keeps the controller's own output v in the RST law's past-u
    /// terms; any other choice puts the clipped command there (the RST anti-windup of Landau
    /// and Astrom: the controller remembers what the actuator did). Digital PI axes carry
    /// their anti-windup in DigitalPi.
    AntiWindup antiWindup = AntiWindup::Clamp;
    /// The table's friction, backlash and amplifier deadband (core/simulation/table_dynamics.h)
    /// for the continuous-plant loops (simulateSampledPi, simulateSampledServoPid): between
    /// samples the held command drives TablePlant. simulateSampledRst (an ARX plant) takes its
    /// Coulomb level plus the amplifier deadband as a dead zone of the plant's input. Null or
    /// inactive: the exact linear step.
    const TableFriction* table = nullptr;
    /// A feedforward (V) per controller sample added to the controller's output before the
    /// limit, as firmware adds its friction compensation after the PI or PID: u = sat(v + uff)
    /// (the PI's anti-windup acts on its own output). Null or empty: none, bit for bit.
    const std::vector<double>* feedforwardVolts = nullptr;
};

/// Largest computation delay accepted (samples).
inline constexpr int kMaxDelaySamples = 100;

/**
 * @throws InvalidInput "delay_samples" unless 0..kMaxDelaySamples, "encoder_resolution" unless
 *         finite and >= 0, "dac_bits" unless 0..32 (and umax finite when > 0), "umax" unless > 0.
 */
void validateSampledDataOptions(const SampledDataOptions& options);

/// The encoder: res * floor(y / res + 1/2) (round half up), or y itself for res = 0.
inline double encoderReading(double positionMm, double resolutionMm) {
    if (resolutionMm == 0.0)
        return positionMm;
    return resolutionMm * std::floor(positionMm / resolutionMm + 0.5);
}

/**
 * The DAC: a bipolar converter of 2^bits codes over +-umax, LSB q = 2 umax / 2^bits, codes
 * -2^(bits-1) .. 2^(bits-1) - 1 (so 0 V is a code and the largest output is umax - q):
 *   u_out = q * clamp(floor(u / q + 1/2), -2^(bits-1), 2^(bits-1) - 1);  bits = 0: u itself.
 */
double dacOutput(double volts, int bits, double umaxVolts);

/**
 * The continuous plant discretized exactly under a zero-order hold at Ts (discretizeZoh of its
 * controllable canonical realization): x[k+1] = phi x[k] + gamma u[k], y[k] = c x[k]. phi is
 * row-major n x n. The sampled-data loop and the exported-code test harness step it with the
 * same sums in the same order: y = sum_j c[j] x[j], x'[i] = sum_j phi[i][j] x[j] + gamma[i] u.
 * @throws InvalidInput "plant" unless continuous and strictly proper, "ts" unless > 0.
 */
struct SampledPlant {
    int states = 0;
    std::vector<double> phi, gamma, c;
    double tsSeconds = 0.0;
};
SampledPlant sampledPlant(const TransferFunction& plant, double tsSeconds);

/// The result of a sampled-data run at the controller's samples k Ts.
struct SampledDataRun {
    /// t, r, y (the plant output at the sample instants, position units), e = r - y, u (the
    /// controller's saturated command, before the DAC) and `clipped` (the controller clipped v).
    SimulationResult result;
    std::vector<double> measured; ///< the encoder reading the controller used
    std::vector<double> applied;  ///< the DAC output the plant received at each sample (delayed)
};

/**
 * The loop a digital PI runs on a continuous plant: every Ts the encoder reads y, the PI of
 * @p pi (stepDigitalPi, with its anti-windup) computes u from e = (r - measured) * unit, the DAC
 * quantizes it and, after delaySamples, a zero-order hold applies it to the plant, which is exact
 * between samples (sampledPlant). The plant starts at rest at 0 with the PI state zero.
 * @param reference r(k Ts), k = 0..n-1, in position units (mm)
 * @param modelUnitsPerPositionUnit as LoopSimulationOptions (0.001 for Braga et al.'s metre models)
 * @throws InvalidInput as sampledPlant, validateSampledDataOptions, "reference" when empty or not
 *         finite, "model_unit_scale" unless > 0.
 */
SampledDataRun simulateSampledPi(const TransferFunction& plant, const DigitalPi& pi,
                                 const std::vector<double>& reference,
                                 const SampledDataOptions& options,
                                 double modelUnitsPerPositionUnit = 1.0);

/// Where a servo PID's feedforward reads the command's derivatives.
enum class CommandDerivativeSource {
    /// Backward differences of the commanded position each period, as LinuxCNC's `pid` forms
    /// them when its derivative pins are not connected.
    BackwardDifferences,
    /// The trajectory generator's own velocity, acceleration and jerk at the sample instant.
    TrajectoryGenerator
};

/**
 * The loop a servo PID with feedforward runs on a continuous plant (stepServoPid, LinuxCNC's
 * `pid` semantics): every Ts the encoder reads y (mm), the PID computes u from the command
 * @p command[k].position and that reading, the output is clipped at +-umax and the DAC quantizes
 * it, and after delaySamples a zero-order hold applies it to the plant (exact between samples,
 * sampledPlant, in model units: y_model = unit * y_mm). The plant starts at rest at 0 with the
 * PID's previous command at the first command (no derivative kick at the first sample) and its
 * previous feedback at 0. result.u is the clipped output, result.uFeedforward its FF0..FF3 part,
 * and `clipped` marks samples where the PID's own limit or umax cut the output.
 * @param command r(k Ts) and, for CommandDerivativeSource::TrajectoryGenerator, its derivatives
 * @throws InvalidInput as simulateSampledPi, "ts" unless > 0.
 */
SampledDataRun simulateSampledServoPid(const TransferFunction& plant, const ServoPidGains& gains,
                                       double tsSeconds, const std::vector<MotionSample>& command,
                                       CommandDerivativeSource source,
                                       const SampledDataOptions& options,
                                       double modelUnitsPerPositionUnit = 1.0);

/**
 * The pole-placement loop (F u = Kf w - G y_measured on the ARX plant A y = B u) with encoder,
 * DAC, saturation and delay; with @p zpetc the loop input w is the ZPETC feedforward of
 * r(k + p) (p = previewSteps), else w = r. As simulateZpetcLoop with StartCondition::AtReference:
 * the loop runs from k = -p at rest at r(0) (u at A(1)/B(1) r(0)) and k = 0..samples-1 is
 * returned; with ideal options it gives the bits of simulateZpetcLoop / simulateFeedbackLoop.
 * @param r r(0 .. samples + p - 1)
 * @throws InvalidInput as validateSampledDataOptions, "reference" when too short or not finite.
 */
SampledDataRun simulateSampledRst(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                                  const std::vector<double>& r, std::size_t samples,
                                  const SampledDataOptions& options);

/**
 * A sampled-data loop advanced one sample at a time (SteppedLoop), for the cross-coupled
 * controller over two digital axes: output() is the encoder's reading the controller uses at
 * the current sample (what the coupling reads too), and advance(v) adds v volts to the axis
 * controller's output before the limit, as firmware adds its friction compensation (a PI's or
 * a PID's anti-windup acts on its own output; a pole-placement law under an anti-windup
 * remembers its own share of the clipped command); advance returns whether the command is at
 * the limit (|u| >= umax). Advanced with v = 0 throughout it is the batch run's, bit for bit.
 */
class SampledLoopStepper : public SteppedLoop {
public:
    /// The whole run (the encoder readings and the applied commands too), once every sample is
    /// recorded.
    virtual SampledDataRun takeRun() = 0;
};

/// simulateSampledPi's loop as a SampledLoopStepper (its inputs copied). Throws as it does.
std::unique_ptr<SampledLoopStepper> steppedSampledPi(const TransferFunction& plant,
                                                     const DigitalPi& pi,
                                                     const std::vector<double>& reference,
                                                     const SampledDataOptions& options,
                                                     double modelUnitsPerPositionUnit = 1.0);

/// simulateSampledServoPid's loop as a SampledLoopStepper. Throws as it does.
std::unique_ptr<SampledLoopStepper>
steppedSampledServoPid(const TransferFunction& plant, const ServoPidGains& gains, double tsSeconds,
                       const std::vector<MotionSample>& command, CommandDerivativeSource source,
                       const SampledDataOptions& options, double modelUnitsPerPositionUnit = 1.0);

/// simulateSampledRst's loop as a SampledLoopStepper; the ZPETC's preview samples before k = 0
/// run at construction, without coupling. Throws as it does.
std::unique_ptr<SampledLoopStepper> steppedSampledRst(const PolePlacementDesign& loop,
                                                      const ZpetcDesign* zpetc,
                                                      const std::vector<double>& r,
                                                      std::size_t samples,
                                                      const SampledDataOptions& options);

/**
 * The closed-loop poles (z-plane) of the linear sampled-data PI loop (no clipping, no
 * quantization) with @p delaySamples: the eigenvalues of its state matrix over
 * [x; I[k-1]; e[k-1]; the notch's s1, s2 when the PI has one; u[k-1] .. u[k-delay]].
 */
std::vector<std::complex<double>> sampledPiLoopPoles(const SampledPlant& plant, const DigitalPi& pi,
                                                     int delaySamples);

/// The closed-loop poles (z-plane) of the RST loop with @p delaySamples: roots of
/// A F + z^-delay B G (with delay 0 they are those of T and the cancelled factors).
std::vector<std::complex<double>> sampledRstLoopPoles(const PolePlacementDesign& loop,
                                                      int delaySamples);

/// The damping ratio of a z-plane pole through s = ln(z) / Ts: -Re s / |s| (1 for z near 0,
/// whose s is far left; negative outside the unit circle).
double zDampingRatio(std::complex<double> z);

/**
 * The warning when the digital loop is unstable, or much less damped (minimum damping ratio
 * below 0.8 times) than @p referenceMinDamping, the continuous design's (or, for a discrete
 * design, the loop without the delay). Poles within 1e-9 of z = 0 are left out. Coded
 * "digital_loop_unstable" or "digital_loop_less_damped" (diagnostic_catalogue.h).
 */
std::optional<Diagnostic>
digitalDampingWarning(const std::vector<std::complex<double>>& digitalPoles,
                      double referenceMinDamping, double tsSeconds);

/// A persistent oscillation at rest (peak-to-peak of the measured position in the last half of
/// the rest, and how many times it turned).
struct RestOscillation {
    double peakToPeak = 0.0;
    int turns = 0;
};

/**
 * A limit cycle at rest: from @p restStart (the first sample after the move) the last half of
 * the measured signal is split in two quarters; it is a limit cycle when the measured value
 * turns (changes direction) at least twice in each quarter and the second quarter's
 * peak-to-peak is at least half the first's (it is not decaying). Unset otherwise, or when the
 * rest holds fewer than 40 samples.
 */
std::optional<RestOscillation> restLimitCycle(const std::vector<double>& measured,
                                              std::size_t restStart);

} // namespace xyt
