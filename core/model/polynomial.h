// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <complex>
#include <string>
#include <vector>

namespace xyt {

/**
 * A real polynomial p(x) = c[0] + c[1] x + ... + c[n] x^n.
 *
 * Coefficient order: ascending, as Eigen's polynomial module stores them: `ascending()[i]` is the
 * coefficient of x^i. The variable is whatever the caller means: s for continuous transfer
 * functions, z for discrete ones in positive powers, or q = z^-1 for the ARX polynomials of the
 * second paper (which users type in ascending powers of z^-1, so `fromAscending` reads them as
 * typed). Polynomials of s are typed highest power first: use `fromDescending`.
 *
 * Normalized at construction: high-degree zero coefficients are trimmed, so the leading
 * coefficient is nonzero unless the polynomial is zero. The zero polynomial has degree 0 and
 * `isZero()`.
 */
class Polynomial {
public:
    using Complex = std::complex<double>;

    /// The zero polynomial.
    Polynomial();
    /// @throws InvalidInput (field @p field) when a coefficient is NaN or infinite.
    static Polynomial fromAscending(std::vector<double> coefficients,
                                    const std::string& field = "polynomial");
    /// Coefficients highest power first, e.g. {1, 125.3, 3665, 0} for s^3 + 125.3 s^2 + 3665 s.
    static Polynomial fromDescending(const std::vector<double>& coefficients,
                                     const std::string& field = "polynomial");
    static Polynomial constant(double c);
    /// x (the monomial of degree 1).
    static Polynomial identity();
    /// gain * prod(x - r_i). Complex roots must come in conjugate pairs; the result is real
    /// (imaginary round-off of the expanded coefficients is dropped).
    static Polynomial fromRoots(const std::vector<Complex>& roots, double gain = 1.0);

    int degree() const { return static_cast<int>(c_.size()) - 1; }
    bool isZero() const { return c_.size() == 1 && c_[0] == 0.0; }
    /// Coefficient of x^i (0 beyond the degree).
    double coefficient(int i) const;
    double leading() const { return c_.back(); }
    const std::vector<double>& ascending() const { return c_; }
    std::vector<double> descending() const;

    double operator()(double x) const;
    Complex operator()(Complex x) const;

    Polynomial derivative() const;
    /// p divided by its leading coefficient. @throws InvalidInput for the zero polynomial.
    Polynomial monic() const;
    /// x^n p(1/x) for n >= degree(): turns a polynomial in z^-1 into one in z and back.
    Polynomial reversed(int n) const;
    /// p(a x): coefficients c_i a^i.
    Polynomial scaledArgument(double a) const;
    /// Largest |c_i|, for relative tolerances.
    double maxAbsCoefficient() const;

    /**
     * All complex roots (degree() of them, with multiplicity). Exact zero roots are split off
     * first; the rest come from the eigenvalues of the companion matrix (Eigen's
     * PolynomialSolver), each polished by Newton steps on the original polynomial while the
     * residual decreases. @throws InvalidInput for the zero polynomial, and when a root is
     * not finite (a leading coefficient negligible against the others, e.g. 5e-324 s^3 + ...).
     */
    std::vector<Complex> roots() const;

    friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
    friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
    friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
    friend Polynomial operator*(double k, const Polynomial& p);
    friend Polynomial operator-(const Polynomial& p) { return -1.0 * p; }
    friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.c_ == b.c_; }

    /// Quotient and remainder of a / b. @throws InvalidInput when b is zero.
    static void divide(const Polynomial& a, const Polynomial& b, Polynomial& quotient,
                       Polynomial& remainder);

    /// "s^3 + 125.3 s^2 + 3665 s" style text (variable name given), for reports and equations.
    std::string toString(const std::string& variable = "s") const;

private:
    explicit Polynomial(std::vector<double> c);
    void trim();
    std::vector<double> c_;
};

/// Sort roots by real part, then imaginary part (for stable output and comparisons).
void sortRoots(std::vector<std::complex<double>>& roots);

} // namespace xyt
