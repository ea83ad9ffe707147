// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/transfer_function.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>
#include <limits>

namespace xyt {

TransferFunction::TransferFunction()
    : num_(Polynomial::constant(1.0)), den_(Polynomial::constant(1.0)) {}

TransferFunction::TransferFunction(const Polynomial& num, const Polynomial& den, double tsSeconds)
    : ts_(tsSeconds) {
    if (!std::isfinite(tsSeconds) || tsSeconds < 0.0)
        throw InvalidInput("ts", makeDiagnostic("model_sample_time"));
    if (den.isZero())
        throw InvalidInput("den", makeDiagnostic("model_denominator_zero"));
    const double scale = 1.0 / den.leading();
    num_ = scale * num;
    den_ = scale * den;
}

TransferFunction TransferFunction::fromDescending(const std::vector<double>& num,
                                                  const std::vector<double>& den) {
    return TransferFunction(Polynomial::fromDescending(num, "num"),
                            Polynomial::fromDescending(den, "den"));
}

TransferFunction TransferFunction::fromZInverse(const Polynomial& numZInv,
                                                const Polynomial& denZInv, double tsSeconds) {
    requirePositive(tsSeconds, "ts");
    if (denZInv.isZero())
        throw InvalidInput("den", makeDiagnostic("model_denominator_zero"));
    if (denZInv.coefficient(0) == 0.0)
        throw InvalidInput("den", makeDiagnostic("model_z0_coefficient_zero"));
    const int n = std::max(numZInv.degree(), denZInv.degree());
    return TransferFunction(numZInv.reversed(n), denZInv.reversed(n), tsSeconds);
}

TransferFunction TransferFunction::gain(double k, double tsSeconds) {
    return TransferFunction(Polynomial::constant(k), Polynomial::constant(1.0), tsSeconds);
}

Polynomial TransferFunction::numZInverse() const {
    if (!isDiscrete())
        throw InvalidInput("ts", makeDiagnostic("model_continuous_no_zinv"));
    if (!isProper())
        throw InvalidInput("num", makeDiagnostic("model_improper_no_zinv"));
    return num_.reversed(den_.degree());
}

Polynomial TransferFunction::denZInverse() const {
    if (!isDiscrete())
        throw InvalidInput("ts", makeDiagnostic("model_continuous_no_zinv"));
    return den_.reversed(den_.degree());
}

std::vector<TransferFunction::Complex> TransferFunction::poles() const {
    auto p = den_.roots();
    sortRoots(p);
    return p;
}

std::vector<TransferFunction::Complex> TransferFunction::zeros() const {
    if (num_.isZero())
        return {};
    auto z = num_.roots();
    sortRoots(z);
    return z;
}

namespace {
/// p(x) == 0 up to the round-off of evaluating it: at x = 1 (discrete DC) the sum of the
/// coefficients of (z - 1)(z - 0.2) is 5.6e-17, not 0. At x = 0 the test is exact.
bool vanishesAt(const Polynomial& p, double x) {
    double magnitude = 0.0;
    for (int i = p.degree(); i >= 0; --i)
        magnitude = magnitude * std::abs(x) + std::abs(p.coefficient(i));
    return std::abs(p(x)) <=
           4.0 * (p.degree() + 1) * std::numeric_limits<double>::epsilon() * magnitude;
}
} // namespace

double TransferFunction::dcGain() const {
    const double x = isDiscrete() ? 1.0 : 0.0;
    Polynomial n = num_;
    Polynomial d = den_;
    // A factor (x - x0) common to both is cancelled first, so s/s has gain 1, not 0/0.
    const Polynomial factor = Polynomial::fromAscending({-x, 1.0});
    while (!n.isZero() && vanishesAt(n, x) && vanishesAt(d, x)) {
        Polynomial q, r;
        Polynomial::divide(n, factor, q, r);
        n = q;
        Polynomial::divide(d, factor, q, r);
        d = q;
    }
    const double dv = d(x);
    const double nv = n(x);
    if (vanishesAt(d, x))
        return nv >= 0 ? std::numeric_limits<double>::infinity()
                       : -std::numeric_limits<double>::infinity();
    return nv / dv;
}

TransferFunction::Complex TransferFunction::operator()(Complex x) const {
    return num_(x) / den_(x);
}

TransferFunction::Complex TransferFunction::frequencyResponse(double omegaRadPerSec) const {
    const Complex x =
        isDiscrete() ? std::polar(1.0, omegaRadPerSec * ts_) : Complex(0.0, omegaRadPerSec);
    return (*this)(x);
}

bool isStableRoot(std::complex<double> root, double tsSeconds) {
    return tsSeconds > 0.0 ? std::abs(root) < 1.0 : root.real() < 0.0;
}

bool TransferFunction::isStable() const {
    for (const Complex& p : poles())
        if (!isStableRoot(p, ts_))
            return false;
    return true;
}

namespace {
double commonSampleTime(const TransferFunction& a, const TransferFunction& b) {
    if (a.tsSeconds() != b.tsSeconds())
        throw InvalidInput("ts", makeDiagnostic("model_different_sample_times"));
    return a.tsSeconds();
}
} // namespace

TransferFunction series(const TransferFunction& a, const TransferFunction& b) {
    const double ts = commonSampleTime(a, b);
    return TransferFunction(a.num() * b.num(), a.den() * b.den(), ts);
}

TransferFunction parallel(const TransferFunction& a, const TransferFunction& b) {
    const double ts = commonSampleTime(a, b);
    return TransferFunction(a.num() * b.den() + b.num() * a.den(), a.den() * b.den(), ts);
}

TransferFunction feedback(const TransferFunction& g, const TransferFunction& h, int sign) {
    const double ts = commonSampleTime(g, h);
    if (sign != 1 && sign != -1)
        throw InvalidInput("sign", makeDiagnostic("model_sign"));
    // g/(1 - sign g h) = Ng Dh / (Dg Dh - sign Ng Nh)
    return TransferFunction(
        g.num() * h.den(), g.den() * h.den() - static_cast<double>(sign) * (g.num() * h.num()), ts);
}

} // namespace xyt
