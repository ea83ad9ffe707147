// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/pid_tuning.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"
#include "core/model/polynomial.h"

#include <cmath>
#include <complex>

namespace xyt {

namespace {

constexpr double kDegPerRad = 180.0 / kPi;

/// L(j omega) = C(j omega) G(j omega) / u for the LinuxCNC gains (position in mm).
std::complex<double> loopAt(const ThirdOrderPlant& plant, double u, double p, double i, double d,
                            double omega) {
    const std::complex<double> jw(0.0, omega);
    const std::complex<double> c(p, d * omega - i / omega);
    const std::complex<double> g = plant.k0 / (jw * (plant.a2 - omega * omega + plant.a1 * jw));
    return c * g / u;
}

/// 180 + arg L in degrees, wrapped to (-180, 180] (std::arg is in (-180, 180]).
double phaseMarginDegOf(std::complex<double> l) {
    const double pm = 180.0 + std::arg(l) * kDegPerRad;
    return pm > 180.0 ? pm - 360.0 : pm;
}

/// Routh-Hurwitz for monic s^4 + b1 s^3 + b2 s^2 + b3 s + b4 (b4 > 0) or, when b4 == 0 (a PI
/// whose I vanished: the controller's pole at 0 cancels its zero there), the cubic
/// s^3 + b1 s^2 + b2 s + b3 that remains.
bool hurwitz(double b1, double b2, double b3, double b4) {
    if (b4 == 0.0)
        return b1 > 0.0 && b2 > 0.0 && b3 > 0.0 && b1 * b2 > b3;
    return b1 > 0.0 && b2 > 0.0 && b3 > 0.0 && b4 > 0.0 && b1 * b2 > b3 &&
           b1 * b2 * b3 > b3 * b3 + b1 * b1 * b4;
}

} // namespace

void requirePositivePlant(const ThirdOrderPlant& plant) {
    requirePositive(plant.k0, "k0");
    requirePositive(plant.a1, "a1");
    requirePositive(plant.a2, "a2");
}

std::string pidStructureName(PidStructure structure) {
    return structure == PidStructure::Pi ? "PI" : "PID";
}

PidTuningResult tunePidForMargin(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit,
                                 PidStructure structure, double crossoverRadPerSec,
                                 double phaseMarginDeg) {
    requirePositivePlant(plant);
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    requirePositive(crossoverRadPerSec, "crossover");
    requirePositive(phaseMarginDeg, "phase_margin");
    const double u = modelUnitsPerPositionUnit;
    const double wc = crossoverRadPerSec;

    PidTuningResult r;
    r.structure = structure;
    r.targetCrossoverRadPerSec = wc;
    r.targetPhaseMarginDeg = phaseMarginDeg;

    // G(j w) = k0 / (j w (a2 - w^2 + j a1 w)): with a1, a2 > 0 the quadratic factor's phase
    // atan2(a1 w, a2 - w^2) runs continuously over (0, 180) degrees, so arg G is in (-270, -90)
    // without unwrapping. In the dimensionless alpha1 = a1/wc, alpha2 = a2/wc^2 nothing
    // overflows before the gains themselves do.
    const double alpha1 = plant.a1 / wc;
    const double alpha2 = plant.a2 / (wc * wc);
    const double quadPhase = std::atan2(alpha1, alpha2 - 1.0);
    const double quadMag = std::hypot(alpha2 - 1.0, alpha1); // |a2 - wc^2 + j a1 wc| / wc^2
    r.plantPhaseDeg = -90.0 - quadPhase * kDegPerRad;
    const double phiC = phaseMarginDeg / kDegPerRad - kPi / 2.0 + quadPhase;
    r.requiredControllerPhaseDeg = phiC * kDegPerRad;
    // |C(j wc)| = u / |G(j wc)| = u wc^3 quadMag / k0.
    const double gainC = u * wc * wc * wc * quadMag / plant.k0;
    r.requiredControllerGainVoltsPerMm = gainC;

    const auto refuse = [&](PidTuningStatus status, const Diagnostic& why) {
        r.status = status;
        r.reason = why;
        return r;
    };
    // The crossover, the plant phase, the phase margin and the controller phase each refusal
    // names (its " at %1 rad/s (plant phase %2 deg, ...)").
    const std::vector<Diagnostic> where = {formatNumber(wc), formatNumber(r.plantPhaseDeg, 4),
                                           formatNumber(phaseMarginDeg, 4),
                                           formatNumber(r.requiredControllerPhaseDeg, 4)};
    if (structure == PidStructure::Pi) {
        if (!(phiC > -kPi / 2.0 && phiC <= 0.0))
            return refuse(PidTuningStatus::PhaseOutOfReach,
                          makeDiagnostic(phiC > 0.0 ? "design_pid_pi_phase_too_high"
                                                    : "design_pid_pi_phase_too_low",
                                         where));
        r.p = gainC * std::cos(phiC);
        r.i = r.p * wc * std::tan(-phiC);
        r.d = 0.0;
        r.tiSeconds = r.i > 0.0 ? r.p / r.i : kInf;
        r.tdSeconds = 0.0;
    } else {
        if (!(phiC > -kPi / 2.0 && phiC < kPi / 2.0))
            return refuse(PidTuningStatus::PhaseOutOfReach,
                          makeDiagnostic("design_pid_phase_out_of_reach", where));
        // tau = wc Td, the positive root of 4 tau^2 - 4 tau tan(phi) - 1 = 0:
        // (tan phi + sec phi)/2 = (1 + sin phi)/(2 cos phi) = tan(pi/4 + phi/2)/2.
        const double tau = 0.5 * std::tan(kPi / 4.0 + phiC / 2.0);
        r.tdSeconds = tau / wc;
        r.tiSeconds = 4.0 * r.tdSeconds;
        r.p = gainC * std::cos(phiC);
        r.i = r.p / r.tiSeconds;
        r.d = r.p * r.tdSeconds;
    }
    if (!std::isfinite(gainC) || !std::isfinite(r.p) || !std::isfinite(r.i) ||
        !std::isfinite(r.d) || !(r.p > 0.0) || !std::isfinite(r.tdSeconds)) {
        std::vector<Diagnostic> args = {formatNumber(r.p), formatNumber(r.i), formatNumber(r.d)};
        args.insert(args.end(), where.begin(), where.end());
        const Diagnostic why = makeDiagnostic("design_pid_gains_out_of_range", args);
        r.p = r.i = r.d = 0.0;
        r.tiSeconds = kInf;
        r.tdSeconds = 0.0;
        return refuse(PidTuningStatus::GainsOutOfRange, why);
    }

    // Check back from the gains. In v = (w/wc)^2, with g = k0/(u wc^3) the plant's scale,
    // gamma0 = g I/wc, gamma1 = g P, gamma2 = g D wc (g |C(j wc)| = quadMag, so each is a
    // dimensionless multiple of quadMag):
    //   |L|^2 = 1  <=>  (gamma0 - gamma2 v)^2 + gamma1^2 v = v^2 ((alpha2 - v)^2 + alpha1^2 v),
    //   closed loop: sigma^4 + alpha1 sigma^3 + (alpha2 + gamma2) sigma^2 + gamma1 sigma + gamma0
    //   (s = wc sigma).
    const double gamma0 = r.i / (wc * gainC) * quadMag;
    const double gamma1 = r.p / gainC * quadMag;
    const double gamma2 = r.d * wc / gainC * quadMag;
    const Polynomial crossing = Polynomial::fromAscending(
        {gamma0 * gamma0, gamma1 * gamma1 - 2.0 * gamma0 * gamma2,
         gamma2 * gamma2 - alpha2 * alpha2, 2.0 * alpha2 - alpha1 * alpha1, -1.0});
    double bestDistance = kInf;
    for (const std::complex<double> v : crossing.roots()) {
        // A real root comes out of the companion matrix with an imaginary part of round-off
        // size (sqrt(eps) for a double root, a tangency of |L| to 1); 1e-6 keeps those.
        if (!(v.real() > 0.0) || std::abs(v.imag()) > 1e-6 * std::abs(v))
            continue;
        ++r.gainCrossoverCount;
        const double distance = std::abs(std::log(v.real()));
        if (distance < bestDistance) {
            bestDistance = distance;
            r.achievedCrossoverRadPerSec = wc * std::sqrt(v.real());
        }
    }
    if (r.gainCrossoverCount > 0)
        r.achievedPhaseMarginDeg =
            phaseMarginDegOf(loopAt(plant, u, r.p, r.i, r.d, r.achievedCrossoverRadPerSec));
    if (r.gainCrossoverCount > 1)
        r.warnings.push_back(makeDiagnostic("design_pid_several_crossovers",
                                            {std::to_string(r.gainCrossoverCount)}));
    r.closedLoopStable = hurwitz(alpha1, alpha2 + gamma2, gamma1, gamma0);
    if (!r.closedLoopStable)
        r.warnings.push_back(makeDiagnostic("design_pid_conditionally_stable"));
    return r;
}

} // namespace xyt
