// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-bench: the one benchmark program (not part of the test run). One line per figure:
//   name: median_us=... min_us=... max_us=... runs=...
// Optional argument: a substring; only the benchmarks whose name contains it are run. The program
// is a table of named benchmarks (benchmarks(), at the end); a row is one figure, or a group of
// figures that share their setup and whose names all begin with the row's name (the G-code
// contour, the slider-to-repaint figures), so the filter on the row selects the whole group. The
// core figures come first; gui_slider_to_repaint (last) times the widgets on the offscreen
// platform.
#include "app/allocator_tuning.h"
#include "app/bench_reference_loop.h"
#include "core/analysis/frequency_response.h"
#include "core/analysis/loop_responses.h"
#include "core/analysis/root_locus.h"
#include "core/analysis/stability_margins.h"
#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/design/digital_controller.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/shaper_recommendation.h"
#include "core/design/zpetc.h"
#include "core/identification/arx.h"
#include "core/identification/continuous_fit.h"
#include "core/identification/experiment_file.h"
#include "core/identification/prediction_error.h"
#include "core/identification/spectral_estimate.h"
#include "core/model/state_space.h"
#include "core/session/contour_run.h"
#include "core/session/design_study.h"
#include "core/session/robustness_problem.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/metrics.h"
#include "core/simulation/sampled_data.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"
#include "core/simulation/zpetc_tracking.h"
#include "core/study/design_sweep.h"
#include "ui/design_space_view.h"
#include "ui/main_window.h"
#include "ui/panels/parameter_slider.h"
#include "ui/panels/pid_feedforward_editor.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/session/tuning_session.h"

#include <QApplication>
#include <QSlider>
#include <qcustomplot.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

volatile double sink = 0.0; // keeps results alive so the optimizer cannot drop the work

/// Times the figures of one run and keeps their medians, which the ratio lines read.
class Runner {
public:
    /// Runs @p body until both minRuns and minSeconds are reached (after one warm-up run),
    /// prints the figure and returns its median in microseconds.
    double time(const std::string& name, const std::function<void()>& body, int minRuns = 20,
                double minSeconds = 0.5) {
        using Clock = std::chrono::steady_clock;
        body();
        std::vector<double> us;
        const auto start = Clock::now();
        while (static_cast<int>(us.size()) < minRuns ||
               std::chrono::duration<double>(Clock::now() - start).count() < minSeconds) {
            const auto t0 = Clock::now();
            body();
            us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
            if (us.size() >= 100000)
                break;
        }
        return report(name, std::move(us));
    }

    /// Prints "name: median_us=... min_us=... max_us=... runs=N" for the times @p us, then
    /// @p extra after a space if there is one; returns the median.
    double report(const std::string& name, std::vector<double> us, const std::string& extra = {}) {
        std::sort(us.begin(), us.end());
        const std::size_t n = us.size();
        const double median = n % 2 ? us[n / 2] : 0.5 * (us[n / 2 - 1] + us[n / 2]);
        std::printf("%s: median_us=%.1f min_us=%.1f max_us=%.1f runs=%zu%s%s\n", name.c_str(),
                    median, us.front(), us.back(), n, extra.empty() ? "" : " ", extra.c_str());
        std::fflush(stdout);
        medians_[name] = median;
        return median;
    }

    /// The median of the figure @p name, NaN when this run did not measure it.
    double median(const std::string& name) const {
        const auto it = medians_.find(name);
        return it == medians_.end() ? std::nan("") : it->second;
    }

private:
    std::map<std::string, double> medians_;
};

/// "name: ratio=R (what over what)" when both were measured in this run.
void printRatio(const char* name, double measured, double reference, const char* what) {
    if (std::isfinite(measured) && std::isfinite(reference) && reference > 0.0)
        std::printf("%s: ratio=%.2f (%s)\n", name, measured / reference, what);
}

/// Braga et al.'s lower base (plant, wn, kp), the design most figures time.
xyt::GtPreset lowerBase() {
    return *xyt::findGtPreset("lower-base");
}

xyt::GtDesign lowerBaseDesign() {
    const xyt::GtPreset lower = lowerBase();
    return xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp);
}

// ---- One design point ---------------------------------------------------------------------------

void gtDesign(Runner& r) {
    const xyt::GtPreset lower = lowerBase();
    r.time("gt_design", [&] {
        const auto d = xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp);
        sink = sink + d.ki;
    });
}

// What one design point of the sweep costs besides its tracking run.
void sweepPointLoopModesAndFoh(Runner& r) {
    const auto d = lowerBaseDesign();
    const auto plant = lowerBase().plant.transferFunction();
    r.time("sweep_point_loop_modes_and_foh", [&] {
        const auto modes = xyt::loopModes(plant, d.controller);
        const auto foh = xyt::discretizeFoh(modes.aLinear, modes.bLinear, 0.01);
        sink = sink + foh.phi(0, 0);
    });
}

void sweepPointStepCharacteristics(Runner& r) {
    const auto d = lowerBaseDesign();
    r.time("sweep_point_step_characteristics",
           [&] { sink = sink + xyt::stepCharacteristics(d.closedLoop).settlingTimeSeconds; });
}

void sweepPointStabilityMargins(Runner& r) {
    const auto d = lowerBaseDesign();
    r.time("sweep_point_stability_margins", [&] {
        sink =
            sink + xyt::stabilityMargins(xyt::gtLoopTransferFunctions(d).openLoop).phaseMarginDeg;
    });
}

/// The 4th-order GT loop at 1,000 frequencies plus all its margins (target under 0.2 ms).
void frequencyResponseAndMargins(Runner& r) {
    const xyt::TransferFunction loop = xyt::gtLoopTransferFunctions(lowerBaseDesign()).openLoop;
    const std::vector<double> omegas = xyt::logFrequencyGrid(1e-3, 1e3, 1000);
    r.time("frequency_response_1000_and_margins", [&] {
        const xyt::FrequencyResponse fr = xyt::frequencyResponse(loop, omegas);
        const xyt::StabilityMargins m = xyt::stabilityMargins(loop);
        sink = sink + fr.magnitudeDb[500] + m.phaseMarginDeg;
    });
}

// ---- The lower base on the cubic 0 -> 600 mm in 130 s -------------------------------------------

/// The lower-base loop and the cubic it tracks at dt 0.01 s, |u| <= 2.5 V.
struct CubicRun {
    xyt::GtPreset lower = lowerBase();
    std::vector<double> reference;
    xyt::GtDesign design = lowerBaseDesign();
    xyt::LoopSimulationOptions options;
    xyt::TransferFunction plant = lower.plant.transferFunction();

    CubicRun() {
        const xyt::CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
        reference = xyt::sampled([&](double t) { return cubic.position(t); },
                                 xyt::sampleTimes(130.0, 0.01));
        options.umaxVolts = 2.5;
        options.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
    }
};

void simulateCubic(Runner& r) {
    const CubicRun c;
    r.time("simulate_cubic_130s_dt0.01", [&] {
        const auto run = xyt::simulateLoop(c.plant, c.design.controller, c.reference, c.options);
        sink = sink + run.y.back();
    });
}

/// The same cubic on a table with Coulomb friction (0.05 V) and backlash (0.01 mm), the issue's
/// case (target: within 3x the linear run; the exact piecewise-affine steps), then with a
/// Stribeck dip too (static 0.07 V, 0.5 mm/s: the Runge-Kutta engine throughout), and the two
/// studies that run the nonlinear plant: 100 robustness plants and a 20 x 20 design-space grid,
/// each beside its linear figure.
void simulateCubicFriction(Runner& r) {
    const CubicRun c;
    xyt::TableFriction table;
    table.coulombVolts = 0.05;
    table.backlashMm = 0.01;
    xyt::LoopSimulationOptions o = c.options;
    o.table = &table;
    const double nonlinear = r.time("simulate_cubic_130s_dt0.01_friction", [&] {
        const auto run = xyt::simulateLoop(c.plant, c.design.controller, c.reference, o);
        sink = sink + run.y.back();
    });
    const double linear = r.time("simulate_cubic_130s_dt0.01_linear_same_run", [&] {
        const auto run = xyt::simulateLoop(c.plant, c.design.controller, c.reference, c.options);
        sink = sink + run.y.back();
    });
    printRatio("simulate_cubic_130s_dt0.01_friction", nonlinear, linear,
               "Coulomb friction and backlash / linear, target 3");
    table.staticVolts = 0.07;
    table.stribeckVelocityMmPerS = 0.5;
    const double stribeck = r.time("simulate_cubic_130s_dt0.01_friction_stribeck", [&] {
        const auto run = xyt::simulateLoop(c.plant, c.design.controller, c.reference, o);
        sink = sink + run.y.back();
    });
    printRatio("simulate_cubic_130s_dt0.01_friction_stribeck", stribeck, linear,
               "with the Stribeck dip (Runge-Kutta throughout) / linear");
    xyt::Session session = xyt::Session::paperDefault();
    session.axes[0].friction = table;
    xyt::Session plain = xyt::Session::paperDefault();
    for (const bool withTable : {true, false}) {
        const xyt::Session& s = withTable ? session : plain;
        xyt::RobustnessProblem p = xyt::sessionRobustnessProblem(s, 0);
        xyt::setRelativeRange(p.parameters, "k0", 0.05);
        xyt::RobustnessOptions options;
        options.samples = 100;
        options.corners = false;
        r.time(withTable ? "robustness_100_plants_friction" : "robustness_100_plants_linear",
               [&] { sink = sink + xyt::analyzeRobustness(p, options).runs.size(); });
        const xyt::DesignEvaluator evaluator(xyt::sessionDesignProblem(s, 0));
        std::vector<double> wn, kp;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) {
                wn.push_back(0.5 + 0.1 * i);
                kp.push_back(10.0 + 2.0 * j);
            }
        std::vector<xyt::DesignPoint> points(wn.size());
        r.time(withTable ? "design_space_20x20_friction" : "design_space_20x20_linear", [&] {
            evaluator.evaluateBatch(wn, kp, points, 8);
            sink = sink + points.back().tracking.rmse;
        });
    }
}

/// The sampled-data loop of the digital PI on the same cubic at 10 ms (target under 1 ms), ideal
/// or with a 1 um encoder, a 16-bit DAC and one sample of delay.
void digitalSimulateCubic(Runner& r, bool quantized) {
    const CubicRun c;
    const auto pi = xyt::digitalPi(c.design.kp, c.design.ki, 0.01, xyt::PiDiscretization::Tustin,
                                   xyt::AntiWindup::Clamp);
    xyt::SampledDataOptions options;
    options.umaxVolts = 2.5;
    if (quantized) {
        options.encoderResolution = 0.001;
        options.dacBits = 16;
        options.delaySamples = 1;
    }
    r.time(quantized ? "digital_simulate_cubic_130s_ts0.01_quantized"
                     : "digital_simulate_cubic_130s_ts0.01",
           [&] {
               const auto run = xyt::simulateSampledPi(c.plant, pi, c.reference, options,
                                                       c.lower.modelUnitsPerPositionUnit);
               sink = sink + run.result.y.back();
           });
}

// The part of a slider step that is the core's: the whole evaluation of the default session
// (both axes, the automatic duration, the digital implementation), and the choice of the
// duration alone (both axes simulated to tf).
void sessionEvaluateDefault(Runner& r) {
    const xyt::Session session = xyt::Session::paperDefault();
    r.time("session_evaluate_default",
           [&] { sink = sink + xyt::evaluateSession(session).axes[0].metrics.rmse; });
}

void sessionRunDurationDefault(Runner& r) {
    const xyt::Session session = xyt::Session::paperDefault();
    r.time("session_run_duration_default",
           [&] { sink = sink + xyt::chooseRunDuration(session).seconds; });
}

/// The cubic run into a kept result (no allocation).
void simulateCubicReused(Runner& r) {
    const CubicRun c;
    xyt::SimulationResult kept;
    r.time("simulate_cubic_130s_dt0.01_reused", [&] {
        xyt::simulateLoopInto(c.plant, c.design.controller, c.reference, c.options, kept);
        sink = sink + kept.y.back();
    });
}

/// The plain scalar reference loop of the same recurrence over preallocated arrays, and the
/// ratios of the two simulateLoop figures to it.
void simulateCubicReferenceLoop(Runner& r) {
    const CubicRun c;
    const std::size_t n = c.reference.size();
    std::vector<double> t(n), y(n), e(n), u(n);
    std::unique_ptr<bool[]> clipped(new bool[n]);
    const double plain = r.time("simulate_cubic_130s_dt0.01_reference_loop", [&] {
        // The discretization is part of the work, as in simulateLoop.
        const auto m = xyt::bench::referenceLoop(c.plant, c.design.controller, c.options.dtSeconds);
        xyt::bench::referenceRun(m, c.reference.data(), n, c.options.dtSeconds, c.options.umaxVolts,
                                 c.options.modelUnitsPerPositionUnit, t.data(), y.data(), e.data(),
                                 u.data(), clipped.get());
        sink = sink + y.back();
    });
    printRatio("simulate_cubic_130s_dt0.01", r.median("simulate_cubic_130s_dt0.01"), plain,
               "simulateLoop / reference loop, target 1.3");
    printRatio("simulate_cubic_130s_dt0.01_reused", r.median("simulate_cubic_130s_dt0.01_reused"),
               plain, "simulateLoopInto / reference loop, target 1.3");
}

/// One full automatic root locus of the 4th-order GT loop (lower base, wn 2, kp 30): K from 0
/// until every branch reached its zero or left the computed view.
void rootLocusGt4(Runner& r) {
    const auto design = xyt::designGuilleminTruxal(lowerBase().plant, 2.0, 30.0);
    r.time("root_locus_gt4", [&] {
        const auto locus = xyt::rootLocus(design.openLoop);
        sink = sink + locus.gains.back();
    });
}

// ---- The design-space study ---------------------------------------------------------------------

/// The design-space study of Braga et al.: 100 x 100 log grid around the lower-base design (wn
/// 0.2..20 rad/s, kp 3..3000), cubic 0 -> 600 mm in 130 s at dt 0.01, |u| <= 2.5 V, the paper's
/// specification, ITAE criterion, with refinement when a point is feasible.
const xyt::SweepAxis kSweepWn{0.2, 20.0, 100, true}, kSweepKp{3.0, 3000.0, 100, true};

xyt::DesignProblem sweepProblem() {
    const xyt::GtPreset lower = lowerBase();
    const xyt::CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
    xyt::DesignProblem problem;
    problem.plant = lower.plant;
    problem.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
    problem.dtSeconds = 0.01;
    problem.reference =
        xyt::sampled([&](double t) { return cubic.position(t); }, xyt::sampleTimes(130.0, 0.01));
    return problem;
}

/// The sweep on all threads (0) or on one.
void sweep100x100(Runner& r, int threads) {
    const xyt::DesignProblem problem = sweepProblem();
    xyt::SweepOptions options;
    options.threads = threads;
    r.time(
        threads == 0 ? "sweep_100x100" : "sweep_100x100_1thread",
        [&] {
            const auto result = xyt::sweepDesignSpace(problem, kSweepWn, kSweepKp, options);
            sink = sink + result.feasibleCount;
        },
        3, 0.0);
}

/// The reference: the plain loop's tracking figures for the same 10,000 designs (their
/// discretization done beforehand), on one core; the sweep's target is 1.5 times half of it
/// with two threads.
void sweep100x100ReferenceLoop(Runner& r) {
    const xyt::DesignProblem problem = sweepProblem();
    std::vector<xyt::bench::ReferenceLoop> loops;
    for (double w : kSweepWn.values("wn"))
        for (double k : kSweepKp.values("kp")) {
            const auto d = xyt::designGuilleminTruxal(problem.plant, w, k);
            loops.push_back(
                xyt::bench::referenceLoop(problem.plant.transferFunction(), d.controller, 0.01));
        }
    const double plainSweep = r.time(
        "sweep_100x100_reference_loop",
        [&] {
            for (const auto& m : loops) {
                const auto f = xyt::bench::referenceFigures(
                    m, problem.reference.data(), problem.reference.size(), 0.01,
                    problem.spec.umaxVolts, problem.modelUnitsPerPositionUnit);
                sink = sink + f.itae;
            }
        },
        3, 0.0);
    const double allThreads = r.median("sweep_100x100");
    printRatio("sweep_100x100", allThreads, 0.5 * plainSweep,
               "all threads / (reference loop over the designs / 2), target 1.5");
    printRatio("sweep_100x100_thread_speedup", r.median("sweep_100x100_1thread"), allThreads,
               "1 thread / all threads");
}

/// The live case: the workbench's preview of the default session (lower base, cubic 600 mm in
/// 130 s run to tf + 2 x 100 s, 1,500 samples, 100 per step-scan span), 50 x 50 designs over the
/// view's default ranges, no refinement, all threads stepped 8 designs at a time (target under
/// 100 ms on an idle machine), or another batch width, or on one thread: the CPU time it costs,
/// which a loaded machine hardly changes.
void designSpaceLive(Runner& r, const std::string& name, int batchWidth, int threads) {
    const xyt::DesignProblem live =
        xyt::sessionDesignProblem(xyt::Session{}, 0, xyt::kLivePreviewFidelity);
    xyt::SweepOptions o;
    o.refine = false;
    o.batchWidth = batchWidth;
    o.threads = threads;
    const xyt::SweepAxis wn50{0.2, 20.0, 50, true}, kp50{3.0, 3000.0, 50, true};
    r.time(
        name, [&] { sink = sink + xyt::sweepDesignSpace(live, wn50, kp50, o).feasibleCount; }, 10,
        1.0);
}

/// The sweep with the overshoot limit at 1 %, so that refinement runs too.
void sweep100x100Refined(Runner& r) {
    xyt::DesignProblem problem = sweepProblem();
    problem.spec.maxOvershootPct = 1.0;
    r.time(
        "sweep_100x100_overshoot1pct_refined",
        [&] {
            const auto result = xyt::sweepDesignSpace(problem, kSweepWn, kSweepKp, {});
            sink = sink + result.feasibleCount;
        },
        3, 0.0);
}

// ---- Pole placement -----------------------------------------------------------------------------

/// 1,000 perturbed plants of the circle of Patrick, Ishak and Adnan (30 mm at 0.1 rad/s, one
/// revolution, both axes, every A and B coefficient +-10 %), each run with and without the
/// nominal ZPETC, all threads, no corners. Target under 1 s.
void robustnessPpCircle(Runner& r) {
    xyt::Session s;
    s.trajectory.kind = xyt::TrajectoryKind::Circle;
    s.trajectory.radius = 30.0;
    s.trajectory.omegaRadPerSec = 0.1;
    s.trajectory.rampInSeconds = 0.0;
    for (std::size_t axis = 0; axis < 2; ++axis) {
        const auto preset = *xyt::findPolePlacementPreset(axis == 0 ? "x-axis" : "y-axis");
        s.axes[axis].method = xyt::DesignMethod::PolePlacementZpetc;
        s.axes[axis].pp.a = preset.a.ascending();
        s.axes[axis].pp.b = preset.b.ascending();
    }
    std::vector<xyt::RobustnessProblem> problems;
    for (int axis = 0; axis < 2; ++axis) {
        problems.push_back(xyt::sessionRobustnessProblem(s, axis));
        for (auto& p : problems.back().parameters)
            p.relative = 0.1;
    }
    xyt::RobustnessOptions o;
    o.samples = 1000;
    o.corners = false;
    r.time(
        "robustness_1000_plants_pp_circle_both_axes",
        [&] {
            for (const auto& p : problems)
                sink = sink + xyt::analyzeRobustness(p, o).rmse.p50;
        },
        3, 0.0);
}

/// Patrick, Ishak and Adnan: x-axis pole placement + ZPETC + one revolution of 30 sin(0.1 t) at
/// 70 ms (898 samples), all three structures.
void ppZpetcRevolution(Runner& r) {
    const xyt::PolePlacementPreset x = *xyt::findPolePlacementPreset("x-axis");
    xyt::Circle circle;
    circle.radius = 30.0;
    circle.omegaRadPerSec = 0.1;
    r.time("pp_zpetc_revolution", [&] {
        const auto loop = xyt::designPolePlacement(x.a, x.b, x.t, x.tsSeconds);
        const auto zpetc = xyt::designZpetc(loop);
        const auto run = xyt::runZpetcTracking(loop, zpetc, circle.xAxis(), circle.periodSeconds());
        sink = sink + run.rmseWithFf;
    });
}

// ---- G-code contour -----------------------------------------------------------------------------

/**
 * A 10 000-block G-code program: a zig-zag of 5000 vertical 1 mm lines joined by
 * 5000 tangent half circles of 0.5 mm radius (alternately clockwise over the top and
 * counter-clockwise under the bottom), at F3000, 3 decimals as a CAM post writes them.
 */
std::string zigZagProgram() {
    std::string text = "G17 G21 G90 G94\nG1 X0 Y0 F3000\n";
    char line[64];
    for (int i = 0; i < 5000; ++i) {
        const bool up = i % 2 == 0;
        std::snprintf(line, sizeof line, "G1 X%d Y%d\n", i, up ? 1 : 0);
        text += line;
        std::snprintf(line, sizeof line, "G%d X%d Y%d I0.5 J0\n", up ? 2 : 3, i + 1, up ? 1 : 0);
        text += line;
    }
    return text;
}

/// Read, profile, simulate both axes at 1 ms and the contour error of that program
/// (target under 200 ms), and each stage alone.
void gcodeContour(Runner& r) {
    const std::string text = zigZagProgram();
    const xyt::Session session = xyt::Session::paperDefault();
    xyt::ContourRunOptions options;
    options.profile.maxAccelMmPerS2 = 2000.0;
    options.profile.dtSeconds = 0.001;
    const xyt::GcodeProgram program = xyt::readGcode(text);
    const xyt::ContourRun once = xyt::runProgramContour(session, program, options);
    std::printf("gcode_contour_10000_blocks: %zu segments, %.0f mm, %.1f s, %zu samples per axis\n",
                program.path.size(), program.path.length(), once.trace.profile.totalTimeSeconds,
                once.trace.profile.t.size());
    r.time(
        "gcode_contour_10000_blocks",
        [&] {
            const auto run = xyt::runProgramContour(session, xyt::readGcode(text), options);
            sink = sink + run.contour.rms;
        },
        5, 0.0);
    // The same run with the cross-coupled controller (its comparison run with independent axes
    // left out): what the coupling costs over the uncoupled run above (target 1.5x).
    xyt::Session coupled = session;
    coupled.crossCoupling = {0.1, 1.0, xyt::ContourEstimateKind::Circular};
    xyt::ContourRunOptions coupledOptions = options;
    coupledOptions.compareIndependentAxes = false;
    r.time(
        "gcode_contour_10000_blocks_cross_coupled",
        [&] {
            const auto run = xyt::runProgramContour(coupled, xyt::readGcode(text), coupledOptions);
            sink = sink + run.contour.rms;
        },
        5, 0.0);
    r.time(
        "gcode_contour_10000_blocks_read",
        [&] { sink = sink + xyt::readGcode(text).path.length(); }, 5, 0.0);
    r.time(
        "gcode_contour_10000_blocks_profile",
        [&] { sink = sink + xyt::planFeedProfile(program, options.profile).totalTimeSeconds; }, 5,
        0.0);
    r.time(
        "gcode_contour_10000_blocks_contour_error",
        [&] {
            const auto& t = once.trace;
            sink = sink + xyt::contourError(program.path, t.profile.t, t.x, t.y).rms;
        },
        5, 0.0);
}

// ---- Identification -----------------------------------------------------------------------------
// The estimators on simulated data of the sizes an experiment gives. Inputs and noise from
// std::mt19937_64 with fixed seeds, one draw per statement.

/// @p n samples of +-1 from a fair coin.
std::vector<double> binarySignal(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution coin(0.5);
    std::vector<double> v(n);
    for (auto& x : v)
        x = coin(rng) ? 1.0 : -1.0;
    return v;
}

/// @p y plus white Gaussian noise of deviation @p sigma.
std::vector<double> withNoise(std::vector<double> y, double sigma, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, sigma);
    for (auto& x : y)
        x += g(rng);
    return y;
}

/// Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model, 100,000 samples, equation noise. Target < 10
/// ms.
void identifyArx(Runner& r) {
    const std::vector<double> a{1.0, -1.6580, 0.6583}, b{0.0, 0.0421, 0.0628, -0.0454};
    xyt::IoData d;
    d.tsSeconds = 0.07;
    d.u = binarySignal(100000, 1);
    d.y = xyt::filterDifferenceEquation(b, a, d.u);
    const std::vector<double> e = xyt::filterDifferenceEquation(
        {1.0}, a, withNoise(std::vector<double>(d.u.size()), 0.01, 2));
    for (std::size_t k = 0; k < d.y.size(); ++k)
        d.y[k] += e[k];
    r.time(
        "identify_arx231_100000",
        [&] {
            sink = sink + xyt::estimateArx(d, xyt::ArxOrders{2, 3, 1}).parameters[0];
        },
        10, 0.5);
}

/// Welch's H1 estimate with coherence and its band (spectral_estimate.h) of Patrick, Ishak and
/// Adnan's x-axis ARX model driven by a binary signal, 100,000 samples with output noise: the
/// default segment (4096, 47 half-overlapping segments, two signals). Target < 50 ms.
void welchFrequencyResponse(Runner& r) {
    const std::vector<double> a{1.0, -1.6580, 0.6583}, b{0.0, 0.0421, 0.0628, -0.0454};
    const std::vector<double> u = binarySignal(100000, 4);
    const std::vector<double> y = withNoise(xyt::filterDifferenceEquation(b, a, u), 0.01, 5);
    r.time(
        "welch_frequency_response_100000_samples",
        [&] { sink = sink + xyt::estimateFrequencyResponse(u, y, 0.07).magnitude[10]; }, 10, 0.5);
}

// Soderstrom & Stoica's plant (q^-1 + 0.5 q^-2) / (1 - 1.5 q^-1 + 0.7 q^-2), 10,000 samples; OE
// with white output noise, BJ with noise (1 - 0.3 q^-1) / (1 - 0.7 q^-1). Target < 300 ms each.
const std::vector<double> kSoderstromB{0.0, 1.0, 0.5}, kSoderstromF{1.0, -1.5, 0.7};

/// The plant's input, 10,000 samples at 10 ms.
xyt::IoData soderstromInput() {
    xyt::IoData d;
    d.tsSeconds = 0.01;
    d.u = binarySignal(10000, 3);
    return d;
}

void identifyOe(Runner& r) {
    xyt::IoData oe = soderstromInput();
    oe.y = withNoise(xyt::filterDifferenceEquation(kSoderstromB, kSoderstromF, oe.u), 0.3, 4);
    r.time(
        "identify_oe221_10000",
        [&] {
            sink = sink + xyt::estimateOe(oe, xyt::OeOrders{2, 2, 1}).loss;
        },
        5, 0.5);
}

void identifyBj(Runner& r) {
    xyt::IoData bj = soderstromInput();
    const std::vector<double> v = xyt::filterDifferenceEquation(
        {1.0, -0.3}, {1.0, -0.7}, withNoise(std::vector<double>(bj.u.size()), 0.3, 5));
    bj.y = xyt::filterDifferenceEquation(kSoderstromB, kSoderstromF, bj.u);
    for (std::size_t k = 0; k < bj.y.size(); ++k)
        bj.y[k] += v[k];
    r.time(
        "identify_bj21121_10000",
        [&] {
            sink = sink + xyt::estimateBj(bj, xyt::BjOrders{2, 1, 1, 2, 1}).loss;
        },
        5, 0.5);
}

/// Braga et al.'s lower base from a +-2.5 V square wave (0.5 s per level) at 10 ms, 10,000
/// samples, 0.1 mm measurement noise. Target < 500 ms.
void identifyGt3Fit(Runner& r) {
    const xyt::ThirdOrderPlant plant = lowerBase().plant;
    xyt::IoData d;
    d.tsSeconds = 0.01;
    for (std::size_t k = 0; k < 10000; ++k)
        d.u.push_back((k / 50) % 2 == 0 ? 2.5 : -2.5);
    d.y = withNoise(xyt::simulateThirdOrderPlant(plant, d.u, d.tsSeconds), 1e-4, 6);
    r.time(
        "identify_gt3_fit_10000", [&] { sink = sink + xyt::fitThirdOrderPlant(d).plant.k0; }, 5,
        0.5);
}

// ---- Input shaping ------------------------------------------------------------------------------

/// The machine's load (the first three fields of /proc/loadavg), "?" when unreadable: the
/// machine is shared, so a figure is read beside it.
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen))
        return "?";
    return one + " " + five + " " + fifteen;
}

/**
 * Klipper's shaper recommendation over all seven shapers, 10 to 200 Hz every 0.2 Hz (950
 * frequencies each, three test damping ratios), target under 200 ms. The spectrum has the size
 * Klipper's calc_freq_response gives for a 2 s log at 3200 Hz: Welch segments of the power of
 * two above 0.5 s of samples, M = 2048, so 1025 bins 1.5625 Hz apart up to 1600 Hz, of which
 * the 129 up to 200 Hz are used. Two resonance peaks (42 and 67 Hz) on a floor.
 */
void shaperRecommendation(Runner& r) {
    xyt::PowerSpectrum psd;
    for (int k = 0; k <= 1024; ++k) {
        const double f = 3200.0 * k / 2048.0;
        const double a = (f - 42.0) / 2.5, b = (f - 67.0) / 4.0;
        psd.frequencyHz.push_back(f);
        psd.power.push_back(1.0 / (1.0 + a * a) + 0.45 / (1.0 + b * b) + 0.01);
    }
    const char* name = "shaper_recommendation_7_shapers_10_200hz_0p2";
    r.time(
        name, [&] { sink = sink + xyt::recommendShaper(psd).best().shaper.frequencyHz; }, 10, 1.0);
    std::printf("%s: loadavg=%s\n", name, loadAverage().c_str());
}

// ---- A 128 MiB experiment file ------------------------------------------------------------------

/// Writes to @p path the largest CSV the reader takes (kMaxExperimentBytes) as a 1 kHz logger
/// writes it ("t,u,y", "12.345,2.5000,-123.4567"); false when it cannot.
bool writeLoggerCsv(const std::string& path, std::size_t& rows, std::size_t& bytes) {
    std::string text = "t,u,y\n";
    text.reserve(xyt::kMaxExperimentBytes);
    char line[96];
    for (rows = 0;; ++rows) {
        const int n =
            std::snprintf(line, sizeof line, "%.3f,%.4f,%.4f\n", 0.001 * double(rows),
                          (rows / 50) % 2 ? 2.5 : -2.5, 0.0001 * double(rows % 2000000) - 100.0);
        if (text.size() + std::size_t(n) > xyt::kMaxExperimentBytes)
            break;
        text.append(line, std::size_t(n));
    }
    bytes = text.size();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    const bool written = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (f)
        std::fclose(f);
    return written;
}

/// The peak RSS growth (bytes) of one read of @p path, measured in a forked child (ru_maxrss
/// after minus before), apart from what this program held before; -1 when it cannot be measured.
long long peakRssGrowthOfRead(const std::string& path) {
    long long growth = -1;
    int fds[2];
    if (::pipe(fds) != 0)
        return growth;
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        rusage before{}, after{};
        ::getrusage(RUSAGE_SELF, &before);
        sink = sink + double(xyt::readExperimentTable(path).columns[2].size());
        ::getrusage(RUSAGE_SELF, &after);
        const long long delta = (static_cast<long long>(after.ru_maxrss) - before.ru_maxrss) * 1024;
        [[maybe_unused]] const auto w = ::write(fds[1], &delta, sizeof delta);
        ::_exit(0);
    }
    ::close(fds[1]);
    if (pid > 0) {
        if (::read(fds[0], &growth, sizeof growth) != sizeof growth)
            growth = -1;
        int status = 0;
        ::waitpid(pid, &status, 0);
    }
    ::close(fds[0]);
    return growth;
}

/**
 * The 128 MiB CSV read by readExperimentTable (the CSV reader, all columns): target under 10 s,
 * and a peak memory of at most the file's size plus 8 bytes a cell plus about 200 MB. The file
 * goes to a temporary folder, removed afterwards.
 */
void readCsv128MiB(Runner& r) {
    const std::string name = "read_csv_128mib";
    char folder[] = "/tmp/xytune-bench-XXXXXX";
    if (!::mkdtemp(folder)) {
        std::printf("%s: cannot make a temporary folder\n", name.c_str());
        return;
    }
    const std::string path = std::string(folder) + "/run.csv";
    std::size_t rows = 0, bytes = 0;
    if (writeLoggerCsv(path, rows, bytes)) {
        const double us = r.time(
            name, [&] { sink = sink + double(xyt::readExperimentTable(path).columns[2].size()); },
            3, 0.0);
        const long long growth = peakRssGrowthOfRead(path);
        const double mb = 1024.0 * 1024.0;
        std::printf("%s: seconds=%.2f peak_rss_delta_mb=%.0f file_mb=%.0f rows=%zu target: under "
                    "10 s, at most "
                    "%.0f MB (file + 8 bytes x %zu cells + 200 MB)\n",
                    name.c_str(), us / 1e6, double(growth) / mb, double(bytes) / mb, rows,
                    (double(bytes) + 8.0 * 3.0 * double(rows)) / mb + 200.0, 3 * rows);
        std::fflush(stdout);
    } else {
        std::printf("%s: cannot write %s\n", name.c_str(), path.c_str());
    }
    std::remove(path.c_str());
    ::rmdir(folder);
}

// ---- The workbench ------------------------------------------------------------------------------

/// One step of a slider drag: the omega_n slider to its other position (a quarter of the range
/// either side of the middle, alternating, so every step changes the design), then the event
/// queue drained twice: the queued replots render the plots, and the paint events they post put
/// them on the (offscreen) window.
class SliderStep {
public:
    explicit SliderStep(QSlider* slider)
        : slider_(slider), positions_{slider->minimum() +
                                          (slider->maximum() - slider->minimum()) / 4,
                                      slider->minimum() +
                                          3 * (slider->maximum() - slider->minimum()) / 4} {}

    void operator()() {
        slider_->setValue(positions_[next_]);
        next_ = 1 - next_;
        QApplication::processEvents();
        QApplication::processEvents();
    }

private:
    QSlider* slider_;
    int positions_[2];
    int next_ = 0;
};

/// Axis x on the PID + feedforward method, its FF1 slider (percent of the model's inverse)
/// dragged as the omega_n slider is: the continuous run with the feedforward, the run without it
/// and the sampled-data PID each step, on the default tabs. The window is left as it was.
void sliderWithPidFeedforward(Runner& r, xyt::ui::TuningSession& session,
                              xyt::ui::MainWindow& window) {
    const xyt::Session before = session.session();
    session.setMethod(0, xyt::DesignMethod::PidFeedforward);
    QApplication::processEvents();
    auto* editor = window.findChild<xyt::ui::PidFeedforwardEditor*>();
    if (!editor)
        return;
    SliderStep step(editor->feedforwardSlider(1)->slider());
    r.time("gui_slider_to_repaint_pid_ff", [&step] { step(); });
    session.apply(before, "back to the default session");
    QApplication::processEvents();
}

/// The digital implementation overlaid (its run, figures and z-plane poles are computed with
/// every design) with a quantized, delayed implementation, and the pole-zero map of the digital
/// loop above (target under 16 ms); the window is left as it was.
void sliderWithDigitalOverlay(Runner& r, xyt::ui::TuningSession& session,
                              xyt::ui::MainWindow& window, SliderStep& step) {
    xyt::Session quantized = session.session();
    quantized.implementation.encoderResolutionMm = 0.001;
    quantized.implementation.dacBits = 16;
    quantized.implementation.delaySamples = 1;
    session.apply(quantized, "quantized implementation");
    window.digitalOverlayAction()->setChecked(true);
    window.zPlaneAction()->setChecked(true);
    window.upperTabs()->setCurrentWidget(window.poleZeroPlot());
    QApplication::processEvents();
    r.time("gui_slider_to_repaint_digital_overlay", [&step] { step(); });
    window.zPlaneAction()->setChecked(false);
    session.undoStack()->undo(); // the other figures keep the default session
    window.upperTabs()->setCurrentIndex(0);
    QApplication::processEvents();
}

/// The live design-space map visible below (root locus above) and recomputing: before each timed
/// slider step a plant change (untimed) starts a live preview on the worker threads; the step is
/// timed while it runs. Says how many steps overlapped a study.
void sliderWithLiveDesignSpace(Runner& r, xyt::ui::TuningSession& session,
                               xyt::ui::MainWindow& window, SliderStep& step) {
    window.upperTabs()->setCurrentIndex(0);
    xyt::ui::DesignSpaceView* map = nullptr;
    for (int i = 0; i < window.lowerTabs()->count() && !map; ++i)
        map = qobject_cast<xyt::ui::DesignSpaceView*>(window.lowerTabs()->widget(i));
    if (!map)
        return;
    window.lowerTabs()->setCurrentWidget(map);
    QApplication::processEvents();
    const xyt::ThirdOrderPlant nominal = session.session().axes[0].gt.plant;
    std::vector<double> us;
    int overlapped = 0;
    for (int run = 0; run < 40; ++run) {
        xyt::ThirdOrderPlant plant = nominal;
        plant.k0 *= run % 2 ? 1.02 : 0.98;
        session.setPlant(0, plant);
        QApplication::processEvents();
        overlapped += map->isRunning() ? 1 : 0;
        const auto t0 = std::chrono::steady_clock::now();
        step();
        us.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0)
                .count());
    }
    r.report("gui_slider_to_repaint_design_space_live", std::move(us),
             "(" + std::to_string(overlapped) + " of them while the map was recomputing)");
}

/// The workbench's reaction to a slider drag: one value change of the omega_n slider (the
/// session redesigns, re-simulates and updates every view through its signals; each visible
/// plot queues one replot), then the queued replots and paints. Offscreen at 1366 x 768,
/// default tabs (root locus above, time response below); then the digital overlay, the Bode tab
/// above (under 16 ms) and the live design-space map below.
void guiSliderToRepaint(Runner& r, int& argc, char* argv[]) {
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    xyt::ui::TuningSession session;
    xyt::ui::MainWindow window(&session);
    window.resize(1366, 768);
    window.show();
    QApplication::processEvents();
    SliderStep step(window.omegaNSlider()->slider());
    r.time("gui_slider_to_repaint", [&step] { step(); });
    sliderWithPidFeedforward(r, session, window);
    sliderWithDigitalOverlay(r, session, window, step);
    window.upperTabs()->setCurrentWidget(window.bodePlot());
    QApplication::processEvents();
    r.time("gui_slider_to_repaint_bode", [&step] { step(); });
    sliderWithLiveDesignSpace(r, session, window, step);
}

// ---- The table ----------------------------------------------------------------------------------

/// One row of the program: its name (the filter's haystack) and what it measures.
struct Benchmark {
    std::string name;
    std::function<void(Runner&)> run;
};

/// Every benchmark, in the order they run.
std::vector<Benchmark> benchmarks(int& argc, char* argv[]) {
    return {
        {"gt_design", gtDesign},
        {"sweep_point_loop_modes_and_foh", sweepPointLoopModesAndFoh},
        {"sweep_point_step_characteristics", sweepPointStepCharacteristics},
        {"sweep_point_stability_margins", sweepPointStabilityMargins},
        {"frequency_response_1000_and_margins", frequencyResponseAndMargins},
        {"simulate_cubic_130s_dt0.01", simulateCubic},
        {"simulate_cubic_130s_dt0.01_friction", simulateCubicFriction},
        {"digital_simulate_cubic_130s_ts0.01", [](Runner& r) { digitalSimulateCubic(r, false); }},
        {"digital_simulate_cubic_130s_ts0.01_quantized",
         [](Runner& r) { digitalSimulateCubic(r, true); }},
        {"session_evaluate_default", sessionEvaluateDefault},
        {"session_run_duration_default", sessionRunDurationDefault},
        {"simulate_cubic_130s_dt0.01_reused", simulateCubicReused},
        {"simulate_cubic_130s_dt0.01_reference_loop", simulateCubicReferenceLoop},
        {"root_locus_gt4", rootLocusGt4},
        {"sweep_100x100", [](Runner& r) { sweep100x100(r, 0); }},
        {"sweep_100x100_1thread", [](Runner& r) { sweep100x100(r, 1); }},
        {"sweep_100x100_reference_loop", sweep100x100ReferenceLoop},
        {"design_space_live_50x50",
         [](Runner& r) { designSpaceLive(r, "design_space_live_50x50", 8, 0); }},
        {"design_space_live_50x50_width1",
         [](Runner& r) { designSpaceLive(r, "design_space_live_50x50_width1", 1, 0); }},
        {"design_space_live_50x50_width4",
         [](Runner& r) { designSpaceLive(r, "design_space_live_50x50_width4", 4, 0); }},
        {"design_space_live_50x50_1thread",
         [](Runner& r) { designSpaceLive(r, "design_space_live_50x50_1thread", 8, 1); }},
        {"sweep_100x100_overshoot1pct_refined", sweep100x100Refined},
        {"robustness_1000_plants_pp_circle_both_axes", robustnessPpCircle},
        {"pp_zpetc_revolution", ppZpetcRevolution},
        {"gcode_contour_10000_blocks", gcodeContour}, // and its _read, _profile, _contour_error
        {"identify_arx231_100000", identifyArx},
        {"welch_frequency_response_100000_samples", welchFrequencyResponse},
        {"identify_oe221_10000", identifyOe},
        {"identify_bj21121_10000", identifyBj},
        {"identify_gt3_fit_10000", identifyGt3Fit},
        {"shaper_recommendation_7_shapers_10_200hz_0p2", shaperRecommendation},
        {"read_csv_128mib", readCsv128MiB},
        // Last: the QApplication lives only in here. Its figures: _digital_overlay, _bode,
        // _design_space_live.
        {"gui_slider_to_repaint", [&argc, argv](Runner& r) { guiSliderToRepaint(r, argc, argv); }},
    };
}

} // namespace

int main(int argc, char* argv[]) {
    xyt::app::keepFreedMemory(); // see allocator_tuning.h: the slider re-simulates megabytes
    const std::string filter = argc > 1 ? argv[1] : "";
    Runner runner;
    for (const Benchmark& b : benchmarks(argc, argv))
        if (b.name.find(filter) != std::string::npos) // the one place the filter applies
            b.run(runner);
    return 0;
}
