// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"

#include <Eigen/Core>

namespace xyt {

/**
 * x' = A x + B u, y = C x + D u (continuous, tsSeconds == 0) or
 * x[k+1] = A x[k] + B u[k], y[k] = C x[k] + D u[k] (discrete). SISO or MIMO by matrix sizes.
 */
struct StateSpace {
    Eigen::MatrixXd a;
    Eigen::MatrixXd b;
    Eigen::MatrixXd c;
    Eigen::MatrixXd d;
    double tsSeconds = 0.0;

    Eigen::Index states() const { return a.rows(); }
};

/**
 * Controllable canonical realization of a proper SISO transfer function. For
 * N/D with D = s^n + d_{n-1} s^{n-1} + ... + d_0 (monic) and N = D_dir D + R (R of degree < n):
 * A is the companion matrix with last row -d_0 ... -d_{n-1}, B = e_n, C = [r_0 ... r_{n-1}],
 * D = D_dir. @throws InvalidInput "num" for an improper transfer function.
 */
StateSpace realize(const TransferFunction& tf);

/**
 * Exact zero-order-hold discretization: Phi = e^{A Ts}, Gamma = int_0^Ts e^{A t} dt B, computed
 * as one matrix exponential of [[A, B], [0, 0]] Ts (Eigen's MatrixFunctions module).
 * @throws InvalidInput "ts" unless tsSeconds > 0, "system" if it is already discrete.
 */
StateSpace discretizeZoh(const StateSpace& continuous, double tsSeconds);

/**
 * Exact ZOH discretization of a transfer function: poles map to e^{p Ts}; the numerator is
 * det(zI - Phi + Gamma C) - det(zI - Phi) + D det(zI - Phi).
 */
TransferFunction c2dZoh(const TransferFunction& continuous, double tsSeconds);

/**
 * Exact discretization with a first-order hold on the inputs (inputs linear between samples):
 * x[k+1] = phi x[k] + gamma0 u[k] + gamma1 (u[k+1] - u[k]) / Ts. This is what makes the time
 * simulation of a linear loop exact at the samples for piecewise-linear references.
 */
struct FohDiscretization {
    Eigen::MatrixXd phi;
    Eigen::MatrixXd gamma0;
    Eigen::MatrixXd gamma1;
};
FohDiscretization discretizeFoh(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                double tsSeconds);

/// The characteristic polynomial det(xI - M), from the eigenvalues of M.
Polynomial characteristicPolynomial(const Eigen::MatrixXd& m);

} // namespace xyt
