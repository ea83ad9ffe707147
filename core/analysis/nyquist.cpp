// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/nyquist.h"

#include "core/analysis/frequency_response.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace xyt {

namespace {

using Complex = std::complex<double>;

/// A pole is on the boundary when |Re s| <= this |s| (continuous) or ||z| - 1| <= this
/// (discrete): the computed roots of an undamped pair scatter by round-off, those of a double
/// pole by sqrt(eps).
constexpr double kPoleOnBoundary = 1e-6;

/// A piece of the upper half contour: point(t) and its frequency for t in [0, 1].
struct Piece {
    std::function<Complex(double)> point; ///< s or z; not called at an infinite end
    std::function<double(double)> omega;
    int indentation = -1;
    bool endsAtInfinity = false; ///< continuous: t = 1 is s = j inf
};

/// D as the product of its boundary factors and the rest, so that L can be evaluated within
/// the indentation radius of a boundary pole: Horner on the expanded D there loses the digits
/// of (x - x_p)^k to round-off (a double pole at z = 1 at distance 1e-6 is 1e-12 against
/// coefficients of order 1), the factored form keeps them.
struct FactoredDen {
    bool discrete = false;
    int lowOrder = 0;                                 ///< (s or z - 1)^lowOrder
    std::vector<std::pair<Polynomial, int>> boundary; ///< (s^2 + w^2), (z^2 - 2 cos z + 1), (z + 1)
    Polynomial regular;

    Complex operator()(Complex x) const {
        Complex v = regular(x);
        const Complex low = discrete ? x - 1.0 : x;
        for (int i = 0; i < lowOrder; ++i)
            v *= low;
        for (const auto& [factor, order] : boundary)
            for (int i = 0; i < order; ++i)
                v *= factor(x);
        return v;
    }
};

class Sampler {
public:
    Sampler(const TransferFunction& l, const FactoredDen& den, const NyquistOptions& o,
            NyquistCurve& out)
        : l_(l), den_(den), maxStep_(o.maxArgStepDeg * kPi / 180.0), maxPoints_(o.maxPoints),
          out_(out) {
        // L at s = j inf (continuous, L proper): the ratio of the leading coefficients.
        atInfinity_ =
            l.num().degree() == l.den().degree() ? l.num().leading() / l.den().leading() : 0.0;
    }

    void sample(const Piece& piece) {
        constexpr int kStart = 32;
        double t0 = 0.0;
        Complex v0 = at(piece, t0);
        push(piece, t0, v0);
        for (int i = 1; i <= kStart; ++i) {
            const double t1 = static_cast<double>(i) / kStart;
            const Complex v1 = at(piece, t1);
            refine(piece, t0, v0, t1, v1, 0);
            push(piece, t1, v1);
            t0 = t1;
            v0 = v1;
        }
    }

    /// The turn of arg(1 + L) along all samples so far.
    double totalTurn() const {
        double sum = 0.0;
        for (std::size_t i = 1; i < out_.points.size(); ++i)
            sum += std::arg((1.0 + out_.points[i]) / (1.0 + out_.points[i - 1]));
        return sum;
    }

private:
    Complex at(const Piece& piece, double t) const {
        if (piece.endsAtInfinity && t >= 1.0)
            return atInfinity_;
        const Complex x = piece.point(t);
        return l_.num()(x) / den_(x);
    }

    void push(const Piece& piece, double t, Complex v) {
        out_.points.push_back(v);
        out_.omegaRadPerSec.push_back(piece.omega(t));
        out_.indentationIndex.push_back(piece.indentation);
        if (std::abs(1.0 + v) < 1e-9)
            out_.passesThroughMinusOne = true;
    }

    bool coarse(Complex a, Complex b) const {
        const Complex ga = 1.0 + a, gb = 1.0 + b;
        if (!(std::abs(std::arg(gb / ga)) <= maxStep_))
            return true;
        if (std::abs(a) > 0.0 && std::abs(b) > 0.0 && !(std::abs(std::arg(b / a)) <= maxStep_))
            return true;
        const double ratio = std::abs(gb) / std::abs(ga);
        return !(ratio <= 2.0 && ratio >= 0.5);
    }

    void refine(const Piece& piece, double t0, Complex v0, double t1, Complex v1, int depth) {
        if (!coarse(v0, v1))
            return;
        if (depth > 60 || t1 - t0 < 1e-15 || static_cast<int>(out_.points.size()) >= maxPoints_) {
            limited_ = true;
            return;
        }
        const double tm = 0.5 * (t0 + t1);
        const Complex vm = at(piece, tm);
        refine(piece, t0, v0, tm, vm, depth + 1);
        push(piece, tm, vm);
        refine(piece, tm, vm, t1, v1, depth + 1);
    }

public:
    bool limited_ = false;

private:
    const TransferFunction& l_;
    const FactoredDen& den_;
    double maxStep_;
    int maxPoints_;
    NyquistCurve& out_;
    Complex atInfinity_;
};

} // namespace

NyquistCurve nyquistCurve(const TransferFunction& openLoop, const NyquistOptions& options) {
    if (!openLoop.isProper())
        throw InvalidInput("num", makeDiagnostic("analysis_loop_improper"));
    if (!(options.indentationRelativeRadius > 0.0 && options.indentationRelativeRadius < 0.1))
        throw InvalidInput("indentationRelativeRadius",
                           makeDiagnostic("analysis_in_open_range", {"0", "0.1"}));
    if (!(options.maxArgStepDeg > 0.0 && options.maxArgStepDeg <= 90.0))
        throw InvalidInput("maxArgStepDeg",
                           makeDiagnostic("analysis_in_range_open_left", {"0", "90"}));
    if (options.maxPoints < 100)
        throw InvalidInput("maxPoints", makeDiagnostic("at_least", {"100"}));

    const bool discrete = openLoop.isDiscrete();
    const double ts = openLoop.tsSeconds();
    NyquistCurve out;
    out.tsSeconds = ts;

    // Open-loop poles: the low-frequency ones split off exactly, the others classified.
    Polynomial rest;
    const int lowOrder = splitLowFrequencyRoots(openLoop.den(), discrete, rest);
    struct BoundaryPole {
        double omega;
        int order;
    };
    std::vector<BoundaryPole> boundary;
    if (lowOrder > 0)
        boundary.push_back({0.0, lowOrder});
    std::vector<double> upper; // frequencies of boundary poles with omega > 0
    if (rest.degree() > 0) {
        for (const Complex& r : rest.roots()) {
            const bool onBoundary = discrete ? std::abs(std::abs(r) - 1.0) <= kPoleOnBoundary
                                             : std::abs(r.real()) <= kPoleOnBoundary * std::abs(r);
            if (onBoundary) {
                const double w = discrete ? std::arg(r) / ts : r.imag();
                if (w >= 0.0 || (discrete && std::abs(std::arg(r)) > kPi - kPoleOnBoundary))
                    upper.push_back(std::abs(w));
            } else if (!isStableRoot(r, ts)) {
                ++out.openLoopUnstablePoles;
            }
        }
    }
    std::sort(upper.begin(), upper.end());
    for (const double w : upper) {
        if (!boundary.empty() &&
            std::abs(w - boundary.back().omega) <=
                kPoleOnBoundary * std::max(w, discrete ? 1.0 / ts : 0.0) + 1e-300)
            ++boundary.back().order;
        else
            boundary.push_back({w, 1});
    }

    // D factored at its boundary poles (see FactoredDen).
    FactoredDen den;
    den.discrete = discrete;
    den.lowOrder = lowOrder;
    den.regular = rest;
    for (const BoundaryPole& bp : boundary) {
        if (bp.omega == 0.0 && lowOrder > 0)
            continue;
        Polynomial factor;
        if (!discrete)
            factor = Polynomial::fromAscending({bp.omega * bp.omega, 0.0, 1.0});
        else if (bp.omega * ts >= kPi * (1.0 - kPoleOnBoundary))
            factor = Polynomial::fromAscending({1.0, 1.0});
        else if (bp.omega == 0.0)
            factor = Polynomial::fromAscending({-1.0, 1.0});
        else
            factor = Polynomial::fromAscending({1.0, -2.0 * std::cos(bp.omega * ts), 1.0});
        if (!discrete && bp.omega == 0.0)
            factor = Polynomial::identity();
        for (int i = 0; i < bp.order; ++i) {
            Polynomial q, r;
            Polynomial::divide(den.regular, factor, q, r);
            den.regular = q; // the remainder is the round-off of the computed root
        }
        den.boundary.emplace_back(factor, bp.order);
    }

    // The frequency scale of the indentation at s = 0.
    double scale = 1.0;
    {
        const std::vector<double> f = characteristicFrequencies(openLoop);
        if (!f.empty()) {
            double logSum = 0.0;
            for (double w : f)
                logSum += std::log(w);
            scale = std::exp(logSum / static_cast<double>(f.size()));
        }
    }
    const double rel = options.indentationRelativeRadius;
    const double nyquist = discrete ? kPi / ts : kInf;

    Sampler sampler(openLoop, den, options, out);
    double axisStart = 0.0; // where the current boundary segment starts (omega)
    auto axisPiece = [&](double a, double b) {
        Piece p;
        if (discrete) {
            p.point = [=](double t) { return std::polar(1.0, (a + (b - a) * t) * ts); };
            p.omega = [=](double t) { return a + (b - a) * t; };
        } else if (std::isinf(b)) {
            p.endsAtInfinity = true;
            p.omega = [=](double t) { return t >= 1.0 ? kInf : a + scale * t / (1.0 - t); };
            p.point = [=](double t) { return Complex(0.0, a + scale * t / (1.0 - t)); };
        } else if (a > 0.0) {
            p.omega = [=](double t) { return a * std::pow(b / a, t); };
            p.point = [=](double t) { return Complex(0.0, a * std::pow(b / a, t)); };
        } else {
            p.omega = [=](double t) { return b * t; };
            p.point = [=](double t) { return Complex(0.0, b * t); };
        }
        sampler.sample(p);
    };
    for (const BoundaryPole& bp : boundary) {
        NyquistIndentation ind;
        ind.omegaRadPerSec = bp.omega;
        ind.order = bp.order;
        ind.radius = discrete ? rel : rel * (bp.omega > 0.0 ? bp.omega : scale);
        const double rho = ind.radius;
        // Angular half-width of the indentation seen on the axis (omega units).
        const double halfWidth = discrete ? rho / ts : rho;
        const bool atZero = bp.omega == 0.0;
        const bool atNyquist = discrete && bp.omega >= nyquist * (1.0 - kPoleOnBoundary);
        if (!atZero)
            axisPiece(axisStart, bp.omega - halfWidth);
        out.indentations.push_back(ind);
        const int index = static_cast<int>(out.indentations.size()) - 1;
        // phi from phiStart to phiEnd: s = j omega_p + rho e^{j phi} (continuous),
        // z = z_p (1 + rho e^{j phi}) (discrete: outward is the direction of z_p).
        const double phiStart = atZero ? 0.0 : -kPi / 2;
        const double phiEnd = atNyquist ? 0.0 : kPi / 2;
        Piece arc;
        arc.indentation = index;
        const double wp = bp.omega;
        arc.omega = [=](double) { return wp; };
        if (discrete) {
            const Complex zp = std::polar(1.0, wp * ts);
            arc.point = [=](double t) {
                return zp * (1.0 + rho * std::polar(1.0, phiStart + (phiEnd - phiStart) * t));
            };
        } else {
            arc.point = [=](double t) {
                return Complex(0.0, wp) + rho * std::polar(1.0, phiStart + (phiEnd - phiStart) * t);
            };
        }
        sampler.sample(arc);
        axisStart = bp.omega + halfWidth;
        if (atNyquist)
            axisStart = kInf; // the contour ends on the indentation
    }
    if (!std::isinf(axisStart)) // else the contour ended on the indentation at z = -1
        axisPiece(axisStart, nyquist);

    const double turns = 2.0 * sampler.totalTurn() / (2.0 * kPi);
    out.clockwiseEncirclements = -static_cast<int>(std::lround(turns));
    out.closedLoopUnstablePoles = out.clockwiseEncirclements + out.openLoopUnstablePoles;
    if (sampler.limited_)
        out.warnings.push_back(makeDiagnostic("analysis_nyquist_sampling_bound"));
    if (std::abs(turns - std::round(turns)) > 0.05)
        out.warnings.push_back(makeDiagnostic("analysis_nyquist_fractional_turns"));
    if (out.passesThroughMinusOne)
        out.warnings.push_back(makeDiagnostic("analysis_nyquist_through_minus_one"));
    return out;
}

} // namespace xyt
