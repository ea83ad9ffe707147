// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/simulation.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/model/state_space.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/table_dynamics.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <string>

namespace xyt {

namespace {

void requireFiniteSignal(const std::vector<double>& v, const std::string& field) {
    if (v.empty())
        throw InvalidInput(field, makeDiagnostic("has_no_samples"));
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw InvalidInput(field, makeDiagnostic("sim_sample_not_finite", {std::to_string(i)}));
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

/**
 * Refuses a loop whose state matrix lost the stability of its transfer functions. The closed
 * loop's poles are the roots of den_p den_c + num_p num_c; a realization of badly scaled
 * transfer functions can move them: a plant with k0 = 4.3e12 and a pole at -5.2e8 under a stable
 * Guillemin-Truxal PI (fuzz_design, corpus crash-ill-conditioned-loop) realized a loop matrix
 * (norm 2e14) with an eigenvalue at +1930 1/s, and its run overflowed although the loop is stable.
 * The threshold, 1e-9 of the largest pole's magnitude, is far above the round-off of a sound
 * realization (eps |A|) and keeps a marginal pole at -1e-12 from being refused for its rounding.
 */
void requireRealizationKeepsStability(const TransferFunction& plant,
                                      const TransferFunction& controller,
                                      const Eigen::MatrixXd& aLoop) {
    if (aLoop.rows() == 0)
        return;
    const std::vector<std::complex<double>> poles =
        (plant.den() * controller.den() + plant.num() * controller.num()).roots();
    double scale = 0.0;
    for (const std::complex<double>& pole : poles) {
        if (!(pole.real() < 0.0))
            return; // an unstable loop: its runs diverge by design
        scale = std::max(scale, std::abs(pole));
    }
    const double realized =
        Eigen::EigenSolver<Eigen::MatrixXd>(aLoop, false).eigenvalues().real().maxCoeff();
    if (realized > 1e-9 * scale)
        throw InvalidInput("plant", makeDiagnostic("sim_realization_loses_stability",
                                                   {formatNumber(realized, 4)}));
}

StepMatrices fohStep(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double dt) {
    try {
        FohDiscretization foh = discretizeFoh(a, b, dt);
        return {std::move(foh.phi), std::move(foh.gamma0), std::move(foh.gamma1)};
    } catch (const InvalidInput& e) {
        throw InvalidInput("dt", e.reasonDiagnostic()); // the simulation's step is the user's dt
    }
}

} // namespace

LoopModes loopModes(const TransferFunction& plant, const TransferFunction& controller) {
    if (plant.isDiscrete() || !plant.isStrictlyProper())
        throw InvalidInput("plant", makeDiagnostic("not_continuous_strictly_proper"));
    if (controller.isDiscrete() || !controller.isProper())
        throw InvalidInput("controller", makeDiagnostic("not_continuous_proper"));
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
    requireRealizationKeepsStability(plant, controller, m.aLinear);

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

namespace {

/// One mode's FOH step x <- phi x + g0 w + g1 rho as flat row-major arrays (n x n, n x m).
struct FlatStep {
    std::vector<double> phi, g0, g1;
    int inputs = 0;
    FlatStep() = default;
    FlatStep(const StepMatrices& s) : inputs(static_cast<int>(s.g0.cols())) {
        const Eigen::Index n = s.phi.rows();
        for (Eigen::Index i = 0; i < n; ++i) {
            for (Eigen::Index j = 0; j < n; ++j)
                phi.push_back(s.phi(i, j));
            for (Eigen::Index j = 0; j < s.g0.cols(); ++j) {
                g0.push_back(s.g0(i, j));
                g1.push_back(s.g1(i, j));
            }
        }
    }
};

/**
 * The sample loop of simulateLoop over plain arrays, with N states known at compile time
 * (N = 0: the run-time size @p runtimeN), so that the loops over states unroll. No allocation:
 * it writes into @p out's buffers, sized by the caller. Same summation order as
 * StepMatrices::step, so every N gives the same bits.
 */
template <int N>
void runLoop(int runtimeN, int np, const double* cp, const double* cc, double dc,
             const FlatStep& linear, const FlatStep& clipped, bool limited, double umax,
             double unit, double dt, const std::vector<double>& reference, const double* ff,
             double* xInOut, SimulationResult& out) {
    const int n = N > 0 ? N : runtimeN;
    const int nc = n - np;
    constexpr int kMax = 16; // a loop of more states takes the run-time path below
    // The state, and for a known order the step matrices, in local arrays: the stores to the
    // output signals (double*) cannot alias them, so the compiler keeps them in registers and
    // vectorizes the matrix-vector product. The arithmetic and its order are unchanged.
    constexpr int kLocal = N > 0 ? N : kMax;
    double xBuffer[kLocal], nextBuffer[kLocal];
    std::vector<double> xHeap(N > 0 || n <= kMax ? 0 : static_cast<std::size_t>(n));
    std::vector<double> nextHeap(xHeap.size());
    double* x = xHeap.empty() ? xBuffer : xHeap.data();
    double* next = nextHeap.empty() ? nextBuffer : nextHeap.data();
    for (int i = 0; i < n; ++i)
        x[i] = xInOut[i];
    // The linear mode has one input (r), or two (r, uff) with a feedforward.
    double phiL[N > 0 ? N * N : 1], g0L[N > 0 ? 2 * N : 1], g1L[N > 0 ? 2 * N : 1];
    double phiC[N > 0 ? N * N : 1], g0C[N > 0 ? 2 * N : 1], g1C[N > 0 ? 2 * N : 1];
    if constexpr (N > 0) {
        std::copy(linear.phi.begin(), linear.phi.end(), phiL);
        std::copy(linear.g0.begin(), linear.g0.end(), g0L);
        std::copy(linear.g1.begin(), linear.g1.end(), g1L);
        if (!clipped.phi.empty()) {
            std::copy(clipped.phi.begin(), clipped.phi.end(), phiC);
            std::copy(clipped.g0.begin(), clipped.g0.end(), g0C);
            std::copy(clipped.g1.begin(), clipped.g1.end(), g1C);
        }
    }
    const std::size_t count = reference.size();
    double* t = out.t.data();
    double* yOut = out.y.data();
    double* eOut = out.e.data();
    double* uOut = out.u.data();
    for (std::size_t k = 0; k < count; ++k) {
        double y = 0.0;
        for (int j = 0; j < np; ++j)
            y += cp[j] * x[j];
        const double rk = reference[k] * unit;
        double v = dc * (rk - y) + (ff ? ff[k] : 0.0);
        for (int j = 0; j < nc; ++j)
            v += cc[j] * x[np + j];
        const bool clip = limited && std::abs(v) > umax;
        const double u = clip ? std::copysign(umax, v) : v;
        t[k] = static_cast<double>(k) * dt;
        yOut[k] = y / unit;
        eOut[k] = reference[k] - y / unit;
        uOut[k] = u;
        out.clipped[k] = clip;
        if (k + 1 == count)
            break;
        const double slope = (reference[k + 1] - reference[k]) * unit / dt;
        const FlatStep& step = clip ? clipped : linear;
        const double ffSlope = ff ? (ff[k + 1] - ff[k]) / dt : 0.0;
        const double w[2] = {rk, clip ? u : (ff ? ff[k] : 0.0)};
        const double rho[2] = {slope, clip ? 0.0 : ffSlope};
        const int m = step.inputs;
        const double* phi = N > 0 ? (clip ? phiC : phiL) : step.phi.data();
        const double* g0 = N > 0 ? (clip ? g0C : g0L) : step.g0.data();
        const double* g1 = N > 0 ? (clip ? g1C : g1L) : step.g1.data();
        for (int i = 0; i < n; ++i) {
            double acc = 0.0;
            for (int j = 0; j < n; ++j)
                acc += phi[i * n + j] * x[j];
            for (int j = 0; j < m; ++j)
                acc += g0[i * m + j] * w[j] + g1[i * m + j] * rho[j];
            next[i] = acc;
        }
        for (int i = 0; i < n; ++i)
            x[i] = next[i];
    }
    for (int i = 0; i < n; ++i)
        xInOut[i] = x[i];
}

} // namespace

namespace {

/// What simulateLoopInto and the stepped loop check and set up alike: the loop's modes, the
/// feedforward (null for none) and the plant's state at rest at the initial output.
struct PreparedLoop {
    LoopModes modes;
    const double* ff = nullptr;
    std::vector<double> x;
};

PreparedLoop prepareLoop(const TransferFunction& plant, const TransferFunction& controller,
                         const std::vector<double>& reference,
                         const LoopSimulationOptions& options) {
    PreparedLoop out{loopModes(plant, controller), nullptr, {}};
    requirePositive(options.dtSeconds, "dt");
    if (std::isnan(options.umaxVolts) || !(options.umaxVolts > 0.0))
        throw InvalidInput("umax", makeDiagnostic("sim_umax_positive"));
    requireFinite(options.initialOutput, "initial_output");
    requirePositive(options.modelUnitsPerPositionUnit, "model_unit_scale");
    requireFiniteSignal(reference, "reference");
    const double unit = options.modelUnitsPerPositionUnit;
    const LoopModes& modes = out.modes;
    const Eigen::Index np = modes.plantStates;
    const Eigen::Index n = np + modes.controllerStates;
    if (options.feedforwardVolts && !options.feedforwardVolts->empty()) {
        if (options.feedforwardVolts->size() != reference.size())
            throw InvalidInput("feedforward", makeDiagnostic("sim_one_sample_per_reference"));
        requireFiniteSignal(*options.feedforwardVolts, "feedforward");
        out.ff = options.feedforwardVolts->data();
    }
    out.x.assign(static_cast<std::size_t>(n), 0.0);
    if (options.initialOutput != 0.0) {
        // At rest with output y0: A_p x = 0 and C_p x = y0 (only possible with a pole at 0).
        Eigen::MatrixXd m(np + 1, np);
        m << modes.plantA, modes.plantC;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(np + 1);
        rhs(np) = options.initialOutput * unit;
        const Eigen::VectorXd xp = m.completeOrthogonalDecomposition().solve(rhs);
        if ((m * xp - rhs).norm() > 1e-9 * (1.0 + std::abs(options.initialOutput)))
            throw InvalidInput("initial_output", makeDiagnostic("sim_plant_cannot_rest_away"));
        for (Eigen::Index i = 0; i < np; ++i)
            out.x[static_cast<std::size_t>(i)] = xp(i);
    }
    return out;
}

/// Sizes @p out's signals for @p reference (keeping their capacity) and sets what a run shares.
void startResult(const std::vector<double>& reference, const LoopSimulationOptions& options,
                 const double* ff, SimulationResult& out) {
    const std::size_t count = reference.size();
    out.dtSeconds = options.dtSeconds;
    out.umaxVolts = options.umaxVolts;
    out.r.assign(reference.begin(), reference.end());
    for (std::vector<double>* v : {&out.t, &out.y, &out.e, &out.u})
        v->resize(count);
    out.clipped.resize(count);
    if (ff)
        out.uFeedforward.assign(ff, ff + count);
    else
        out.uFeedforward.clear();
    out.sliding.clear();
}

/// simulateLoop's linear-table loop, one sample at a time (SteppedLoop). The linear mode always
/// has the command's input column, carrying the feedforward plus the extra voltage. The sample
/// allocates nothing.
class LinearLoopStepper final : public SteppedLoop {
public:
    LinearLoopStepper(PreparedLoop prepared, const std::vector<double>& reference,
                      const LoopSimulationOptions& options)
        : x_(std::move(prepared.x)), next_(x_.size()),
          np_(static_cast<std::size_t>(prepared.modes.plantStates)),
          cp_(prepared.modes.plantC.data(), prepared.modes.plantC.data() + np_),
          cc_(prepared.modes.controllerC.data(),
              prepared.modes.controllerC.data() + prepared.modes.controllerStates),
          dc_(prepared.modes.controllerD), unit_(options.modelUnitsPerPositionUnit),
          umax_(options.umaxVolts), dt_(options.dtSeconds) {
        const LoopModes& modes = prepared.modes;
        if (prepared.ff)
            ff_.assign(prepared.ff, prepared.ff + reference.size());
        startResult(reference, options, prepared.ff ? ff_.data() : nullptr, out_);
        Eigen::MatrixXd b(modes.bLinear.rows(), 2);
        b << modes.bLinear, modes.bClipped.col(1);
        linear_ = fohStep(modes.aLinear, b, dt_);
        if (std::isfinite(umax_))
            clipped_ = fohStep(modes.aClipped, modes.bClipped, dt_);
    }
    std::size_t samples() const override { return out_.r.size(); }
    double periodSeconds() const override { return dt_; }
    std::size_t index() const override { return k_; }
    double output() const override { return plantOutput() / unit_; }
    double reference() const override { return out_.r[k_]; }
    bool advance(double extraVolts) override {
        const std::size_t k = k_;
        const double ffk = ff_.empty() ? 0.0 : ff_[k];
        const double y = plantOutput();
        const double rk = out_.r[k] * unit_;
        double v = dc_ * (rk - y) + ffk + extraVolts;
        for (std::size_t j = 0; j < cc_.size(); ++j)
            v += cc_[j] * x_[np_ + j];
        const bool clip = std::abs(v) > umax_;
        const double u = clip ? std::copysign(umax_, v) : v;
        out_.t[k] = static_cast<double>(k) * dt_;
        out_.y[k] = y / unit_;
        out_.e[k] = out_.r[k] - y / unit_;
        out_.u[k] = u;
        out_.clipped[k] = clip;
        ++k_;
        if (k_ == samples())
            return clip;
        const double slope = (out_.r[k + 1] - out_.r[k]) * unit_ / dt_;
        const double ffSlope = ff_.empty() ? 0.0 : (ff_[k + 1] - ff_[k]) / dt_;
        const double w[2] = {rk, clip ? u : ffk + extraVolts};
        const double rho[2] = {slope, clip ? 0.0 : ffSlope};
        (clip ? clipped_ : linear_).step(x_.data(), w, rho, next_.data());
        x_.swap(next_);
        return clip;
    }
    const SimulationResult& result() const override { return out_; }
    SimulationResult takeResult() override { return std::move(out_); }

private:
    double plantOutput() const {
        double y = 0.0;
        for (std::size_t j = 0; j < np_; ++j)
            y += cp_[j] * x_[j];
        return y;
    }

    std::vector<double> x_, next_;
    std::size_t np_;
    std::vector<double> cp_, cc_;
    double dc_;
    std::vector<double> ff_;
    StepMatrices linear_, clipped_;
    double unit_, umax_, dt_;
    std::size_t k_ = 0;
    SimulationResult out_;
};

} // namespace

std::unique_ptr<SteppedLoop> steppedLoop(const TransferFunction& plant,
                                         const TransferFunction& controller,
                                         const std::vector<double>& reference,
                                         const LoopSimulationOptions& options) {
    PreparedLoop prepared = prepareLoop(plant, controller, reference, options);
    if (options.table && options.table->active())
        return steppedTableLoop(plant, controller, reference, options, prepared.ff);
    return std::make_unique<LinearLoopStepper>(std::move(prepared), reference, options);
}

void simulateLoopInto(const TransferFunction& plant, const TransferFunction& controller,
                      const std::vector<double>& reference, const LoopSimulationOptions& options,
                      SimulationResult& out) {
    PreparedLoop prepared = prepareLoop(plant, controller, reference, options);
    const LoopModes& modes = prepared.modes;
    const double* ff = prepared.ff;
    const double unit = options.modelUnitsPerPositionUnit;
    const Eigen::Index np = modes.plantStates;
    const Eigen::Index nc = modes.controllerStates;
    const Eigen::Index n = np + nc;
    // With a feedforward the linear mode's second input is uff, entering where u does.
    Eigen::MatrixXd bLinear = modes.bLinear;
    if (ff) {
        bLinear.conservativeResize(Eigen::NoChange, 2);
        bLinear.col(1) = modes.bClipped.col(1);
    }
    const FlatStep linear(fohStep(modes.aLinear, bLinear, options.dtSeconds));
    const bool limited = std::isfinite(options.umaxVolts);
    FlatStep clipped;
    if (limited)
        clipped = FlatStep(fohStep(modes.aClipped, modes.bClipped, options.dtSeconds));
    std::vector<double>& x = prepared.x;

    // The buffers keep their capacity: a caller that simulates again and again with one
    // SimulationResult (a live view, a benchmark) allocates nothing after the first run.
    startResult(reference, options, ff, out);
    if (options.table && options.table->active()) {
        simulateTableLoopInto(plant, controller, reference, options, ff, out);
        return;
    }
    const std::vector<double> cp(modes.plantC.data(), modes.plantC.data() + np);
    const std::vector<double> cc(modes.controllerC.data(), modes.controllerC.data() + nc);
    const double umax = options.umaxVolts;
    const double dt = options.dtSeconds;
    const int states = static_cast<int>(n);
    const int plantStates = static_cast<int>(np);
    if (states == 4) // a third-order plant under a PI controller: every Guillemin-Truxal loop
        runLoop<4>(4, plantStates, cp.data(), cc.data(), modes.controllerD, linear, clipped,
                   limited, umax, unit, dt, reference, ff, x.data(), out);
    else
        runLoop<0>(states, plantStates, cp.data(), cc.data(), modes.controllerD, linear, clipped,
                   limited, umax, unit, dt, reference, ff, x.data(), out);
}

SimulationResult simulateLoop(const TransferFunction& plant, const TransferFunction& controller,
                              const std::vector<double>& reference,
                              const LoopSimulationOptions& options) {
    SimulationResult out;
    simulateLoopInto(plant, controller, reference, options, out);
    return out;
}

std::vector<double> simulateLinear(const TransferFunction& system, const std::vector<double>& input,
                                   double dtSeconds) {
    if (system.isDiscrete() || !system.isProper())
        throw InvalidInput("system", makeDiagnostic("not_continuous_proper"));
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
