// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/stability_margins.h"

#include "core/analysis/frequency_response.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

namespace xyt {

namespace {

using Complex = std::complex<double>;

/// A root u of a real polynomial counts as real when |Im u| <= this * |u|. Loose on purpose:
/// a tangency (double root) comes out of the companion matrix with an imaginary part of about
/// sqrt(eps) |u|; false candidates are removed after refinement by the residual check.
constexpr double kRealRootTolerance = 1e-6;
/// A refined crossing is accepted when its residual (log|L| or arg(-L), radians) is below this.
constexpr double kCrossingResidual = 1e-7;
/// A closed-loop root this close to the boundary (relative) puts a pole on it: Ms = Mt = inf.
constexpr double kBoundaryTolerance = 1e-9;

/// P(j omega) = E(u) + j omega O(u), u = omega^2.
struct EvenOdd {
    Polynomial e, o;
};

EvenOdd evenOdd(const Polynomial& p) {
    const auto& c = p.ascending();
    std::vector<double> e(c.size() / 2 + 1, 0.0), o(c.size() / 2 + 1, 0.0);
    for (std::size_t k = 0; k < c.size(); ++k) {
        const std::size_t half = k / 2;
        const double sign = (half % 2 == 0) ? 1.0 : -1.0; // j^k = (-1)^(k/2) (times j if odd)
        (k % 2 == 0 ? e : o)[half] = sign * c[k];
    }
    return {Polynomial::fromAscending(std::move(e)), Polynomial::fromAscending(std::move(o))};
}

/// |P(j omega)|^2 = E^2 + u O^2.
Polynomial squaredMagnitude(const EvenOdd& p) {
    return p.e * p.e + Polynomial::identity() * (p.o * p.o);
}

/// The positive real roots of p (see kRealRootTolerance), unsorted. Leading coefficients below
/// 1e-12 of the largest are dropped first: the polynomials here are differences whose top
/// terms cancel analytically (A'B - AB' for deg A = deg B, |N|^2 - |D|^2 for a biproper L), and
/// the round-off left there would put a spurious root near infinity and spoil the
/// companion-matrix accuracy of the others (seen: a peak of |S| missed). The variable is scaled
/// to the loop's frequencies, so a genuine root is not that far out; the end of the axis is
/// checked separately.
std::vector<double> positiveRealRoots(const Polynomial& p) {
    std::vector<double> out;
    if (p.isZero() || p.degree() < 1)
        return out;
    std::vector<double> c = p.ascending();
    const double size = p.maxAbsCoefficient();
    while (c.size() > 1 && std::abs(c.back()) <= 1e-12 * size)
        c.pop_back();
    const Polynomial trimmed = Polynomial::fromAscending(std::move(c));
    if (trimmed.degree() < 1)
        return out;
    for (const Complex& r : trimmed.roots())
        if (r.real() > 0.0 && std::abs(r.imag()) <= kRealRootTolerance * std::abs(r))
            out.push_back(r.real());
    return out;
}

/// The loop in its own domain (s, or z on the unit circle), for evaluation and refinement.
struct Loop {
    Polynomial n, d, c; ///< N, D and the closed-loop characteristic D + N
    Polynomial dn, dd, dc;
    double ts = 0.0;

    double nyquist() const { return ts > 0.0 ? kPi / ts : kInf; }
    Complex x(double w) const { return boundaryPoint(w, ts); }
    /// dx/domega.
    Complex dx(double w) const { return ts > 0.0 ? Complex(0.0, ts) * x(w) : Complex(0.0, 1.0); }
    Complex value(double w) const { return n(x(w)) / d(x(w)); }
    /// d/domega of log P(x(omega)).
    Complex dlog(const Polynomial& p, const Polynomial& dp, double w) const {
        return dp(x(w)) / p(x(w)) * dx(w);
    }
};

/// Newton steps on f(omega) = 0 (f returns the residual and its derivative), kept while |f|
/// decreases and omega stays in (0, nyquist]. Returns the refined frequency and residual.
std::pair<double, double> refine(double w, const Loop& loop,
                                 const std::function<std::pair<double, double>(double)>& f) {
    auto [r, slope] = f(w);
    for (int step = 0; step < 12 && std::abs(r) > 0.0; ++step) {
        if (!(std::abs(slope) > 0.0) || !std::isfinite(slope))
            break;
        const double candidate = w - r / slope;
        if (!(candidate > 0.0) || candidate > loop.nyquist())
            break;
        const auto [rc, sc] = f(candidate);
        if (!(std::abs(rc) < std::abs(r)))
            break;
        w = candidate;
        r = rc;
        slope = sc;
    }
    return {w, r};
}

/// Geometric mean of the root moduli of a and b, rounded to a power of two (1 if none). Roots
/// below 1e-6 of the largest are left out: an integrator of a discrete loop maps to a root
/// w ~ 1e-17 (round-off of D(1)), which would drag the scale down and the scaled coefficients
/// out of range.
double frequencyScale(const Polynomial& a, const Polynomial& b) {
    std::vector<double> moduli;
    for (const Polynomial* p : {&a, &b}) {
        if (p->isZero() || p->degree() < 1)
            continue;
        for (const Complex& r : p->roots())
            if (std::isfinite(std::abs(r)))
                moduli.push_back(std::abs(r));
    }
    const double largest = moduli.empty() ? 0.0 : *std::max_element(moduli.begin(), moduli.end());
    double logSum = 0.0;
    int count = 0;
    for (const double m : moduli)
        if (m > 1e-6 * largest) {
            logSum += std::log2(m);
            ++count;
        }
    if (count == 0)
        return 1.0;
    return std::exp2(std::round(logSum / count));
}

void sortAndDedupe(std::vector<double>& w) {
    std::sort(w.begin(), w.end());
    w.erase(std::unique(w.begin(), w.end(),
                        [](double a, double b) { return std::abs(b - a) <= 1e-9 * std::abs(b); }),
            w.end());
}

} // namespace

Polynomial bilinearToW(const Polynomial& p, int n) {
    if (n < p.degree())
        throw InvalidInput("n", makeDiagnostic("analysis_below_degree"));
    const Polynomial plus = Polynomial::fromAscending({1.0, 1.0});
    const Polynomial minus = Polynomial::fromAscending({1.0, -1.0});
    // Powers of (1 + w) and (1 - w) built once.
    std::vector<Polynomial> plusPow(static_cast<std::size_t>(n) + 1), minusPow(plusPow.size());
    plusPow[0] = minusPow[0] = Polynomial::constant(1.0);
    for (std::size_t i = 1; i < plusPow.size(); ++i) {
        plusPow[i] = plusPow[i - 1] * plus;
        minusPow[i] = minusPow[i - 1] * minus;
    }
    Polynomial out;
    for (int i = 0; i <= p.degree(); ++i) {
        const double c = p.coefficient(i);
        if (c != 0.0)
            out = out + c * (plusPow[static_cast<std::size_t>(i)] *
                             minusPow[static_cast<std::size_t>(n - i)]);
    }
    return out;
}

StabilityMargins stabilityMargins(const TransferFunction& openLoop) {
    if (!openLoop.isProper())
        throw InvalidInput("num", makeDiagnostic("analysis_loop_improper"));
    Loop loop;
    loop.n = openLoop.num();
    loop.d = openLoop.den();
    loop.c = loop.d + loop.n;
    if (loop.c.isZero())
        throw InvalidInput("den", makeDiagnostic("analysis_return_difference_zero"));
    loop.dn = loop.n.derivative();
    loop.dd = loop.d.derivative();
    loop.dc = loop.c.derivative();
    loop.ts = openLoop.tsSeconds();
    const bool discrete = openLoop.isDiscrete();

    StabilityMargins out;
    out.tsSeconds = loop.ts;
    if (!discrete)
        out.delayMarginSamples = kNaN;

    // Closed-loop stability, and closed-loop poles on the boundary (infinite peaks).
    std::vector<double> boundaryPoles; // frequencies
    out.closedLoopStable = true;
    if (loop.c.degree() > 0) {
        for (const Complex& r : loop.c.roots()) {
            if (!isStableRoot(r, loop.ts))
                out.closedLoopStable = false;
            const bool onBoundary =
                discrete ? std::abs(std::abs(r) - 1.0) <= kBoundaryTolerance
                         : std::abs(r.real()) <= kBoundaryTolerance * std::max(1.0, std::abs(r));
            if (onBoundary)
                boundaryPoles.push_back(discrete ? std::abs(std::arg(r)) / loop.ts
                                                 : std::abs(r.imag()));
        }
    }

    // The polynomials on the imaginary axis of s or of w (discrete: bilinear image), with the
    // variable scaled by sigma and the coefficients normalized (both ratios are unchanged).
    const int n = std::max(loop.n.degree(), loop.d.degree());
    Polynomial ns = discrete ? bilinearToW(loop.n, n) : loop.n;
    Polynomial ds = discrete ? bilinearToW(loop.d, n) : loop.d;
    const double sigma = frequencyScale(ns, ds);
    ns = ns.scaledArgument(sigma);
    ds = ds.scaledArgument(sigma);
    const double norm = 1.0 / std::max(ns.maxAbsCoefficient(), ds.maxAbsCoefficient());
    ns = norm * ns;
    ds = norm * ds;
    const EvenOdd en = evenOdd(ns), ed = evenOdd(ds), ec = evenOdd(ns + ds);
    const Polynomial magN = squaredMagnitude(en), magD = squaredMagnitude(ed),
                     magC = squaredMagnitude(ec);
    // u (of the scaled variable) to omega.
    auto toOmega = [&](double u) {
        const double nu = sigma * std::sqrt(u);
        return discrete ? 2.0 * std::atan(nu) / loop.ts : nu;
    };

    // Gain crossovers: |N|^2 - |D|^2 = 0, refined on log|L|.
    auto logMagnitude = [&](double w) {
        const double r =
            std::log(std::abs(loop.n(loop.x(w)))) - std::log(std::abs(loop.d(loop.x(w))));
        const double slope = (loop.dlog(loop.n, loop.dn, w) - loop.dlog(loop.d, loop.dd, w)).real();
        return std::pair<double, double>(r, slope);
    };
    std::vector<double> gainCrossovers;
    if (!loop.n.isZero()) {
        for (const double u : positiveRealRoots(magN - magD)) {
            const auto [w, r] = refine(toOmega(u), loop, logMagnitude);
            if (std::abs(r) <= kCrossingResidual)
                gainCrossovers.push_back(w);
        }
    }
    sortAndDedupe(gainCrossovers);
    for (const double w : gainCrossovers) {
        PhaseMarginCrossing c;
        c.omegaRadPerSec = w;
        double pm = 180.0 + std::arg(loop.value(w)) * 180.0 / kPi; // (0, 360]
        if (pm > 180.0)
            pm -= 360.0;
        c.phaseMarginDeg = pm;
        const double positive = pm < 0.0 ? pm + 360.0 : pm;
        c.delayMarginSeconds = positive * kPi / 180.0 / w;
        c.delayMarginSamples = discrete ? c.delayMarginSeconds / loop.ts : kNaN;
        out.phaseMargins.push_back(c);
    }

    // Phase crossovers: Im(N(j omega) D(-j omega)) / omega = N_o D_e - N_e D_o = 0 with
    // Re L < 0, refined on arg(-L).
    auto argMinusL = [&](double w) {
        const double r = std::arg(-loop.value(w));
        const double slope = (loop.dlog(loop.n, loop.dn, w) - loop.dlog(loop.d, loop.dd, w)).imag();
        return std::pair<double, double>(r, slope);
    };
    std::vector<double> phaseCrossovers;
    if (!loop.n.isZero()) {
        for (const double u : positiveRealRoots(en.o * ed.e - en.e * ed.o)) {
            const auto [w, r] = refine(toOmega(u), loop, argMinusL);
            if (std::abs(r) <= kCrossingResidual && w < loop.nyquist())
                phaseCrossovers.push_back(w);
        }
        // The ends of the frequency axis, where L is real: omega = 0 (L(0) finite and negative),
        // and z = -1 for a discrete loop.
        for (const double w : {0.0, loop.nyquist()}) {
            if (!std::isfinite(w))
                continue;
            // A pole there (an integrator; D(1) of a discrete one is only round-off): L is
            // infinite, not a crossing.
            Polynomial rest;
            const Polynomial shifted =
                w == 0.0 ? loop.d : loop.d.scaledArgument(-1.0); // z = -1 -> 1
            if (splitLowFrequencyRoots(shifted, discrete, rest) > 0)
                continue;
            const Complex v = loop.value(w);
            if (std::isfinite(std::abs(v)) && v.real() < 0.0)
                phaseCrossovers.push_back(w);
        }
    }
    sortAndDedupe(phaseCrossovers);
    for (const double w : phaseCrossovers) {
        GainMarginCrossing c;
        c.omegaRadPerSec = w;
        c.gainFactor = 1.0 / std::abs(loop.value(w));
        c.gainDb = 20.0 * std::log10(c.gainFactor);
        out.gainMargins.push_back(c);
    }

    // The reported margins.
    for (const GainMarginCrossing& c : out.gainMargins) {
        if (std::abs(c.gainDb) < std::abs(out.gainMarginDb)) {
            out.gainMarginDb = c.gainDb;
            out.gainMarginFactor = c.gainFactor;
            out.gainMarginOmegaRadPerSec = c.omegaRadPerSec;
        }
        if (c.gainFactor > 1.0)
            out.upperGainMarginFactor = std::min(out.upperGainMarginFactor, c.gainFactor);
        else if (c.gainFactor < 1.0)
            out.lowerGainMarginFactor = std::max(out.lowerGainMarginFactor, c.gainFactor);
    }
    for (const PhaseMarginCrossing& c : out.phaseMargins) {
        if (std::abs(c.phaseMarginDeg) < std::abs(out.phaseMarginDeg)) {
            out.phaseMarginDeg = c.phaseMarginDeg;
            out.phaseMarginOmegaRadPerSec = c.omegaRadPerSec;
        }
        if (c.delayMarginSeconds < out.delayMarginSeconds) {
            out.delayMarginSeconds = c.delayMarginSeconds;
            out.delayMarginSamples = c.delayMarginSamples;
            out.delayMarginOmegaRadPerSec = c.omegaRadPerSec;
        }
    }

    // Peaks of |S| = |D/(D+N)| and |T| = |N/(D+N)|: stationary points of the squared
    // magnitudes A/B and C/B (roots of A'B - AB'), the ends of the axis, and the closed-loop
    // poles on the boundary.
    auto peak = [&](const Polynomial& top, const Polynomial& topMag, double& best, double& bestW) {
        best = -1.0;
        bestW = kNaN;
        std::vector<double> candidates = {0.0, loop.nyquist()};
        for (const double u :
             positiveRealRoots(topMag.derivative() * magC - topMag * magC.derivative()))
            candidates.push_back(toOmega(u));
        for (const double w : candidates) {
            double m;
            if (std::isfinite(w)) {
                m = std::abs(top(loop.x(w)) / loop.c(loop.x(w)));
            } else { // continuous omega -> inf: ratio of the leading terms (L proper)
                m = top.degree() == loop.c.degree() ? std::abs(top.leading() / loop.c.leading())
                                                    : 0.0;
            }
            if (m > best) {
                best = m;
                bestW = w;
            }
        }
        for (const double w : boundaryPoles) {
            best = kInf;
            bestW = w;
        }
    };
    peak(loop.d, magD, out.peakSensitivity, out.peakSensitivityOmegaRadPerSec);
    peak(loop.n, magN, out.peakComplementarySensitivity,
         out.peakComplementarySensitivityOmegaRadPerSec);

    // Bandwidth: the lowest root of 2 |N|^2 - T0^2 |D + N|^2, refined on log|T| - log(T0/sqrt 2).
    const double x0 = discrete ? 1.0 : 0.0;
    const double t0 = std::abs(loop.n(x0) / loop.c(x0));
    if (std::isfinite(t0) && t0 > 0.0) {
        // T0 in the scaled, normalized polynomials is the same ratio.
        const Polynomial eq = 2.0 * magN - (t0 * t0) * magC;
        std::vector<double> roots = positiveRealRoots(eq);
        auto logT = [&](double w) {
            const double r = std::log(std::abs(loop.n(loop.x(w)) / loop.c(loop.x(w)))) -
                             std::log(t0 / std::sqrt(2.0));
            const double slope =
                (loop.dlog(loop.n, loop.dn, w) - loop.dlog(loop.c, loop.dc, w)).real();
            return std::pair<double, double>(r, slope);
        };
        out.bandwidthRadPerSec = kInf;
        for (const double u : roots) {
            const auto [w, r] = refine(toOmega(u), loop, logT);
            if (std::abs(r) <= kCrossingResidual && w < out.bandwidthRadPerSec)
                out.bandwidthRadPerSec = w;
        }
    }
    if (!out.closedLoopStable)
        out.warnings.push_back(makeDiagnostic("analysis_margins_closed_loop_unstable"));
    return out;
}

} // namespace xyt
