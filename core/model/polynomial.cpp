// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/polynomial.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <Eigen/Core>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace xyt {

Polynomial::Polynomial() : c_{0.0} {}

Polynomial::Polynomial(std::vector<double> c) : c_(std::move(c)) {
    trim();
}

void Polynomial::trim() {
    while (c_.size() > 1 && c_.back() == 0.0)
        c_.pop_back();
    if (c_.empty())
        c_.push_back(0.0);
}

Polynomial Polynomial::fromAscending(std::vector<double> coefficients, const std::string& field) {
    for (std::size_t i = 0; i < coefficients.size(); ++i)
        requireFinite(coefficients[i], field + "[" + std::to_string(i) + "]");
    return Polynomial(std::move(coefficients));
}

Polynomial Polynomial::fromDescending(const std::vector<double>& coefficients,
                                      const std::string& field) {
    for (std::size_t i = 0; i < coefficients.size(); ++i)
        requireFinite(coefficients[i], field + "[" + std::to_string(i) + "]");
    return Polynomial(std::vector<double>(coefficients.rbegin(), coefficients.rend()));
}

Polynomial Polynomial::constant(double c) {
    return fromAscending({c});
}

Polynomial Polynomial::identity() {
    return Polynomial(std::vector<double>{0.0, 1.0});
}

Polynomial Polynomial::fromRoots(const std::vector<Complex>& roots, double gain) {
    std::vector<Complex> c{Complex(gain)};
    for (const Complex& r : roots) {
        requireFinite(r.real(), "roots");
        requireFinite(r.imag(), "roots");
        std::vector<Complex> next(c.size() + 1, Complex(0.0));
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = std::move(next);
    }
    std::vector<double> real(c.size());
    std::transform(c.begin(), c.end(), real.begin(), [](const Complex& v) { return v.real(); });
    return Polynomial(std::move(real));
}

double Polynomial::coefficient(int i) const {
    return (i >= 0 && i < static_cast<int>(c_.size())) ? c_[static_cast<std::size_t>(i)] : 0.0;
}

std::vector<double> Polynomial::descending() const {
    return {c_.rbegin(), c_.rend()};
}

double Polynomial::operator()(double x) const {
    double acc = 0.0;
    for (auto it = c_.rbegin(); it != c_.rend(); ++it)
        acc = acc * x + *it;
    return acc;
}

Polynomial::Complex Polynomial::operator()(Complex x) const {
    Complex acc(0.0);
    for (auto it = c_.rbegin(); it != c_.rend(); ++it)
        acc = acc * x + *it;
    return acc;
}

Polynomial Polynomial::derivative() const {
    if (c_.size() <= 1)
        return Polynomial();
    std::vector<double> d(c_.size() - 1);
    for (std::size_t i = 1; i < c_.size(); ++i)
        d[i - 1] = static_cast<double>(i) * c_[i];
    return Polynomial(std::move(d));
}

Polynomial Polynomial::monic() const {
    if (isZero())
        throw InvalidInput("polynomial", makeDiagnostic("model_zero_polynomial_no_leading"));
    return (1.0 / leading()) * *this;
}

Polynomial Polynomial::reversed(int n) const {
    if (n < degree())
        throw InvalidInput("n",
                           makeDiagnostic("model_at_least_degree", {std::to_string(degree())}));
    std::vector<double> r(static_cast<std::size_t>(n) + 1, 0.0);
    for (std::size_t i = 0; i < c_.size(); ++i)
        r[static_cast<std::size_t>(n) - i] = c_[i];
    return Polynomial(std::move(r));
}

Polynomial Polynomial::scaledArgument(double a) const {
    std::vector<double> r(c_);
    double p = 1.0;
    for (double& v : r) {
        v *= p;
        p *= a;
    }
    return Polynomial(std::move(r));
}

double Polynomial::maxAbsCoefficient() const {
    double m = 0.0;
    for (double v : c_)
        m = std::max(m, std::abs(v));
    return m;
}

std::vector<Polynomial::Complex> Polynomial::roots() const {
    if (isZero())
        throw InvalidInput("polynomial", makeDiagnostic("model_zero_polynomial_no_roots"));
    std::vector<Complex> result;
    // Roots at exactly zero: split them off so the companion matrix stays nonsingular.
    std::size_t low = 0;
    while (low + 1 < c_.size() && c_[low] == 0.0) {
        result.emplace_back(0.0, 0.0);
        ++low;
    }
    const std::size_t n = c_.size() - low;
    if (n == 2) {
        result.emplace_back(-c_[low] / c_[low + 1], 0.0);
    } else if (n > 2) {
        Eigen::VectorXd coeffs(static_cast<Eigen::Index>(n));
        for (std::size_t i = 0; i < n; ++i)
            coeffs(static_cast<Eigen::Index>(i)) = c_[low + i];
        Eigen::PolynomialSolver<double, Eigen::Dynamic> solver;
        solver.compute(coeffs);
        const Polynomial d = derivative();
        for (Eigen::Index i = 0; i < solver.roots().size(); ++i) {
            Complex r = solver.roots()(i);
            // Newton polish on the full polynomial: the companion eigenvalues of an
            // ill-scaled polynomial can be off by far more than the root's conditioning.
            // A step is kept only while it lowers |p|, which protects multiple roots.
            double residual = std::abs((*this)(r));
            for (int step = 0; step < 4 && residual > 0.0; ++step) {
                const Complex slope = d(r);
                if (std::abs(slope) == 0.0)
                    break;
                const Complex candidate = r - (*this)(r) / slope;
                const double candidateResidual = std::abs((*this)(candidate));
                if (!(candidateResidual < residual))
                    break;
                r = candidate;
                residual = candidateResidual;
            }
            result.push_back(r);
        }
    }
    // A negligible leading coefficient (say 5e-324 against 1e-6) puts a root beyond the range
    // of double, and an overflowing companion matrix gives NaN: such a polynomial is not a
    // usable model, so it is rejected rather than handed on as roots nobody can plot (found by
    // fuzz_design, tests/fuzz/corpus/fuzz_design/crash-root-beyond-double).
    for (const Complex& r : result)
        if (!std::isfinite(r.real()) || !std::isfinite(r.imag()))
            throw InvalidInput("polynomial", makeDiagnostic("model_root_beyond_double"));
    return result;
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
    std::vector<double> r(std::max(a.c_.size(), b.c_.size()), 0.0);
    for (std::size_t i = 0; i < a.c_.size(); ++i)
        r[i] += a.c_[i];
    for (std::size_t i = 0; i < b.c_.size(); ++i)
        r[i] += b.c_[i];
    return Polynomial(std::move(r));
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) {
    return a + (-1.0) * b;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
    std::vector<double> r(a.c_.size() + b.c_.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.c_.size(); ++i)
        for (std::size_t j = 0; j < b.c_.size(); ++j)
            r[i + j] += a.c_[i] * b.c_[j];
    return Polynomial(std::move(r));
}

Polynomial operator*(double k, const Polynomial& p) {
    std::vector<double> r(p.c_);
    for (double& v : r)
        v *= k;
    return Polynomial(std::move(r));
}

void Polynomial::divide(const Polynomial& a, const Polynomial& b, Polynomial& quotient,
                        Polynomial& remainder) {
    if (b.isZero())
        throw InvalidInput("divisor", makeDiagnostic("model_division_by_zero_polynomial"));
    std::vector<double> rem(a.c_);
    const int db = b.degree();
    const int da = a.degree();
    if (da < db) {
        quotient = Polynomial();
        remainder = a;
        return;
    }
    std::vector<double> q(static_cast<std::size_t>(da - db) + 1, 0.0);
    for (int k = da - db; k >= 0; --k) {
        const double coef = rem[static_cast<std::size_t>(k + db)] / b.leading();
        q[static_cast<std::size_t>(k)] = coef;
        for (int j = 0; j <= db; ++j)
            rem[static_cast<std::size_t>(k + j)] -= coef * b.c_[static_cast<std::size_t>(j)];
        rem[static_cast<std::size_t>(k + db)] = 0.0;
    }
    rem.resize(static_cast<std::size_t>(std::max(db, 1)));
    quotient = Polynomial(std::move(q));
    remainder = Polynomial(std::move(rem));
}

std::string Polynomial::toString(const std::string& variable) const {
    if (isZero())
        return "0";
    std::ostringstream out;
    bool first = true;
    for (int i = degree(); i >= 0; --i) {
        const double c = c_[static_cast<std::size_t>(i)];
        if (c == 0.0)
            continue;
        const double mag = std::abs(c);
        if (first)
            out << (c < 0 ? "-" : "");
        else
            out << (c < 0 ? " - " : " + ");
        const bool showCoef = i == 0 || mag != 1.0;
        if (showCoef)
            out << formatNumber(mag);
        if (i > 0) {
            if (showCoef)
                out << " ";
            out << variable;
            if (i > 1)
                out << "^" << i;
        }
        first = false;
    }
    return out.str();
}

void sortRoots(std::vector<std::complex<double>>& roots) {
    std::sort(roots.begin(), roots.end(), [](const auto& a, const auto& b) {
        if (a.real() != b.real())
            return a.real() < b.real();
        return a.imag() < b.imag();
    });
}

} // namespace xyt
