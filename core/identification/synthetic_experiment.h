// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/guillemin_truxal.h"
#include "core/identification/excitation.h"
#include "core/identification/polynomial_model.h"

#include <cstdint>

namespace xyt {

/**
 * A synthetic logged experiment (the examples, teaching): the open-loop response of an
 * axis model to @p command, y[k] at k Ts from rest at 0, plus white Gaussian measurement noise of
 * standard deviation @p noiseStdMm (Box-Muller on 53-bit uniforms of std::mt19937_64 seeded with
 * @p seed, one normal draw per sample in order: the same file on every machine and library).
 * The description says it is synthetic and names the model, noise and seed.
 *  - plantMm: Braga et al.'s k0 / (s^3 + a1 s^2 + a2 s) with y in mm (k0 in mm / (V s^3)),
 *    simulated exactly under the zero-order-held command (simulateThirdOrderPlant);
 *  - model: a z^-1 polynomial model (y in mm) whose sample time must be the command's.
 * @throws InvalidInput "noise_std" (< 0 or not finite), "ts" (the model's Ts differs from the
 *         command's by more than 1e-9 relative), and from the model.
 */
ExcitationSignal simulateExperiment(ExcitationSignal command, const ThirdOrderPlant& plantMm,
                                    double noiseStdMm, std::uint64_t seed);
ExcitationSignal simulateExperiment(ExcitationSignal command, const PolynomialModel& model,
                                    double noiseStdMm, std::uint64_t seed);

} // namespace xyt
