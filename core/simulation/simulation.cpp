// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/simulation.h"

#include "core/model/errors.h"
#include "core/model/state_space.h"

#include <Eigen/QR>

#include <cmath>
#include <string>

namespace xyt {

namespace {

void requireFiniteSignal(const std::vector<double>& v, const std::string& field) {
    if (v.empty())
        throw InvalidInput(field, "has no samples");
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw InvalidInput(field, "sample " + std::to_string(i) + " is not a finite number");
}

/// x <- phi x + g0 w + g1 rho, with raw loops: the matrices are tiny and this is the hot path.
struct StepMatrices {
    Eigen::MatrixXd phi, g0, g1;
    void step(const double* x, const double* w, const double* rho, double* out) const {
        const Eigen::Index n = phi.rows();
        const Eigen::Index m = g0.cols();
        for (Eigen::Index i = 0; i < n; ++i) {
            double acc = 0.0;
            for (Eigen::Index j = 0; j < n; ++j)
                acc += phi(i, j) * x[j];
            for (Eigen::Index j = 0; j < m; ++j)
                acc += g0(i, j) * w[j] + g1(i, j) * rho[j];
            out[i] = acc;
        }
    }
};

StepMatrices fohStep(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double dt) {
    try {
        FohDiscretization foh = discretizeFoh(a, b, dt);
        return {std::move(foh.phi), std::move(foh.gamma0), std::move(foh.gamma1)};
    } catch (const InvalidInput& e) {
        throw InvalidInput("dt", e.reason()); // the simulation's step is the user's dt
    }
}

} // namespace

LoopModes loopModes(const TransferFunction& plant, const TransferFunction& controller) {
    if (plant.isDiscrete() || !plant.isStrictlyProper())
        throw InvalidInput("plant", "must be a continuous, strictly proper transfer function");
    if (controller.isDiscrete() || !controller.isProper())
        throw InvalidInput("controller", "must be a continuous, proper transfer function");
    const StateSpace p = realize(plant);
    const StateSpace c = realize(controller);
    LoopModes m;
    const Eigen::Index np = m.plantStates = p.states();
    const Eigen::Index nc = m.controllerStates = c.states();
    const Eigen::Index n = np + nc;
    const double dc = m.controllerD = c.d(0, 0);
    m.plantA = p.a;
    m.plantC = p.c.row(0);
    m.controllerC = c.c.row(0);

    // Linear mode: u = Cc xc + Dc (r - Cp xp).
    m.aLinear = Eigen::MatrixXd::Zero(n, n);
    m.aLinear.topLeftCorner(np, np) = p.a - dc * p.b * p.c;
    m.aLinear.topRightCorner(np, nc) = p.b * c.c;
    m.aLinear.bottomLeftCorner(nc, np) = -c.b * p.c;
    m.aLinear.bottomRightCorner(nc, nc) = c.a;
    m.bLinear.resize(n, 1);
    m.bLinear << dc * p.b, c.b;

    // Saturated mode: inputs [r, u] with u held at +-umax over the step.
    m.aClipped = Eigen::MatrixXd::Zero(n, n);
    m.aClipped.topLeftCorner(np, np) = p.a;
    m.aClipped.bottomLeftCorner(nc, np) = -c.b * p.c;
    m.aClipped.bottomRightCorner(nc, nc) = c.a;
    m.bClipped = Eigen::MatrixXd::Zero(n, 2);
    m.bClipped.bottomLeftCorner(nc, 1) = c.b;
    m.bClipped.topRightCorner(np, 1) = p.b;
    return m;
}

SimulationResult simulateLoop(const TransferFunction& plant, const TransferFunction& controller,
                              const std::vector<double>& reference,
                              const LoopSimulationOptions& options) {
    const LoopModes modes = loopModes(plant, controller);
    requirePositive(options.dtSeconds, "dt");
    if (std::isnan(options.umaxVolts) || !(options.umaxVolts > 0.0))
        throw InvalidInput("umax", "must be greater than zero (infinity for no limit)");
    requireFinite(options.initialOutput, "initial_output");
    requirePositive(options.modelUnitsPerPositionUnit, "model_unit_scale");
    requireFiniteSignal(reference, "reference");
    const double unit = options.modelUnitsPerPositionUnit;

    const Eigen::Index np = modes.plantStates;
    const Eigen::Index nc = modes.controllerStates;
    const Eigen::Index n = np + nc;
    const double dc = modes.controllerD;
    const StepMatrices linear = fohStep(modes.aLinear, modes.bLinear, options.dtSeconds);
    const bool limited = std::isfinite(options.umaxVolts);
    StepMatrices clipped;
    if (limited)
        clipped = fohStep(modes.aClipped, modes.bClipped, options.dtSeconds);

    std::vector<double> x(static_cast<std::size_t>(n), 0.0), next(x.size());
    if (options.initialOutput != 0.0) {
        // At rest with output y0: A_p x = 0 and C_p x = y0 (only possible with a pole at 0).
        Eigen::MatrixXd m(np + 1, np);
        m << modes.plantA, modes.plantC;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(np + 1);
        rhs(np) = options.initialOutput * unit;
        const Eigen::VectorXd xp = m.completeOrthogonalDecomposition().solve(rhs);
        if ((m * xp - rhs).norm() > 1e-9 * (1.0 + std::abs(options.initialOutput)))
            throw InvalidInput("initial_output",
                               "the plant has no pole at s = 0, so it cannot rest away from 0");
        for (Eigen::Index i = 0; i < np; ++i)
            x[static_cast<std::size_t>(i)] = xp(i);
    }

    const std::size_t count = reference.size();
    SimulationResult out;
    out.dtSeconds = options.dtSeconds;
    out.umaxVolts = options.umaxVolts;
    out.t.resize(count);
    out.r = reference;
    out.y.resize(count);
    out.e.resize(count);
    out.u.resize(count);
    out.clipped.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        double y = 0.0;
        for (Eigen::Index j = 0; j < np; ++j)
            y += modes.plantC(j) * x[static_cast<std::size_t>(j)];
        const double rk = reference[k] * unit;
        double v = dc * (rk - y);
        for (Eigen::Index j = 0; j < nc; ++j)
            v += modes.controllerC(j) * x[static_cast<std::size_t>(np + j)];
        const bool clip = limited && std::abs(v) > options.umaxVolts;
        const double u = clip ? std::copysign(options.umaxVolts, v) : v;
        out.t[k] = static_cast<double>(k) * options.dtSeconds;
        out.y[k] = y / unit;
        out.e[k] = reference[k] - y / unit;
        out.u[k] = u;
        out.clipped[k] = clip;
        if (k + 1 == count)
            break;
        const double slope = (reference[k + 1] - reference[k]) * unit / options.dtSeconds;
        if (clip) {
            const double w[2] = {rk, u};
            const double rho[2] = {slope, 0.0};
            clipped.step(x.data(), w, rho, next.data());
        } else {
            linear.step(x.data(), &rk, &slope, next.data());
        }
        x.swap(next);
    }
    return out;
}

std::vector<double> simulateLinear(const TransferFunction& system, const std::vector<double>& input,
                                   double dtSeconds) {
    if (system.isDiscrete() || !system.isProper())
        throw InvalidInput("system", "must be a continuous, proper transfer function");
    requirePositive(dtSeconds, "dt");
    requireFiniteSignal(input, "input");
    const StateSpace ss = realize(system);
    const StepMatrices step = fohStep(ss.a, ss.b, dtSeconds);
    const std::size_t n = static_cast<std::size_t>(ss.states());
    std::vector<double> x(n, 0.0), next(n), y(input.size());
    for (std::size_t k = 0; k < input.size(); ++k) {
        double acc = ss.d(0, 0) * input[k];
        for (std::size_t j = 0; j < n; ++j)
            acc += ss.c(0, static_cast<Eigen::Index>(j)) * x[j];
        y[k] = acc;
        if (k + 1 == input.size())
            break;
        const double slope = (input[k + 1] - input[k]) / dtSeconds;
        step.step(x.data(), &input[k], &slope, next.data());
        x.swap(next);
    }
    return y;
}

} // namespace xyt
