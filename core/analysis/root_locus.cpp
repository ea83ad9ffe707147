// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/root_locus.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/model/root_matching.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace xyt {

namespace {

using Complex = std::complex<double>;
/// A gain K = -D(s)/N(s) counts as real when |Im K| <= this * |K|.
constexpr double kRealGainTolerance = 1e-6;
/// |D(s)| below this times sum |d_i||s|^i: s is an open-loop pole (K = 0), not a feature.
constexpr double kPoleResidual = 1e-10;

/// |a - b| without the overflow guard of std::abs (hypot), which the trace cannot reach.
double distance(Complex a, Complex b) {
    return std::sqrt(std::norm(a - b));
}

/// sum |c_i| r^i: the scale against which |p(x)| is small for |x| = r.
double absoluteSum(const Polynomial& p, double r) {
    double acc = 0.0;
    const auto& c = p.ascending();
    for (auto it = c.rbegin(); it != c.rend(); ++it)
        acc = acc * r + std::abs(*it);
    return acc;
}

/// x^k p(x).
Polynomial shifted(const Polynomial& p, int k) {
    std::vector<double> c(static_cast<std::size_t>(k), 0.0);
    c.insert(c.end(), p.ascending().begin(), p.ascending().end());
    return Polynomial::fromAscending(std::move(c));
}

/// The real gain at which @p s is a closed-loop pole, if there is one (K > 0, Im K negligible,
/// s not an open-loop pole).
std::optional<double> positiveRealGainAt(const Polynomial& num, const Polynomial& den, Complex s) {
    const Complex d = den(s);
    const Complex n = num(s);
    if (std::abs(d) <= kPoleResidual * absoluteSum(den, std::abs(s)) || std::abs(n) == 0.0)
        return std::nullopt;
    const Complex k = -d / n;
    if (!(k.real() > 0.0) || std::abs(k.imag()) > kRealGainTolerance * std::abs(k) ||
        !std::isfinite(k.real()))
        return std::nullopt;
    return k.real();
}

void sortByGain(std::vector<LocusFeature>& features) {
    std::sort(features.begin(), features.end(), [](const LocusFeature& a, const LocusFeature& b) {
        if (a.gain != b.gain)
            return a.gain < b.gain;
        if (a.point.real() != b.point.real())
            return a.point.real() < b.point.real();
        return a.point.imag() > b.point.imag();
    });
}

/// p(j w) = E(u) + j w O(u) with u = w^2: E(u) = sum c_2k (-u)^k, O(u) = sum c_2k+1 (-u)^k.
void evenOddParts(const Polynomial& p, Polynomial& even, Polynomial& odd) {
    std::vector<double> e, o;
    const auto& c = p.ascending();
    for (std::size_t i = 0; i < c.size(); ++i) {
        const double sign = (i / 2) % 2 == 0 ? 1.0 : -1.0;
        (i % 2 == 0 ? e : o).push_back(sign * c[i]);
    }
    even = Polynomial::fromAscending(e.empty() ? std::vector<double>{0.0} : e);
    odd = Polynomial::fromAscending(o.empty() ? std::vector<double>{0.0} : o);
}

std::string formatComplex(Complex z) {
    std::ostringstream s;
    s.precision(6);
    s << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "j";
    return s.str();
}

void validateOptions(const RootLocusOptions& o) {
    if (o.view)
        o.view->validate();
    if (!(o.kMax >= 0.0) || !std::isfinite(o.kMax))
        throw InvalidInput("kMax", makeDiagnostic("analysis_kmax_range"));
    if (!(o.maxStepFraction > 0.0 && o.maxStepFraction <= 0.5))
        throw InvalidInput("maxStepFraction",
                           makeDiagnostic("analysis_in_range_open_left", {"0", "0.5"}));
    if (!(o.approachFraction > 0.0 && o.approachFraction <= 1.0))
        throw InvalidInput("approachFraction", makeDiagnostic("in_zero_one_open_left"));
    if (!(o.minStepFraction > 0.0 && o.minStepFraction <= 1.0))
        throw InvalidInput("minStepFraction", makeDiagnostic("in_zero_one_open_left"));
    if (o.maxPoints < 2)
        throw InvalidInput("maxPoints", makeDiagnostic("at_least", {"2"}));
    if (!(o.maxWork > 0.0))
        throw InvalidInput("maxWork", makeDiagnostic("analysis_positive"));
    if (!(o.maxSeconds > 0.0))
        throw InvalidInput("maxSeconds", makeDiagnostic("analysis_positive"));
}

/**
 * Refines approximations @p r of all roots of @p p at once by Aberth-Ehrlich iterations
 * (Newton with implicit deflation by the other approximations, cubically convergent for simple
 * roots). Returns false unless every correction fell below the round-off level and the roots'
 * sum matches -c_{n-1}/c_n: the caller then solves from scratch. This is the corrector of the
 * continuation: the roots of the previous step are within one step bound of the new ones, and
 * refining them costs a fraction of a companion eigenvalue solve (the trace's speed target).
 */
bool refineAllRoots(const Polynomial& p, const Polynomial& dp, std::vector<Complex>& r,
                    double absoluteScale) {
    const std::size_t n = r.size();
    if (static_cast<int>(n) != p.degree() || n < 2)
        return false;
    // Divisions as multiplications by conj(x)/|x|^2 and sizes as squared norms: this loop is
    // the hot spot of the trace, and the library complex division and hypot are slow.
    auto inverse = [](Complex x) { return std::conj(x) / std::norm(x); };
    constexpr double tolerance2 = 1e-28; // (1e-14)^2: relative size of the last correction
    for (int iteration = 0; iteration < 10; ++iteration) {
        bool converged = true;
        for (std::size_t i = 0; i < n; ++i) {
            const Complex value = p(r[i]);
            if (value == Complex(0.0))
                continue;
            Complex repulsion(0.0);
            for (std::size_t j = 0; j < n; ++j) {
                if (j == i)
                    continue;
                const Complex gap = r[i] - r[j];
                if (gap == Complex(0.0))
                    return false;
                repulsion += inverse(gap);
            }
            const Complex denominator = dp(r[i]) - value * repulsion;
            if (denominator == Complex(0.0))
                return false;
            const Complex correction = value * inverse(denominator);
            r[i] -= correction;
            const double size = std::sqrt(std::norm(r[i])) + absoluteScale;
            if (!(std::norm(correction) <= tolerance2 * size * size))
                converged = false;
        }
        if (converged) {
            // Tiny corrections alone can mislead: two approximations of one root that are
            // closer than round-off repel each other by tiny amounts. Demand small backward
            // errors and the right sum of roots too.
            Complex sum(0.0);
            double magnitude = 0.0;
            for (const Complex& root : r) {
                const double radius = std::sqrt(std::norm(root));
                if (std::norm(p(root)) > 1e-26 * std::pow(absoluteSum(p, radius), 2))
                    return false;
                sum += root;
                magnitude += radius;
            }
            const double expected = -p.coefficient(p.degree() - 1) / p.leading();
            return std::sqrt(std::norm(sum - expected)) <= 1e-9 * (magnitude + absoluteScale);
        }
    }
    return false;
}

LocusView automaticView(const RootLocus& r) {
    std::vector<Complex> pts = r.poles;
    pts.insert(pts.end(), r.zeros.begin(), r.zeros.end());
    for (const auto& f : r.breakaways)
        pts.push_back(f.point);
    for (const auto& f : r.crossings)
        pts.push_back(f.point);
    if (r.asymptotes.count > 0)
        pts.emplace_back(r.asymptotes.centroid, 0.0);
    if (r.tsSeconds > 0.0)
        pts.insert(pts.end(), {Complex(1, 0), Complex(-1, 0), Complex(0, 1)});
    double reMin = kInf, reMax = -kInf, imAbs = 0.0, maxAbs = 0.0;
    for (const Complex& p : pts) {
        reMin = std::min(reMin, p.real());
        reMax = std::max(reMax, p.real());
        imAbs = std::max(imAbs, std::abs(p.imag()));
        maxAbs = std::max(maxAbs, std::abs(p));
    }
    double span = std::max(reMax - reMin, 2.0 * imAbs);
    if (!(span > 1e-9 * maxAbs) || span == 0.0)
        span = maxAbs > 0.0 ? maxAbs : 1.0;
    const double margin = 0.25 * span;
    LocusView v;
    v.reMin = reMin - margin;
    v.reMax = reMax + margin;
    // At least as tall as wide: branches leaving the real axis stay in view for a while.
    const double half = std::max(imAbs + margin, 0.5 * (v.reMax - v.reMin));
    v.imMin = -half;
    v.imMax = half;
    return v;
}

/// The tracing state machine of rootLocus().
class Tracer {
public:
    Tracer(const Polynomial& num, const Polynomial& den, const RootLocusOptions& options,
           RootLocus& result)
        : num_(num), den_(den), dNum_(num.derivative()), dDen_(den.derivative()), o_(options),
          r_(result), n_(den.degree()), m_(num.degree()) {
        maxStep_ = r_.maxStep;
        minStep_ = o_.minStepFraction * maxStep_;
        // A biproper loop whose leading coefficient d_n + K n_n vanishes at K* > 0 sends one
        // root through infinity there: the trace may not stop before K*.
        if (n_ == m_) {
            const double kStar = -den.leading() / num.leading();
            if (kStar > 0.0) {
                mustPassGain_ = kStar;
                r_.warnings.push_back(
                    makeDiagnostic("analysis_locus_biproper_infinity", {std::to_string(kStar)}));
            }
        }
    }

    void run() {
        std::vector<Complex> current = den_.roots();
        double k = 0.0, lastStep = 0.0;
        std::vector<std::vector<Complex>> columns(static_cast<std::size_t>(n_));
        auto append = [&](double gain, const std::vector<Complex>& roots) {
            r_.gains.push_back(gain);
            for (std::size_t i = 0; i < roots.size(); ++i)
                columns[i].push_back(roots[i]);
        };
        append(0.0, current);
        const auto started = std::chrono::steady_clock::now();
        bool warnedBound = false;
        while (!finished(current, k)) {
            if (static_cast<int>(r_.gains.size()) >= o_.maxPoints) {
                r_.status = RootLocusStatus::PointLimitReached;
                r_.warnings.push_back(
                    makeDiagnostic("analysis_locus_point_limit",
                                   {std::to_string(o_.maxPoints), std::to_string(k)}));
                break;
            }
            if (work_ > o_.maxWork) {
                r_.status = RootLocusStatus::PointLimitReached;
                r_.warnings.push_back(makeDiagnostic(
                    "analysis_locus_work_bound",
                    {std::to_string(static_cast<long long>(o_.maxWork / 1e6)),
                     std::to_string(r_.gains.size()), std::to_string(k), std::to_string(n_)}));
                break;
            }
            if (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
                o_.maxSeconds) {
                r_.status = RootLocusStatus::PointLimitReached;
                std::ostringstream bound;
                bound << o_.maxSeconds;
                r_.warnings.push_back(makeDiagnostic(
                    "analysis_locus_time_bound",
                    {bound.str(), std::to_string(r_.gains.size()), std::to_string(k)}));
                break;
            }
            if (k > 1e250) {
                r_.status = RootLocusStatus::GainLimitReached;
                r_.warnings.push_back(makeDiagnostic("analysis_locus_gain_limit"));
                break;
            }
            const std::vector<double> bounds = stepBounds(current);
            double step = predictedStep(current, k, bounds);
            if (lastStep > 0.0)
                step = std::min(step, 4.0 * lastStep);
            if (!std::isfinite(step))
                step = std::max(1.0, k); // every root is outside the view: only kMax limits
            const double minGainStep = 1e-15 * std::max(k, 1e-300);
            std::vector<Complex> next;
            double nextK = k;
            for (int attempt = 0;; ++attempt) {
                nextK = k + step;
                if (o_.kMax > 0.0 && nextK >= o_.kMax)
                    nextK = o_.kMax;
                next = rootsAt(nextK, current);
                if (next.size() != current.size()) { // the leading coefficient vanished
                    step *= 0.5;
                    continue;
                }
                next = continueBranches(current, next);
                const double worst = worstRatio(current, next, bounds);
                if (worst <= 1.0)
                    break;
                if (attempt >= 80 || step <= minGainStep) {
                    if (!warnedBound) {
                        r_.warnings.push_back(
                            makeDiagnostic("analysis_locus_step_bound", {std::to_string(nextK)}));
                        warnedBound = true;
                    }
                    break;
                }
                // Displacement grows like the gain step (simple roots) or its square root
                // (near a multiple root): shrinking by the squared ratio covers both.
                step *= std::clamp(0.8 / (worst * worst), 0.05, 0.5);
            }
            lastStep = nextK - k;
            k = nextK;
            current = std::move(next);
            append(k, current);
        }
        r_.work = work_;
        r_.branches.resize(columns.size());
        for (std::size_t i = 0; i < columns.size(); ++i) {
            LocusBranch& b = r_.branches[i];
            b.roots = std::move(columns[i]);
            b.start = b.roots.front();
            if (o_.kMax == 0.0 && r_.status == RootLocusStatus::Complete)
                if (const auto z = nearZero(b.roots.back()))
                    b.end = *z;
        }
    }

private:
    /// The roots of D + K N: the corrector from @p guess, else the eigenvalue solver.
    std::vector<Complex> rootsAt(double k, const std::vector<Complex>& guess) const {
        const Polynomial p = den_ + k * num_;
        if (p.degree() != n_)
            return {};
        const double n = static_cast<double>(n_);
        work_ += 20.0 * n * n; // a few Newton sweeps over n roots of degree n
        std::vector<Complex> roots = guess;
        if (refineAllRoots(p, dDen_ + k * dNum_, roots, 1e-6 * maxStep_))
            return roots;
        work_ += 10.0 * n * n * n; // the companion-matrix eigenvalue solve
        return p.roots();
    }

    /// Operations spent on root finding (bounded by RootLocusOptions::maxWork).
    mutable double work_ = 0.0;

    std::optional<Complex> nearZero(Complex root) const {
        std::optional<Complex> best;
        double bestDistance = maxStep_;
        for (const Complex& z : r_.zeros) {
            const double d = std::abs(root - z);
            if (d <= bestDistance) {
                bestDistance = d;
                best = z;
            }
        }
        return best;
    }

    /// Every branch has reached its zero or left the view (or K reached kMax).
    bool finished(const std::vector<Complex>& roots, double k) const {
        if (o_.kMax > 0.0)
            return k >= o_.kMax;
        if (k == 0.0 || k <= mustPassGain_)
            return false;
        int outside = 0;
        for (const Complex& root : roots) {
            if (!r_.view.contains(root))
                ++outside;
            else if (!nearZero(root))
                return false;
        }
        return outside >= n_ - m_;
    }

    /// The displacement allowed to each root in the next step (infinite outside the view).
    std::vector<double> stepBounds(const std::vector<Complex>& roots) const {
        std::vector<double> bounds(roots.size(), kInf);
        for (std::size_t i = 0; i < roots.size(); ++i) {
            if (!r_.view.contains(roots[i]))
                continue;
            double separation = kInf;
            for (std::size_t j = 0; j < roots.size(); ++j)
                if (j != i)
                    separation = std::min(separation, distance(roots[i], roots[j]));
            bounds[i] = std::clamp(o_.approachFraction * separation, minStep_, maxStep_);
        }
        return bounds;
    }

    /// The gain step that moves each root by about its bound: |P_K(r + delta)| / |N(r + delta)|
    /// is the gain increment that puts a closed-loop pole at distance delta from r (to first
    /// order |P'| delta/|N| = delta/|dr/dK| for a simple root, and the right power of delta
    /// for a multiple one, where the velocity is infinite).
    double predictedStep(const std::vector<Complex>& roots, double k,
                         const std::vector<double>& bounds) const {
        double step = kInf;
        for (std::size_t i = 0; i < roots.size(); ++i) {
            if (!std::isfinite(bounds[i]))
                continue;
            for (const Complex dir : {Complex(1.0, 0.0), Complex(0.0, 1.0)}) {
                const Complex s = roots[i] + bounds[i] * dir;
                const double n = std::abs(num_(s));
                if (n > 0.0)
                    step = std::min(step, std::abs(den_(s) + k * num_(s)) / n);
            }
        }
        return step;
    }

    /// The largest displacement / bound over the roots inside the view at either end.
    double worstRatio(const std::vector<Complex>& from, const std::vector<Complex>& to,
                      const std::vector<double>& bounds) const {
        double worst = 0.0;
        for (std::size_t i = 0; i < from.size(); ++i) {
            const bool inside = r_.view.contains(from[i]);
            if (!inside && !r_.view.contains(to[i]))
                continue;
            const double bound = inside ? bounds[i] : maxStep_; // entering the view
            worst = std::max(worst, distance(to[i], from[i]) / bound);
        }
        return worst;
    }

    const Polynomial& num_;
    const Polynomial& den_;
    Polynomial dNum_, dDen_;
    const RootLocusOptions& o_;
    RootLocus& r_;
    int n_, m_;
    double maxStep_ = 0.0, minStep_ = 0.0;
    double mustPassGain_ = 0.0;
};

} // namespace

double LocusView::span() const {
    return std::max(reMax - reMin, imMax - imMin);
}

bool LocusView::contains(std::complex<double> p) const {
    return p.real() >= reMin && p.real() <= reMax && p.imag() >= imMin && p.imag() <= imMax;
}

void LocusView::validate() const {
    for (double v : {reMin, reMax, imMin, imMax})
        requireFinite(v, "view");
    if (!(reMin < reMax) || !(imMin < imMax))
        throw InvalidInput("view", makeDiagnostic("analysis_view_empty"));
}

LocusAsymptotes locusAsymptotes(const Polynomial& num, const Polynomial& den) {
    LocusAsymptotes a;
    const int n = den.degree(), m = num.degree();
    a.count = n - m;
    if (a.count <= 0 || num.isZero())
        return a;
    const double sumPoles = -den.coefficient(n - 1) / den.leading();
    const double sumZeros = m > 0 ? -num.coefficient(m - 1) / num.leading() : 0.0;
    a.centroid = (sumPoles - sumZeros) / a.count;
    const bool sameSign = num.leading() / den.leading() > 0.0;
    for (int q = 0; q < a.count; ++q) {
        const double angle = (sameSign ? 2 * q + 1 : 2 * q) * 180.0 / a.count;
        a.anglesDeg.push_back(std::fmod(angle, 360.0));
    }
    return a;
}

std::vector<LocusFeature> locusBreakaways(const Polynomial& num, const Polynomial& den) {
    const Polynomial b = num * den.derivative() - num.derivative() * den;
    std::vector<LocusFeature> result;
    if (b.degree() < 1)
        return result;
    for (Complex s : b.roots()) {
        if (std::abs(s.imag()) <= 1e-9 * (1.0 + std::abs(s)))
            s = Complex(s.real(), 0.0);
        if (const auto k = positiveRealGainAt(num, den, s))
            result.push_back({s, *k});
    }
    sortByGain(result);
    return result;
}

std::vector<LocusFeature> locusCrossings(const Polynomial& num, const Polynomial& den,
                                         double tsSeconds) {
    std::vector<LocusFeature> result;
    auto addPair = [&](Complex p) {
        if (const auto k = positiveRealGainAt(num, den, p)) {
            result.push_back({p, *k});
            if (p.imag() != 0.0)
                result.push_back({std::conj(p), *k});
        }
    };
    if (tsSeconds == 0.0) {
        addPair(Complex(0.0, 0.0));
        Polynomial dEven, dOdd, nEven, nOdd;
        evenOddParts(den, dEven, dOdd);
        evenOddParts(num, nEven, nOdd);
        const Polynomial q = dOdd * nEven - dEven * nOdd;
        if (q.degree() >= 1)
            for (const Complex& u : q.roots())
                if (u.real() > 0.0 && std::abs(u.imag()) <= 1e-7 * std::abs(u))
                    addPair(Complex(0.0, std::sqrt(u.real())));
    } else {
        addPair(Complex(1.0, 0.0));
        addPair(Complex(-1.0, 0.0));
        const int n = den.degree(), m = num.degree();
        const Polynomial r = shifted(den * num.reversed(m), n - m) - den.reversed(n) * num;
        if (r.degree() >= 1)
            for (const Complex& z : r.roots())
                if (z.imag() > 1e-9 && std::abs(std::abs(z) - 1.0) <= 1e-6)
                    addPair(z / std::abs(z));
    }
    sortByGain(result);
    return result;
}

namespace {

/**
 * Warns when computed roots cannot be trusted. A root r is moved by a relative coefficient
 * perturbation eps (round-off) by about min over m of (eps S / |c_m|)^(1/m), where
 * p(r + d) = sum_m c_m d^m (Taylor coefficients at r) and S = sum |a_i| |r|^i: the first-order
 * condition number for a simple root (m = 1; Higham, "Accuracy and Stability of Numerical
 * Algorithms", Sec. 26.3), the eps^(1/m) law for a cluster of m roots. (s+1)^40 is computed
 * with poles at -2.28 instead of -1; a double pole of a discrete loop (about 1e-8) is fine.
 * We warn when the estimate exceeds 1e-6 relative.
 */
void warnIllConditioned(const Polynomial& p, const std::vector<Complex>& roots, const char* code,
                        std::vector<Diagnostic>& warnings) {
    const auto& a = p.ascending();
    const double eps = std::numeric_limits<double>::epsilon();
    double worst = 0.0;
    Complex where{};
    for (const Complex& r : roots) {
        const double magnitude = std::abs(r);
        if (magnitude == 0.0)
            continue; // exact zero roots are split off exactly
        double scale = 0.0, power = 1.0;
        for (const double c : a) {
            scale += std::abs(c) * power;
            power *= magnitude;
        }
        // Taylor coefficients at r by repeated synthetic division (Horner), O(n^2).
        std::vector<Complex> b(a.begin(), a.end());
        double move = std::numeric_limits<double>::infinity();
        for (std::size_t m = 0; m < a.size(); ++m) {
            for (std::size_t i = b.size() - 1; i > m; --i)
                b[i - 1] += r * b[i];
            if (m > 0 && std::abs(b[m]) > 0.0)
                move = std::min(
                    move, std::pow(eps * scale / std::abs(b[m]), 1.0 / static_cast<double>(m)));
        }
        const double relative = move / magnitude;
        if (!(relative <= worst)) {
            worst = relative;
            where = r;
        }
    }
    if (!(worst <= 1e-6)) {
        char size[32];
        std::snprintf(size, sizeof size, "%.2g", worst);
        warnings.push_back(makeDiagnostic(code, {formatComplex(where), std::string(size)}));
    }
}

} // namespace

RootLocus rootLocus(const Polynomial& num, const Polynomial& den, double tsSeconds,
                    const RootLocusOptions& options) {
    if (!(tsSeconds >= 0.0) || !std::isfinite(tsSeconds))
        throw InvalidInput("ts", makeDiagnostic("analysis_ts_range"));
    if (num.isZero())
        throw InvalidInput("num", makeDiagnostic("analysis_locus_zero_numerator"));
    if (den.degree() < 1)
        throw InvalidInput("den", makeDiagnostic("analysis_locus_no_poles"));
    if (num.degree() > den.degree())
        throw InvalidInput(
            "num", makeDiagnostic("analysis_locus_improper",
                                  {std::to_string(num.degree()), std::to_string(den.degree())}));
    validateOptions(options);
    RootLocus r;
    r.tsSeconds = tsSeconds;
    const auto rootsOf = [](const Polynomial& p, const char* field) {
        try {
            return p.roots();
        } catch (const InvalidInput& e) {
            throw InvalidInput(field, e.reasonDiagnostic());
        }
    };
    r.poles = rootsOf(den, "den");
    r.zeros = num.degree() > 0 ? rootsOf(num, "num") : std::vector<Complex>{};
    warnIllConditioned(den, r.poles, "analysis_locus_poles_ill_conditioned", r.warnings);
    warnIllConditioned(num, r.zeros, "analysis_locus_zeros_ill_conditioned", r.warnings);
    sortRoots(r.poles);
    sortRoots(r.zeros);
    for (const Complex& p : r.poles)
        for (const Complex& z : r.zeros)
            if (std::abs(p - z) <= 1e-8 * (1.0 + std::abs(p))) {
                r.warnings.push_back(
                    makeDiagnostic("analysis_locus_cancellation", {formatComplex(p)}));
                break;
            }
    r.asymptotes = locusAsymptotes(num, den);
    r.breakaways = locusBreakaways(num, den);
    r.crossings = locusCrossings(num, den, tsSeconds);
    r.view = options.view ? *options.view : automaticView(r);
    r.maxStep = options.maxStepFraction * r.view.span();
    Tracer(num, den, options, r).run();
    return r;
}

RootLocus rootLocus(const TransferFunction& openLoop, const RootLocusOptions& options) {
    return rootLocus(openLoop.num(), openLoop.den(), openLoop.tsSeconds(), options);
}

std::optional<LocusPick> pickLocusPoint(const RootLocus& locus, std::complex<double> clicked) {
    requireFinite(clicked.real(), "clicked");
    requireFinite(clicked.imag(), "clicked");
    std::optional<LocusPick> best;
    for (std::size_t b = 0; b < locus.branches.size(); ++b) {
        const auto& roots = locus.branches[b].roots;
        for (std::size_t i = 0; i < roots.size(); ++i) {
            const double d = std::abs(roots[i] - clicked);
            if (!best || d < best->distance)
                best = LocusPick{b, i, locus.gains[i], roots[i], d, {}};
        }
    }
    if (best)
        best->damping = dampingOf(best->point, locus.tsSeconds);
    return best;
}

double locusResidual(const Polynomial& num, const Polynomial& den, double gain,
                     std::complex<double> root) {
    const double r = std::abs(root);
    const double scale = absoluteSum(den, r) + std::abs(gain) * absoluteSum(num, r);
    return scale > 0.0 ? std::abs(den(root) + gain * num(root)) / scale : 0.0;
}

} // namespace xyt
