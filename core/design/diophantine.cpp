// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/diophantine.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

/// The pole of A and the zero of B (both in z) closest to each other.
struct ClosestPair {
    std::complex<double> pole;
    std::complex<double> zero;
    bool found = false;
};

ClosestPair closestPoleZero(const Polynomial& a, const Polynomial& b) {
    ClosestPair best;
    if (a.degree() == 0 || b.degree() == 0)
        return best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& p : zInverseRoots(a))
        for (const auto& z : zInverseRoots(b))
            if (const double d = std::abs(p - z); d < bestDistance) {
                bestDistance = d;
                best = {p, z, true};
            }
    return best;
}

} // namespace

std::vector<std::complex<double>> zInverseRoots(const Polynomial& p) {
    if (p.isZero())
        throw InvalidInput("polynomial", makeDiagnostic("design_zero_polynomial_no_roots"));
    // z^n p(1/z); the Polynomial constructor trims the high powers a delay leaves at zero.
    std::vector<std::complex<double>> r = p.reversed(p.degree()).roots();
    sortRoots(r);
    return r;
}

DiophantineSolution solveDiophantine(const Polynomial& a, const Polynomial& b,
                                     const Polynomial& t) {
    if (a.isZero())
        throw InvalidInput("a", makeDiagnostic("zero"));
    if (a.coefficient(0) == 0.0)
        throw InvalidInput("a", makeDiagnostic("design_z0_nonzero"));
    if (b.isZero())
        throw InvalidInput("b", makeDiagnostic("zero"));
    if (t.isZero())
        throw InvalidInput("t", makeDiagnostic("zero"));

    const int na = a.degree();
    const int nb = b.degree();
    const int nt = t.degree();
    const int nf = std::max({nb - 1, nt - na, 0});
    const int ng = na - 1; // -1: no G unknowns (A constant)
    const int n = na + nf + 1;

    // Column blocks scaled to unit largest coefficient: the condition number then measures how
    // close A and B are to a common factor, not how small the plant gain is.
    const double sa = a.maxAbsCoefficient();
    const double sb = b.maxAbsCoefficient();
    Eigen::MatrixXd e = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j <= nf; ++j)
        for (int i = 0; i <= na; ++i)
            e(i + j, j) = a.coefficient(i) / sa;
    for (int j = 0; j <= ng; ++j)
        for (int i = 0; i <= nb; ++i)
            e(i + j, nf + 1 + j) = b.coefficient(i) / sb;
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    for (int i = 0; i <= nt; ++i)
        d(i) = t.coefficient(i);

    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(e, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    const double condition =
        sv(n - 1) > 0.0 ? sv(0) / sv(n - 1) : std::numeric_limits<double>::infinity();

    if (!(condition <= kCommonFactorCondition)) {
        const ClosestPair pair = closestPoleZero(a, b);
        if (pair.found)
            throw InvalidInput("b", makeDiagnostic("design_common_factor_root",
                                                   {formatComplex(0.5 * (pair.pole + pair.zero)),
                                                    formatNumber(condition, 3)}));
        throw InvalidInput("b",
                           makeDiagnostic("design_common_factor", {formatNumber(condition, 3)}));
    }

    const Eigen::VectorXd m = svd.solve(d);
    std::vector<double> fc(static_cast<std::size_t>(nf) + 1);
    for (int j = 0; j <= nf; ++j)
        fc[static_cast<std::size_t>(j)] = m(j) / sa;
    std::vector<double> gc(static_cast<std::size_t>(std::max(ng + 1, 1)), 0.0);
    for (int j = 0; j <= ng; ++j)
        gc[static_cast<std::size_t>(j)] = m(nf + 1 + j) / sb;

    DiophantineSolution out;
    out.f = Polynomial::fromAscending(fc, "f");
    out.g = Polynomial::fromAscending(gc, "g");
    out.conditionNumber = condition;
    out.residual = (a * out.f + b * out.g - t).maxAbsCoefficient();
    if (!std::isfinite(out.residual))
        // F and G are finite but A F + B G overflows: coefficients near the double range
        // (found by fuzz_design, input kept in tests/fuzz/corpus/fuzz_design).
        throw InvalidInput("b", makeDiagnostic("design_diophantine_overflow"));
    if (condition > kNearCommonFactorCondition) {
        const ClosestPair pair = closestPoleZero(a, b);
        if (pair.found)
            out.warnings.push_back(makeDiagnostic(
                "design_near_common_factor_pair",
                {formatComplex(pair.pole), formatComplex(pair.zero),
                 formatNumber(std::abs(pair.pole - pair.zero), 3), formatNumber(condition, 3)}));
        else
            out.warnings.push_back(
                makeDiagnostic("design_near_common_factor", {formatNumber(condition, 3)}));
    }
    return out;
}

} // namespace xyt
