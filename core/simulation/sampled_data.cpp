// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/sampled_data.h"

#include "core/simulation/table_dynamics.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/model/state_space.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>

namespace xyt {

void validateSampledDataOptions(const SampledDataOptions& options) {
    if (options.delaySamples < 0 || options.delaySamples > kMaxDelaySamples)
        throw InvalidInput("delay_samples",
                           makeDiagnostic("sim_integer_up_to", {std::to_string(kMaxDelaySamples)}));
    if (!std::isfinite(options.encoderResolution) || options.encoderResolution < 0.0)
        throw InvalidInput("encoder_resolution", makeDiagnostic("sim_encoder_resolution"));
    if (options.dacBits < 0 || options.dacBits > 32)
        throw InvalidInput("dac_bits", makeDiagnostic("sim_dac_bits"));
    if (std::isnan(options.umaxVolts) || !(options.umaxVolts > 0.0))
        throw InvalidInput("umax", makeDiagnostic("sim_umax_positive"));
    if (options.dacBits > 0 && !std::isfinite(options.umaxVolts))
        throw InvalidInput("dac_bits", makeDiagnostic("sim_dac_needs_umax"));
}

double dacOutput(double volts, int bits, double umaxVolts) {
    if (bits == 0)
        return volts;
    const double levels = std::ldexp(1.0, bits); // 2^bits, exact
    const double q = 2.0 * umaxVolts / levels;
    const double half = levels / 2.0;
    const double code = std::clamp(std::floor(volts / q + 0.5), -half, half - 1.0);
    return code * q;
}

SampledPlant sampledPlant(const TransferFunction& plant, double tsSeconds) {
    if (plant.isDiscrete() || !plant.isStrictlyProper())
        throw InvalidInput("plant", makeDiagnostic("not_continuous_strictly_proper"));
    requirePositive(tsSeconds, "ts");
    const StateSpace d = discretizeZoh(realize(plant), tsSeconds);
    SampledPlant p;
    p.states = static_cast<int>(d.states());
    p.tsSeconds = tsSeconds;
    for (Eigen::Index i = 0; i < d.states(); ++i) {
        for (Eigen::Index j = 0; j < d.states(); ++j)
            p.phi.push_back(d.a(i, j));
        p.gamma.push_back(d.b(i, 0));
        p.c.push_back(d.c(0, i));
    }
    for (double v : p.phi)
        if (!std::isfinite(v))
            throw InvalidInput("ts", makeDiagnostic("sim_discretization_overflows"));
    return p;
}

namespace {

void requireFiniteSamples(const std::vector<double>& v, std::size_t count) {
    if (count == 0 || v.size() < count)
        throw InvalidInput(
            "reference",
            makeDiagnostic("sim_needs_samples", {std::to_string(std::max<std::size_t>(count, 1)),
                                                 std::to_string(v.size())}));
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(v[i]))
            throw InvalidInput("reference",
                               makeDiagnostic("sim_sample_not_finite", {std::to_string(i)}));
}

void resizeRun(SampledDataRun& run, std::size_t n, double ts, double umax) {
    SimulationResult& s = run.result;
    for (std::vector<double>* v : {&s.t, &s.r, &s.y, &s.e, &s.u, &run.measured, &run.applied})
        v->resize(n);
    s.clipped.resize(n);
    s.dtSeconds = ts;
    s.umaxVolts = umax;
}

/// The delay line between the controller and the DAC output the plant sees: a ring of the
/// last `delay` commands, oldest out first.
class DelayLine {
public:
    DelayLine(int delay, double rest) : buffer_(static_cast<std::size_t>(delay), rest) {}
    double push(double u) {
        if (buffer_.empty())
            return u;
        const double out = buffer_[head_];
        buffer_[head_] = u;
        head_ = head_ + 1 == buffer_.size() ? 0 : head_ + 1;
        return out;
    }

private:
    std::vector<double> buffer_;
    std::size_t head_ = 0;
};

} // namespace

namespace {

/// The table of @p options on @p plant, or none for a linear table.
std::optional<TablePlant> tablePlantFor(const TransferFunction& plant,
                                        const SampledDataOptions& options, double unit) {
    if (!options.table || !options.table->active())
        return std::nullopt;
    return TablePlant(tableMechanics(plant, *options.table, unit));
}

/// The feedforward of @p options for @p n samples, or null for none.
const double* sampledFeedforward(const SampledDataOptions& options, std::size_t n) {
    if (!options.feedforwardVolts || options.feedforwardVolts->empty())
        return nullptr;
    if (options.feedforwardVolts->size() < n)
        throw InvalidInput("feedforward", makeDiagnostic("sim_one_sample_per_reference"));
    for (double v : *options.feedforwardVolts)
        if (!std::isfinite(v))
            throw InvalidInput("feedforward", makeDiagnostic("sim_must_be_finite"));
    return options.feedforwardVolts->data();
}

/// dacOutput with 2^bits, q and the code range computed once for a run (the same values, so the
/// same results).
struct Dac {
    Dac(int bits, double umaxVolts) : bits(bits) {
        if (bits > 0) {
            const double levels = std::ldexp(1.0, bits);
            q = 2.0 * umaxVolts / levels;
            half = levels / 2.0;
        }
    }
    double operator()(double volts) const {
        if (bits == 0)
            return volts;
        return std::clamp(std::floor(volts / q + 0.5), -half, half - 1.0) * q;
    }
    int bits;
    double q = 0.0, half = 0.0;
};

/// The plant state: a fixed array for the orders the workbench meets (N > 0, so that the sums
/// unroll), a vector otherwise (N = 0).
template <int N> struct PlantState {
    explicit PlantState(int) {}
    std::array<double, static_cast<std::size_t>(N)> x{}, next{};
    static constexpr int size(int) { return N; }
};
template <> struct PlantState<0> {
    explicit PlantState(int n) : x(static_cast<std::size_t>(n), 0.0), next(x.size()) {}
    std::vector<double> x, next;
    static int size(int n) { return n; }
};

/// The loop of simulateSampledPi for a plant of N states (0: any), one sample at a time: at
/// sample k measured() is the encoder's reading the controller uses, and advance(extra) forms
/// the command (the PI, then the feedforward and @p extra volts added and clipped, as firmware
/// adds its friction compensation after the PI), records sample k and moves the plant on.
template <int N> class SampledPiLoop {
public:
    SampledPiLoop(const SampledPlant& p, const DigitalPi& pi, const std::vector<double>& reference,
                  const SampledDataOptions& options, double unit, TablePlant* table,
                  SampledDataRun& run)
        : p_(p), pi_(pi), reference_(reference), options_(options), unit_(unit), table_(table),
          run_(run), plant_(p.states), delay_(options.delaySamples, 0.0),
          dac_(options.dacBits, options.umaxVolts),
          ff_(sampledFeedforward(options, reference.size())) {
        read();
    }
    std::size_t index() const { return k_; }
    double measured() const { return measured_; }

    bool advance(double extra) {
        const int ns = PlantState<N>::size(p_.states);
        auto& x = plant_.x;
        auto& next = plant_.next;
        const std::size_t k = k_;
        double error = (reference_[k] - measured_) * unit_;
        if (pi_.hasNotch)
            error = stepBiquad(pi_.errorNotch, notch_, error);
        double u = stepDigitalPi(pi_, state_, error, options_.umaxVolts);
        if (ff_ || extra != 0.0) {
            double total = u;
            if (ff_)
                total += ff_[k];
            if (extra != 0.0)
                total += extra;
            u = std::clamp(total, -options_.umaxVolts, options_.umaxVolts);
        }
        const double applied = delay_.push(dac_(u));
        SimulationResult& out = run_.result;
        out.t[k] = static_cast<double>(k) * pi_.tsSeconds;
        out.r[k] = reference_[k];
        out.y[k] = position_;
        out.e[k] = reference_[k] - position_;
        out.u[k] = u;
        const bool clipped = std::abs(u) >= options_.umaxVolts;
        out.clipped[k] = clipped;
        run_.measured[k] = measured_;
        run_.applied[k] = applied;
        ++k_;
        if (table_) {
            if (!out.sliding.empty())
                out.sliding[k] = static_cast<std::int8_t>(table_->state().sliding);
            table_->hold(applied, pi_.tsSeconds);
        } else {
            const double* phi = p_.phi.data();
            const double* gamma = p_.gamma.data();
            for (int i = 0; i < ns; ++i) {
                double acc = 0.0;
                for (int j = 0; j < ns; ++j)
                    acc += phi[i * ns + j] * x[static_cast<std::size_t>(j)];
                acc += gamma[i] * applied;
                next[static_cast<std::size_t>(i)] = acc;
            }
            x.swap(next);
        }
        if (k_ < reference_.size())
            read();
        return clipped;
    }

private:
    /// The plant's output and the encoder's reading at the current sample.
    void read() {
        const int ns = PlantState<N>::size(p_.states);
        double y = 0.0;
        for (int j = 0; j < ns; ++j)
            y += p_.c[static_cast<std::size_t>(j)] * plant_.x[static_cast<std::size_t>(j)];
        if (table_)
            y = table_->state().table;
        position_ = y / unit_;
        measured_ = encoderReading(position_, options_.encoderResolution);
    }

    const SampledPlant& p_;
    const DigitalPi& pi_;
    const std::vector<double>& reference_;
    const SampledDataOptions& options_;
    double unit_;
    TablePlant* table_;
    SampledDataRun& run_;
    PlantState<N> plant_;
    DigitalPiState state_;
    BiquadState notch_;
    DelayLine delay_;
    const Dac dac_;
    const double* ff_;
    std::size_t k_ = 0;
    double position_ = 0.0, measured_ = 0.0;
};

template <int N>
void runSampledPi(const SampledPlant& p, const DigitalPi& pi, const std::vector<double>& reference,
                  const SampledDataOptions& options, double unit, TablePlant* table,
                  SampledDataRun& run) {
    SampledPiLoop<N> loop(p, pi, reference, options, unit, table, run);
    for (std::size_t k = 0; k < reference.size(); ++k)
        loop.advance(0.0);
}

} // namespace

namespace {

/// What simulateSampledPi checks and sizes before its loop (shared with its stepper): the
/// run's signals and the table.
std::optional<TablePlant> startPiRun(SampledDataRun& run, const TransferFunction& plant,
                                     const DigitalPi& pi, const std::vector<double>& reference,
                                     const SampledDataOptions& options, double unit) {
    validateSampledDataOptions(options);
    requirePositive(unit, "model_unit_scale");
    requireFiniteSamples(reference, reference.size());
    resizeRun(run, reference.size(), pi.tsSeconds, options.umaxVolts);
    if (const double* ff = sampledFeedforward(options, reference.size()))
        run.result.uFeedforward.assign(ff, ff + reference.size());
    std::optional<TablePlant> table = tablePlantFor(plant, options, unit);
    if (table && options.table->breakawayVolts() > 0.0)
        run.result.sliding.resize(reference.size());
    return table;
}

} // namespace

SampledDataRun simulateSampledPi(const TransferFunction& plant, const DigitalPi& pi,
                                 const std::vector<double>& reference,
                                 const SampledDataOptions& options,
                                 double modelUnitsPerPositionUnit) {
    validateSampledDataOptions(options);
    const SampledPlant p = sampledPlant(plant, pi.tsSeconds);
    SampledDataRun run;
    std::optional<TablePlant> table =
        startPiRun(run, plant, pi, reference, options, modelUnitsPerPositionUnit);
    if (table) {
        runSampledPi<0>(p, pi, reference, options, modelUnitsPerPositionUnit, &*table, run);
        return run;
    }
    // The same sums in the same order for every order: the fixed sizes only let them unroll.
    switch (p.states) {
    case 1:
        runSampledPi<1>(p, pi, reference, options, modelUnitsPerPositionUnit, nullptr, run);
        break;
    case 2:
        runSampledPi<2>(p, pi, reference, options, modelUnitsPerPositionUnit, nullptr, run);
        break;
    case 3:
        runSampledPi<3>(p, pi, reference, options, modelUnitsPerPositionUnit, nullptr, run);
        break;
    case 4:
        runSampledPi<4>(p, pi, reference, options, modelUnitsPerPositionUnit, nullptr, run);
        break;
    default:
        runSampledPi<0>(p, pi, reference, options, modelUnitsPerPositionUnit, nullptr, run);
        break;
    }
    return run;
}

namespace {

/// The loop of simulateSampledServoPid one sample at a time (as SampledPiLoop): @p extra volts
/// join the PID's output and the feedforward before the limit.
class SampledServoPidLoop {
public:
    SampledServoPidLoop(const SampledPlant& p, const ServoPidGains& gains, double tsSeconds,
                        const std::vector<MotionSample>& command, CommandDerivativeSource source,
                        const SampledDataOptions& options, double unit, TablePlant* table,
                        SampledDataRun& run)
        : p_(p), gains_(gains), ts_(tsSeconds), command_(command), source_(source),
          options_(options), unit_(unit), table_(table), run_(run),
          x_(static_cast<std::size_t>(p.states), 0.0), next_(x_.size()),
          state_(servoPidAtRest(command.front().position)), delay_(options.delaySamples, 0.0),
          dac_(options.dacBits, options.umaxVolts),
          ff_(sampledFeedforward(options, command.size())) {
        state_.previousFeedback = 0.0;
        read();
    }
    std::size_t index() const { return k_; }
    double measured() const { return measured_; }

    bool advance(double extra) {
        const std::size_t k = k_;
        const double umax = options_.umaxVolts;
        const MotionSample& c = command_[k];
        const ServoPidCommandDerivatives given{c.velocity, c.acceleration, c.jerk};
        const ServoPidTerms terms = stepServoPid(
            gains_, state_, c.position, measured_, ts_,
            source_ == CommandDerivativeSource::TrajectoryGenerator ? &given : nullptr);
        double v = ff_ ? terms.output + ff_[k] : terms.output;
        if (extra != 0.0)
            v += extra;
        const bool clip = std::abs(v) > umax;
        const double u = clip ? std::copysign(umax, v) : v;
        const double applied = delay_.push(dac_(u));
        SimulationResult& out = run_.result;
        out.t[k] = static_cast<double>(k) * ts_;
        out.r[k] = c.position;
        out.y[k] = position_;
        out.e[k] = c.position - position_;
        out.u[k] = u;
        out.uFeedforward[k] = terms.feedforward + (ff_ ? ff_[k] : 0.0);
        out.clipped[k] = clip || terms.output != terms.feedback + terms.feedforward;
        const bool clipped =
            std::abs(u) >= umax; // at the limit: what the coupling's anti-windup reads
        run_.measured[k] = measured_;
        run_.applied[k] = applied;
        ++k_;
        if (table_) {
            if (!out.sliding.empty())
                out.sliding[k] = static_cast<std::int8_t>(table_->state().sliding);
            table_->hold(applied, ts_);
        } else {
            const std::size_t ns = x_.size();
            for (std::size_t i = 0; i < ns; ++i) {
                double acc = 0.0;
                for (std::size_t j = 0; j < ns; ++j)
                    acc += p_.phi[i * ns + j] * x_[j];
                next_[i] = acc + p_.gamma[i] * applied;
            }
            x_.swap(next_);
        }
        if (k_ < command_.size())
            read();
        return clipped;
    }

private:
    void read() {
        double y = 0.0;
        for (std::size_t j = 0; j < x_.size(); ++j)
            y += p_.c[j] * x_[j];
        if (table_)
            y = table_->state().table;
        position_ = y / unit_;
        measured_ = encoderReading(position_, options_.encoderResolution);
    }

    const SampledPlant& p_;
    const ServoPidGains& gains_;
    double ts_;
    const std::vector<MotionSample>& command_;
    CommandDerivativeSource source_;
    const SampledDataOptions& options_;
    double unit_;
    TablePlant* table_;
    SampledDataRun& run_;
    std::vector<double> x_, next_;
    ServoPidState state_;
    DelayLine delay_;
    const Dac dac_;
    const double* ff_;
    std::size_t k_ = 0;
    double position_ = 0.0, measured_ = 0.0;
};

void requireFiniteCommand(const std::vector<MotionSample>& command) {
    if (command.empty())
        throw InvalidInput("reference", makeDiagnostic("sim_needs_samples", {"1", "0"}));
    for (std::size_t i = 0; i < command.size(); ++i) {
        const MotionSample& m = command[i];
        if (!std::isfinite(m.position) || !std::isfinite(m.velocity) ||
            !std::isfinite(m.acceleration) || !std::isfinite(m.jerk))
            throw InvalidInput("reference",
                               makeDiagnostic("sim_sample_not_finite", {std::to_string(i)}));
    }
}

/// Sizes a servo PID's run and its table: what simulateSampledServoPid and its stepper share.
void startServoPidRun(SampledDataRun& run, std::optional<TablePlant>& table,
                      const TransferFunction& plant, double tsSeconds, std::size_t n,
                      const SampledDataOptions& options, double unit) {
    resizeRun(run, n, tsSeconds, options.umaxVolts);
    run.result.uFeedforward.resize(n);
    table = tablePlantFor(plant, options, unit);
    if (table && options.table->breakawayVolts() > 0.0)
        run.result.sliding.resize(n);
}

} // namespace

SampledDataRun simulateSampledServoPid(const TransferFunction& plant, const ServoPidGains& gains,
                                       double tsSeconds, const std::vector<MotionSample>& command,
                                       CommandDerivativeSource source,
                                       const SampledDataOptions& options,
                                       double modelUnitsPerPositionUnit) {
    validateSampledDataOptions(options);
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    const SampledPlant p = sampledPlant(plant, tsSeconds);
    requireFiniteCommand(command);
    SampledDataRun run;
    std::optional<TablePlant> table;
    startServoPidRun(run, table, plant, tsSeconds, command.size(), options,
                     modelUnitsPerPositionUnit);
    SampledServoPidLoop loop(p, gains, tsSeconds, command, source, options,
                             modelUnitsPerPositionUnit, table ? &*table : nullptr, run);
    for (std::size_t k = 0; k < command.size(); ++k)
        loop.advance(0.0);
    return run;
}

namespace {

/// The loop of simulateSampledRst one sample at a time (as SampledPiLoop), from j = 0 (k = -p,
/// the ZPETC's preview) to samples + p - 1: @p extra volts join the RST law's output before
/// the limit; the law remembers its own share of what the actuator did (the clipped command
/// less @p extra) under an anti-windup, its own output without.
class SampledRstLoop {
public:
    SampledRstLoop(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                   const std::vector<double>& r, std::size_t samples,
                   const SampledDataOptions& options, SampledDataRun& run)
        : loop_(loop), r_(r), samples_(samples),
          preview_(zpetc ? static_cast<std::size_t>(zpetc->previewSteps) : 0), options_(options),
          run_(run), a_(loop.a.ascending()), b_(loop.b.ascending()), f_(loop.f.ascending()),
          g_(loop.g.ascending()), ffNum_(zpetc ? zpetc->feedforwardNum.ascending() : kOne()),
          ffDen_(zpetc ? zpetc->feedforwardDen.ascending() : kOne()),
          deadzone_(options.table
                        ? options.table->coulombVolts + options.table->amplifierDeadbandVolts
                        : 0.0),
          delay_(options.delaySamples, loop.a(1.0) / loop.b(1.0) * r.front()) {
        if (ffDen_[0] == 0.0)
            throw InvalidInput("zpetc", makeDiagnostic("sim_zpetc_den_zero"));
        const double rest = r.front();
        const double uRest = loop.a(1.0) / loop.b(1.0) * rest;
        // Histories, newest first: index i holds the value i samples back (shift registers, as
        // the exported C code keeps them).
        const std::size_t h = static_cast<std::size_t>(
            std::max({loop.a.degree(), loop.b.degree(), loop.f.degree(), loop.g.degree()}) + 1);
        yTrue_.assign(h, rest);
        uApplied_.assign(h, uRest);
        yMeasured_.assign(g_.size(), rest);
        uController_.assign(f_.size(), uRest);
        ffIn_.assign(ffNum_.size(), rest);
        ffOut_.assign(ffDen_.size(), rest);
        read();
    }
    std::size_t preview() const { return preview_; }
    std::size_t step() const { return j_; } ///< j: k + preview
    double measured() const { return measured_; }

    bool advance(double extra) {
        const std::size_t j = j_;
        // Feedforward on r(k + p) (or w = r without it).
        shift(ffIn_);
        shift(ffOut_);
        ffIn_[0] = r_[j];
        double w = 0.0;
        for (std::size_t i = 0; i < ffNum_.size(); ++i)
            w += ffNum_[i] * ffIn_[i];
        for (std::size_t i = 1; i < ffDen_.size(); ++i)
            w -= ffDen_[i] * ffOut_[i];
        w = w / ffDen_[0];
        ffOut_[0] = w;
        // Controller F u = Kf w - G y_measured.
        shift(yMeasured_);
        shift(uController_);
        yMeasured_[0] = measured_;
        double v = loop_.kf * w;
        for (std::size_t i = 0; i < g_.size(); ++i)
            v -= g_[i] * yMeasured_[i];
        for (std::size_t i = 1; i < f_.size(); ++i)
            v -= f_[i] * uController_[i];
        v = v / f_[0];
        const double umax = options_.umaxVolts;
        const double total = extra != 0.0 ? v + extra : v;
        const double u = total > umax ? umax : (total < -umax ? -umax : total);
        const double own = extra != 0.0 ? u - extra : u;
        uController_[0] = options_.antiWindup == AntiWindup::None ? v : own;
        const double applied = delay_.push(dacOutput(u, options_.dacBits, umax));
        // An ARX axis' table (AxisSettings::friction): its Coulomb level and the amplifier's
        // deadband as a dead zone of the plant's input.
        uApplied_[0] =
            deadzone_ == 0.0 ? applied : applied - std::clamp(applied, -deadzone_, deadzone_);
        const bool clipped = std::abs(u) >= umax; // at the limit: what the coupling reads
        if (j >= preview_) {
            const std::size_t k = j - preview_;
            const double rk = r_[k];
            SimulationResult& out = run_.result;
            out.t[k] = static_cast<double>(k) * loop_.tsSeconds;
            out.r[k] = rk;
            out.y[k] = yk_;
            out.e[k] = rk - yk_;
            out.u[k] = u;
            out.clipped[k] = u != total;
            run_.measured[k] = measured_;
            run_.applied[k] = applied;
        }
        ++j_;
        if (j_ < samples_ + preview_)
            read();
        return clipped;
    }

private:
    static const std::vector<double>& kOne() {
        static const std::vector<double> one{1.0};
        return one;
    }
    static void shift(std::vector<double>& v) {
        for (std::size_t i = v.size() - 1; i > 0; --i)
            v[i] = v[i - 1];
    }
    /// Plant A y = B u (A(0) = 1, B(0) = 0): y(k) from the past applied commands, and its
    /// reading.
    void read() {
        shift(yTrue_);
        shift(uApplied_);
        double yk = 0.0;
        for (std::size_t i = 1; i < b_.size(); ++i)
            yk += b_[i] * uApplied_[i];
        for (std::size_t i = 1; i < a_.size(); ++i)
            yk -= a_[i] * yTrue_[i];
        yTrue_[0] = yk;
        yk_ = yk;
        measured_ = encoderReading(yk, options_.encoderResolution);
    }

    const PolePlacementDesign& loop_;
    const std::vector<double>& r_;
    std::size_t samples_, preview_;
    const SampledDataOptions& options_;
    SampledDataRun& run_;
    const std::vector<double>&a_, &b_, &f_, &g_, &ffNum_, &ffDen_;
    double deadzone_;
    std::vector<double> yTrue_, uApplied_, yMeasured_, uController_, ffIn_, ffOut_;
    DelayLine delay_;
    std::size_t j_ = 0;
    double yk_ = 0.0, measured_ = 0.0;
};

void checkRstRun(const ZpetcDesign* zpetc, const std::vector<double>& r, std::size_t samples,
                 const SampledDataOptions& options) {
    validateSampledDataOptions(options);
    const std::size_t preview = zpetc ? static_cast<std::size_t>(zpetc->previewSteps) : 0;
    requireFiniteSamples(r, samples + preview);
    if (samples == 0)
        throw InvalidInput("reference", makeDiagnostic("sim_needs_one_sample"));
}

} // namespace

SampledDataRun simulateSampledRst(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                                  const std::vector<double>& r, std::size_t samples,
                                  const SampledDataOptions& options) {
    checkRstRun(zpetc, r, samples, options);
    SampledDataRun run;
    resizeRun(run, samples, loop.tsSeconds, options.umaxVolts);
    SampledRstLoop rst(loop, zpetc, r, samples, options, run);
    for (std::size_t j = 0; j < samples + rst.preview(); ++j)
        rst.advance(0.0);
    return run;
}

namespace {

/// What a stepped sampled-data loop owns of its options: copies of the table and the
/// feedforward they point to, so that the loop's references into them stay valid.
struct OwnedOptions {
    explicit OwnedOptions(const SampledDataOptions& o) : options(o) {
        if (o.table) {
            table = *o.table;
            options.table = &table;
        }
        if (o.feedforwardVolts && !o.feedforwardVolts->empty()) {
            feedforward = *o.feedforwardVolts;
            options.feedforwardVolts = &feedforward;
        }
    }
    OwnedOptions(const OwnedOptions&) = delete;
    SampledDataOptions options;
    TableFriction table;
    std::vector<double> feedforward;
};

/// What the sampled steppers share: the run, the loop (built by each stepper once its inputs
/// are in place) and the overrides that only forward to them.
template <class Loop> class SampledStepperBase : public SampledLoopStepper {
public:
    double output() const override { return loop_->measured(); }
    bool advance(double extraVolts) override { return loop_->advance(extraVolts); }
    const SimulationResult& result() const override { return run_.result; }
    SimulationResult takeResult() override { return std::move(run_.result); }
    SampledDataRun takeRun() override { return std::move(run_); }

protected:
    SampledDataRun run_;
    std::optional<Loop> loop_;
};

/// simulateSampledPi's loop as a SampledLoopStepper.
class SampledPiStepper final : public SampledStepperBase<SampledPiLoop<0>> {
public:
    SampledPiStepper(const TransferFunction& plant, const DigitalPi& pi,
                     std::vector<double> reference, const SampledDataOptions& options, double unit)
        : owned_(options), pi_(pi), reference_(std::move(reference)),
          plant_((validateSampledDataOptions(options), sampledPlant(plant, pi.tsSeconds))),
          table_(startPiRun(run_, plant, pi_, reference_, owned_.options, unit)) {
        loop_.emplace(plant_, pi_, reference_, owned_.options, unit, table_ ? &*table_ : nullptr,
                      run_);
    }
    std::size_t samples() const override { return reference_.size(); }
    double periodSeconds() const override { return pi_.tsSeconds; }
    std::size_t index() const override { return loop_->index(); }
    double reference() const override { return reference_[loop_->index()]; }

private:
    OwnedOptions owned_;
    DigitalPi pi_;
    std::vector<double> reference_;
    SampledPlant plant_;
    std::optional<TablePlant> table_;
};

/// simulateSampledServoPid's loop as a SampledLoopStepper.
class SampledServoPidStepper final : public SampledStepperBase<SampledServoPidLoop> {
public:
    SampledServoPidStepper(const TransferFunction& plant, const ServoPidGains& gains,
                           double tsSeconds, std::vector<MotionSample> command,
                           CommandDerivativeSource source, const SampledDataOptions& options,
                           double unit)
        : owned_(options), gains_(gains), ts_(tsSeconds), command_(std::move(command)) {
        validateSampledDataOptions(options);
        requirePositive(unit, "model_unit_scale");
        plant_ = sampledPlant(plant, tsSeconds);
        requireFiniteCommand(command_);
        startServoPidRun(run_, table_, plant, tsSeconds, command_.size(), owned_.options, unit);
        loop_.emplace(plant_, gains_, ts_, command_, source, owned_.options, unit,
                      table_ ? &*table_ : nullptr, run_);
    }
    std::size_t samples() const override { return command_.size(); }
    double periodSeconds() const override { return ts_; }
    std::size_t index() const override { return loop_->index(); }
    double reference() const override { return command_[loop_->index()].position; }

private:
    OwnedOptions owned_;
    ServoPidGains gains_;
    double ts_;
    std::vector<MotionSample> command_;
    SampledPlant plant_;
    std::optional<TablePlant> table_;
};

/// simulateSampledRst's loop as a SampledLoopStepper: the ZPETC's preview samples before
/// k = 0 are run at construction, without coupling, as the batch run has them.
class SampledRstStepper final : public SampledStepperBase<SampledRstLoop> {
public:
    SampledRstStepper(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                      std::vector<double> r, std::size_t samples, const SampledDataOptions& options)
        : owned_(options), design_(loop), r_(std::move(r)), samples_(samples) {
        if (zpetc)
            zpetc_ = *zpetc;
        checkRstRun(zpetc, r_, samples, options);
        resizeRun(run_, samples, loop.tsSeconds, options.umaxVolts);
        loop_.emplace(design_, zpetc_ ? &*zpetc_ : nullptr, r_, samples, owned_.options, run_);
        for (std::size_t j = 0; j < loop_->preview(); ++j)
            loop_->advance(0.0);
    }
    std::size_t samples() const override { return samples_; }
    double periodSeconds() const override { return design_.tsSeconds; }
    std::size_t index() const override { return loop_->step() - loop_->preview(); }
    double reference() const override { return r_[index()]; }

private:
    OwnedOptions owned_;
    PolePlacementDesign design_;
    std::optional<ZpetcDesign> zpetc_;
    std::vector<double> r_;
    std::size_t samples_;
};

} // namespace

std::unique_ptr<SampledLoopStepper> steppedSampledPi(const TransferFunction& plant,
                                                     const DigitalPi& pi,
                                                     const std::vector<double>& reference,
                                                     const SampledDataOptions& options,
                                                     double modelUnitsPerPositionUnit) {
    return std::make_unique<SampledPiStepper>(plant, pi, reference, options,
                                              modelUnitsPerPositionUnit);
}

std::unique_ptr<SampledLoopStepper>
steppedSampledServoPid(const TransferFunction& plant, const ServoPidGains& gains, double tsSeconds,
                       const std::vector<MotionSample>& command, CommandDerivativeSource source,
                       const SampledDataOptions& options, double modelUnitsPerPositionUnit) {
    return std::make_unique<SampledServoPidStepper>(plant, gains, tsSeconds, command, source,
                                                    options, modelUnitsPerPositionUnit);
}

std::unique_ptr<SampledLoopStepper> steppedSampledRst(const PolePlacementDesign& loop,
                                                      const ZpetcDesign* zpetc,
                                                      const std::vector<double>& r,
                                                      std::size_t samples,
                                                      const SampledDataOptions& options) {
    return std::make_unique<SampledRstStepper>(loop, zpetc, r, samples, options);
}

std::vector<std::complex<double>> sampledPiLoopPoles(const SampledPlant& plant, const DigitalPi& pi,
                                                     int delaySamples) {
    const int n = plant.states;
    const int d = std::max(delaySamples, 0);
    // The state: x (n), I[k-1], e_f[k-1], the notch's s1 and s2 when it has one, then the delay
    // line. With r = 0 the error is e = -C x (model units) and the PI reads e_f = b0 e + s1
    // (b0 = 1, s1 = 0 without a notch).
    const int notchStates = pi.hasNotch ? 2 : 0;
    const int s1 = n + 2, s2 = n + 3;
    const int line = n + 2 + notchStates; // the first delay-line state
    const int size = line + d;
    const Biquad& f = pi.errorNotch;
    const double b0 = pi.hasNotch ? f.b0 : 1.0;
    // e_f as a row over the state.
    Eigen::RowVectorXd ef = Eigen::RowVectorXd::Zero(size);
    for (int j = 0; j < n; ++j)
        ef(j) = -b0 * plant.c[static_cast<std::size_t>(j)];
    if (pi.hasNotch)
        ef(s1) = 1.0;
    // u[k] = (kp + c0) e_f + I[k-1] + c1 e_f[k-1].
    Eigen::RowVectorXd uRow = (pi.kp + pi.c0) * ef;
    uRow(n) += 1.0;
    uRow(n + 1) += pi.c1;
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size, size);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            m(i, j) = plant.phi[static_cast<std::size_t>(i * n + j)];
        const double gamma = plant.gamma[static_cast<std::size_t>(i)];
        if (d == 0)
            m.row(i) += gamma * uRow;
        else
            m(i, line + d - 1) += gamma; // the oldest command in the delay line
    }
    m.row(n) = pi.c0 * ef; // I[k] = I[k-1] + c0 e_f + c1 e_f[k-1]
    m(n, n) += 1.0;
    m(n, n + 1) += pi.c1;
    m.row(n + 1) = ef; // e_f[k]
    if (pi.hasNotch) {
        // s1' = b1 e - a1 e_f + s2,  s2' = b2 e - a2 e_f,  e = -C x.
        for (int j = 0; j < n; ++j) {
            const double c = plant.c[static_cast<std::size_t>(j)];
            m(s1, j) = -f.b1 * c;
            m(s2, j) = -f.b2 * c;
        }
        m.row(s1) -= f.a1 * ef;
        m(s1, s2) += 1.0;
        m.row(s2) -= f.a2 * ef;
    }
    if (d > 0) {
        m.row(line) = uRow; // u[k]
        for (int i = 1; i < d; ++i)
            m(line + i, line + i - 1) = 1.0;
    }
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(m, false);
    std::vector<std::complex<double>> poles;
    for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
        poles.push_back(solver.eigenvalues()(i));
    sortRoots(poles);
    return poles;
}

std::vector<std::complex<double>> sampledRstLoopPoles(const PolePlacementDesign& loop,
                                                      int delaySamples) {
    std::vector<double> delay(static_cast<std::size_t>(std::max(delaySamples, 0)) + 1, 0.0);
    delay.back() = 1.0;
    const Polynomial characteristic =
        loop.a * loop.f + Polynomial::fromAscending(delay) * loop.b * loop.g;
    // sum p_i z^-i = 0  <=>  sum p_i z^(m-i) = 0: the coefficients read highest power first.
    const Polynomial inZ = Polynomial::fromDescending(characteristic.ascending());
    auto poles = inZ.roots();
    sortRoots(poles);
    return poles;
}

double zDampingRatio(std::complex<double> z) {
    if (std::abs(z) < 1e-9)
        return 1.0;
    const std::complex<double> s = std::log(z);
    const double magnitude = std::abs(s);
    if (magnitude == 0.0)
        return 0.0; // z = 1: an undamped integrator
    return -s.real() / magnitude;
}

std::optional<Diagnostic>
digitalDampingWarning(const std::vector<std::complex<double>>& digitalPoles,
                      double referenceMinDamping, double tsSeconds) {
    double largest = 0.0, minDamping = 1.0;
    for (const auto& z : digitalPoles) {
        if (std::abs(z) < 1e-9)
            continue;
        largest = std::max(largest, std::abs(z));
        minDamping = std::min(minDamping, zDampingRatio(z));
    }
    if (!(largest < 1.0))
        return makeDiagnostic("digital_loop_unstable",
                              {formatNumber(tsSeconds), formatNumber(largest)});
    if (minDamping < 0.8 * referenceMinDamping)
        return makeDiagnostic("digital_loop_less_damped",
                              {formatNumber(tsSeconds), formatNumber(minDamping, 3),
                               formatNumber(referenceMinDamping, 3)});
    return std::nullopt;
}

namespace {

/// How many times @p v changes direction in [begin, end), and its peak-to-peak there.
RestOscillation oscillation(const std::vector<double>& v, std::size_t begin, std::size_t end) {
    RestOscillation o;
    double lo = v[begin], hi = v[begin];
    int lastDirection = 0;
    for (std::size_t k = begin + 1; k < end; ++k) {
        lo = std::min(lo, v[k]);
        hi = std::max(hi, v[k]);
        const double step = v[k] - v[k - 1];
        const int direction = step > 0.0 ? 1 : (step < 0.0 ? -1 : 0);
        if (direction == 0)
            continue;
        if (lastDirection != 0 && direction != lastDirection)
            ++o.turns;
        lastDirection = direction;
    }
    o.peakToPeak = hi - lo;
    return o;
}

} // namespace

std::optional<RestOscillation> restLimitCycle(const std::vector<double>& measured,
                                              std::size_t restStart) {
    if (restStart >= measured.size() || measured.size() - restStart < 40)
        return std::nullopt;
    const std::size_t n = measured.size();
    const std::size_t half = restStart + (n - restStart) / 2;
    const std::size_t quarter = half + (n - half) / 2;
    const RestOscillation first = oscillation(measured, half, quarter);
    const RestOscillation second = oscillation(measured, quarter, n);
    if (first.turns < 2 || second.turns < 2 || !(second.peakToPeak > 0.0) ||
        second.peakToPeak < 0.5 * first.peakToPeak)
        return std::nullopt;
    RestOscillation out = oscillation(measured, half, n);
    return out;
}

} // namespace xyt
