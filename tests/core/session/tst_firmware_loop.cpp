// SPDX-License-Identifier: GPL-3.0-or-later
// The exported C controller in the loop. The C export (exportCHeader) is written to a
// temporary folder with a harness (kHarness below) that plays the hardware: it steps the plant
// of the core's sampled-data simulation (the ZOH matrices of sampledPlant, or the ARX model),
// reads it through the encoder, calls the generated xyt_<axis>_step, passes the command through
// the generated DAC conversion and the delay, and prints u(k) and y(k) with %.17g. Compiled with
// the project's C compiler (CMAKE_C_COMPILER: gcc or clang) as
// `-std=c99 -Wall -Wextra -Werror -pedantic`. Source of the expected values: the core's own
// sampled-data run of the same session (AxisEvaluation::digital).
//  - double: the C code performs the core's operations in the same order, so the runs agree
//    to the bit; asserted to 1e-12 of the signal's largest magnitude.
//  - float: the bound derived in floatBound() below (rounding of the float arithmetic carried
//    through the closed loop's l1 gains).
#include "core/session/export_text.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/discrete_simulation.h"
#include "core/simulation/sampled_data.h"
#include "tests/support/c_harness.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace xyt;

using xyt::test::maxAbs;

namespace {

/// The hardware around the generated controller. KIND 0: continuous plant (ZOH matrices), the
/// Guillemin-Truxal PI; KIND 1: ARX plant, the RST law (+ ZPETC). The sums are written in the
/// order of core/simulation/sampled_data.cpp. Input on stdin: see writeInput().
constexpr const char* kHarness = R"(
static double line[MAX_DELAY];
static int delay, head;
static double delayed(double u) {
    double out;
    if (delay == 0)
        return u;
    out = line[head];
    line[head] = u;
    head = (head + 1) % delay;
    return out;
}

int main(void) {
    const int samples = (int)read_number();
    const int preview = (int)read_number();
    const double resolution = read_number();
    int i, j, k;
    double *r;
    delay = (int)read_number();
    if (delay < 0 || delay > MAX_DELAY)
        return 2;
    r = malloc(sizeof(double) * (size_t)(samples + preview));
    if (!r)
        return 2;
#if KIND == 0
    {
        const double unit = read_number();
        const int n = (int)read_number();
        double phi[MAX_STATES * MAX_STATES], gamma[MAX_STATES], c[MAX_STATES], x[MAX_STATES], next[MAX_STATES];
        STATE s;
        if (n < 1 || n > MAX_STATES)
            return 2;
        for (i = 0; i < n * n; ++i)
            phi[i] = read_number();
        for (i = 0; i < n; ++i)
            gamma[i] = read_number();
        for (i = 0; i < n; ++i)
            c[i] = read_number();
        for (k = 0; k < samples; ++k)
            r[k] = read_number();
        for (i = 0; i < n; ++i)
            x[i] = 0.0;
        for (i = 0; i < delay; ++i)
            line[i] = 0.0;
        INIT(&s);
        for (k = 0; k < samples; ++k) {
            double y = 0.0, position, measured, applied;
            xyt_real u;
            for (j = 0; j < n; ++j)
                y += c[j] * x[j];
            position = y / unit;
            measured = encoder(position, resolution);
            u = STEP(&s, (xyt_real)r[k], (xyt_real)measured);
            applied = delayed(dac(u));
            printf("%.17g %.17g\n", (double)u, position);
            for (i = 0; i < n; ++i) {
                double acc = 0.0;
                for (j = 0; j < n; ++j)
                    acc += phi[i * n + j] * x[j];
                acc += gamma[i] * applied;
                next[i] = acc;
            }
            for (i = 0; i < n; ++i)
                x[i] = next[i];
        }
    }
#else
    {
        const int na = (int)read_number();
        double a[MAX_STATES], b[MAX_STATES], y[MAX_STATES], ua[MAX_STATES], rest, u_rest;
        int nb, h;
        STATE s;
        if (na < 1 || na > MAX_STATES)
            return 2;
        for (i = 0; i < na; ++i)
            a[i] = read_number();
        nb = (int)read_number();
        if (nb < 1 || nb > MAX_STATES)
            return 2;
        for (i = 0; i < nb; ++i)
            b[i] = read_number();
        rest = read_number();
        u_rest = read_number();
        for (k = 0; k < samples + preview; ++k)
            r[k] = read_number();
        h = na > nb ? na : nb;
        for (i = 0; i < h; ++i) {
            y[i] = rest;
            ua[i] = u_rest;
        }
        for (i = 0; i < delay; ++i)
            line[i] = u_rest;
        INIT(&s, (xyt_real)rest);
        for (j = 0; j < samples + preview; ++j) {
            double yk = 0.0, measured;
            xyt_real u;
            for (i = h - 1; i > 0; --i) {
                y[i] = y[i - 1];
                ua[i] = ua[i - 1];
            }
            for (i = 1; i < nb; ++i)
                yk += b[i] * ua[i];
            for (i = 1; i < na; ++i)
                yk -= a[i] * y[i];
            y[0] = yk;
            measured = encoder(yk, resolution);
            u = STEP(&s, (xyt_real)r[j], (xyt_real)measured);
            ua[0] = delayed(dac(u));
            if (j >= preview)
                printf("%.17g %.17g\n", (double)u, yk);
        }
    }
#endif
    free(r);
    return 0;
}
)";

struct LoopRun {
    std::vector<double> u, y;
};

std::string numbers(const std::vector<double>& v) {
    std::string out;
    char buf[40];
    for (double x : v) {
        std::snprintf(buf, sizeof buf, "%.17g ", x);
        out += buf;
    }
    return out + "\n";
}

/// What the harness reads for axis @p i of @p session, and the reference samples it used.
std::string writeInput(const Session& session, const SessionEvaluation& evaluation, int i) {
    const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
    const DigitalEvaluation& d = *a.digital;
    const std::size_t n = d.run.result.t.size();
    const ImplementationSettings& impl = session.implementation;
    std::ostringstream out;
    if (a.gt) {
        const SampledPlant p = sampledPlant(a.gt->loopPlant, d.tsSeconds);
        out << n << " 0 " << numbers({impl.encoderResolutionMm}) << impl.delaySamples << "\n"
            << numbers({session.axes[static_cast<std::size_t>(i)].gt.modelUnitsPerPositionUnit})
            << p.states << "\n"
            << numbers(p.phi) << numbers(p.gamma) << numbers(p.c) << numbers(d.run.result.r);
        return out.str();
    }
    const bool ff = session.axes[static_cast<std::size_t>(i)].pp.zpetcEnabled;
    const std::size_t preview = ff ? static_cast<std::size_t>(a.zpetc->previewSteps) : 0;
    const auto reference = axisReference(session.trajectory, i);
    std::vector<double> r(n + preview);
    for (std::size_t k = 0; k < r.size(); ++k)
        r[k] = reference(static_cast<double>(k) * a.pp->tsSeconds); // as evaluatePp samples it
    out << n << " " << preview << " " << numbers({impl.encoderResolutionMm}) << impl.delaySamples
        << "\n"
        << a.pp->a.ascending().size() << "\n"
        << numbers(a.pp->a.ascending()) << a.pp->b.ascending().size() << "\n"
        << numbers(a.pp->b.ascending()) << numbers({r[0], a.pp->a(1.0) / a.pp->b(1.0) * r[0]})
        << numbers(r);
    return out.str();
}

/// Compiles the harness for axis @p i against @p header and runs it on @p input.
LoopRun runHarness(const QString& dir, const std::string& header, const std::string& id, bool pi,
                   const std::string& input) {
    const QString name = QString::fromStdString(id);
    const test::CHarnessRun run = test::runCHarness(
        dir, header, QByteArray(test::kCHarnessCommon) + kHarness, QByteArray::fromStdString(input),
        {"-DKIND=" + QString(pi ? "0" : "1"), "-DSTATE=xyt_" + name + "_state",
         "-DINIT=xyt_" + name + "_init", "-DSTEP=xyt_" + name + "_step"});
    if (!run.ok)
        qFatal("%s", qPrintable(run.error));
    LoopRun out;
    for (const QByteArray& line : run.output.split('\n')) {
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() != 2)
            continue;
        out.u.push_back(parts[0].toDouble());
        out.y.push_back(parts[1].toDouble());
    }
    return out;
}

/// The largest |a - b| over the run.
double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        m = std::max(m, std::abs(a[k] - b[k]));
    return m;
}

// ---- The float bound ---------------------------------------------------------------------
//
// Derivation. With eps = 2^-24 (float's unit roundoff) and gamma(n) = n eps / (1 - n eps), every
// float operation of the step returns the exact result times (1 + theta), |theta| <= eps, and
// every coefficient read as float carries one more such factor (Higham, Accuracy and Stability of
// Numerical Algorithms, 2002, sections 2.2 and 3.1). The float step therefore equals the exact
// (double) controller driven by the float run's own signals plus three kinds of perturbation:
//   n_k   on the measurement (the rounding of r and y to float and of e = (r - y) UNIT),
//   rho_k on the controller's stored state (what the step keeps for the next sample),
//   d_k   on the output only.
// Without clipping or quantization (the float cases) the loop is linear, so the differences
// between the float and the double runs are the closed loop's responses to these
// perturbations: |dy(k)| <= sum over kinds of ||h_kind->y||_1 max_k |perturbation|, the same
// for u, with h the impulse responses of the sampled-data loop from each injection point
// (computed below over the run's length, which bounds every partial sum). The per-step bounds
// use the magnitudes of the double run; the float run's differ from them by a relative O(eps)
// that the factor 1.01 covers, as it covers the O(eps^2) terms of gamma.
//  PI:  n  <= gamma(5) (|r| + |y_measured|)                 (2 reads, -, UNIT, *)
//       rho <= gamma(4) (|C0 e| + |C1 e'| + |I|)             (2 coefficients, 2 *, +, +)
//       d  <= gamma(3) (|KP e| + |I|)                        (coefficient, *, +)
//  RST: n_r <= eps |r|, n_y <= eps |y|                      (the reads)
//       rho_w <= gamma(L_ff + 4) (sum |FF_NUM| max|r| + sum |FF_DEN[1..]| max|w|) / |FF_DEN[0]|
//       rho_v <= gamma(L_rst + 5) (|KF| max|w| + sum |G| max|y| + sum |F[1..]| max|u|) / |F[0]|
//       (every product: coefficient and multiply; the sums; the division and its divisor)
double gammaN(int n) {
    const double eps = std::ldexp(1.0, -24);
    return n * eps / (1.0 - n * eps);
}

/// l1 norms of the responses of y and u (over @p n samples) to a unit impulse at each injection
/// point of the linear PI loop: 0 measurement, 1 controller state, 2 output.
std::array<std::array<double, 2>, 3> piL1Gains(const SampledPlant& p, const DigitalPi& pi,
                                               double unit, std::size_t n) {
    std::array<std::array<double, 2>, 3> gains{};
    for (int where = 0; where < 3; ++where) {
        std::vector<double> x(static_cast<std::size_t>(p.states), 0.0), next(x.size());
        double integrator = 0.0, previous = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            double y = 0.0;
            for (int j = 0; j < p.states; ++j)
                y += p.c[static_cast<std::size_t>(j)] * x[static_cast<std::size_t>(j)];
            const double impulse = k == 0 ? 1.0 : 0.0;
            const double measured = y / unit + (where == 0 ? impulse : 0.0);
            const double e = -measured * unit;
            integrator += pi.c0 * e + pi.c1 * previous + (where == 1 ? impulse : 0.0);
            previous = e;
            const double u = pi.kp * e + integrator + (where == 2 ? impulse : 0.0);
            gains[static_cast<std::size_t>(where)][0] += std::abs(y / unit);
            gains[static_cast<std::size_t>(where)][1] += std::abs(u);
            for (int i = 0; i < p.states; ++i) {
                double acc = 0.0;
                for (int j = 0; j < p.states; ++j)
                    acc += p.phi[static_cast<std::size_t>(i * p.states + j)] *
                           x[static_cast<std::size_t>(j)];
                next[static_cast<std::size_t>(i)] = acc + p.gamma[static_cast<std::size_t>(i)] * u;
            }
            x.swap(next);
        }
    }
    return gains;
}

/// The same for the RST loop: 0 reference read, 1 measurement, 2 feedforward state w, 3 u.
std::array<std::array<double, 2>, 4> rstL1Gains(const PolePlacementDesign& d, const ZpetcDesign* z,
                                                std::size_t n) {
    std::array<std::array<double, 2>, 4> gains{};
    const auto& a = d.a.ascending();
    const auto& b = d.b.ascending();
    const auto& f = d.f.ascending();
    const auto& g = d.g.ascending();
    const std::vector<double> one{1.0};
    const auto& fn = z ? z->feedforwardNum.ascending() : one;
    const auto& fd = z ? z->feedforwardDen.ascending() : one;
    for (int where = 0; where < 4; ++where) {
        std::vector<double> y(n, 0.0), u(n, 0.0), m(n, 0.0), r(n, 0.0), w(n, 0.0);
        const auto at = [](const std::vector<double>& v, std::size_t k, std::size_t i) {
            return i <= k ? v[k - i] : 0.0;
        };
        for (std::size_t k = 0; k < n; ++k) {
            const double impulse = k == 0 ? 1.0 : 0.0;
            double yk = 0.0;
            for (std::size_t i = 1; i < b.size(); ++i)
                yk += b[i] * at(u, k, i);
            for (std::size_t i = 1; i < a.size(); ++i)
                yk -= a[i] * at(y, k, i);
            y[k] = yk;
            m[k] = yk + (where == 1 ? impulse : 0.0);
            r[k] = where == 0 ? impulse : 0.0;
            double wk = 0.0;
            for (std::size_t i = 0; i < fn.size(); ++i)
                wk += fn[i] * at(r, k, i);
            for (std::size_t i = 1; i < fd.size(); ++i)
                wk -= fd[i] * at(w, k, i);
            w[k] = wk / fd[0] + (where == 2 ? impulse : 0.0);
            double v = d.kf * w[k];
            for (std::size_t i = 0; i < g.size(); ++i)
                v -= g[i] * at(m, k, i);
            for (std::size_t i = 1; i < f.size(); ++i)
                v -= f[i] * at(u, k, i);
            u[k] = v / f[0] + (where == 3 ? impulse : 0.0);
            gains[static_cast<std::size_t>(where)][0] += std::abs(y[k]);
            gains[static_cast<std::size_t>(where)][1] += std::abs(u[k]);
        }
    }
    return gains;
}

double sumAbs(const std::vector<double>& v, std::size_t from = 0) {
    double s = 0.0;
    for (std::size_t i = from; i < v.size(); ++i)
        s += std::abs(v[i]);
    return s;
}

/// The bound on |y_float - y_double| (index 0) and |u_float - u_double| (index 1) of the
/// derivation above, for axis @p i of @p session (no clipping, no quantization, no delay).
std::array<double, 2> floatBound(const Session& session, const SessionEvaluation& evaluation,
                                 int i) {
    const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
    const SampledDataRun& run = a.digital->run;
    const std::size_t n = run.result.t.size();
    std::array<double, 2> bound{};
    if (a.gt) {
        const DigitalPi pi = sessionDigitalPi(session, *a.gt, i);
        const double unit = session.axes[static_cast<std::size_t>(i)].gt.modelUnitsPerPositionUnit;
        double nMax = 0.0, rhoMax = 0.0, dMax = 0.0, integrator = 0.0, previous = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const double e = (run.result.r[k] - run.measured[k]) * unit;
            nMax =
                std::max(nMax, gammaN(5) * (std::abs(run.result.r[k]) + std::abs(run.measured[k])));
            rhoMax =
                std::max(rhoMax, gammaN(4) * (std::abs(pi.c0 * e) + std::abs(pi.c1 * previous) +
                                              std::abs(integrator)));
            integrator += pi.c0 * e + pi.c1 * previous;
            previous = e;
            dMax = std::max(dMax, gammaN(3) * (std::abs(pi.kp * e) + std::abs(integrator)));
        }
        const auto gains =
            piL1Gains(sampledPlant(a.gt->plant.transferFunction(), pi.tsSeconds), pi, unit, n);
        for (int s = 0; s < 2; ++s)
            bound[static_cast<std::size_t>(s)] = gains[0][static_cast<std::size_t>(s)] * nMax +
                                                 gains[1][static_cast<std::size_t>(s)] * rhoMax +
                                                 gains[2][static_cast<std::size_t>(s)] * dMax;
    } else {
        const PolePlacementDesign& d = *a.pp;
        const bool ff = session.axes[static_cast<std::size_t>(i)].pp.zpetcEnabled;
        const ZpetcDesign* z = ff ? &*a.zpetc : nullptr;
        const double eps = std::ldexp(1.0, -24);
        const double rMax =
            maxAbs(run.result.r) * 1.01 + 1e-300; // the preview's r are on the same circle
        const double yMax = maxAbs(run.measured), uMax = maxAbs(run.result.u);
        double rhoW = 0.0, wMax = rMax;
        if (z) {
            const auto& fn = z->feedforwardNum.ascending();
            const auto& fd = z->feedforwardDen.ascending();
            // |w| <= l1 gain of the feedforward filter times max |r|.
            std::vector<double> impulse(n, 0.0);
            impulse[0] = 1.0;
            wMax = sumAbs(filterZInverse(z->feedforwardNum, z->feedforwardDen, impulse)) * rMax;
            rhoW = gammaN(static_cast<int>(fn.size() + fd.size()) + 4) *
                   (sumAbs(fn) * rMax + sumAbs(fd, 1) * wMax) / std::abs(fd[0]);
        }
        const auto& f = d.f.ascending();
        const auto& g = d.g.ascending();
        const double rhoV = gammaN(static_cast<int>(f.size() + g.size()) + 5) *
                            (std::abs(d.kf) * wMax + sumAbs(g) * yMax + sumAbs(f, 1) * uMax) /
                            std::abs(f[0]);
        const auto gains =
            rstL1Gains(d, z, n + (z ? static_cast<std::size_t>(z->previewSteps) : 0));
        for (int s = 0; s < 2; ++s)
            bound[static_cast<std::size_t>(s)] =
                gains[0][static_cast<std::size_t>(s)] * eps * rMax +
                gains[1][static_cast<std::size_t>(s)] * eps * yMax +
                gains[2][static_cast<std::size_t>(s)] * rhoW +
                gains[3][static_cast<std::size_t>(s)] * rhoV;
    }
    return {1.01 * bound[0], 1.01 * bound[1]};
}

/// Braga et al.'s session with a cubic that saturates (0 -> 600 mm in 10 s), a 1 um encoder, a
/// 16-bit DAC and one sample of delay: every path of the PI (clipping, anti-windup, quantizers).
Session saturatingGtSession(PiDiscretization method, AntiWindup antiWindup) {
    Session s = Session::paperDefault();
    s.trajectory.tfSeconds = 10.0;
    s.trajectory.durationSeconds = 40.0;
    s.piDiscretization = method;
    s.implementation.antiWindup = antiWindup;
    s.implementation.trackingTimeSeconds = antiWindup == AntiWindup::BackCalculation ? 2.0 : 0.0;
    s.implementation.encoderResolutionMm = 0.001;
    s.implementation.dacBits = 16;
    s.implementation.delaySamples = 1;
    return s;
}

/// Both axes by Patrick, Ishak and Adnan's pole placement on the 25 mm circle; x with ZPETC, y
/// without.
Session ppSession() {
    Session s = Session::paperDefault();
    for (auto& axis : s.axes)
        axis.method = DesignMethod::PolePlacementZpetc;
    s.axes[1].pp.zpetcEnabled = false;
    s.trajectory.kind = TrajectoryKind::Circle;
    s.trajectory.radius = 25.0;
    s.trajectory.omegaRadPerSec = 0.2;
    s.trajectory.rampInSeconds = 5.0;
    return s;
}

} // namespace

class TstFirmwareLoop : public QObject {
    Q_OBJECT
private slots:
    void doubleMatchesTheCore_data();
    void doubleMatchesTheCore();
    void floatStaysWithinTheDerivedBound_data();
    void floatStaysWithinTheDerivedBound();
};

void TstFirmwareLoop::doubleMatchesTheCore_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("antiWindup");
    for (const AntiWindup aw : {AntiWindup::None, AntiWindup::Clamp, AntiWindup::BackCalculation}) {
        const QByteArray name = QByteArray::fromStdString(antiWindupName(aw));
        QTest::newRow("GT tustin " + name) << 0 << static_cast<int>(aw);
        QTest::newRow("GT backward euler " + name) << 1 << static_cast<int>(aw);
    }
    // A table with a flexible mode and the notch designed for it: the notch's biquad in C.
    QTest::newRow("GT tustin clamp, mode and notch") << 3 << static_cast<int>(AntiWindup::Clamp);
    QTest::newRow("pole placement clamp") << 2 << static_cast<int>(AntiWindup::Clamp);
    QTest::newRow("pole placement none") << 2 << static_cast<int>(AntiWindup::None);
}

// Source: the core's sampled-data run of the same session. Tolerance: 1e-12 of the signal's
// largest magnitude (the issue's 1e-12 relative); the operations are the same, so the runs
// agree to the bit, and the assertion only leaves room for the %.17g text round trip (exact).
void TstFirmwareLoop::doubleMatchesTheCore() {
    QFETCH(int, kind);
    QFETCH(int, antiWindup);
    Session s;
    if (kind < 2 || kind == 3) {
        s = saturatingGtSession(kind == 1 ? PiDiscretization::BackwardEuler
                                          : PiDiscretization::Tustin,
                                static_cast<AntiWindup>(antiWindup));
        if (kind == 3)
            for (AxisSettings& a : s.axes) {
                a.gt.flexibleMode = {20.0, 0.05, 0.0, 0.02};
                a.gt.notch = notchForMode(a.gt.flexibleMode);
            }
    } else {
        s = ppSession();
        s.implementation.antiWindup = static_cast<AntiWindup>(antiWindup);
        s.implementation.encoderResolutionMm = 0.001;
        s.implementation.dacBits = 16;
        s.implementation.delaySamples = 1;
        // A limit below the ideal loop's largest command, so the RST law clips.
        const SessionEvaluation ideal = evaluateSession(ppSession());
        s.umaxVolts = 0.7 * std::min(maxAbs(ideal.axes[0].run.u), maxAbs(ideal.axes[1].run.u));
    }
    const SessionEvaluation e = evaluateSession(s);
    ExportOptions options;
    options.piMethod = s.piDiscretization;
    const std::string header = exportCHeader(s, e, options);
    QTemporaryDir dir;
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& a = e.axes[static_cast<std::size_t>(i)];
        QVERIFY2(a.ok && a.digital, a.error.text.c_str());
        const SimulationResult& core = a.digital->run.result;
        QVERIFY(std::count(core.clipped.begin(), core.clipped.end(), true) >
                0); // clipping exercised
        const LoopRun c = runHarness(dir.path(), header, s.axes[static_cast<std::size_t>(i)].id,
                                     a.gt.has_value(), writeInput(s, e, i));
        QCOMPARE(c.u.size(), core.u.size());
        const double du = maxDifference(c.u, core.u), dy = maxDifference(c.y, core.y);
        qInfo("axis %d: %zu samples, max |du| %.3g V, max |dy| %.3g mm", i, c.u.size(), du, dy);
        QVERIFY2(du <= 1e-12 * maxAbs(core.u), qPrintable(QString::number(du)));
        QVERIFY2(dy <= 1e-12 * maxAbs(core.y), qPrintable(QString::number(dy)));
    }
}

void TstFirmwareLoop::floatStaysWithinTheDerivedBound_data() {
    QTest::addColumn<int>("kind");
    QTest::newRow("GT tustin") << 0;
    QTest::newRow("GT backward euler") << 1;
    QTest::newRow("pole placement") << 2;
}

// Source: the core's double run and the bound of floatBound() (derivation above it), on runs
// without clipping or quantization (there the loop is linear and the bound holds; a float
// rounding can move a clipping or quantization decision, which no rounding bound covers).
void TstFirmwareLoop::floatStaysWithinTheDerivedBound() {
    QFETCH(int, kind);
    Session s;
    if (kind < 2) {
        s = Session::paperDefault(); // the paper's 130 s cubic: unclipped
        s.trajectory.durationSeconds = 150.0;
        s.piDiscretization = kind == 0 ? PiDiscretization::Tustin : PiDiscretization::BackwardEuler;
    } else {
        s = ppSession();
        s.umaxVolts = 1e6; // no clipping
    }
    const SessionEvaluation e = evaluateSession(s);
    ExportOptions options;
    options.piMethod = s.piDiscretization;
    options.precision = CPrecision::Float;
    const std::string header = exportCHeader(s, e, options);
    QVERIFY(header.find("typedef float xyt_real;") != std::string::npos);
    QTemporaryDir dir;
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& a = e.axes[static_cast<std::size_t>(i)];
        QVERIFY(a.ok && a.digital);
        const SimulationResult& core = a.digital->run.result;
        QCOMPARE(std::count(core.clipped.begin(), core.clipped.end(), true), 0);
        const LoopRun c = runHarness(dir.path(), header, s.axes[static_cast<std::size_t>(i)].id,
                                     a.gt.has_value(), writeInput(s, e, i));
        QCOMPARE(c.u.size(), core.u.size());
        const double du = maxDifference(c.u, core.u), dy = maxDifference(c.y, core.y);
        const auto bound = floatBound(s, e, i);
        qInfo("axis %d float: max |dy| %.3g mm (bound %.3g), max |du| %.3g V (bound %.3g)", i, dy,
              bound[0], du, bound[1]);
        QVERIFY(dy > 0.0); // it is float: the runs differ
        QVERIFY2(dy <= bound[0], qPrintable(QString("dy %1 > bound %2").arg(dy).arg(bound[0])));
        QVERIFY2(du <= bound[1], qPrintable(QString("du %1 > bound %2").arg(du).arg(bound[1])));
    }
}

QTEST_APPLESS_MAIN(TstFirmwareLoop)
#include "tst_firmware_loop.moc"
