// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/table_dynamics.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/state_space.h"
#include "core/simulation/loop_stepper.h"
#include "core/simulation/simulation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

namespace xyt {

TableMechanics tableMechanics(const TransferFunction& plant, const TableFriction& friction,
                              double modelUnitsPerMm) {
    validateTableFriction(friction);
    requirePositive(modelUnitsPerMm, "model_unit_scale");
    const auto& num = plant.num().ascending();
    const auto& den = plant.den().ascending();
    const auto shapeDiagnostic = [] { return makeDiagnostic("sim_table_plant_shape"); };
    if (plant.isDiscrete() || plant.num().degree() != 0 || plant.den().degree() != 3 ||
        den[0] != 0.0)
        throw InvalidInput("plant", shapeDiagnostic());
    const double lead = den[3];
    const double k0 = num[0] / lead, a1 = den[2] / lead, a2 = den[1] / lead;
    if (!(k0 > 0.0) || !std::isfinite(k0))
        throw InvalidInput("plant", shapeDiagnostic());
    const double disc = a1 * a1 - 4.0 * a2;
    if (!(disc >= 0.0) || !(a1 > 0.0) || a2 < 0.0)
        throw InvalidInput("plant", makeDiagnostic("sim_table_poles_not_real"));
    // Roots of s^2 + a1 s + a2 as -fast and -slow, the smaller one from the product (no
    // cancellation).
    const double fast = 0.5 * (a1 + std::sqrt(disc));
    const double slow = a2 / fast;
    TableMechanics m;
    m.electricalPole = friction.electricalPole == ElectricalPole::Faster ? fast : slow;
    m.mechanicalPole = friction.electricalPole == ElectricalPole::Faster ? slow : fast;
    if (!(m.electricalPole > 0.0))
        throw InvalidInput("plant", makeDiagnostic("sim_table_electrical_pole"));
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
        return stribeckFriction(m_.coulomb, m_.breakaway, m_.stribeckVelocity, m_.viscous, v,
                                static_cast<double>(sliding));
    }

    void rk4(const Drive& d, int sliding, double tau, const Vec& x, double table, double h, int n,
             Vec& out) const {
        Vec k1, k2, k3, k4, tmp{}; // tmp zeroed: its entries past n are never read
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

namespace {

/**
 * The exact steps of the loop on a table whose friction is Coulomb and viscous only (no Stribeck
 * dip) and whose amplifier has no deadband: in each mode (the mass stuck or sliding either way;
 * the motor pushing the table forward, backward or crossing the backlash gap; u inside the limits
 * or clipped at either one) the loop is affine, x' = A x + B w with w = [r, uff, 1, y_free], and
 * its sample step is discretized exactly (first-order hold on r and uff, discretizeFoh), once per
 * mode met. A sample whose mode holds from start to end (checked at its end: the mass did not
 * reverse, stick or break away, the gap was not crossed, u did not cross a limit) takes that
 * step; any other sample is integrated by the Runge-Kutta engine with its located events. So the
 * run costs about one linear step per sample away from the events, and the events keep the
 * engine's accuracy. (A switch and its undoing within one sample would go unseen; at the
 * sample times of a loop this is a motion faster than the loop resolves.)
 */
class AffineModes {
public:
    AffineModes(const TableMechanics& m, int nc, const double* ac, const double* bc,
                const double* cc, double dc, double umax, double dt)
        : m_(m), nc_(nc), ac_(ac), bc_(bc), cc_(cc), dc_(dc), umax_(umax), dt_(dt),
          half_(0.5 * m.backlash) {}

    static bool applies(const TableMechanics& m) {
        return m.deadband == 0.0 && !(m.breakaway > m.coulomb);
    }

    /// One sample from @p x in mode (sliding, contact, clip) with inputs w and slopes rho.
    void step(int sliding, int contact, int clip, const double* x, const double* w,
              const double* rho, double* out) {
        const int key = (sliding + 1) * 9 + (contact + 1) * 3 + (clip + 1);
        if (key != lastKey_) {
            auto it = steps_.find(key);
            if (it == steps_.end())
                it = steps_.emplace(key, flat(build(sliding, contact, clip))).first;
            last_ = &it->second;
            lastKey_ = key;
        }
        const int n = 3 + nc_;
        const double* phi = last_->phi.data();
        const double* g0 = last_->g0.data();
        const double* g1 = last_->g1.data();
        for (int i = 0; i < n; ++i) {
            double acc = 0.0;
            for (int j = 0; j < n; ++j)
                acc += phi[i * n + j] * x[j];
            for (int j = 0; j < 4; ++j)
                acc += g0[i * 4 + j] * w[j] + g1[i * 4 + j] * rho[j];
            out[i] = acc;
        }
    }

private:
    /// A mode's step in row-major arrays (the hot loop reads them in order).
    struct FlatMode {
        std::vector<double> phi, g0, g1;
    };
    static FlatMode flat(const FohDiscretization& f) {
        FlatMode out;
        const auto rows = [](const Eigen::MatrixXd& m) {
            std::vector<double> v(static_cast<std::size_t>(m.size()));
            for (Eigen::Index i = 0; i < m.rows(); ++i)
                for (Eigen::Index j = 0; j < m.cols(); ++j)
                    v[static_cast<std::size_t>(i * m.cols() + j)] = m(i, j);
            return v;
        };
        out.phi = rows(f.phi);
        out.g0 = rows(f.gamma0);
        out.g1 = rows(f.gamma1);
        return out;
    }

    FohDiscretization build(int sliding, int contact, int clip) const {
        const int n = 3 + nc_;
        // e = r - y: engaged y = x_m - contact b/2; free y = y_free.
        Eigen::RowVectorXd ex = Eigen::RowVectorXd::Zero(n), ew = Eigen::RowVectorXd::Zero(4);
        ew(0) = 1.0;
        if (contact != 0) {
            ex(2) = -1.0;
            ew(2) = static_cast<double>(contact) * half_;
        } else {
            ew(3) = -1.0;
        }
        Eigen::RowVectorXd ux = Eigen::RowVectorXd::Zero(n), uw = Eigen::RowVectorXd::Zero(4);
        if (clip == 0) {
            ux = dc_ * ex;
            uw = dc_ * ew;
            for (int j = 0; j < nc_; ++j)
                ux(3 + j) += cc_[j];
            uw(1) += 1.0;
        } else {
            uw(2) = static_cast<double>(clip) * umax_;
        }
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n), b = Eigen::MatrixXd::Zero(n, 4);
        a.row(0) = m_.electricalPole * ux;
        a(0, 0) -= m_.electricalPole;
        b.row(0) = m_.electricalPole * uw;
        if (sliding != 0) {
            a(1, 0) = m_.forceGain;
            a(1, 1) = -(m_.mechanicalPole + m_.forceGain * m_.viscous);
            b(1, 2) = -m_.forceGain * static_cast<double>(sliding) * m_.coulomb;
            a(2, 1) = 1.0;
        }
        for (int i = 0; i < nc_; ++i) {
            a.row(3 + i) = bc_[i] * ex;
            for (int j = 0; j < nc_; ++j)
                a(3 + i, 3 + j) += ac_[i * nc_ + j];
            b.row(3 + i) = bc_[i] * ew;
        }
        return discretizeFoh(a, b, dt_);
    }

    const TableMechanics& m_;
    int nc_;
    const double *ac_, *bc_, *cc_;
    double dc_, umax_, dt_, half_;
    std::unordered_map<int, FlatMode> steps_;
    const FlatMode* last_ = nullptr;
    int lastKey_ = -1;
};

} // namespace

namespace {

/// simulateTableLoopInto's loop, one sample at a time: its state is the run's, so that
/// simulateTableLoopInto and the stepped loop (SteppedLoop) are the very same arithmetic.
class TableLoop {
public:
    TableLoop(const TransferFunction& plant, const TransferFunction& controller,
              const LoopSimulationOptions& options, const double* ff, SimulationResult& out)
        : engine_(tableMechanics(plant, *options.table, options.modelUnitsPerPositionUnit)),
          unit_(options.modelUnitsPerPositionUnit), dt_(options.dtSeconds), ff_(ff), out_(out) {
        const StateSpace c = realize(controller);
        nc_ = static_cast<int>(c.states());
        if (nc_ + 3 > kMaxStates)
            throw InvalidInput("controller", makeDiagnostic("sim_table_controller_states",
                                                            {std::to_string(kMaxStates - 3)}));
        const auto size = static_cast<std::size_t>(nc_);
        ac_.resize(size * size);
        bc_.resize(size);
        cc_.resize(size);
        for (int i = 0; i < nc_; ++i) {
            for (int j = 0; j < nc_; ++j)
                ac_[static_cast<std::size_t>(i * nc_ + j)] = c.a(i, j);
            bc_[static_cast<std::size_t>(i)] = c.b(i, 0);
            cc_[static_cast<std::size_t>(i)] = c.c(0, i);
        }
        // The fastest rate of the loop: the table's own and the linear closed loop's poles.
        double rate = engine_.tableRate();
        const LoopModes modes = loopModes(plant, controller);
        for (const Eigen::MatrixXd* a : {&modes.aLinear, &modes.aClipped})
            if (a->rows() > 0)
                rate = std::max(rate, a->eigenvalues().cwiseAbs().maxCoeff());
        if (options.tableSubsteps < 0)
            throw InvalidInput("table_substeps", makeDiagnostic("sim_substeps_not_negative"));
        steps_ = options.tableSubsteps > 0 ? options.tableSubsteps : substepsFor(rate, dt_, 1);
        h_ = dt_ / steps_;

        d_.closed = true;
        d_.nc = nc_;
        d_.ac = ac_.data();
        d_.bc = bc_.data();
        d_.cc = cc_.data();
        d_.dc = c.d(0, 0);
        d_.umax = options.umaxVolts;
        n_ = 3 + nc_;
        x_[2] = options.initialOutput * unit_;
        table_ = x_[2];
        const TableMechanics& mech = engine_.mechanics();
        sliding_ = mech.dry() ? 0 : 1;
        // The exact steps where they apply (AffineModes); the engine for the rest.
        if (AffineModes::applies(mech) && options.tableSubsteps == 0)
            affine_.emplace(mech, nc_, ac_.data(), bc_.data(), cc_.data(), c.d(0, 0),
                            options.umaxVolts, dt_);
        half_ = 0.5 * mech.backlash;
        out_.sliding.assign(mech.dry() ? out_.r.size() : 0, 0);
    }

    std::size_t index() const { return k_; }
    double output() const { return table_ / unit_; }

    /// Records sample k with @p extra volts held over the period (a feedforward offset) and
    /// advances to k + 1; returns whether u was clipped.
    bool advance(double extra) {
        const std::size_t k = k_++;
        const std::vector<double>& reference = out_.r;
        const std::size_t count = reference.size();
        d_.r0 = reference[k] * unit_;
        d_.ff0 = (ff_ ? ff_[k] : 0.0) + extra;
        const bool last = k + 1 == count;
        d_.rSlope = last ? 0.0 : (reference[k + 1] - reference[k]) * unit_ / dt_;
        d_.ffSlope = (ff_ && !last) ? (ff_[k + 1] - ff_[k]) / dt_ : 0.0;
        double raw = 0.0;
        const double u = engine_.command(d_, 0.0, x_, table_, &raw);
        out_.t[k] = static_cast<double>(k) * dt_;
        out_.y[k] = table_ / unit_;
        out_.e[k] = reference[k] - table_ / unit_;
        out_.u[k] = u;
        const bool clip = std::abs(raw) > d_.umax;
        out_.clipped[k] = clip;
        if (engine_.mechanics().dry())
            out_.sliding[k] = static_cast<std::int8_t>(sliding_);
        if (last)
            return clip;
        if (affine_ && exactStep(raw))
            return clip;
        for (int i = 0; i < steps_; ++i)
            engine_.substep(d_, static_cast<double>(i) * h_, h_, n_, x_, table_, sliding_,
                            transitions_);
        return clip;
    }

private:
    /// The side the motor pushes the table from (+1: the table at x_m - b/2), or 0 inside the
    /// gap.
    int contactOf() const {
        if (half_ == 0.0)
            return 1;
        // At the gap's edge to round-off: x_m - (x_m - b/2) is b/2 to a few ulps of x_m.
        const double gap = x_[2] - table_;
        const double tolerance = 1e-9 * half_ + 1e-14 * std::abs(x_[2]);
        if (gap >= half_ - tolerance)
            return 1;
        if (gap <= -half_ + tolerance)
            return -1;
        return 0;
    }

    /// One exact step of the sample (AffineModes) when its mode holds to the sample's end.
    bool exactStep(double raw) {
        const TableMechanics& mech = engine_.mechanics();
        const int contact = contactOf();
        int& s = sliding_;
        // Moving forward the motor can only push forward (or cross the gap), and so on. Without
        // dry friction the mass never sticks (s stays +1): its velocity gives the direction.
        const int direction = mech.dry() ? s : (x_[1] > 0.0 ? 1 : (x_[1] < 0.0 ? -1 : 0));
        if (direction != 0 && contact != 0 && contact != direction && half_ > 0.0)
            return false;
        const int clip = std::abs(raw) > d_.umax ? (raw > 0.0 ? 1 : -1) : 0;
        const double w[4] = {d_.r0, d_.ff0, 1.0, table_};
        const double rho[4] = {d_.rSlope, d_.ffSlope, 0.0, 0.0};
        Vec next; // its first n entries are written
        affine_->step(s, contact, clip, x_.data(), w, rho, next.data());
        // The mode must hold to the sample's end.
        if (mech.dry() && s != 0 && static_cast<double>(s) * next[1] < 0.0)
            return false; // the mass reversed or stopped: the engine locates it
        if (half_ > 0.0 && contact != 0 && static_cast<double>(contact) * next[1] < 0.0)
            return false; // the motor turned back from the table: the gap opens
        if (s == 0 && std::abs(next[0]) > mech.breakaway)
            return false; // it broke away
        const double yNext = contact != 0 ? next[2] - static_cast<double>(contact) * half_ : table_;
        if (contact == 0 && std::abs(next[2] - table_) >= half_)
            return false; // the motor reached the other side of the gap
        Drive end = d_;
        end.r0 = d_.r0 + d_.rSlope * dt_;
        end.ff0 = d_.ff0 + d_.ffSlope * dt_;
        end.rSlope = end.ffSlope = 0.0;
        double rawEnd = 0.0;
        engine_.command(end, 0.0, next, yNext, &rawEnd);
        const int clipEnd = std::abs(rawEnd) > d_.umax ? (rawEnd > 0.0 ? 1 : -1) : 0;
        if (clipEnd != clip)
            return false; // u crossed a limit
        std::copy_n(next.begin(), n_, x_.begin());
        table_ = yNext;
        return true;
    }

    const Engine engine_;
    double unit_, dt_;
    const double* ff_;
    SimulationResult& out_;
    int nc_ = 0, n_ = 0, steps_ = 1;
    double h_ = 0.0, half_ = 0.0;
    std::vector<double> ac_, bc_, cc_;
    Drive d_;
    Vec x_{};
    double table_ = 0.0;
    int sliding_ = 0;
    std::uint64_t transitions_ = 0;
    std::optional<AffineModes> affine_;
    std::size_t k_ = 0;
};

/// TableLoop as a SteppedLoop, owning its run and its feedforward.
class TableLoopStepper final : public SteppedLoop {
public:
    TableLoopStepper(const TransferFunction& plant, const TransferFunction& controller,
                     const std::vector<double>& reference, const LoopSimulationOptions& options,
                     const double* ff)
        : ff_(ff ? std::vector<double>(ff, ff + reference.size()) : std::vector<double>()),
          dt_(options.dtSeconds) {
        out_.dtSeconds = options.dtSeconds;
        out_.umaxVolts = options.umaxVolts;
        out_.r = reference;
        for (std::vector<double>* v : {&out_.t, &out_.y, &out_.e, &out_.u})
            v->resize(reference.size());
        out_.clipped.resize(reference.size());
        out_.uFeedforward = ff_;
        loop_.emplace(plant, controller, options, ff_.empty() ? nullptr : ff_.data(), out_);
    }
    std::size_t samples() const override { return out_.r.size(); }
    double periodSeconds() const override { return dt_; }
    std::size_t index() const override { return loop_->index(); }
    double output() const override { return loop_->output(); }
    double reference() const override { return out_.r[loop_->index()]; }
    bool advance(double extraVolts) override { return loop_->advance(extraVolts); }
    const SimulationResult& result() const override { return out_; }
    SimulationResult takeResult() override { return std::move(out_); }

private:
    std::vector<double> ff_;
    double dt_;
    SimulationResult out_;
    std::optional<TableLoop> loop_;
};

} // namespace

void simulateTableLoopInto(const TransferFunction& plant, const TransferFunction& controller,
                           const std::vector<double>& reference,
                           const LoopSimulationOptions& options, const double* ff,
                           SimulationResult& out) {
    TableLoop loop(plant, controller, options, ff, out);
    for (std::size_t k = 0; k < reference.size(); ++k)
        loop.advance(0.0);
}

std::unique_ptr<SteppedLoop> steppedTableLoop(const TransferFunction& plant,
                                              const TransferFunction& controller,
                                              const std::vector<double>& reference,
                                              const LoopSimulationOptions& options,
                                              const double* ff) {
    return std::make_unique<TableLoopStepper>(plant, controller, reference, options, ff);
}

} // namespace xyt
