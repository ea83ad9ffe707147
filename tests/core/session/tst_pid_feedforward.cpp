// SPDX-License-Identifier: GPL-3.0-or-later
// The PID + feedforward method (core/session/pid_feedforward_method.h) against its sources:
// the closed forms of the quintic move and of the model's inverse, the invariant that the exact
// inverse leaves no continuous tracking error but that of the first-order hold (falling as dt^2),
// an independent loop's figures for Braga et al.'s lower base (the 1000x of the feedforward),
// the z-plane poles of the sampled PID loop against its own simulation, and the firmware C in
// the loop (double: equal to the core's sampled-data run to 1e-12 of the signal).
#include "core/design/model_feedforward.h"
#include "core/model/number_format.h"
#include "core/session/design_method_module.h"
#include "core/session/design_study.h"
#include "core/session/export_text.h"
#include "core/session/linuxcnc_export.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/robustness_problem.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"
#include "core/study/robustness.h"
#include "tests/support/c_harness.h"
#include "tests/support/core_checks.h"
#include "tests/support/tolerance.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

using namespace xyt;

using xyt::test::maxAbs;

namespace {

/// Braga et al.'s session, axis x on the PID + feedforward method with the paper's PI
/// (P = kp unit, I = ki unit: wn = 2, kp = 30) and feedforward @p ffScale times the model's.
Session pidSession(double ffScale = 1.0, double durationSeconds = 130.0) {
    Session s = Session::paperDefault();
    s.trajectory.durationSeconds = durationSeconds;
    AxisSettings& x = s.axes[0];
    x.method = DesignMethod::PidFeedforward;
    const ModelFeedforwardGains ff =
        modelFeedforwardGains(x.gt.plant, x.gt.modelUnitsPerPositionUnit);
    const GtDesign gt = designGuilleminTruxal(x.gt.plant, 2.0, 30.0);
    x.parameters = {{"p", gt.kp * 0.001},
                    {"i", gt.ki * 0.001},
                    {"ff1", ffScale * ff.ff1},
                    {"ff2", ffScale * ff.ff2},
                    {"ff3", ffScale * ff.ff3}};
    return s;
}

} // namespace

class TstPidFeedforward : public QObject {
    Q_OBJECT
private slots:
    void quinticMeetsItsEndConditions();
    void modelFeedforwardIsThePlantsInverse();
    void exactFeedforwardLeavesOnlyTheHoldsError();
    void sampledErrorFallsWithTheControllerPeriod();
    void feedforwardCutsTheLowerBasesErrorThousandfold();
    void feedforwardSurvivesAMistunedGain();
    void sampledLoopPolesGovernItsDecay();
    void refusalsNameTheField();
    void firmwareRunsTheCoresLoop();
    void linuxCncExportReadsBackTheGains();
    void movedZeroIsTheControllersZero();
    void programContourAndExportsCarryTheFeedforward();
    void designSpaceMapsThePiWithItsFeedforward();
};

namespace {

/// The `setp pid.<joint>.<pin> value` lines and the commented INI `NAME = value` lines of a
/// LinuxCNC export, by "<joint>.<pin>" and "<joint>.<NAME>".
std::map<std::string, double> parseLinuxCnc(const std::string& text) {
    std::map<std::string, double> out;
    std::istringstream in(text);
    std::string line;
    std::string joint;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string first, name, equals;
        double value = 0.0;
        words >> first;
        if (first == "setp") {
            words >> name >> value;
            out[name.substr(4)] = value; // "pid.0.Pgain" -> "0.Pgain"
        } else if (first == "#") {
            words >> name;
            if (name.rfind("[JOINT_", 0) == 0)
                joint = name.substr(7, name.size() - 8);
            else if ((name == "FERROR" || name == "MIN_FERROR") && (words >> equals >> value))
                out[joint + "." + name] = value;
        }
    }
    return out;
}

} // namespace

void TstPidFeedforward::quinticMeetsItsEndConditions() {
    // Source: the six end conditions the closed form solves (trajectory.h), and the derivatives
    // against central differences of the position (error O(h^2) f''', h = 1e-4 s: < 1e-6 here).
    const QuinticTrajectory q(10.0, 610.0, 2.0, 132.0, 1.5, -0.5);
    const MotionSample start = q.motion(2.0 + 1e-12), end = q.motion(132.0 - 1e-12);
    XYT_COMPARE_NEAR(start.position, 10.0, 0.0, 1e-9);
    XYT_COMPARE_NEAR(start.velocity, 1.5, 0.0, 1e-9);
    XYT_COMPARE_NEAR(start.acceleration, 0.0, 0.0, 1e-9);
    XYT_COMPARE_NEAR(end.position, 610.0, 0.0, 1e-9);
    XYT_COMPARE_NEAR(end.velocity, -0.5, 0.0, 1e-9);
    XYT_COMPARE_NEAR(end.acceleration, 0.0, 0.0, 1e-9);
    const double h = 1e-4;
    for (double t : {20.0, 67.0, 101.5}) {
        const MotionSample m = q.motion(t);
        XYT_COMPARE_NEAR(m.velocity, (q.position(t + h) - q.position(t - h)) / (2 * h), 0.0, 1e-6);
        XYT_COMPARE_NEAR(m.acceleration,
                         (q.motion(t + h).velocity - q.motion(t - h).velocity) / (2 * h), 0.0,
                         1e-6);
        XYT_COMPARE_NEAR(m.jerk,
                         (q.motion(t + h).acceleration - q.motion(t - h).acceleration) / (2 * h),
                         0.0, 1e-6);
    }
    // At rest the classical 10 s^3 - 15 s^4 + 6 s^5: half way it is half way.
    const QuinticTrajectory rest(0.0, 600.0, 0.0, 130.0);
    XYT_COMPARE_NEAR(rest.position(65.0), 300.0, 1e-14, 0.0);
    XYT_COMPARE_NEAR(rest.motion(65.0).velocity, 600.0 / 130.0 * 30.0 / 16.0, 1e-14, 0.0);
}

void TstPidFeedforward::modelFeedforwardIsThePlantsInverse() {
    // Source: the closed form u = (r''' + a1 r'' + a2 r') unit / k0; the issue's figure FF1 =
    // 0.0471 V/(mm/s) for the lower base (3665 * 0.001 / 77.8 = 0.047108...).
    const ModelFeedforwardGains ff = modelFeedforwardGains({77.8, 125.3, 3665.0}, 0.001);
    XYT_COMPARE_NEAR(ff.ff1, 3665.0 * 0.001 / 77.8, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ff.ff2, 125.3 * 0.001 / 77.8, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ff.ff3, 0.001 / 77.8, 1e-15, 0.0);
    QCOMPARE(std::round(ff.ff1 * 1e4) / 1e4, 0.0471);
    // The defaults of a new axis are exactly those gains.
    for (const MethodParameter& p : pidFeedforwardParameters())
        if (p.name == "ff1")
            XYT_COMPARE_NEAR(p.defaultValue, ff.ff1, 1e-15, 0.0);
    // r -> y with the exact inverse is 1 at every frequency (T + S F G / unit = (CG + FG/u) /
    // (1 + CG) and F G / u = 1 for the exact inverse): checked at three frequencies to 1e-9.
    const Session s = pidSession();
    const PidFeedforwardDesign d = designPidFeedforward(s, 0);
    for (double w : {0.1, 3.0, 60.0}) {
        const auto v = d.trackingWithFeedforward(std::complex<double>(0.0, w));
        XYT_COMPARE_NEAR(std::abs(v - 1.0), 0.0, 0.0, 1e-9);
    }
    // The equations panel's lines with words are coded (translated by the workbench); their
    // English names the model inverse's gains as formatNumber prints them (6 digits).
    const AxisEvaluation a = evaluateAxis(s, 0);
    const std::vector<Diagnostic> lines =
        designMethodModule(DesignMethod::PidFeedforward).equations(s.axes[0], a);
    QCOMPARE(lines.size(), std::size_t(4));
    QVERIFY(!lines[0].coded()); // symbols and numbers only
    QCOMPARE(lines[2].code, std::string("session_pid_equation_feedforward"));
    QCOMPARE(lines[2].args.size(), std::size_t(6));
    QCOMPARE(lines[2].args[3].text, formatNumber(ff.ff1, 6));
    QVERIFY2(lines[2].text.find("(model inverse: a2 u/k0 = " + formatNumber(ff.ff1, 6) + ", ") !=
                 std::string::npos,
             lines[2].text.c_str());
    QCOMPARE(lines[3].code, std::string("session_pid_equation_controller"));
    QVERIFY2(lines[3].text.find(", u = 0.001 model units per mm") != std::string::npos,
             lines[3].text.c_str());
}

void TstPidFeedforward::exactFeedforwardLeavesOnlyTheHoldsError() {
    // Invariant: with the plant's exact inverse on a move whose derivatives start and end at
    // rest (the quintic), e = 0 for the continuous loop; what remains is the first-order hold of
    // r and u_ff between samples, O(dt^2). So the largest error falls 4x when dt halves (within
    // 3.5..4.5: the next term is O(dt^3)), and is far below the feedback's alone.
    std::array<double, 2> errors{};
    double feedbackOnly = 0.0;
    for (int k = 0; k < 2; ++k) {
        Session s = pidSession(1.0, 150.0);
        s.trajectory.profile = MoveProfile::Quintic;
        s.trajectory.dtSeconds = k == 0 ? 0.01 : 0.005;
        const AxisEvaluation a = evaluateAxis(s, 0);
        QVERIFY2(a.ok, a.error.text.c_str());
        errors[static_cast<std::size_t>(k)] = maxAbs(a.run.e);
        feedbackOnly = maxAbs(a.feedbackOnlyRun.e);
    }
    const double ratio = errors[0] / errors[1];
    QVERIFY2(ratio > 3.5 && ratio < 4.5, qPrintable(QString::number(ratio)));
    QVERIFY2(errors[1] < 1e-6 * feedbackOnly, qPrintable(QString::number(errors[1])));
}

void TstPidFeedforward::sampledErrorFallsWithTheControllerPeriod() {
    // Invariant: with the model's exact inverse on the quintic move, what the digital loop
    // still misses comes from sampling: the zero-order hold delays the command by half a period
    // and the backward differences by half a period per order, so the error is first order in
    // Ts. Halving Ts (10 -> 5 -> 2.5 ms) halves the largest error: each ratio in 1.8 .. 2.2 (the
    // next term is O(Ts^2)), for both sources of the command's derivatives.
    for (const double source : {0.0, 1.0}) {
        std::vector<double> errors;
        for (const double ts : {0.01, 0.005, 0.0025}) {
            Session s = pidSession(1.0, 150.0);
            s.trajectory.profile = MoveProfile::Quintic;
            s.controllerTsSeconds = ts;
            s.axes[0].parameters["command_derivatives"] = source;
            const AxisEvaluation a = evaluateAxis(s, 0);
            QVERIFY2(a.ok && a.digital, a.error.text.c_str());
            errors.push_back(a.digital->metrics.maxAbsError);
        }
        for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
            const double ratio = errors[k] / errors[k + 1];
            QVERIFY2(ratio > 1.8 && ratio < 2.2, qPrintable(QString("source %1: %2 / %3 = %4")
                                                                .arg(source)
                                                                .arg(errors[k])
                                                                .arg(errors[k + 1])
                                                                .arg(ratio)));
        }
    }
}

void TstPidFeedforward::feedforwardCutsTheLowerBasesErrorThousandfold() {
    // Source: an independent loop in SciPy (tests/data/gen_pid_feedforward.py, its figures in
    // tests/data/README.md) gives, for the lower base under the paper's PI at 10 ms on the 130 s
    // cubic, RMSE 5.87346 mm without feedforward, 0.00183526 mm with the model's from backward
    // differences, 0.000917733 mm from the cubic's exact derivatives. Required: at least 1000x.
    // Tolerances: 1e-5 relative where both loops do the same operations (the script prints six
    // digits); 0.2 % for the exact derivatives, where the script counts the samples t = t0 and
    // t = tf as inside the move and the core as at rest (one sample of the acceleration step
    // each: 0.09 % of the RMSE). The paper's PI as the session discretizes it (Tustin) differs
    // from LinuxCNC's rectangle rule by 0.003 % of the RMSE: 1e-4.
    const Session gt = [] {
        Session s = Session::paperDefault();
        s.trajectory.durationSeconds = 130.0;
        return s;
    }();
    const AxisEvaluation without = evaluateAxis(gt, 0);
    QVERIFY(without.digital);
    const double rmseWithout = without.digital->metrics.rmse;
    XYT_COMPARE_NEAR(rmseWithout, 5.87346, 1e-4, 0.0);
    const AxisEvaluation with = evaluateAxis(pidSession(), 0);
    QVERIFY2(with.ok, with.error.text.c_str());
    QVERIFY(with.digital);
    const double rmseWith = with.digital->metrics.rmse;
    QVERIFY2(rmseWithout / rmseWith >= 1000.0, qPrintable(QString::number(rmseWith)));
    XYT_COMPARE_NEAR(rmseWith, 0.00183526, 1e-5, 0.0);
    // The same PID with its feedforward off tracks as the paper's PI does.
    const AxisEvaluation off = evaluateAxis(pidSession(0.0), 0);
    XYT_COMPARE_NEAR(off.digital->metrics.rmse, 5.87346, 1e-5, 0.0);
    // From the trajectory generator's exact derivatives.
    Session exact = pidSession();
    exact.axes[0].parameters["command_derivatives"] = 1.0;
    const AxisEvaluation e = evaluateAxis(exact, 0);
    XYT_COMPARE_NEAR(e.digital->metrics.rmse, 0.000917733, 2e-3, 0.0);
    // The sampled loop's u is split: u = feedback + feedforward while not clipped.
    const SimulationResult& run = with.digital->run.result;
    QCOMPARE(run.uFeedforward.size(), run.u.size());
    XYT_COMPARE_NEAR(run.uFeedforward[6500], 0.0471 * 600.0 * 1.5 / 130.0, 0.01, 0.0);
}

void TstPidFeedforward::feedforwardSurvivesAMistunedGain() {
    // Required: with the plant's k0 10 % off the model the feedforward was computed from, the
    // RMSE is still at least 5x below the feedback's alone. The SciPy loop
    // (gen_pid_feedforward.py) gives 0.533662 mm for the digital loop on that plant (1e-5).
    Session s = pidSession();
    s.axes[0].gt.plant.k0 *= 1.1;
    const AxisEvaluation a = evaluateAxis(s, 0);
    QVERIFY(a.ok);
    QVERIFY2(a.rmseWithoutFf / a.metrics.rmse >= 5.0,
             qPrintable(QString::number(a.rmseWithoutFf / a.metrics.rmse)));
    QVERIFY2(a.digital->metrics.rmse * 5.0 <= a.rmseWithoutFf, "digital");
    XYT_COMPARE_NEAR(a.digital->metrics.rmse, 0.533662, 1e-5, 0.0);
    // The robustness study's nominal plant reproduces the evaluation's run (the problem carries
    // the feedforward): same RMSE to 1e-12 relative.
    const AxisEvaluation nominal = evaluateAxis(pidSession(), 0);
    const RobustnessProblem p = designMethodModule(DesignMethod::PidFeedforward)
                                    .robustnessProblem(pidSession(), 0, nominal);
    QCOMPARE(p.feedforwardVolts.size(), nominal.run.u.size());
    RobustnessOptions o;
    o.samples = 2;
    o.corners = false;
    RobustnessResult r = analyzeRobustness(p, o);
    XYT_COMPARE_NEAR(r.nominal.tracking.rmse, nominal.metrics.rmse, 1e-12, 0.0);
    // ... and the feedback's alone (AxisEvaluation::rmseWithoutFf): what the feedforward gains.
    XYT_COMPARE_NEAR(r.nominal.rmseWithoutFf, nominal.rmseWithoutFf, 1e-12, 0.0);
    // On the corner k0 + 10 % the robustness run is the evaluation of that plant above.
    RobustnessProblem off = p;
    for (UncertainParameter& u : off.parameters)
        if (u.name == "k0")
            u.relative = 0.1;
    o.corners = true;
    o.samples = 1;
    r = analyzeRobustness(off, o);
    bool found = false;
    for (const PlantRun& run : r.runs)
        if (run.corner && run.values[0] > 77.8 && run.values[1] == 125.3 &&
            run.values[2] == 3665.0) {
            XYT_COMPARE_NEAR(run.tracking.rmse, a.metrics.rmse, 1e-9, 0.0);
            XYT_COMPARE_NEAR(run.rmseWithoutFf, a.rmseWithoutFf, 1e-9, 0.0);
            found = true;
        }
    QVERIFY(found);
}

void TstPidFeedforward::sampledLoopPolesGovernItsDecay() {
    // Invariant: the error of the linear sampled loop (no limit, quantization or deadband)
    // after a position step decays as |z_max|^k for the slowest pole. Late in the run (4000
    // samples, where the faster poles have decayed by many decades more) the envelope's
    // geometric decay over 400 samples equals |z_max| to 1e-6.
    Session s = pidSession(0.0);
    s.umaxVolts = 1e9;
    s.axes[0].parameters["d"] = 0.0005;
    s.axes[0].parameters["derivative_filter"] = 0.01;
    const PidFeedforwardDesign d = designPidFeedforward(s, 0);
    const auto poles =
        sampledServoPidLoopPoles(sampledPlant(d.plant, d.tsSeconds), d.gains, d.unit, 0);
    double slowest = 0.0;
    for (const auto& p : poles)
        slowest = std::max(slowest, std::abs(p));
    QVERIFY(slowest < 1.0);
    std::vector<MotionSample> step(6000, MotionSample{1.0, 0.0, 0.0, 0.0});
    SampledDataOptions o;
    const SampledDataRun run =
        simulateSampledServoPid(d.plant, d.gains, d.tsSeconds, step,
                                CommandDerivativeSource::BackwardDifferences, o, d.unit);
    // Peak |e| over windows one oscillation long, 400 samples apart, late in the run.
    const auto peak = [&](std::size_t from) {
        double m = 0.0;
        for (std::size_t k = from; k < from + 400; ++k)
            m = std::max(m, std::abs(run.result.e[k]));
        return m;
    };
    const double measured = std::pow(peak(4400) / peak(4000), 1.0 / 400.0);
    XYT_COMPARE_NEAR(measured, slowest, 1e-6, 0.0);
}

void TstPidFeedforward::refusalsNameTheField() {
    Session s = pidSession();
    s.axes[0].parameters["ff1"] = -1.0;
    AxisEvaluation a = evaluateAxis(s, 0);
    QVERIFY(!a.ok);
    QCOMPARE(QString::fromStdString(a.errorField), QStringLiteral("axes[0].parameters.ff1"));
    s = pidSession();
    s.axes[0].parameters["derivative_filter"] = 0.001; // below Ts/pi = 0.00318 s
    a = evaluateAxis(s, 0);
    QVERIFY(!a.ok);
    QCOMPARE(QString::fromStdString(a.errorField),
             QStringLiteral("axes[0].parameters.derivative_filter"));
    s = pidSession();
    s.axes[0].parameters["derivative_on_measurement"] = 0.5;
    a = evaluateAxis(s, 0);
    QCOMPARE(QString::fromStdString(a.errorField),
             QStringLiteral("axes[0].parameters.derivative_on_measurement"));
    s = pidSession();
    s.axes[0].parameters["p"] = 0.0;
    s.axes[0].parameters["i"] = 0.0;
    a = evaluateAxis(s, 0);
    QCOMPARE(QString::fromStdString(a.errorField), QStringLiteral("axes[0].parameters.p"));
    s = pidSession();
    s.axes[0].parameters["ff2"] = std::nan("");
    a = evaluateAxis(s, 0);
    QCOMPARE(QString::fromStdString(a.errorField), QStringLiteral("axes[0].parameters.ff2"));
}

void TstPidFeedforward::firmwareRunsTheCoresLoop() {
    // The exported step function, compiled with -Wall -Wextra -Werror -pedantic, driven by the
    // plant of the core's sampled-data run (sampledPlant, the same sums in the same order):
    // u and y equal the core's run to 1e-12 of their largest magnitude (the same operations in
    // the same order in double; the bound only allows for the C compiler's printing).
    Session s = pidSession(1.0, 30.0);
    s.axes[0].parameters["d"] = 0.0005;
    s.axes[0].parameters["derivative_filter"] = 0.02;
    s.axes[0].parameters["max_error_i"] = 50.0;
    s.axes[0].parameters["deadband"] = 1e-4;
    const SessionEvaluation e = evaluateSession(s);
    QVERIFY(e.axes[0].ok && e.axes[0].digital);
    const std::string header = exportCHeader(s, e);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const char* harness = R"(#include <math.h>
#include <stdio.h>
#include "xyt.h"
int main(void) {
    int n, k, i, j, samples;
    double phi[64], gamma[8], c[8], x[8], next[8], unit;
    xyt_x_state s;
    if (scanf("%d %lf %d", &samples, &unit, &n) != 3 || n > 8) return 2;
    for (i = 0; i < n * n; ++i) if (scanf("%lf", &phi[i]) != 1) return 2;
    for (i = 0; i < n; ++i) if (scanf("%lf", &gamma[i]) != 1) return 2;
    for (i = 0; i < n; ++i) if (scanf("%lf", &c[i]) != 1) return 2;
    for (i = 0; i < n; ++i) x[i] = 0.0;
    xyt_x_init(&s);
    for (k = 0; k < samples; ++k) {
        double r, y = 0.0, u;
        if (scanf("%lf", &r) != 1) return 2;
        for (j = 0; j < n; ++j) y += c[j] * x[j];
        u = xyt_x_step(&s, r, y / unit);
        printf("%.17g %.17g\n", u, y / unit);
        for (i = 0; i < n; ++i) {
            double acc = 0.0;
            for (j = 0; j < n; ++j) acc += phi[i * n + j] * x[j];
            next[i] = acc + gamma[i] * u;
        }
        for (i = 0; i < n; ++i) x[i] = next[i];
    }
    return 0;
}
)";
    const DigitalEvaluation& d = *e.axes[0].digital;
    const PidFeedforwardDesign& design = pidFeedforwardDesign(e.axes[0]);
    const SampledPlant p = sampledPlant(design.plant, d.tsSeconds);
    std::ostringstream in;
    in.precision(17);
    in << d.run.result.r.size() << " " << design.unit << " " << p.states << "\n";
    for (double v : p.phi)
        in << v << " ";
    for (double v : p.gamma)
        in << v << " ";
    for (double v : p.c)
        in << v << " ";
    for (double v : d.run.result.r)
        in << v << " ";
    const test::CHarnessRun run =
        test::runCHarness(dir.path(), header, harness, QByteArray::fromStdString(in.str()));
    QVERIFY2(run.ok, qPrintable(run.error));
    std::vector<double> u, y;
    for (const QByteArray& line : run.output.split('\n')) {
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() == 2) {
            u.push_back(parts[0].toDouble());
            y.push_back(parts[1].toDouble());
        }
    }
    QCOMPARE(u.size(), d.run.result.u.size());
    double du = 0.0, dy = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        du = std::max(du, std::abs(u[k] - d.run.result.u[k]));
        dy = std::max(dy, std::abs(y[k] - d.run.result.y[k]));
    }
    QVERIFY2(du <= 1e-12 * maxAbs(d.run.result.u), qPrintable(QString::number(du)));
    QVERIFY2(dy <= 1e-12 * maxAbs(d.run.result.y), qPrintable(QString::number(dy)));
}

void TstPidFeedforward::linuxCncExportReadsBackTheGains() {
    // Source: the session's own gains; the file writes 17 significant digits, so reading it
    // back gives the same doubles (exact comparison). Axis y (Guillemin-Truxal) maps to P = kp u,
    // I = ki u; FERROR and MIN_FERROR are kFollowingErrorMargin x the digital run's errors.
    Session s = pidSession(1.0, 130.0);
    s.axes[0].parameters["d"] = 0.0004;
    s.axes[0].parameters["deadband"] = 0.002;
    s.axes[0].parameters["max_error_i"] = 30.0;
    const SessionEvaluation e = evaluateSession(s);
    auto pins = parseLinuxCnc(exportLinuxCnc(s, e));
    const ServoPidGains& g = pidFeedforwardDesign(e.axes[0]).gains;
    QCOMPARE(pins.at("0.Pgain"), g.p);
    QCOMPARE(pins.at("0.Igain"), g.i);
    QCOMPARE(pins.at("0.Dgain"), 0.0004);
    QCOMPARE(pins.at("0.FF1"), g.ff1);
    QCOMPARE(pins.at("0.FF2"), g.ff2);
    QCOMPARE(pins.at("0.FF3"), g.ff3);
    QCOMPARE(pins.at("0.deadband"), 0.002);
    QCOMPARE(pins.at("0.maxerrorI"), 30.0);
    QCOMPARE(pins.at("0.maxoutput"), 2.5);
    QCOMPARE(pins.at("0.FERROR"), kFollowingErrorMargin * maxAbs(e.axes[0].digital->run.result.e));
    QVERIFY(pins.at("0.MIN_FERROR") <= pins.at("0.FERROR"));
    const GtDesign y = *e.axes[1].gt;
    QCOMPARE(pins.at("1.Pgain"), y.kp * 0.001);
    QCOMPARE(pins.at("1.Igain"), y.ki * 0.001);
    QCOMPARE(pins.at("1.FF1"), 0.0);
    // With the model's feedforward: written for the Guillemin-Truxal axis too.
    pins = parseLinuxCnc(exportLinuxCnc(s, e, true));
    const ModelFeedforwardGains upper = modelFeedforwardGains(s.axes[1].gt.plant, 0.001);
    QCOMPARE(pins.at("1.FF1"), upper.ff1);
    QCOMPARE(pins.at("1.FF3"), upper.ff3);
    // A pole-placement axis has no pid equivalent: refused by name.
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    const SessionEvaluation pp = evaluateSession(s);
    try {
        exportLinuxCnc(s, pp);
        QFAIL("a pole-placement axis was exported");
    } catch (const InvalidInput& error) {
        QCOMPARE(QString::fromStdString(error.field()), QStringLiteral("axes[1].method"));
    }
    // withModelFeedforward refuses it too, and turns a Guillemin-Truxal axis into its PI + FF.
    QCOMPARE(test::invalidInputField([&] { withModelFeedforward(s.axes[1], 1); }),
             QStringLiteral("axes[1].method"));
    const AxisSettings converted = withModelFeedforward(Session::paperDefault().axes[0], 0);
    QCOMPARE(converted.method, DesignMethod::PidFeedforward);
    Session gtFf = Session::paperDefault();
    gtFf.trajectory.durationSeconds = 130.0;
    gtFf.axes[0] = converted;
    XYT_COMPARE_NEAR(evaluateAxis(gtFf, 0).digital->metrics.rmse, 0.00183526, 1e-5, 0.0);
}

void TstPidFeedforward::movedZeroIsTheControllersZero() {
    // Invariant: the gains pidGainsWithMovedZero returns give a controller C(s) whose zeros are
    // the moved zero and the kept one (checked on the designed controller's numerator, to 1e-9
    // relative), with the high-frequency gain n2 kept.
    Session s = pidSession();
    PidFeedforwardDesign d = designPidFeedforward(s, 0);
    // PI: the one zero -I/P to -0.05 rad/s: I' = 0.05 P (closed form).
    PidFeedbackGains g = pidGainsWithMovedZero(d, {-d.gains.i / d.gains.p, 0.0}, {-0.05, 0.3});
    QVERIFY(g.ok);
    QCOMPARE(g.p, d.gains.p);
    XYT_COMPARE_NEAR(g.i, 0.05 * d.gains.p, 1e-15, 0.0);
    // PID: move one real zero, keep the other; then pull the pair off the axis.
    s.axes[0].parameters["d"] = 0.002;
    s.axes[0].parameters["derivative_filter"] = 0.01;
    d = designPidFeedforward(s, 0);
    std::vector<std::complex<double>> zeros = d.controller.zeros();
    QCOMPARE(zeros.size(), std::size_t{2});
    const auto check = [&](const PidFeedbackGains& moved, std::complex<double> expected1,
                           std::complex<double> expected2) {
        QVERIFY2(moved.ok, moved.reason.text.c_str());
        Session t = s;
        t.axes[0].parameters["p"] = moved.p;
        t.axes[0].parameters["i"] = moved.i;
        t.axes[0].parameters["d"] = moved.d;
        const PidFeedforwardDesign e = designPidFeedforward(t, 0);
        XYT_COMPARE_NEAR(e.controller.num().descending().front(),
                         d.controller.num().descending().front(), 1e-12, 0.0);
        std::vector<std::complex<double>> z = e.controller.zeros();
        QCOMPARE(z.size(), std::size_t{2});
        const bool direct = std::abs(z[0] - expected1) <= std::abs(z[1] - expected1);
        const std::complex<double> a = direct ? z[0] : z[1], b = direct ? z[1] : z[0];
        QVERIFY(std::abs(a - expected1) <= 1e-9 * std::abs(expected1));
        QVERIFY(std::abs(b - expected2) <= 1e-9 * std::abs(expected2));
    };
    const std::complex<double> fast = std::abs(zeros[0]) > std::abs(zeros[1]) ? zeros[0] : zeros[1];
    const std::complex<double> slow = fast == zeros[0] ? zeros[1] : zeros[0];
    check(pidGainsWithMovedZero(d, slow, {-0.5, 0.0}), {-0.5, 0.0}, fast);
    const std::complex<double> pair(0.8 * fast.real(), 0.3 * std::abs(fast.real()));
    check(pidGainsWithMovedZero(d, fast, pair), pair, std::conj(pair));
    // Refused: the right half plane, and a zero that needs a negative gain.
    QVERIFY(!pidGainsWithMovedZero(d, slow, {0.5, 0.0}).ok);
    QVERIFY(!pidGainsWithMovedZero(d, slow, {-1e6, 0.0}).ok);
}

void TstPidFeedforward::programContourAndExportsCarryTheFeedforward() {
    // A G-code program (a line, a half circle, a line back) run by both axes: with each axis'
    // exact model inverse (central differences of the planned path) the contour error is far
    // below the paper's PI alone (at least 10x in RMS: the requirement's figure for the plain
    // trajectory is 1000x; the planned profile's acceleration steps and the differences cost
    // some). Then the Octave script carries the PID and the tracking response.
    Session s = Session::paperDefault();
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.program =
        "G21 G90 G17\nG0 X0 Y0\nG1 X20 Y0 F600\nG3 X20 Y20 I0 J10\nG1 X0 Y20\nM2\n";
    const SessionEvaluation alone = evaluateSession(s);
    QVERIFY2(alone.program, alone.programError.text.c_str());
    for (int axis : {0, 1})
        s.axes[static_cast<std::size_t>(axis)] =
            withModelFeedforward(s.axes[static_cast<std::size_t>(axis)], axis);
    const SessionEvaluation withFf = evaluateSession(s);
    QVERIFY2(withFf.program, withFf.programError.text.c_str());
    QVERIFY2(
        withFf.program->contour.rms * 10.0 < alone.program->contour.rms,
        qPrintable(
            QString("%1 vs %2").arg(withFf.program->contour.rms).arg(alone.program->contour.rms)));
    // (A program's feed profile has no closed form for the script: a quintic move instead, whose
    // reference the script writes with the closed form's coefficients.)
    s.trajectory.kind = TrajectoryKind::Cubic;
    s.trajectory.profile = MoveProfile::Quintic;
    const std::string m = exportOctaveScript(s, evaluateSession(s));
    const QuinticTrajectory quintic(0.0, 600.0, 0.0, 130.0);
    const auto& c = quintic.localCoefficients();
    QVERIFY(m.find(exactNumber(c[5]) + " * tau.^5;  % quintic") != std::string::npos);
    QVERIFY(m.find("controller_x = (P_x + I_x / s + D_x * s / (Tf_x * s + 1)) / unit_x;") !=
            std::string::npos);
    QVERIFY(m.find("tracking_y = closed_loop_y + feedback(1, controller_y * plant_y) * "
                   "ff_plant_y;") != std::string::npos);
}

void TstPidFeedforward::designSpaceMapsThePiWithItsFeedforward() {
    // Source: the sweep's batched kernel with a feedforward equals simulateLoop with it bit for
    // bit (the same two-column discretization and sums: exact comparison); and the map's point
    // of the paper's (wn, kp) is the evaluation of the PID + feedforward axis with that PI (its
    // controller's coefficients differ by the mm/model-unit round trip: 1e-9).
    const Session s = pidSession(1.0, 130.0);
    const DesignProblem problem = sessionDesignProblem(s, 0);
    QCOMPARE(problem.feedforwardVolts.size(), problem.reference.size());
    const DesignEvaluator evaluator(problem);
    const DesignPoint point = evaluator.evaluate(2.0, 30.0);
    const GtDesign gt = designGuilleminTruxal(problem.plant, 2.0, 30.0);
    LoopSimulationOptions o;
    o.dtSeconds = problem.dtSeconds;
    o.umaxVolts = problem.spec.umaxVolts;
    o.modelUnitsPerPositionUnit = problem.modelUnitsPerPositionUnit;
    o.feedforwardVolts = &problem.feedforwardVolts;
    const TrackingMetrics direct = trackingMetrics(
        simulateLoop(problem.plant.transferFunction(), gt.controller, problem.reference, o));
    QCOMPARE(point.tracking.rmse, direct.rmse);
    QCOMPARE(point.tracking.itae, direct.itae);
    const AxisEvaluation a = evaluateAxis(s, 0);
    XYT_COMPARE_NEAR(point.tracking.rmse, a.metrics.rmse, 1e-9, 0.0);
    // Without the feedforward the same point tracks as the Guillemin-Truxal axis does.
    Session plain = Session::paperDefault();
    plain.trajectory.durationSeconds = 130.0;
    QVERIFY(point.tracking.rmse * 1000.0 <
            DesignEvaluator(sessionDesignProblem(plain, 0)).evaluate(2.0, 30.0).tracking.rmse);
    // A PID with D is refused by name.
    Session withD = s;
    withD.axes[0].parameters["d"] = 0.001;
    QCOMPARE(test::invalidInputField([&] { sessionDesignProblem(withD, 0); }),
             QStringLiteral("axes[0].parameters.d"));
}

QTEST_APPLESS_MAIN(TstPidFeedforward)
#include "tst_pid_feedforward.moc"
