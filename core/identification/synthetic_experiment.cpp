// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/synthetic_experiment.h"

#include "core/identification/continuous_fit.h"
#include "core/identification/validation.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/normal_draws.h"
#include "core/model/number_format.h"

#include <cmath>
#include <random>

namespace xyt {

namespace {

/// Adds N(0, sigma^2) noise to y, sample by sample (Box-Muller, the cosine branch only).
void addNoise(std::vector<double>& y, double sigma, std::uint64_t seed) {
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
        throw InvalidInput("noise_std", makeDiagnostic("ident_noise_std"));
    if (sigma == 0.0)
        return;
    std::mt19937_64 rng(seed);
    for (double& v : y)
        v += sigma * standardNormal(rng);
}

std::string noiseText(double sigma, std::uint64_t seed) {
    return sigma > 0.0 ? ", white Gaussian measurement noise " + formatNumber(sigma) +
                             " mm rms, seed " + std::to_string(seed)
                       : ", no noise";
}

} // namespace

ExcitationSignal simulateExperiment(ExcitationSignal command, const ThirdOrderPlant& plantMm,
                                    double noiseStdMm, std::uint64_t seed) {
    command.y = simulateThirdOrderPlant(plantMm, command.u, command.tsSeconds);
    addNoise(command.y, noiseStdMm, seed);
    command.description =
        "SYNTHETIC experiment (simulated by XY Tune, not measured): " + command.description +
        " into k0/(s^3+a1 s^2+a2 s) with k0 = " + formatNumber(plantMm.k0) +
        " mm/(V s^3), a1 = " + formatNumber(plantMm.a1) + ", a2 = " + formatNumber(plantMm.a2) +
        noiseText(noiseStdMm, seed);
    return command;
}

ExcitationSignal simulateExperiment(ExcitationSignal command, const PolynomialModel& model,
                                    double noiseStdMm, std::uint64_t seed) {
    model.validate();
    if (!(std::abs(model.tsSeconds - command.tsSeconds) <= 1e-9 * command.tsSeconds))
        throw InvalidInput(
            "ts", makeDiagnostic("ident_synthetic_sample_time",
                                 {formatNumber(command.tsSeconds), formatNumber(model.tsSeconds)}));
    command.y = simulateModel(model, command.u);
    addNoise(command.y, noiseStdMm, seed);
    std::string a, b;
    for (double v : model.inputDenominator())
        a += (a.empty() ? "" : ", ") + formatNumber(v);
    for (double v : model.b)
        b += (b.empty() ? "" : ", ") + formatNumber(v);
    command.description =
        "SYNTHETIC experiment (simulated by XY Tune, not measured): " + command.description +
        " into B/A with A = [" + a + "], B = [" + b + "] (ascending z^-1, Ts " +
        formatNumber(model.tsSeconds) + " s)" + noiseText(noiseStdMm, seed);
    return command;
}

} // namespace xyt
