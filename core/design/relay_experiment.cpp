// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/relay_experiment.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/number_format.h"
#include "core/model/state_space.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// x = [y, y', y''] (model units): the header's realization.
StateSpace relayRealization(const ThirdOrderPlant& plant) {
    StateSpace ss;
    ss.a = Eigen::MatrixXd::Zero(3, 3);
    ss.a(0, 1) = 1.0;
    ss.a(1, 2) = 1.0;
    ss.a(2, 1) = -plant.a2;
    ss.a(2, 2) = -plant.a1;
    ss.b = Eigen::MatrixXd::Zero(3, 1);
    ss.b(2, 0) = plant.k0;
    ss.c = Eigen::MatrixXd::Zero(1, 3);
    ss.c(0, 0) = 1.0;
    ss.d = Eigen::MatrixXd::Zero(1, 1);
    return ss;
}

/// Phi = e^{A t} and Gamma = int_0^t e^{A s} B ds (one matrix exponential, discretizeZoh).
struct RelayZohStep {
    Matrix3d phi;
    Vector3d gamma;
};

RelayZohStep relayZohStep(const StateSpace& ss, double tSeconds) {
    const StateSpace d = discretizeZoh(ss, tSeconds);
    return {d.a, d.b.col(0)};
}

void validateRelay(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit,
                   double relayAmplitudeVolts) {
    requirePositivePlant(plant);
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    requirePositive(relayAmplitudeVolts, "relay_amplitude");
}

/// Bisection on (lo, hi) to adjacent doubles: @p inUpper(s) tells whether s is at or past the
/// point sought (false at lo, true at hi). Returns the upper end, where inUpper holds.
template <class F> double bisectToAdjacent(double lo, double hi, F&& inUpper) {
    for (;;) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            return hi;
        (inUpper(mid) ? hi : lo) = mid;
    }
}

} // namespace

RelayLimitCycle relayLimitCycle(const ThirdOrderPlant& plant, double modelUnitsPerPositionUnit,
                                double relayAmplitudeVolts) {
    validateRelay(plant, modelUnitsPerPositionUnit, relayAmplitudeVolts);
    const double u = modelUnitsPerPositionUnit;
    const double d = relayAmplitudeVolts;
    const StateSpace ss = relayRealization(plant);
    RelayLimitCycle r;

    // x0 is proportional to d and the half period does not depend on it (the relay loop is
    // homogeneous): search with d = 1.
    const auto unitSwitchState = [&](double h) -> Vector3d {
        const RelayZohStep s = relayZohStep(ss, h);
        return -(Matrix3d::Identity() + s.phi).partialPivLu().solve(s.gamma);
    };
    const auto yAtSwitch = [&](double h) { return unitSwitchState(h)(0); };

    // Bracket: y(0) = C x0(h) > 0 below the root, < 0 above it. Each failed end moves the
    // other one (a lower end found negative is an upper end), so the bracket stays tight.
    const double hDf = kPi / std::sqrt(plant.a2);
    double lo = 0.5 * hDf, hi = 2.0 * hDf;
    for (int k = 0; k < 60 && !(yAtSwitch(lo) > 0.0); ++k) {
        hi = std::min(hi, lo);
        lo *= 0.5;
    }
    for (int k = 0; k < 60 && !(yAtSwitch(hi) < 0.0); ++k) {
        lo = std::max(lo, hi);
        hi *= 2.0;
    }
    if (!(yAtSwitch(lo) > 0.0 && yAtSwitch(hi) < 0.0)) {
        r.status =
            makeDiagnostic("design_relay_no_half_period", {formatNumber(lo), formatNumber(hi)});
        return r;
    }
    const double h = bisectToAdjacent(lo, hi, [&](double t) { return !(yAtSwitch(t) > 0.0); });
    const Vector3d x0 = unitSwitchState(h) * d;
    r.halfPeriodSeconds = h;
    r.periodSeconds = 2.0 * h;
    r.frequencyRadPerSec = kPi / h;
    r.switchState = {x0(0), x0(1), x0(2)};

    // The relay goes to +d because e = -y turns positive: y must be falling at t = 0 ...
    if (!(x0(1) < 0.0)) {
        r.status =
            makeDiagnostic("design_relay_not_falling", {formatNumber(h), formatNumber(x0(1) / u)});
        return r;
    }
    // ... and stay negative until t = h, or the relay would have switched earlier.
    constexpr int kGrid = 2000;
    const double dt = h / kGrid;
    const RelayZohStep grid = relayZohStep(ss, dt);
    std::vector<Vector3d> x(kGrid + 1);
    x[0] = x0;
    int kMin = 1;
    for (int k = 1; k <= kGrid; ++k) {
        x[std::size_t(k)] = grid.phi * x[std::size_t(k - 1)] + grid.gamma * d;
        if (k < kGrid && !(x[std::size_t(k)](0) < 0.0)) {
            r.status = makeDiagnostic("design_relay_early_crossing",
                                      {formatNumber(h), formatNumber(k * dt)});
            return r;
        }
        if (k < kGrid && x[std::size_t(k)](0) < x[std::size_t(kMin)](0))
            kMin = k;
    }
    // The peak: y' = 0 between the grid points on either side of the grid's minimum, where y'
    // goes from negative to positive. y is stationary there, so the bisection's last bit in t
    // costs nothing in y.
    const Vector3d& before = x[std::size_t(kMin - 1)];
    const auto stateAfter = [&](double tau) -> Vector3d {
        const RelayZohStep s = relayZohStep(ss, tau);
        return s.phi * before + s.gamma * d;
    };
    double yPeak = x[std::size_t(kMin)](0);
    double tPeak = kMin * dt;
    if (before(1) < 0.0 && x[std::size_t(kMin + 1)](1) > 0.0) {
        const double tau =
            bisectToAdjacent(0.0, 2.0 * dt, [&](double s) { return stateAfter(s)(1) >= 0.0; });
        const double y = stateAfter(tau)(0);
        if (y < yPeak) {
            yPeak = y;
            tPeak = (kMin - 1) * dt + tau;
        }
    }
    r.amplitudeMm = -yPeak / u;
    r.peakTimeSeconds = tPeak;
    r.ultimateGainVoltsPerMm = 4.0 * d / (kPi * r.amplitudeMm);
    r.found = true;
    return r;
}

RelayDescribingFunction relayDescribingFunction(const ThirdOrderPlant& plant,
                                                double modelUnitsPerPositionUnit,
                                                double relayAmplitudeVolts) {
    validateRelay(plant, modelUnitsPerPositionUnit, relayAmplitudeVolts);
    RelayDescribingFunction r;
    r.omega180RadPerSec = std::sqrt(plant.a2);
    r.periodSeconds = kTwoPi / r.omega180RadPerSec;
    r.amplitudeMm = 4.0 * relayAmplitudeVolts * plant.k0 / (kPi * plant.a1 * plant.a2) /
                    modelUnitsPerPositionUnit;
    r.ultimateGainVoltsPerMm = 4.0 * relayAmplitudeVolts / (kPi * r.amplitudeMm);
    return r;
}

RelaySimulation simulateRelayFeedback(const ThirdOrderPlant& plant,
                                      double modelUnitsPerPositionUnit, double relayAmplitudeVolts,
                                      const RelaySimulationOptions& options) {
    validateRelay(plant, modelUnitsPerPositionUnit, relayAmplitudeVolts);
    requireNonZero(options.initialOffsetMm, "initial_offset");
    requirePositive(options.durationSeconds, "duration");
    requirePositive(options.stepSeconds, "step");
    double stepCount = std::ceil(options.durationSeconds / options.stepSeconds);
    // The quotient can round up past an integer (0.07 / 0.01 = 7.000000000000001): no step that
    // would start at or after the end.
    if (stepCount > 1.0 && (stepCount - 1.0) * options.stepSeconds >= options.durationSeconds)
        stepCount -= 1.0;
    if (!(stepCount <= 2e6))
        throw InvalidInput(
            "step", makeDiagnostic("design_relay_too_many_steps",
                                   {formatNumber(options.stepSeconds), formatNumber(stepCount),
                                    formatNumber(options.durationSeconds)}));
    if (options.cyclesToMeasure < 1)
        throw InvalidInput("cycles_to_measure", makeDiagnostic("at_least", {"1"}));

    const double u = modelUnitsPerPositionUnit;
    const double d = relayAmplitudeVolts;
    const double step = options.stepSeconds;
    const StateSpace ss = relayRealization(plant);
    const RelayZohStep full = relayZohStep(ss, step);
    RelaySimulation sim;
    const double periodDf = kTwoPi / std::sqrt(plant.a2);
    if (step > periodDf / 50.0)
        sim.warnings.push_back(makeDiagnostic("design_relay_coarse_step",
                                              {formatNumber(step), formatNumber(periodDf)}));

    Vector3d x(options.initialOffsetMm * u, 0.0, 0.0); // at rest at the offset
    double relay = x(0) > 0.0 ? -d : d;                // u = d sign(-y)
    double t = 0.0;
    const auto record = [&] {
        sim.tSeconds.push_back(t);
        sim.yMm.push_back(x(0) / u);
        sim.uVolts.push_back(relay);
    };
    record();
    std::vector<double> upSwitches; // the switches to +d
    const long n = static_cast<long>(stepCount);
    for (long k = 1; k <= n; ++k) {
        const double tEnd = k == n ? options.durationSeconds : double(k) * step;
        bool whole = k < n; // a full step from a step boundary: the precomputed Phi, Gamma
        int switchesInStep = 0;
        while (t < tEnd) {
            const Vector3d from = x;
            const double driven = relay;
            const auto advance = [&](double tau) -> Vector3d {
                const RelayZohStep s = relayZohStep(ss, tau);
                return s.phi * from + s.gamma * driven;
            };
            const double tau = tEnd - t;
            Vector3d to = whole ? Vector3d(full.phi * from + full.gamma * driven) : advance(tau);
            whole = false;
            // y changed sign (e = -y now opposes u): the switch, found to adjacent doubles of
            // the sub-step; the state is taken just past it, so the new u agrees with e there.
            const bool crossed = driven * to(0) > 0.0;
            double tauEnd = tau;
            if (crossed) {
                tauEnd = bisectToAdjacent(0.0, tau,
                                          [&](double s) { return driven * advance(s)(0) > 0.0; });
                to = advance(tauEnd);
            }
            // An extremum of y on the way (y' changes sign strictly inside).
            if ((from(1) < 0.0 && to(1) >= 0.0) || (from(1) > 0.0 && to(1) <= 0.0)) {
                const bool rising = from(1) < 0.0;
                const double tp = bisectToAdjacent(0.0, tauEnd, [&](double s) {
                    const double yDot = advance(s)(1);
                    return rising ? yDot >= 0.0 : yDot <= 0.0;
                });
                sim.peakTimesSeconds.push_back(t + tp);
                sim.peakValuesMm.push_back(advance(tp)(0) / u);
            }
            t += tauEnd;
            x = to;
            if (crossed) {
                record();
                relay = -relay;
                record();
                sim.switchTimesSeconds.push_back(t);
                if (relay > 0.0)
                    upSwitches.push_back(t);
                if (++switchesInStep > 64) {
                    sim.warnings.push_back(
                        makeDiagnostic("design_relay_chattering", {formatNumber(t)}));
                    k = n;
                    break;
                }
            }
        }
        record();
    }

    const std::size_t ups = upSwitches.size();
    if (ups < 2) {
        sim.warnings.push_back(makeDiagnostic("design_relay_too_few_switches",
                                              {formatNumber(options.durationSeconds)}));
        return sim;
    }
    const std::size_t cycles = std::min<std::size_t>(std::size_t(options.cyclesToMeasure), ups - 1);
    const double first = upSwitches[ups - 1 - cycles];
    const double last = upSwitches[ups - 1];
    sim.cyclesMeasured = static_cast<int>(cycles);
    sim.measuredPeriodSeconds = (last - first) / double(cycles);
    double amplitude = 0.0;
    for (std::size_t i = 0; i < sim.peakTimesSeconds.size(); ++i)
        if (sim.peakTimesSeconds[i] >= first && sim.peakTimesSeconds[i] <= last)
            amplitude = std::max(amplitude, std::abs(sim.peakValuesMm[i]));
    sim.measuredAmplitudeMm = amplitude;
    return sim;
}

std::string ultimateCycleRuleName(UltimateCycleRule rule) {
    return rule == UltimateCycleRule::ZieglerNichols ? "Ziegler-Nichols" : "Tyreus-Luyben";
}

UltimateCycleGains ultimateCycleGains(double ultimateGainVoltsPerMm, double ultimatePeriodSeconds,
                                      UltimateCycleRule rule, PidStructure structure) {
    requirePositive(ultimateGainVoltsPerMm, "ultimate_gain");
    requirePositive(ultimatePeriodSeconds, "ultimate_period");
    const double ku = ultimateGainVoltsPerMm;
    const double tu = ultimatePeriodSeconds;
    UltimateCycleGains g;
    const bool pid = structure == PidStructure::Pid;
    if (rule == UltimateCycleRule::ZieglerNichols) {
        g.p = pid ? 0.6 * ku : 0.45 * ku;
        g.tiSeconds = pid ? tu / 2.0 : tu / 1.2;
        g.tdSeconds = pid ? tu / 8.0 : 0.0;
    } else {
        g.p = pid ? ku / 2.2 : ku / 3.2;
        g.tiSeconds = 2.2 * tu;
        g.tdSeconds = pid ? tu / 6.3 : 0.0;
    }
    g.i = g.p / g.tiSeconds;
    g.d = g.p * g.tdSeconds;
    return g;
}

} // namespace xyt
