// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/state_space.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

namespace xyt {

StateSpace realize(const TransferFunction& tf) {
    if (!tf.isProper())
        throw InvalidInput("num", makeDiagnostic("model_improper_no_realization"));
    const int n = tf.den().degree();
    Polynomial direct, rest;
    Polynomial::divide(tf.num(), tf.den(), direct, rest);
    StateSpace ss;
    ss.tsSeconds = tf.tsSeconds();
    ss.a = Eigen::MatrixXd::Zero(n, n);
    ss.b = Eigen::MatrixXd::Zero(n, 1);
    ss.c = Eigen::MatrixXd::Zero(1, n);
    ss.d = Eigen::MatrixXd::Constant(1, 1, direct.coefficient(0));
    for (int i = 0; i + 1 < n; ++i)
        ss.a(i, i + 1) = 1.0;
    for (int j = 0; j < n; ++j) {
        ss.a(n - 1, j) = -tf.den().coefficient(j); // the denominator is monic
        ss.c(0, j) = rest.coefficient(j);
    }
    if (n > 0)
        ss.b(n - 1, 0) = 1.0;
    return ss;
}

StateSpace discretizeZoh(const StateSpace& continuous, double tsSeconds) {
    requirePositive(tsSeconds, "ts");
    if (continuous.tsSeconds > 0.0)
        throw InvalidInput("system", makeDiagnostic("model_already_discrete"));
    const Eigen::Index n = continuous.states();
    const Eigen::Index m = continuous.b.cols();
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + m, n + m);
    aug.topLeftCorner(n, n) = continuous.a * tsSeconds;
    aug.topRightCorner(n, m) = continuous.b * tsSeconds;
    const Eigen::MatrixXd e = aug.exp();
    StateSpace d = continuous;
    d.tsSeconds = tsSeconds;
    d.a = e.topLeftCorner(n, n);
    d.b = e.topRightCorner(n, m);
    return d;
}

Polynomial characteristicPolynomial(const Eigen::MatrixXd& m) {
    if (m.rows() == 0)
        return Polynomial::constant(1.0);
    Eigen::EigenSolver<Eigen::MatrixXd> solver(m, false);
    const Eigen::VectorXcd ev = solver.eigenvalues();
    std::vector<std::complex<double>> roots(ev.data(), ev.data() + ev.size());
    return Polynomial::fromRoots(roots);
}

TransferFunction c2dZoh(const TransferFunction& continuous, double tsSeconds) {
    if (continuous.isDiscrete())
        throw InvalidInput("system", makeDiagnostic("model_already_discrete"));
    const StateSpace d = discretizeZoh(realize(continuous), tsSeconds);
    const Polynomial den = characteristicPolynomial(d.a);
    const Polynomial closed = characteristicPolynomial(d.a - d.b * d.c);
    const Polynomial num = closed - den + d.d(0, 0) * den;
    return TransferFunction(num, den, tsSeconds);
}

FohDiscretization discretizeFoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                double tsSeconds) {
    requirePositive(tsSeconds, "ts");
    const Eigen::Index n = a.rows();
    const Eigen::Index m = b.cols();
    // Augmented state [x; w; rho] with w the input and rho its slope: x' = A x + B w, w' = rho.
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 2 * m, n + 2 * m);
    aug.block(0, 0, n, n) = a;
    aug.block(0, n, n, m) = b;
    aug.block(n, n + m, m, m) = Eigen::MatrixXd::Identity(m, m);
    const Eigen::MatrixXd e = (aug * tsSeconds).exp();
    FohDiscretization foh;
    foh.phi = e.block(0, 0, n, n);
    foh.gamma0 = e.block(0, n, n, m);
    foh.gamma1 = e.block(0, n + m, n, m); // multiplies the slope rho = (u[k+1] - u[k]) / Ts
    // A very stiff system (a pole near -8e11 at Ts = 0.04 s, found by fuzz_design, input kept
    // as crash-stiff-discretization) makes the scaling and squaring of exp() overflow on the way
    // (transient growth of a non-normal matrix) although the exact result is finite.
    if (!e.allFinite())
        throw InvalidInput(
            "ts", makeDiagnostic("model_discretization_overflows", {formatNumber(tsSeconds)}));
    // The same loss can stay finite: a plant with k0 = 4e12 and a pole at -5e8 (fuzz_design,
    // crash-stiff-loop) gave a step matrix with eigenvalues of 1e38 for a stable A, whose run
    // then overflowed. By the spectral mapping theorem the eigenvalues of e^{A Ts} are
    // e^{lambda Ts}, so rho(phi) = e^{alpha Ts} with alpha the largest real part of A's
    // eigenvalues. A discrepancy beyond 1e-3 (relative, plus 1e-3 absolute for rho near 0)
    // means exp() lost the matrix: far above the eigenvalue error of a sound result (about
    // eps^(1/m) for an m-fold defective eigenvalue, 1e-4 for m = 4), far below the failures seen.
    if (n > 0) {
        const double alpha =
            Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues().real().maxCoeff();
        const double rho =
            Eigen::EigenSolver<Eigen::MatrixXd>(foh.phi, false).eigenvalues().cwiseAbs().maxCoeff();
        const double expected = std::exp(alpha * tsSeconds);
        if (std::isfinite(expected) && !(std::abs(rho - expected) <= 1e-3 * expected + 1e-3))
            throw InvalidInput("ts", makeDiagnostic("model_discretization_loses_precision",
                                                    {formatNumber(tsSeconds), formatNumber(rho, 3),
                                                     formatNumber(expected, 3)}));
    }
    return foh;
}

} // namespace xyt
