// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/discrete_simulation.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>

namespace xyt {

namespace {

/// A signal with `history` samples of its past stored ahead of k = 0, so that index
/// k - i for i <= history reads the past value without a branch.
class History {
public:
    History(std::size_t history, std::size_t samples, double past)
        : offset_(history), v_(history + samples, past) {}
    double& operator[](std::ptrdiff_t k) { return v_[static_cast<std::size_t>(k + offset_)]; }
    std::vector<double> present() const {
        return {v_.begin() + static_cast<std::ptrdiff_t>(offset_), v_.end()};
    }

private:
    std::ptrdiff_t offset_;
    std::vector<double> v_;
};

std::size_t maxDegree(std::initializer_list<const Polynomial*> ps) {
    int n = 0;
    for (const Polynomial* p : ps)
        n = std::max(n, p->degree());
    return static_cast<std::size_t>(n);
}

} // namespace

RstLoopStepper::RstLoopStepper(const PolePlacementDesign& design, std::vector<double> loopInput,
                               double rest, double inputDeadzoneVolts)
    : d_(design), v_(std::move(loopInput)), deadzone_(inputDeadzoneVolts),
      history_(maxDegree({&d_.a, &d_.b, &d_.f, &d_.g})) {
    const std::size_t n = v_.size();
    const std::size_t h = history_;
    const double uRest = d_.a(1.0) / d_.b(1.0) * rest;
    y_.assign(h + n, rest);
    u_.assign(h + n, uRest);
    ua_.assign(h + n, dead(uRest));
    command_.assign(n, 0.0);
    if (n > 0)
        y_[h] = plantOutput(0);
}

double RstLoopStepper::dead(double x) const {
    return deadzone_ == 0.0 ? x : x - std::clamp(x, -deadzone_, deadzone_);
}

double RstLoopStepper::plantOutput(std::size_t k) const {
    // Plant A y = B u with A(0) = 1 and B(0) = 0: y(k) from the past only.
    const std::size_t at = k + history_;
    const auto& a = d_.a.ascending();
    const auto& b = d_.b.ascending();
    double yk = 0.0;
    for (std::size_t i = 1; i < b.size(); ++i)
        yk += b[i] * ua_[at - i];
    for (std::size_t i = 1; i < a.size(); ++i)
        yk -= a[i] * y_[at - i];
    return yk;
}

double RstLoopStepper::advance(double extraVolts) {
    const std::size_t k = k_++;
    const std::size_t at = k + history_;
    const auto& f = d_.f.ascending();
    const auto& g = d_.g.ascending();
    // Controller F u = Kf v - G y with F(0) = 1.
    double uk = d_.kf * v_[k];
    for (std::size_t i = 0; i < g.size(); ++i)
        uk -= g[i] * y_[at - i];
    for (std::size_t i = 1; i < f.size(); ++i)
        uk -= f[i] * u_[at - i];
    u_[at] = uk / f[0];
    const double command = u_[at] + extraVolts;
    command_[k] = command;
    ua_[at] = dead(command);
    if (k_ < v_.size())
        y_[at + 1] = plantOutput(k_);
    return command;
}

DiscreteRun RstLoopStepper::run(std::size_t from) const {
    const auto begin = static_cast<std::ptrdiff_t>(history_ + from);
    const auto end = static_cast<std::ptrdiff_t>(history_ + k_);
    return {std::vector<double>(y_.begin() + begin, y_.begin() + end),
            std::vector<double>(command_.begin() + static_cast<std::ptrdiff_t>(from),
                                command_.begin() + static_cast<std::ptrdiff_t>(k_))};
}

namespace {

/// The RST loop on the loop input v(0 .. n-1), histories at the steady state of v = rest (the
/// closed loop has unity DC gain, so y = rest and u = A(1)/B(1) rest) or zero.
DiscreteRun runRstLoop(const PolePlacementDesign& d, const std::vector<double>& v, double rest,
                       double deadzone) {
    RstLoopStepper loop(d, v, rest, deadzone);
    for (std::size_t k = 0; k < v.size(); ++k)
        loop.advance(0.0);
    return loop.run();
}

void requireReference(const std::vector<double>& r, std::size_t samples, std::size_t needed) {
    if (samples == 0)
        throw InvalidInput("reference", makeDiagnostic("sim_needs_one_sample"));
    if (r.size() < needed)
        throw InvalidInput("reference",
                           makeDiagnostic("sim_needs_samples_preview",
                                          {std::to_string(needed), std::to_string(r.size())}));
}

} // namespace

std::vector<double> filterZInverse(const Polynomial& num, const Polynomial& den,
                                   const std::vector<double>& x, double pastInput,
                                   double pastOutput) {
    const double d0 = den.coefficient(0);
    if (d0 == 0.0)
        throw InvalidInput("den", makeDiagnostic("sim_filter_not_causal"));
    const std::size_t h = maxDegree({&num, &den});
    History in(h, x.size(), pastInput), out(h, x.size(), pastOutput);
    const auto& nc = num.ascending();
    const auto& dc = den.ascending();
    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(x.size()); ++k) {
        in[k] = x[static_cast<std::size_t>(k)];
        double acc = 0.0;
        for (std::size_t i = 0; i < nc.size(); ++i)
            acc += nc[i] * in[k - static_cast<std::ptrdiff_t>(i)];
        for (std::size_t i = 1; i < dc.size(); ++i)
            acc -= dc[i] * out[k - static_cast<std::ptrdiff_t>(i)];
        out[k] = acc / d0;
    }
    return out.present();
}

DiscreteRun simulateFeedbackLoop(const PolePlacementDesign& loop, const std::vector<double>& r,
                                 StartCondition start, double inputDeadzoneVolts) {
    requireReference(r, r.size(), 1);
    return runRstLoop(loop, r, start == StartCondition::AtReference ? r.front() : 0.0,
                      inputDeadzoneVolts);
}

std::vector<double> zpetcLoopInput(const ZpetcDesign& zpetc, const std::vector<double>& r,
                                   std::size_t samples, double rest) {
    const auto p = static_cast<std::size_t>(zpetc.previewSteps);
    requireReference(r, samples, samples + p);
    // Run on k = -p .. samples-1: the feedforward input at k is r(k + p) = r[k + p].
    const std::vector<double> w(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(samples + p));
    // Both the feedforward filter and the loop have unity DC gain: at rest every signal is r(0)
    // (u_ff included), so the steady state of the extended reference is the histories' value.
    return filterZInverse(zpetc.feedforwardNum, zpetc.feedforwardDen, w, rest, rest);
}

DiscreteRun simulateZpetcLoop(const PolePlacementDesign& loop, const ZpetcDesign& zpetc,
                              const std::vector<double>& r, std::size_t samples,
                              StartCondition start, double inputDeadzoneVolts) {
    const auto p = static_cast<std::size_t>(zpetc.previewSteps);
    requireReference(r, samples, samples + p);
    const double rest = start == StartCondition::AtReference ? r.front() : 0.0;
    const std::vector<double> uff = zpetcLoopInput(zpetc, r, samples, rest);
    DiscreteRun run = runRstLoop(loop, uff, rest, inputDeadzoneVolts);
    run.y.erase(run.y.begin(), run.y.begin() + static_cast<std::ptrdiff_t>(p));
    run.u.erase(run.u.begin(), run.u.begin() + static_cast<std::ptrdiff_t>(p));
    return run;
}

void discreteResult(const std::vector<double>& r, const DiscreteRun& run, double ts, double umax,
                    std::size_t n, SimulationResult& out) {
    out.t.resize(n);
    out.r.assign(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(n));
    out.y.assign(run.y.begin(), run.y.begin() + static_cast<std::ptrdiff_t>(n));
    out.u.assign(n, 0.0);
    std::copy_n(run.u.begin(), std::min(n, run.u.size()), out.u.begin());
    out.e.resize(n);
    out.clipped.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        out.t[k] = static_cast<double>(k) * ts;
        out.e[k] = out.r[k] - out.y[k];
        out.clipped[k] = std::abs(out.u[k]) > umax;
    }
    out.dtSeconds = ts;
    out.umaxVolts = umax;
}

namespace {

/// steppedRstRun's loop: an RstLoopStepper on the (ZPETC-filtered) reference.
class RstRunStepper final : public SteppedLoop {
public:
    RstRunStepper(const PolePlacementDesign& loop, const ZpetcDesign* zpetc,
                  const std::vector<double>& r, std::size_t samples, double umax, double deadzone)
        : r_(r), samples_(samples),
          preview_(zpetc ? static_cast<std::size_t>(zpetc->previewSteps) : 0), umax_(umax),
          ts_(loop.tsSeconds),
          loop_(loop,
                zpetc ? zpetcLoopInput(*zpetc, r, samples, r.front())
                      : std::vector<double>(r.begin(),
                                            r.begin() + static_cast<std::ptrdiff_t>(samples)),
                r.front(), deadzone) {
        for (std::size_t k = 0; k < preview_; ++k)
            loop_.advance(0.0);
    }
    std::size_t samples() const override { return samples_; }
    double periodSeconds() const override { return ts_; }
    std::size_t index() const override { return loop_.index() - preview_; }
    double output() const override { return loop_.output(); }
    double reference() const override { return r_[index()]; }
    bool advance(double extraVolts) override {
        const bool clipped = std::abs(loop_.advance(extraVolts)) > umax_;
        if (index() == samples_)
            finish();
        return clipped;
    }
    const SimulationResult& result() const override { return out_; }
    SimulationResult takeResult() override { return std::move(out_); }

private:
    void finish() { discreteResult(r_, loop_.run(preview_), ts_, umax_, samples_, out_); }

    std::vector<double> r_;
    std::size_t samples_, preview_;
    double umax_, ts_;
    RstLoopStepper loop_;
    SimulationResult out_;
};

} // namespace

std::unique_ptr<SteppedLoop> steppedRstRun(const PolePlacementDesign& loop,
                                           const ZpetcDesign* zpetc, const std::vector<double>& r,
                                           std::size_t samples, double umaxVolts,
                                           double inputDeadzoneVolts) {
    const std::size_t preview = zpetc ? static_cast<std::size_t>(zpetc->previewSteps) : 0;
    requireReference(r, samples, samples + preview);
    return std::make_unique<RstRunStepper>(loop, zpetc, r, samples, umaxVolts, inputDeadzoneVolts);
}

DiscreteRun simulateTrajectoryZpetc(const ZpetcDesign& zpetc, const std::vector<double>& r,
                                    std::size_t samples, StartCondition start) {
    const auto s = static_cast<std::size_t>(zpetc.bMinus.degree());
    requireReference(r, samples, samples + s);
    const std::vector<double> w(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(samples + s));
    const double rest = start == StartCondition::AtReference ? r.front() : 0.0;
    // y(k) = sum_j h_j r(k + s - j): the FIR on the input r(k + s), output index k.
    DiscreteRun run;
    run.y = filterZInverse(zpetc.overallFir, Polynomial::constant(1.0), w, rest, rest);
    // The FIR output at input index i belongs to time k = i - s.
    run.y.erase(run.y.begin(), run.y.begin() + static_cast<std::ptrdiff_t>(s));
    return run;
}

} // namespace xyt
