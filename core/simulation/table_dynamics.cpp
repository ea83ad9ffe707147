// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/table_dynamics.h"

#include "core/model/errors.h"
#include "core/model/state_space.h"
#include "core/simulation/simulation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace xyt {

TableMechanics tableMechanics(const TransferFunction& plant, const TableFriction& friction,
                              double modelUnitsPerMm) {
    validateTableFriction(friction);
    requirePositive(modelUnitsPerMm, "model_unit_scale");
    const auto& num = plant.num().ascending();
    const auto& den = plant.den().ascending();
    const char* shape = "must be k0 / (s (s^2 + a1 s + a2)) with k0 > 0 for the table's friction";
    if (plant.isDiscrete() || plant.num().degree() != 0 || plant.den().degree() != 3 ||
        den[0] != 0.0)
        throw InvalidInput("plant", shape);
    const double lead = den[3];
    const double k0 = num[0] / lead, a1 = den[2] / lead, a2 = den[1] / lead;
    if (!(k0 > 0.0) || !std::isfinite(k0))
        throw InvalidInput("plant", shape);
    const double disc = a1 * a1 - 4.0 * a2;
    if (!(disc >= 0.0) || !(a1 > 0.0) || a2 < 0.0)
        throw InvalidInput("plant", "the poles of s^2 + a1 s + a2 must be real and stable to "
                                    "split the plant into an electrical lag and a moving mass");
    // Roots of s^2 + a1 s + a2 as -fast and -slow, the smaller one from the product (no
    // cancellation).
    const double fast = 0.5 * (a1 + std::sqrt(disc));
    const double slow = a2 / fast;
    TableMechanics m;
    m.electricalPole = friction.electricalPole == ElectricalPole::Faster ? fast : slow;
    m.mechanicalPole = friction.electricalPole == ElectricalPole::Faster ? slow : fast;
    if (!(m.electricalPole > 0.0))
        throw InvalidInput("plant", "the electrical pole must be > 0 (a2 = 0 leaves one pole at "
                                    "0, which can only be the mechanical one)");
    m.forceGain = k0 / m.electricalPole;
    m.coulomb = friction.coulombVolts;
    m.breakaway = friction.breakawayVolts();
    m.stribeckVelocity = friction.stribeckVelocityMmPerS * modelUnitsPerMm;
    m.viscous = friction.viscousVoltsPerMmPerS / modelUnitsPerMm;
    m.backlash = friction.backlashMm * modelUnitsPerMm;
    m.deadband = friction.amplifierDeadbandVolts;
    return m;
}

namespace {

constexpr int kMaxStates = 24; // z, v, x_m and up to 21 controller states
using Vec = std::array<double, kMaxStates>;
constexpr double kEventTimeTolerance = 1e-13; // s
constexpr int kMaxEventsPerSubstep = 16;      // a guard against a Zeno sequence of switches

/// What commands the table over one sample: a held command, or the continuous controller with
/// the reference and feedforward linear in time from the sample's start.
struct Drive {
    bool closed = false;
    double heldVolts = 0.0;
    int nc = 0;
    const double* ac = nullptr;
    const double* bc = nullptr;
    const double* cc = nullptr;
    double dc = 0.0;
    double r0 = 0.0, rSlope = 0.0, ff0 = 0.0, ffSlope = 0.0;
    double umax = std::numeric_limits<double>::infinity();
};

/// The hybrid system of TableMechanics with its Runge-Kutta step and event location.
class Engine {
public:
    explicit Engine(const TableMechanics& m) : m_(m), half_(0.5 * m.backlash) {}

    double play(double table, double motor) const {
        if (half_ == 0.0)
            return motor;
        return std::clamp(table, motor - half_, motor + half_);
    }

    /// The controller's command before the limit and the limited one.
    double command(const Drive& d, double tau, const Vec& x, double y,
                   double* raw = nullptr) const {
        if (!d.closed)
            return d.heldVolts;
        const double e = d.r0 + d.rSlope * tau - y;
        double v = d.dc * e + d.ff0 + d.ffSlope * tau;
        for (int j = 0; j < d.nc; ++j)
            v += d.cc[j] * x[static_cast<std::size_t>(3 + j)];
        if (raw)
            *raw = v;
        return std::clamp(v, -d.umax, d.umax);
    }

    void derivative(const Drive& d, int sliding, double tau, const Vec& x, double table,
                    Vec& dx) const {
        const double y = play(table, x[2]);
        const double u = command(d, tau, x, y);
        const double ua = m_.deadband == 0.0 ? u : u - std::clamp(u, -m_.deadband, m_.deadband);
        dx[0] = m_.electricalPole * (ua - x[0]);
        if (sliding == 0) {
            dx[1] = 0.0;
            dx[2] = 0.0;
        } else {
            dx[1] = m_.forceGain * (x[0] - friction(x[1], sliding)) - m_.mechanicalPole * x[1];
            dx[2] = x[1];
        }
        if (d.closed) {
            const double e = d.r0 + d.rSlope * tau - y;
            for (int i = 0; i < d.nc; ++i) {
                double acc = d.bc[i] * e;
                for (int j = 0; j < d.nc; ++j)
                    acc += d.ac[i * d.nc + j] * x[static_cast<std::size_t>(3 + j)];
                dx[static_cast<std::size_t>(3 + i)] = acc;
            }
        }
    }

    double friction(double v, int sliding) const {
        if (!m_.dry())
            return m_.viscous * v;
        double level = m_.coulomb;
        if (m_.breakaway > m_.coulomb) {
            const double q = v / m_.stribeckVelocity;
            level += (m_.breakaway - m_.coulomb) * std::exp(-q * q);
        }
        return static_cast<double>(sliding) * level + m_.viscous * v;
    }

    void rk4(const Drive& d, int sliding, double tau, const Vec& x, double table, double h, int n,
             Vec& out) const {
        Vec k1, k2, k3, k4, tmp;
        derivative(d, sliding, tau, x, table, k1);
        for (int i = 0; i < n; ++i)
            tmp[i] = x[i] + 0.5 * h * k1[i];
        derivative(d, sliding, tau + 0.5 * h, tmp, table, k2);
        for (int i = 0; i < n; ++i)
            tmp[i] = x[i] + 0.5 * h * k2[i];
        derivative(d, sliding, tau + 0.5 * h, tmp, table, k3);
        for (int i = 0; i < n; ++i)
            tmp[i] = x[i] + h * k3[i];
        derivative(d, sliding, tau + h, tmp, table, k4);
        for (int i = 0; i < n; ++i)
            out[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }

    /// >= 0 in the current mode, < 0 past its switch: the velocity along the sliding direction,
    /// or the margin of the drive force below breakaway while stuck.
    double eventValue(int sliding, const Vec& x) const {
        return sliding != 0 ? static_cast<double>(sliding) * x[1] : m_.breakaway - std::abs(x[0]);
    }

    /// Advances [tau, tau + h], switching at the located stick and slip events.
    void substep(const Drive& d, double tau, double h, int n, Vec& x, double& table, int& sliding,
                 std::uint64_t& transitions) const {
        double remaining = h;
        for (int events = 0;; ++events) {
            if (m_.dry() && sliding == 0 && std::abs(x[0]) > m_.breakaway) {
                sliding = x[0] > 0.0 ? 1 : -1; // breakaway at the sub-step's start
                ++transitions;
            }
            Vec end;
            rk4(d, sliding, tau, x, table, remaining, n, end);
            if (!m_.dry() || events >= kMaxEventsPerSubstep || eventValue(sliding, end) >= 0.0) {
                x = end;
                table = play(table, x[2]);
                return;
            }
            const double at = locate(d, sliding, tau, x, table, remaining, n, end);
            x = end;
            table = play(table, x[2]);
            tau += at;
            remaining -= at;
            if (sliding != 0) {
                x[1] = 0.0;
                sliding = std::abs(x[0]) <= m_.breakaway ? 0 : (x[0] > 0.0 ? 1 : -1);
            } else {
                sliding = x[0] > 0.0 ? 1 : -1;
            }
            ++transitions;
            if (remaining <= 0.0)
                return;
        }
    }

    const TableMechanics& mechanics() const { return m_; }

    /// The largest rate of the table alone: pe, pm and the friction's slopes times g.
    double tableRate() const {
        double rate = std::max(m_.electricalPole, m_.mechanicalPole);
        rate = std::max(rate, m_.forceGain * m_.viscous + m_.mechanicalPole);
        if (m_.breakaway > m_.coulomb) // max |d/dv exp(-(v/vs)^2)| = sqrt(2/e) / vs
            rate = std::max(rate, m_.forceGain * (m_.breakaway - m_.coulomb) *
                                      std::sqrt(2.0 / std::exp(1.0)) / m_.stribeckVelocity);
        return rate;
    }

private:
    /// The switch time in (0, h] (Illinois regula falsi on the Runge-Kutta solution from @p x);
    /// @p at receives the state there.
    double locate(const Drive& d, int sliding, double tau, const Vec& x, double table, double h,
                  int n, Vec& at) const {
        double lo = 0.0, hi = h;
        double gLo = eventValue(sliding, x);
        double gHi = eventValue(sliding, at);
        int side = 0;
        Vec trial;
        for (int iter = 0; iter < 200 && hi - lo > kEventTimeTolerance; ++iter) {
            double theta = gLo > gHi ? (gLo * hi - gHi * lo) / (gLo - gHi) : 0.5 * (lo + hi);
            if (!(theta > lo && theta < hi))
                theta = 0.5 * (lo + hi);
            rk4(d, sliding, tau, x, table, theta, n, trial);
            const double g = eventValue(sliding, trial);
            if (g >= 0.0) {
                lo = theta;
                gLo = g;
                if (side == 1)
                    gHi *= 0.5;
                side = 1;
            } else {
                hi = theta;
                gHi = g;
                at = trial;
                if (side == -1)
                    gLo *= 0.5;
                side = -1;
            }
        }
        return hi;
    }

    TableMechanics m_;
    double half_;
};

int substepsFor(double rate, double seconds, int minimum) {
    // h rate <= 1/4, at most 1000 sub-steps per sample.
    const double wanted = std::ceil(4.0 * rate * seconds);
    const int count = wanted > 1000.0 ? 1000 : std::max(1, static_cast<int>(wanted));
    return std::max(count, minimum);
}

} // namespace

TablePlant::TablePlant(const TableMechanics& mechanics, double initialModel) : m_(mechanics) {
    state_.motor = initialModel;
    state_.table = initialModel;
    state_.sliding = m_.dry() ? 0 : 1;
}

void TablePlant::hold(double volts, double seconds, int minSubsteps) {
    const Engine engine(m_);
    Drive d;
    d.heldVolts = volts;
    const int steps = substepsFor(engine.tableRate(), seconds, minSubsteps);
    const double h = seconds / steps;
    Vec x{};
    x[0] = state_.drive;
    x[1] = state_.velocity;
    x[2] = state_.motor;
    for (int i = 0; i < steps; ++i)
        engine.substep(d, static_cast<double>(i) * h, h, 3, x, state_.table, state_.sliding,
                       transitions_);
    state_.drive = x[0];
    state_.velocity = x[1];
    state_.motor = x[2];
}

void simulateTableLoopInto(const TransferFunction& plant, const TransferFunction& controller,
                           const std::vector<double>& reference,
                           const LoopSimulationOptions& options, const double* ff,
                           SimulationResult& out) {
    const double unit = options.modelUnitsPerPositionUnit;
    const Engine engine(tableMechanics(plant, *options.table, unit));
    const StateSpace c = realize(controller);
    const int nc = static_cast<int>(c.states());
    if (nc + 3 > kMaxStates)
        throw InvalidInput("controller", "has more states than the friction simulation holds (" +
                                             std::to_string(kMaxStates - 3) + ")");
    std::vector<double> ac(static_cast<std::size_t>(nc * nc)), bc(static_cast<std::size_t>(nc)),
        cc(static_cast<std::size_t>(nc));
    for (int i = 0; i < nc; ++i) {
        for (int j = 0; j < nc; ++j)
            ac[static_cast<std::size_t>(i * nc + j)] = c.a(i, j);
        bc[static_cast<std::size_t>(i)] = c.b(i, 0);
        cc[static_cast<std::size_t>(i)] = c.c(0, i);
    }
    // The fastest rate of the loop: the table's own and the linear closed loop's poles.
    double rate = engine.tableRate();
    const LoopModes modes = loopModes(plant, controller);
    for (const Eigen::MatrixXd* a : {&modes.aLinear, &modes.aClipped})
        if (a->rows() > 0)
            rate = std::max(rate, a->eigenvalues().cwiseAbs().maxCoeff());
    const double dt = options.dtSeconds;
    if (options.tableSubsteps < 0)
        throw InvalidInput("table_substeps", "must be >= 0 (0: automatic)");
    const int steps = options.tableSubsteps > 0 ? options.tableSubsteps : substepsFor(rate, dt, 1);
    const double h = dt / steps;

    Drive d;
    d.closed = true;
    d.nc = nc;
    d.ac = ac.data();
    d.bc = bc.data();
    d.cc = cc.data();
    d.dc = c.d(0, 0);
    d.umax = options.umaxVolts;
    const int n = 3 + nc;
    Vec x{};
    x[2] = options.initialOutput * unit;
    double table = x[2];
    int sliding = engine.mechanics().dry() ? 0 : 1;
    std::uint64_t transitions = 0;
    const std::size_t count = reference.size();
    const bool dry = engine.mechanics().dry();
    out.sliding.assign(dry ? count : 0, 0);
    for (std::size_t k = 0; k < count; ++k) {
        d.r0 = reference[k] * unit;
        d.ff0 = ff ? ff[k] : 0.0;
        const bool last = k + 1 == count;
        d.rSlope = last ? 0.0 : (reference[k + 1] - reference[k]) * unit / dt;
        d.ffSlope = (ff && !last) ? (ff[k + 1] - ff[k]) / dt : 0.0;
        double raw = 0.0;
        const double u = engine.command(d, 0.0, x, table, &raw);
        out.t[k] = static_cast<double>(k) * dt;
        out.y[k] = table / unit;
        out.e[k] = reference[k] - table / unit;
        out.u[k] = u;
        out.clipped[k] = std::abs(raw) > d.umax;
        if (dry)
            out.sliding[k] = static_cast<std::int8_t>(sliding);
        if (last)
            break;
        for (int i = 0; i < steps; ++i)
            engine.substep(d, static_cast<double>(i) * h, h, n, x, table, sliding, transitions);
    }
}

} // namespace xyt
