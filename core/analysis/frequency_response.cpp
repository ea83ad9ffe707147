// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/frequency_response.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace xyt {

namespace {

/// Relative residual below which z = 1 counts as a root of a discrete polynomial: integrators
/// typed as (z - 1) products evaluate to round-off there, a genuine root at 1 - 1e-10 is an
/// integrator for every frequency a plot can show.
constexpr double kUnitRootTolerance = 1e-10;

} // namespace

int splitLowFrequencyRoots(const Polynomial& p, bool discrete, Polynomial& rest) {
    rest = p;
    if (p.isZero())
        return 0;
    int k = 0;
    if (!discrete) {
        const auto& c = p.ascending();
        while (k < p.degree() && c[static_cast<std::size_t>(k)] == 0.0)
            ++k;
        rest = Polynomial::fromAscending(std::vector<double>(c.begin() + k, c.end()));
        return k;
    }
    const Polynomial unitRoot = Polynomial::fromAscending({-1.0, 1.0});
    while (rest.degree() >= 1) {
        double size = 0.0;
        for (double v : rest.ascending())
            size += std::abs(v);
        if (std::abs(rest(1.0)) > kUnitRootTolerance * size)
            break;
        Polynomial q, r;
        Polynomial::divide(rest, unitRoot, q, r);
        rest = q;
        ++k;
    }
    return k;
}

namespace {

/// Angle of (j omega - r), continuous in omega on [0, inf) unless r is on the axis.
double continuousFactorAngle(double omega, std::complex<double> r) {
    const double y = omega - r.imag();
    if (r.real() < 0.0)
        return std::atan2(y, -r.real());
    if (r.real() > 0.0)
        return kPi - std::atan(y / r.real());
    return y > 0.0 ? kPi / 2 : (y < 0.0 ? -kPi / 2 : 0.0);
}

/// Angle of (e^{j theta} - r), continuous in theta on [0, pi] unless |r| = 1: for |r| <= 1 it is
/// theta + arg(1 - r e^{-j theta}) (that factor has a positive real part), for |r| > 1 it is
/// arg(-r) + arg(1 - e^{j theta}/r) (likewise).
double discreteFactorAngle(double theta, std::complex<double> r) {
    const std::complex<double> e = std::polar(1.0, theta);
    if (std::abs(r) <= 1.0) {
        const std::complex<double> w = 1.0 - r * std::conj(e);
        return theta + std::atan2(w.imag(), w.real());
    }
    const std::complex<double> w = 1.0 - e / r;
    return std::arg(-r) + std::atan2(w.imag(), w.real());
}

/// The poles, then the zeros (none for G = 0).
std::vector<std::complex<double>> polesAndZeros(const TransferFunction& g) {
    std::vector<std::complex<double>> roots;
    if (g.den().degree() > 0)
        roots = g.den().roots();
    if (!g.num().isZero() && g.num().degree() > 0) {
        const auto z = g.num().roots();
        roots.insert(roots.end(), z.begin(), z.end());
    }
    return roots;
}

void requireFrequency(double omega, double tsSeconds) {
    requireFinite(omega, "omega");
    if (omega < 0.0)
        throw InvalidInput("omega", makeDiagnostic("analysis_frequencies_not_negative"));
    if (tsSeconds > 0.0 && omega > (kPi / tsSeconds) * (1.0 + 1e-12))
        throw InvalidInput("omega", makeDiagnostic("analysis_above_nyquist_discrete"));
}

} // namespace

std::complex<double> boundaryPoint(double omegaRadPerSec, double tsSeconds) {
    if (tsSeconds > 0.0)
        return std::polar(1.0, omegaRadPerSec * tsSeconds);
    return {0.0, omegaRadPerSec};
}

ContinuousPhase::ContinuousPhase(const TransferFunction& g) : ts_(g.tsSeconds()) {
    const bool discrete = g.isDiscrete();
    if (g.num().isZero())
        return; // G = 0: no phase; phaseRad returns 0
    Polynomial numRest, denRest;
    const int numLow = splitLowFrequencyRoots(g.num(), discrete, numRest);
    const int denLow = splitLowFrequencyRoots(g.den(), discrete, denRest);
    integrators_ = denLow - numLow;
    if (numRest.degree() > 0)
        zeros_ = numRest.roots();
    if (denRest.degree() > 0)
        poles_ = denRest.roots();
    // Both rests keep the leading coefficients of N and D.
    constantRad_ = (numRest.leading() / denRest.leading() < 0.0) ? kPi : 0.0;
    const double x0 = discrete ? 1.0 : 0.0;
    const double c = numRest(x0) / denRest(x0);
    const double target = -integrators_ * kPi / 2 - ((c < 0.0) ? kPi : 0.0);
    offsetRad_ = 2 * kPi * std::round((target - factorSum(0.0)) / (2 * kPi));
}

double ContinuousPhase::factorSum(double omega) const {
    double sum = constantRad_;
    if (ts_ > 0.0) {
        const double theta = omega * ts_;
        for (const auto& z : zeros_)
            sum += discreteFactorAngle(theta, z);
        for (const auto& p : poles_)
            sum -= discreteFactorAngle(theta, p);
        sum -= integrators_ * (theta + kPi) / 2; // arg(e^{j theta} - 1) on (0, 2 pi)
    } else {
        for (const auto& z : zeros_)
            sum += continuousFactorAngle(omega, z);
        for (const auto& p : poles_)
            sum -= continuousFactorAngle(omega, p);
        sum -= integrators_ * kPi / 2;
    }
    return sum;
}

double ContinuousPhase::phaseRad(double omegaRadPerSec, std::complex<double> value) const {
    const double reference = factorSum(omegaRadPerSec) + offsetRad_;
    const double magnitude = std::abs(value);
    if (!(magnitude > 0.0) || !std::isfinite(magnitude))
        return reference;
    const double principal = std::arg(value);
    return principal + 2 * kPi * std::round((reference - principal) / (2 * kPi));
}

FrequencyResponse frequencyResponse(const TransferFunction& g,
                                    const std::vector<double>& omegaRadPerSec) {
    for (const double w : omegaRadPerSec)
        requireFrequency(w, g.tsSeconds());
    const ContinuousPhase phase(g);
    FrequencyResponse out;
    out.tsSeconds = g.tsSeconds();
    out.lowFrequencyIntegrators = phase.lowFrequencyIntegrators();
    out.omegaRadPerSec = omegaRadPerSec;
    const std::size_t n = omegaRadPerSec.size();
    out.value.resize(n);
    out.magnitudeDb.resize(n);
    out.phaseDeg.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double w = omegaRadPerSec[i];
        const std::complex<double> v = g.frequencyResponse(w);
        out.value[i] = v;
        out.magnitudeDb[i] = 20.0 * std::log10(std::abs(v));
        out.phaseDeg[i] = phase.phaseRad(w, v) * 180.0 / kPi;
    }
    return out;
}

std::vector<double> logFrequencyGrid(double omegaMin, double omegaMax, int points) {
    requirePositive(omegaMin, "omegaMin");
    requirePositive(omegaMax, "omegaMax");
    if (!(omegaMin < omegaMax))
        throw InvalidInput("omegaMax", makeDiagnostic("analysis_above_omega_min"));
    if (points < 2)
        throw InvalidInput("points", makeDiagnostic("at_least", {"2"}));
    std::vector<double> w(static_cast<std::size_t>(points));
    const double a = std::log10(omegaMin), b = std::log10(omegaMax);
    for (int i = 0; i < points; ++i)
        w[static_cast<std::size_t>(i)] = std::pow(10.0, a + (b - a) * i / (points - 1.0));
    w.front() = omegaMin;
    w.back() = omegaMax;
    return w;
}

std::vector<double> characteristicFrequencies(const TransferFunction& g) {
    const std::vector<std::complex<double>> roots = polesAndZeros(g);
    std::vector<double> f;
    for (const auto& r : roots) {
        if (r == 0.0)
            continue;
        const double w = g.isDiscrete() ? std::abs(std::log(r)) / g.tsSeconds() : std::abs(r);
        if (w > 0.0 && std::isfinite(w))
            f.push_back(w);
    }
    std::sort(f.begin(), f.end());
    return f;
}

FrequencyResponse adaptiveFrequencyResponse(const TransferFunction& g,
                                            const FrequencyGridOptions& options) {
    if (!(options.pointsPerDecade >= 1))
        throw InvalidInput("pointsPerDecade", makeDiagnostic("at_least", {"1"}));
    if (!(options.maxMagnitudeStepDb > 0.0) || !std::isfinite(options.maxMagnitudeStepDb))
        throw InvalidInput("maxMagnitudeStepDb", makeDiagnostic("analysis_finite_above_zero"));
    if (!(options.maxPhaseStepDeg > 0.0) || !std::isfinite(options.maxPhaseStepDeg))
        throw InvalidInput("maxPhaseStepDeg", makeDiagnostic("analysis_finite_above_zero"));
    if (!(options.minFrequencyRatio > 1.0) || !std::isfinite(options.minFrequencyRatio))
        throw InvalidInput("minFrequencyRatio", makeDiagnostic("analysis_finite_above_one"));
    if (options.maxPoints < 2)
        throw InvalidInput("maxPoints", makeDiagnostic("at_least", {"2"}));
    const double ts = g.tsSeconds();
    const double nyquist = ts > 0.0 ? kPi / ts : std::numeric_limits<double>::infinity();

    // The range: whole decades around the characteristic frequencies.
    std::vector<double> f;
    for (double w : characteristicFrequencies(g))
        if (w <= nyquist)
            f.push_back(w);
    double lo = 0.1, hi = 10.0;
    if (!f.empty()) {
        lo = std::pow(10.0, std::floor(std::log10(f.front())) - 1.0);
        hi = std::pow(10.0, std::ceil(std::log10(f.back())) + 1.0);
    }
    if (ts > 0.0) {
        hi = nyquist;
        lo = std::min(lo, 1e-2 * nyquist);
    }
    if (options.omegaMinRadPerSec != 0.0) {
        requirePositive(options.omegaMinRadPerSec, "omegaMin");
        lo = options.omegaMinRadPerSec;
    }
    if (options.omegaMaxRadPerSec != 0.0) {
        requirePositive(options.omegaMaxRadPerSec, "omegaMax");
        if (options.omegaMaxRadPerSec > nyquist * (1.0 + 1e-12))
            throw InvalidInput("omegaMax", makeDiagnostic("analysis_above_nyquist"));
        hi = std::min(options.omegaMaxRadPerSec, nyquist);
    }
    if (!(lo < hi))
        throw InvalidInput("omegaMax", makeDiagnostic("analysis_above_omega_min"));

    const double decades = std::log10(hi / lo);
    const int start =
        std::max(2, static_cast<int>(std::ceil(decades * options.pointsPerDecade)) + 1);
    std::vector<double> grid = logFrequencyGrid(lo, hi, std::min(start, options.maxPoints));

    // Seeds: the natural frequency of each pole and zero, and for a lightly damped one the
    // half-power points omega_n (1 -+ zeta) of its peak or notch.
    const std::vector<std::complex<double>> roots = polesAndZeros(g);
    std::vector<double> seeds = options.extraFrequencies;
    for (const auto& r : roots) {
        if (r == 0.0)
            continue;
        const std::complex<double> s = ts > 0.0 ? std::log(r) / ts : r;
        const double wn = std::abs(s);
        if (!(wn > 0.0) || !std::isfinite(wn))
            continue;
        seeds.push_back(wn);
        const double zeta = std::abs(s.real()) / wn;
        if (zeta < 0.5) {
            seeds.push_back(wn * (1.0 - zeta));
            seeds.push_back(wn * (1.0 + zeta));
        }
    }
    for (double w : seeds)
        if (std::isfinite(w) && w > lo && w < hi &&
            static_cast<int>(grid.size()) < options.maxPoints)
            grid.push_back(w);
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end(),
                           [&](double a, double b) { return b < a * options.minFrequencyRatio; }),
               grid.end());

    FrequencyResponse out = frequencyResponse(g, grid);
    const ContinuousPhase phase(g);
    const double maxDb = options.maxMagnitudeStepDb;
    const double maxPhase = options.maxPhaseStepDeg;
    auto needsSplit = [&](std::size_t i) {
        const double a = out.omegaRadPerSec[i], b = out.omegaRadPerSec[i + 1];
        if (!(b > a * options.minFrequencyRatio))
            return false;
        const double dDb = out.magnitudeDb[i + 1] - out.magnitudeDb[i];
        const double dPhase = out.phaseDeg[i + 1] - out.phaseDeg[i];
        return !(std::abs(dDb) <= maxDb) || !(std::abs(dPhase) <= maxPhase);
    };
    FrequencyResponse next;
    next.tsSeconds = out.tsSeconds;
    next.lowFrequencyIntegrators = out.lowFrequencyIntegrators;
    for (;;) {
        const std::size_t n = out.omegaRadPerSec.size();
        std::size_t total = n;
        bool inserted = false;
        next.omegaRadPerSec.clear();
        next.value.clear();
        next.magnitudeDb.clear();
        next.phaseDeg.clear();
        for (std::size_t i = 0; i < n; ++i) {
            next.omegaRadPerSec.push_back(out.omegaRadPerSec[i]);
            next.value.push_back(out.value[i]);
            next.magnitudeDb.push_back(out.magnitudeDb[i]);
            next.phaseDeg.push_back(out.phaseDeg[i]);
            if (i + 1 < n && total < static_cast<std::size_t>(options.maxPoints) && needsSplit(i)) {
                const double w = std::sqrt(out.omegaRadPerSec[i] * out.omegaRadPerSec[i + 1]);
                const std::complex<double> v = g.frequencyResponse(w);
                next.omegaRadPerSec.push_back(w);
                next.value.push_back(v);
                next.magnitudeDb.push_back(20.0 * std::log10(std::abs(v)));
                next.phaseDeg.push_back(phase.phaseRad(w, v) * 180.0 / kPi);
                ++total;
                inserted = true;
            }
        }
        std::swap(out, next);
        if (!inserted)
            break;
    }
    return out;
}

} // namespace xyt
