// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/sampled_data.h"

#include "core/simulation/table_dynamics.h"

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
                           "must be an integer in 0.." + std::to_string(kMaxDelaySamples));
    if (!std::isfinite(options.encoderResolution) || options.encoderResolution < 0.0)
        throw InvalidInput("encoder_resolution",
                           "must be a finite number >= 0 (mm per count; 0: ideal)");
    if (options.dacBits < 0 || options.dacBits > 32)
        throw InvalidInput("dac_bits", "must be an integer in 0..32 (0: ideal DAC)");
    if (std::isnan(options.umaxVolts) || !(options.umaxVolts > 0.0))
        throw InvalidInput("umax", "must be greater than zero (infinity for no limit)");
    if (options.dacBits > 0 && !std::isfinite(options.umaxVolts))
        throw InvalidInput("dac_bits", "a DAC needs a finite actuator limit umax (its full scale)");
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
        throw InvalidInput("plant", "must be a continuous, strictly proper transfer function");
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
            throw InvalidInput("ts", "the plant's discretization at this sample time overflows");
    return p;
}

namespace {

void requireFiniteSamples(const std::vector<double>& v, std::size_t count) {
    if (count == 0 || v.size() < count)
        throw InvalidInput("reference", "needs " + std::to_string(std::max<std::size_t>(count, 1)) +
                                            " samples, got " + std::to_string(v.size()));
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(v[i]))
            throw InvalidInput("reference",
                               "sample " + std::to_string(i) + " is not a finite number");
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
        throw InvalidInput("feedforward", "must have one sample per reference sample");
    for (double v : *options.feedforwardVolts)
        if (!std::isfinite(v))
            throw InvalidInput("feedforward", "must be finite");
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

/// The loop of simulateSampledPi for a plant of N states (0: any).
template <int N>
void runSampledPi(const SampledPlant& p, const DigitalPi& pi, const std::vector<double>& reference,
                  const SampledDataOptions& options, double unit, TablePlant* table,
                  SampledDataRun& run) {
    const int ns = PlantState<N>::size(p.states);
    const std::size_t n = reference.size();
    PlantState<N> plant(p.states);
    auto& x = plant.x;
    auto& next = plant.next;
    DigitalPiState state;
    DelayLine delay(options.delaySamples, 0.0);
    const Dac dac(options.dacBits, options.umaxVolts);
    const double* phi = p.phi.data();
    const double* gamma = p.gamma.data();
    const double* c = p.c.data();
    const double* ff = sampledFeedforward(options, n);
    SimulationResult& out = run.result;
    for (std::size_t k = 0; k < n; ++k) {
        double y = 0.0;
        for (int j = 0; j < ns; ++j)
            y += c[j] * x[static_cast<std::size_t>(j)];
        if (table)
            y = table->state().table;
        const double position = y / unit;
        const double measured = encoderReading(position, options.encoderResolution);
        const double error = (reference[k] - measured) * unit;
        double u = stepDigitalPi(pi, state, error, options.umaxVolts);
        if (ff)
            u = std::clamp(u + ff[k], -options.umaxVolts, options.umaxVolts);
        const double applied = delay.push(dac(u));
        out.t[k] = static_cast<double>(k) * pi.tsSeconds;
        out.r[k] = reference[k];
        out.y[k] = position;
        out.e[k] = reference[k] - position;
        out.u[k] = u;
        out.clipped[k] = std::abs(u) >= options.umaxVolts;
        run.measured[k] = measured;
        run.applied[k] = applied;
        if (table) {
            if (!out.sliding.empty())
                out.sliding[k] = static_cast<std::int8_t>(table->state().sliding);
            table->hold(applied, pi.tsSeconds);
            continue;
        }
        for (int i = 0; i < ns; ++i) {
            double acc = 0.0;
            for (int j = 0; j < ns; ++j)
                acc += phi[i * ns + j] * x[static_cast<std::size_t>(j)];
            acc += gamma[i] * applied;
            next[static_cast<std::size_t>(i)] = acc;
        }
        x.swap(next);
    }
}

} // namespace

SampledDataRun simulateSampledPi(const TransferFunction& plant, const DigitalPi& pi,
                                 const std::vector<double>& reference,
                                 const SampledDataOptions& options,
                                 double modelUnitsPerPositionUnit) {
    validateSampledDataOptions(options);
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    const SampledPlant p = sampledPlant(plant, pi.tsSeconds);
    requireFiniteSamples(reference, reference.size());
    SampledDataRun run;
    resizeRun(run, reference.size(), pi.tsSeconds, options.umaxVolts);
    if (const double* ff = sampledFeedforward(options, reference.size()))
        run.result.uFeedforward.assign(ff, ff + reference.size());
    std::optional<TablePlant> table = tablePlantFor(plant, options, modelUnitsPerPositionUnit);
    if (table) {
        if (options.table->breakawayVolts() > 0.0)
            run.result.sliding.resize(reference.size());
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

SampledDataRun simulateSampledServoPid(const TransferFunction& plant, const ServoPidGains& gains,
                                       double tsSeconds, const std::vector<MotionSample>& command,
                                       CommandDerivativeSource source,
                                       const SampledDataOptions& options,
                                       double modelUnitsPerPositionUnit) {
    validateSampledDataOptions(options);
    requirePositive(modelUnitsPerPositionUnit, "model_unit_scale");
    const SampledPlant p = sampledPlant(plant, tsSeconds);
    if (command.empty())
        throw InvalidInput("reference", "needs 1 samples, got 0");
    for (std::size_t i = 0; i < command.size(); ++i) {
        const MotionSample& m = command[i];
        if (!std::isfinite(m.position) || !std::isfinite(m.velocity) ||
            !std::isfinite(m.acceleration) || !std::isfinite(m.jerk))
            throw InvalidInput("reference",
                               "sample " + std::to_string(i) + " is not a finite number");
    }
    const double unit = modelUnitsPerPositionUnit;
    const std::size_t n = command.size();
    SampledDataRun run;
    resizeRun(run, n, tsSeconds, options.umaxVolts);
    run.result.uFeedforward.resize(n);
    std::optional<TablePlant> table = tablePlantFor(plant, options, unit);
    if (table && options.table->breakawayVolts() > 0.0)
        run.result.sliding.resize(n);
    const std::size_t ns = static_cast<std::size_t>(p.states);
    std::vector<double> x(ns, 0.0), next(ns);
    ServoPidState state = servoPidAtRest(command.front().position);
    state.previousFeedback = 0.0;
    DelayLine delay(options.delaySamples, 0.0);
    const Dac dac(options.dacBits, options.umaxVolts);
    const double umax = options.umaxVolts;
    const double* ff = sampledFeedforward(options, n);
    SimulationResult& out = run.result;
    for (std::size_t k = 0; k < n; ++k) {
        double y = 0.0;
        for (std::size_t j = 0; j < ns; ++j)
            y += p.c[j] * x[j];
        if (table)
            y = table->state().table;
        const double position = y / unit;
        const double measured = encoderReading(position, options.encoderResolution);
        const MotionSample& c = command[k];
        const ServoPidCommandDerivatives given{c.velocity, c.acceleration, c.jerk};
        const ServoPidTerms terms =
            stepServoPid(gains, state, c.position, measured, tsSeconds,
                         source == CommandDerivativeSource::TrajectoryGenerator ? &given : nullptr);
        const double v = ff ? terms.output + ff[k] : terms.output;
        const bool clip = std::abs(v) > umax;
        const double u = clip ? std::copysign(umax, v) : v;
        const double applied = delay.push(dac(u));
        out.t[k] = static_cast<double>(k) * tsSeconds;
        out.r[k] = c.position;
        out.y[k] = position;
        out.e[k] = c.position - position;
        out.u[k] = u;
        out.uFeedforward[k] = terms.feedforward + (ff ? ff[k] : 0.0);
        out.clipped[k] = clip || terms.output != terms.feedback + terms.feedforward;
        run.measured[k] = measured;
        run.applied[k] = applied;
        if (table) {
            if (!out.sliding.empty())
                out.sliding[k] = static_cast<std::int8_t>(table->state().sliding);
            table->hold(applied, tsSeconds);
            continue;
        }
        for (std::size_t i = 0; i < ns; ++i) {
            double acc = 0.0;
            for (std::size_t j = 0; j < ns; ++j)
                acc += p.phi[i * ns + j] * x[j];
            next[i] = acc + p.gamma[i] * applied;
        }
        x.swap(next);
    }
    return run;
}

SampledDataRun simulateSampledRst(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                                  const std::vector<double>& r, std::size_t samples,
                                  const SampledDataOptions& options) {
    validateSampledDataOptions(options);
    const std::size_t preview = zpetc ? static_cast<std::size_t>(zpetc->previewSteps) : 0;
    requireFiniteSamples(r, samples + preview);
    if (samples == 0)
        throw InvalidInput("reference", "needs at least one sample");
    const auto& a = loop.a.ascending();
    const auto& b = loop.b.ascending();
    const auto& f = loop.f.ascending();
    const auto& g = loop.g.ascending();
    static const std::vector<double> kOne{1.0};
    const auto& ffNum = zpetc ? zpetc->feedforwardNum.ascending() : kOne;
    const auto& ffDen = zpetc ? zpetc->feedforwardDen.ascending() : kOne;
    if (ffDen[0] == 0.0)
        throw InvalidInput("zpetc", "the feedforward's z^0 denominator coefficient is zero");
    const double rest = r.front();
    const double uRest = loop.a(1.0) / loop.b(1.0) * rest;
    // Histories, newest first: index i holds the value i samples back (shift registers, as the
    // exported C code keeps them).
    const std::size_t h = static_cast<std::size_t>(
        std::max({loop.a.degree(), loop.b.degree(), loop.f.degree(), loop.g.degree()}) + 1);
    const double deadzone =
        options.table ? options.table->coulombVolts + options.table->amplifierDeadbandVolts : 0.0;
    std::vector<double> yTrue(h, rest), uApplied(h, uRest), yMeasured(g.size(), rest),
        uController(f.size(), uRest), ffIn(ffNum.size(), rest), ffOut(ffDen.size(), rest);
    const auto shift = [](std::vector<double>& v) {
        for (std::size_t i = v.size() - 1; i > 0; --i)
            v[i] = v[i - 1];
    };
    DelayLine delay(options.delaySamples, uRest);
    const double ts = loop.tsSeconds;
    SampledDataRun run;
    resizeRun(run, samples, ts, options.umaxVolts);
    const double umax = options.umaxVolts;
    for (std::size_t j = 0; j < samples + preview; ++j) {
        // Plant A y = B u (A(0) = 1, B(0) = 0): y(k) from the past applied commands.
        shift(yTrue);
        shift(uApplied);
        double yk = 0.0;
        for (std::size_t i = 1; i < b.size(); ++i)
            yk += b[i] * uApplied[i];
        for (std::size_t i = 1; i < a.size(); ++i)
            yk -= a[i] * yTrue[i];
        yTrue[0] = yk;
        const double measured = encoderReading(yk, options.encoderResolution);
        // Feedforward on r(k + p) (or w = r without it).
        shift(ffIn);
        shift(ffOut);
        ffIn[0] = r[j];
        double w = 0.0;
        for (std::size_t i = 0; i < ffNum.size(); ++i)
            w += ffNum[i] * ffIn[i];
        for (std::size_t i = 1; i < ffDen.size(); ++i)
            w -= ffDen[i] * ffOut[i];
        w = w / ffDen[0];
        ffOut[0] = w;
        // Controller F u = Kf w - G y_measured.
        shift(yMeasured);
        shift(uController);
        yMeasured[0] = measured;
        double v = loop.kf * w;
        for (std::size_t i = 0; i < g.size(); ++i)
            v -= g[i] * yMeasured[i];
        for (std::size_t i = 1; i < f.size(); ++i)
            v -= f[i] * uController[i];
        v = v / f[0];
        const double u = v > umax ? umax : (v < -umax ? -umax : v);
        uController[0] = options.antiWindup == AntiWindup::None ? v : u;
        const double applied = delay.push(dacOutput(u, options.dacBits, umax));
        // An ARX axis' table (AxisSettings::friction): its Coulomb level and the amplifier's
        // deadband as a dead zone of the plant's input.
        uApplied[0] =
            deadzone == 0.0 ? applied : applied - std::clamp(applied, -deadzone, deadzone);
        if (j < preview)
            continue;
        const std::size_t k = j - preview;
        const double rk = r[k];
        run.result.t[k] = static_cast<double>(k) * ts;
        run.result.r[k] = rk;
        run.result.y[k] = yk;
        run.result.e[k] = rk - yk;
        run.result.u[k] = u;
        run.result.clipped[k] = u != v;
        run.measured[k] = measured;
        run.applied[k] = applied;
    }
    return run;
}

std::vector<std::complex<double>> sampledPiLoopPoles(const SampledPlant& plant, const DigitalPi& pi,
                                                     int delaySamples) {
    const int n = plant.states;
    const int d = std::max(delaySamples, 0);
    const int size = n + 2 + d;
    // u[k] = -(kp + c0) C x + I[k-1] + c1 e[k-1] (r = 0, e = -C x in model units).
    Eigen::RowVectorXd uRow = Eigen::RowVectorXd::Zero(size);
    for (int j = 0; j < n; ++j)
        uRow(j) = -(pi.kp + pi.c0) * plant.c[static_cast<std::size_t>(j)];
    uRow(n) = 1.0;
    uRow(n + 1) = pi.c1;
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size, size);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            m(i, j) = plant.phi[static_cast<std::size_t>(i * n + j)];
        const double gamma = plant.gamma[static_cast<std::size_t>(i)];
        if (d == 0)
            m.row(i) += gamma * uRow;
        else
            m(i, n + 1 + d) += gamma; // the oldest command in the delay line
    }
    for (int j = 0; j < n; ++j) {
        m(n, j) = -pi.c0 * plant.c[static_cast<std::size_t>(j)]; // I[k] = I[k-1] + c0 e + c1 e[k-1]
        m(n + 1, j) = -plant.c[static_cast<std::size_t>(j)];     // e[k]
    }
    m(n, n) = 1.0;
    m(n, n + 1) = pi.c1;
    if (d > 0) {
        m.row(n + 2) = uRow; // u[k]
        for (int i = 1; i < d; ++i)
            m(n + 2 + i, n + 1 + i) = 1.0;
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

std::optional<std::string>
digitalDampingWarning(const std::vector<std::complex<double>>& digitalPoles,
                      double referenceMinDamping, double tsSeconds) {
    double largest = 0.0, minDamping = 1.0;
    for (const auto& z : digitalPoles) {
        if (std::abs(z) < 1e-9)
            continue;
        largest = std::max(largest, std::abs(z));
        minDamping = std::min(minDamping, zDampingRatio(z));
    }
    const std::string at = "the digital loop at Ts = " + formatNumber(tsSeconds) + " s";
    if (!(largest < 1.0))
        return at +
               " is unstable (its largest closed-loop pole has |z| = " + formatNumber(largest) +
               "); lower the controller sample time";
    if (minDamping < 0.8 * referenceMinDamping)
        return at + " is much less damped than the design (damping ratio " +
               formatNumber(minDamping, 3) + " against " + formatNumber(referenceMinDamping, 3) +
               " in the z-plane poles); lower the controller sample time or the delay";
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
