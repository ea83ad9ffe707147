// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-bench: the one benchmark program (not part of the test run). One line per figure:
//   name: median_us=... min_us=... max_us=... runs=...
// Optional argument: a substring; only figures whose name contains it are run. The core figures
// come first; gui_slider_to_repaint (last) times the widgets on the offscreen platform.
#include "app/allocator_tuning.h"
#include "core/study/design_sweep.h"
#include "core/session/design_study.h"
#include "core/session/robustness_problem.h"
#include "core/design/guillemin_truxal.h"
#include "core/analysis/root_locus.h"
#include "core/design/pole_placement.h"
#include "core/simulation/metrics.h"
#include "core/simulation/simulation.h"
#include "core/model/state_space.h"
#include "core/simulation/trajectory.h"
#include "core/design/zpetc.h"
#include "core/simulation/zpetc_tracking.h"
#include "core/analysis/frequency_response.h"
#include "core/analysis/loop_responses.h"
#include "core/analysis/stability_margins.h"
#include "core/contour/contour_metrics.h"
#include "core/contour/feed_profile.h"
#include "core/contour/gcode_reader.h"
#include "core/design/digital_controller.h"
#include "core/identification/arx.h"
#include "core/identification/experiment_file.h"
#include "core/identification/continuous_fit.h"
#include "core/identification/prediction_error.h"
#include "core/session/contour_run.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/sampled_data.h"
#include "app/bench_reference_loop.h"
#include "ui/design_space_view.h"
#include "ui/main_window.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/panels/parameter_slider.h"
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
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

/// Runs @p body until both minRuns and minSeconds are reached (after one warm-up run).
/// Returns the median in microseconds, or NaN when @p filter skips it.
double benchmark(const char* filter, const std::string& name, const std::function<void()>& body,
                 int minRuns = 20, double minSeconds = 0.5) {
    if (filter && name.find(filter) == std::string::npos)
        return std::nan("");
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
    std::sort(us.begin(), us.end());
    const std::size_t n = us.size();
    const double median = n % 2 ? us[n / 2] : 0.5 * (us[n / 2 - 1] + us[n / 2]);
    std::printf("%s: median_us=%.1f min_us=%.1f max_us=%.1f runs=%zu\n", name.c_str(), median,
                us.front(), us.back(), n);
    std::fflush(stdout);
    return median;
}

/// "name: ratio=R (what over what)" when both were measured in this run.
void printRatio(const char* name, double measured, double reference, const char* what) {
    if (std::isfinite(measured) && std::isfinite(reference) && reference > 0.0)
        std::printf("%s: ratio=%.2f (%s)\n", name, measured / reference, what);
}

volatile double sink = 0.0; // keeps results alive so the optimizer cannot drop the work

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

/**
 * A 128 MiB CSV as a 1 kHz logger writes it ("t,u,y", "12.345,2.5000,-123.4567"), read by
 * readExperimentTable (the CSV reader, all columns): target under 10 s, and a peak memory of at
 * most the file's size plus 8 bytes a cell plus about 200 MB. The read is timed here; its peak
 * RSS growth is measured in a forked child (ru_maxrss after minus before), apart from what this
 * program held before. The file goes to a temporary folder, removed afterwards.
 */
void readCsv128MiB(const char* filter) {
    const std::string name = "read_csv_128mib";
    if (filter && name.find(filter) == std::string::npos)
        return;
    char folder[] = "/tmp/xytune-bench-XXXXXX";
    if (!::mkdtemp(folder)) {
        std::printf("%s: cannot make a temporary folder\n", name.c_str());
        return;
    }
    const std::string path = std::string(folder) + "/run.csv";
    std::size_t rows = 0, bytes = 0;
    {
        std::string text = "t,u,y\n";
        text.reserve(xyt::kMaxExperimentBytes);
        char line[96];
        for (;; ++rows) {
            const int n = std::snprintf(line, sizeof line, "%.3f,%.4f,%.4f\n", 0.001 * double(rows),
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
        if (!written) {
            std::printf("%s: cannot write %s\n", name.c_str(), path.c_str());
            std::remove(path.c_str());
            ::rmdir(folder);
            return;
        }
    }
    const double us = benchmark(filter, name, [&] {
        sink = sink + double(xyt::readExperimentTable(path).columns[2].size());
    }, 3, 0.0);
    long long growth = -1;
    int fds[2];
    if (::pipe(fds) == 0) {
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
    }
    const double mb = 1024.0 * 1024.0;
    std::printf("%s: seconds=%.2f peak_rss_delta_mb=%.0f file_mb=%.0f rows=%zu target: under 10 s, at most "
                "%.0f MB (file + 8 bytes x %zu cells + 200 MB)\n",
                name.c_str(), us / 1e6, double(growth) / mb, double(bytes) / mb, rows,
                (double(bytes) + 8.0 * 3.0 * double(rows)) / mb + 200.0, 3 * rows);
    std::fflush(stdout);
    std::remove(path.c_str());
    ::rmdir(folder);
}

/// Read, profile, simulate both axes at 1 ms and the contour error of that program
/// (target under 200 ms), and each stage alone.
void gcodeContour(const char* filter) {
    if (filter && std::string("gcode_contour_10000_blocks").find(filter) == std::string::npos)
        return;
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
    benchmark(filter, "gcode_contour_10000_blocks", [&] {
        const auto run = xyt::runProgramContour(session, xyt::readGcode(text), options);
        sink = sink + run.contour.rms;
    }, 5, 0.0);
    benchmark(filter, "gcode_contour_10000_blocks_read", [&] {
        sink = sink + xyt::readGcode(text).path.length();
    }, 5, 0.0);
    benchmark(filter, "gcode_contour_10000_blocks_profile", [&] {
        sink = sink + xyt::planFeedProfile(program, options.profile).totalTimeSeconds;
    }, 5, 0.0);
    benchmark(filter, "gcode_contour_10000_blocks_contour_error", [&] {
        const auto& t = once.trace;
        sink = sink + xyt::contourError(program.path, t.profile.t, t.x, t.y).rms;
    }, 5, 0.0);
}

/// The workbench's reaction to a slider drag: one value change of the omega_n slider (the
/// session redesigns, re-simulates and updates every view through its signals; each visible
/// plot queues one replot), then the event queue drained twice: the queued replots render the
/// plots, and the paint events they post put them on the (offscreen) window. Offscreen at
/// 1366 x 768, default tabs (root locus above, time response below).
void guiSliderToRepaint(const char* filter, int& argc, char* argv[]) {
    if (filter && std::string("gui_slider_to_repaint").find(filter) == std::string::npos)
        return;
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    xyt::ui::TuningSession session;
    xyt::ui::MainWindow window(&session);
    window.resize(1366, 768);
    window.show();
    QApplication::processEvents();
    QSlider* slider = window.omegaNSlider()->slider();
    // Two positions a quarter of the range either side of the middle, alternating, so every
    // run changes the design.
    const int span = slider->maximum() - slider->minimum();
    const int positions[2] = {slider->minimum() + span / 4, slider->minimum() + 3 * span / 4};
    int next = 0;
    // One timed step: the slider to its other position, then the queued replots and paints.
    const auto sliderStep = [&] {
        slider->setValue(positions[next]);
        next = 1 - next;
        QApplication::processEvents();
        QApplication::processEvents();
    };
    benchmark(filter, "gui_slider_to_repaint", sliderStep);
    // The digital implementation overlaid (its run, figures and z-plane poles are
    // computed with every design) with a quantized, delayed implementation, and the pole-zero
    // map of the digital loop above (target under 16 ms).
    {
        xyt::Session quantized = session.session();
        quantized.implementation.encoderResolutionMm = 0.001;
        quantized.implementation.dacBits = 16;
        quantized.implementation.delaySamples = 1;
        session.apply(quantized, "quantized implementation");
        window.digitalOverlayAction()->setChecked(true);
        window.zPlaneAction()->setChecked(true);
        window.upperTabs()->setCurrentWidget(window.poleZeroPlot());
        QApplication::processEvents();
        benchmark(filter, "gui_slider_to_repaint_digital_overlay", sliderStep);
        window.zPlaneAction()->setChecked(false);
        session.undoStack()->undo(); // the other figures keep the default session
        window.upperTabs()->setCurrentIndex(0);
        QApplication::processEvents();
    }
    // The same with the Bode tab above (under 16 ms).
    window.upperTabs()->setCurrentWidget(window.bodePlot());
    QApplication::processEvents();
    benchmark(filter, "gui_slider_to_repaint_bode", sliderStep);
    // The live design-space map visible below (root locus above) and recomputing:
    // before each timed slider step a plant change (untimed) starts a live preview on the
    // worker threads; the step is timed while it runs. Prints how many steps overlapped a study.
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
        slider->setValue(positions[next]);
        next = 1 - next;
        QApplication::processEvents();
        QApplication::processEvents();
        us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(us.begin(), us.end());
    std::printf("gui_slider_to_repaint_design_space_live: median_us=%.1f min_us=%.1f max_us=%.1f runs=%zu "
                "(%d of them while the map was recomputing)\n",
                0.5 * (us[19] + us[20]), us.front(), us.back(), us.size(), overlapped);
    std::fflush(stdout);
}

/// The estimators on simulated data of the sizes an experiment gives. Inputs and
/// noise from std::mt19937_64 with fixed seeds, one draw per statement.
void identification(const char* filter) {
    const auto binary = [](std::size_t n, std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::bernoulli_distribution coin(0.5);
        std::vector<double> v(n);
        for (auto& x : v)
            x = coin(rng) ? 1.0 : -1.0;
        return v;
    };
    const auto noisy = [](std::vector<double> y, double sigma, std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> g(0.0, sigma);
        for (auto& x : y)
            x += g(rng);
        return y;
    };
    {
        // Patrick, Ishak and Adnan's x-axis ARX(2,3,1) model, 100,000 samples, equation noise. Target < 10 ms.
        const std::vector<double> a{1.0, -1.6580, 0.6583}, b{0.0, 0.0421, 0.0628, -0.0454};
        xyt::IoData d;
        d.tsSeconds = 0.07;
        d.u = binary(100000, 1);
        d.y = xyt::filterDifferenceEquation(b, a, d.u);
        const std::vector<double> e = xyt::filterDifferenceEquation({1.0}, a, noisy(std::vector<double>(d.u.size()), 0.01, 2));
        for (std::size_t k = 0; k < d.y.size(); ++k)
            d.y[k] += e[k];
        benchmark(filter, "identify_arx231_100000", [&] {
            sink = sink + xyt::estimateArx(d, xyt::ArxOrders{2, 3, 1}).parameters[0];
        }, 10, 0.5);
    }
    {
        // Soderstrom & Stoica's plant (q^-1 + 0.5 q^-2) / (1 - 1.5 q^-1 + 0.7 q^-2), 10,000
        // samples; OE with white output noise, BJ with noise (1 - 0.3 q^-1) / (1 - 0.7 q^-1).
        // Target < 300 ms each.
        const std::vector<double> b{0.0, 1.0, 0.5}, f{1.0, -1.5, 0.7};
        xyt::IoData oe;
        oe.tsSeconds = 0.01;
        oe.u = binary(10000, 3);
        oe.y = noisy(xyt::filterDifferenceEquation(b, f, oe.u), 0.3, 4);
        xyt::IoData bj = oe;
        const std::vector<double> v = xyt::filterDifferenceEquation(
            {1.0, -0.3}, {1.0, -0.7}, noisy(std::vector<double>(oe.u.size()), 0.3, 5));
        bj.y = xyt::filterDifferenceEquation(b, f, oe.u);
        for (std::size_t k = 0; k < bj.y.size(); ++k)
            bj.y[k] += v[k];
        benchmark(filter, "identify_oe221_10000", [&] {
            sink = sink + xyt::estimateOe(oe, xyt::OeOrders{2, 2, 1}).loss;
        }, 5, 0.5);
        benchmark(filter, "identify_bj21121_10000", [&] {
            sink = sink + xyt::estimateBj(bj, xyt::BjOrders{2, 1, 1, 2, 1}).loss;
        }, 5, 0.5);
    }
    {
        // Braga et al.'s lower base from a +-2.5 V square wave (0.5 s per level) at 10 ms, 10,000
        // samples, 0.1 mm measurement noise. Target < 500 ms.
        const xyt::ThirdOrderPlant plant = xyt::findGtPreset("lower-base")->plant;
        xyt::IoData d;
        d.tsSeconds = 0.01;
        for (std::size_t k = 0; k < 10000; ++k)
            d.u.push_back((k / 50) % 2 == 0 ? 2.5 : -2.5);
        d.y = noisy(xyt::simulateThirdOrderPlant(plant, d.u, d.tsSeconds), 1e-4, 6);
        benchmark(filter, "identify_gt3_fit_10000", [&] {
            sink = sink + xyt::fitThirdOrderPlant(d).plant.k0;
        }, 5, 0.5);
    }
}

} // namespace

int main(int argc, char* argv[]) {
    xyt::app::keepFreedMemory(); // see allocator_tuning.h: the slider re-simulates megabytes
    const char* filter = argc > 1 ? argv[1] : nullptr;
    const xyt::GtPreset lower = *xyt::findGtPreset("lower-base");

    benchmark(filter, "gt_design", [&] {
        const auto d = xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp);
        sink = sink + d.ki;
    });

    {
        // What one design point of the sweep costs besides its tracking run.
        const auto d = xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp);
        const auto plant = lower.plant.transferFunction();
        benchmark(filter, "sweep_point_loop_modes_and_foh", [&] {
            const auto modes = xyt::loopModes(plant, d.controller);
            const auto foh = xyt::discretizeFoh(modes.aLinear, modes.bLinear, 0.01);
            sink = sink + foh.phi(0, 0);
        });
        benchmark(filter, "sweep_point_step_characteristics", [&] {
            sink = sink + xyt::stepCharacteristics(d.closedLoop).settlingTimeSeconds;
        });
        benchmark(filter, "sweep_point_stability_margins", [&] {
            sink = sink + xyt::stabilityMargins(xyt::gtLoopTransferFunctions(d).openLoop).phaseMarginDeg;
        });
    }

    {
        // The 4th-order GT loop at 1,000 frequencies plus all its margins (target
        // under 0.2 ms).
        const xyt::TransferFunction loop = xyt::gtLoopTransferFunctions(
            xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp)).openLoop;
        const std::vector<double> omegas = xyt::logFrequencyGrid(1e-3, 1e3, 1000);
        benchmark(filter, "frequency_response_1000_and_margins", [&] {
            const xyt::FrequencyResponse r = xyt::frequencyResponse(loop, omegas);
            const xyt::StabilityMargins m = xyt::stabilityMargins(loop);
            sink = sink + r.magnitudeDb[500] + m.phaseMarginDeg;
        });
    }

    {
        const xyt::CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
        const auto times = xyt::sampleTimes(130.0, 0.01);
        const auto reference = xyt::sampled([&](double t) { return cubic.position(t); }, times);
        const auto design = xyt::designGuilleminTruxal(lower.plant, lower.omegaNRadPerSec, lower.kp);
        xyt::LoopSimulationOptions options;
        options.umaxVolts = 2.5;
        options.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
        const auto plant = lower.plant.transferFunction();
        const double fresh = benchmark(filter, "simulate_cubic_130s_dt0.01", [&] {
            const auto run = xyt::simulateLoop(plant, design.controller, reference, options);
            sink = sink + run.y.back();
        });
        // The sampled-data loop of the digital PI on the same cubic at 10 ms (target
        // under 1 ms), ideal and with a 1 um encoder, a 16-bit DAC and one sample of delay.
        {
            const auto pi = xyt::digitalPi(design.kp, design.ki, 0.01, xyt::PiDiscretization::Tustin,
                                           xyt::AntiWindup::Clamp);
            xyt::SampledDataOptions ideal;
            ideal.umaxVolts = 2.5;
            benchmark(filter, "digital_simulate_cubic_130s_ts0.01", [&] {
                const auto run = xyt::simulateSampledPi(plant, pi, reference, ideal, lower.modelUnitsPerPositionUnit);
                sink = sink + run.result.y.back();
            });
            xyt::SampledDataOptions quantized = ideal;
            quantized.encoderResolution = 0.001;
            quantized.dacBits = 16;
            quantized.delaySamples = 1;
            benchmark(filter, "digital_simulate_cubic_130s_ts0.01_quantized", [&] {
                const auto run =
                    xyt::simulateSampledPi(plant, pi, reference, quantized, lower.modelUnitsPerPositionUnit);
                sink = sink + run.result.y.back();
            });
        }
        // The part of a slider step that is the core's: the whole evaluation of the default
        // session (both axes, the automatic duration, the digital implementation), and the
        // choice of the duration alone (both axes simulated to tf).
        {
            const xyt::Session session = xyt::Session::paperDefault();
            benchmark(filter, "session_evaluate_default", [&] {
                sink = sink + xyt::evaluateSession(session).axes[0].metrics.rmse;
            });
            benchmark(filter, "session_run_duration_default", [&] {
                sink = sink + xyt::chooseRunDuration(session).seconds;
            });
        }
        // The same run into a kept result (no allocation), against the plain scalar
        // reference loop of the same recurrence over preallocated arrays, timed here too.
        xyt::SimulationResult kept;
        const double reused = benchmark(filter, "simulate_cubic_130s_dt0.01_reused", [&] {
            xyt::simulateLoopInto(plant, design.controller, reference, options, kept);
            sink = sink + kept.y.back();
        });
        const std::size_t n = reference.size();
        std::vector<double> t(n), y(n), e(n), u(n);
        std::unique_ptr<bool[]> clipped(new bool[n]);
        const double plain = benchmark(filter, "simulate_cubic_130s_dt0.01_reference_loop", [&] {
            // The discretization is part of the work, as in simulateLoop.
            const auto m = xyt::bench::referenceLoop(plant, design.controller, options.dtSeconds);
            xyt::bench::referenceRun(m, reference.data(), n, options.dtSeconds, options.umaxVolts,
                                     options.modelUnitsPerPositionUnit, t.data(), y.data(), e.data(), u.data(),
                                     clipped.get());
            sink = sink + y.back();
        });
        printRatio("simulate_cubic_130s_dt0.01", fresh, plain, "simulateLoop / reference loop, target 1.3");
        printRatio("simulate_cubic_130s_dt0.01_reused", reused, plain,
                   "simulateLoopInto / reference loop, target 1.3");
    }

    {
        // One full automatic root locus of the 4th-order GT loop (lower base, wn 2, kp 30):
        // K from 0 until every branch reached its zero or left the computed view.
        const auto design = xyt::designGuilleminTruxal(lower.plant, 2.0, 30.0);
        benchmark(filter, "root_locus_gt4", [&] {
            const auto locus = xyt::rootLocus(design.openLoop);
            sink = sink + locus.gains.back();
        });
        // The design-space study of Braga et al.: 100 x 100 log grid around the lower-base design
        // (wn 0.2..20 rad/s, kp 3..3000), cubic 0 -> 600 mm in 130 s at dt 0.01, |u| <= 2.5 V,
        // the paper's specification, ITAE criterion, with refinement when a point is feasible.
        const xyt::CubicTrajectory cubic(0.0, 600.0, 0.0, 130.0);
        xyt::DesignProblem problem;
        problem.plant = lower.plant;
        problem.modelUnitsPerPositionUnit = lower.modelUnitsPerPositionUnit;
        problem.dtSeconds = 0.01;
        problem.reference = xyt::sampled([&](double t) { return cubic.position(t); },
                                         xyt::sampleTimes(130.0, 0.01));
        const xyt::SweepAxis wn{0.2, 20.0, 100, true}, kp{3.0, 3000.0, 100, true};
        double sweepUs[2] = {std::nan(""), std::nan("")};
        for (const int threads : {0, 1}) {
            xyt::SweepOptions options;
            options.threads = threads;
            sweepUs[threads] = benchmark(filter, threads == 0 ? "sweep_100x100" : "sweep_100x100_1thread", [&] {
                const auto r = xyt::sweepDesignSpace(problem, wn, kp, options);
                sink = sink + r.feasibleCount;
            }, 3, 0.0);
        }
        // The reference: the plain loop's tracking figures for the same 10,000 designs (their
        // discretization done beforehand), on one core; the sweep's target is 1.5 times half of
        // it with two threads.
        std::vector<xyt::bench::ReferenceLoop> loops;
        if (!filter || std::string("sweep_100x100_reference_loop").find(filter) != std::string::npos)
            for (double w : wn.values("wn"))
                for (double k : kp.values("kp")) {
                    const auto d = xyt::designGuilleminTruxal(problem.plant, w, k);
                    loops.push_back(xyt::bench::referenceLoop(problem.plant.transferFunction(), d.controller, 0.01));
                }
        const double plainSweep = benchmark(filter, "sweep_100x100_reference_loop", [&] {
            for (const auto& m : loops) {
                const auto f = xyt::bench::referenceFigures(m, problem.reference.data(), problem.reference.size(),
                                                            0.01, problem.spec.umaxVolts,
                                                            problem.modelUnitsPerPositionUnit);
                sink = sink + f.itae;
            }
        }, 3, 0.0);
        printRatio("sweep_100x100", sweepUs[0], 0.5 * plainSweep,
                   "all threads / (reference loop over the designs / 2), target 1.5");
        printRatio("sweep_100x100_thread_speedup", sweepUs[1], sweepUs[0], "1 thread / all threads");
        // The live case: the workbench's preview of the default session (lower base,
        // cubic 600 mm in 130 s run to tf + 2 x 100 s, 1,500 samples, 100 per step-scan span),
        // 50 x 50 designs over the view's default ranges, all threads, no refinement. Target
        // under 100 ms on an idle machine.
        {
            const xyt::DesignProblem live = xyt::sessionDesignProblem(xyt::Session{}, 0, xyt::kLivePreviewFidelity);
            xyt::SweepOptions o;
            o.refine = false;
            const xyt::SweepAxis wn50{0.2, 20.0, 50, true}, kp50{3.0, 3000.0, 50, true};
            benchmark(filter, "design_space_live_50x50", [&] {
                sink = sink + xyt::sweepDesignSpace(live, wn50, kp50, o).feasibleCount;
            }, 10, 1.0);
            for (const int width : {1, 4}) {
                o.batchWidth = width;
                benchmark(filter, "design_space_live_50x50_width" + std::to_string(width), [&] {
                    sink = sink + xyt::sweepDesignSpace(live, wn50, kp50, o).feasibleCount;
                }, 10, 1.0);
            }
            // On one thread: the CPU time it costs, which a loaded machine hardly changes.
            o.batchWidth = 8;
            o.threads = 1;
            benchmark(filter, "design_space_live_50x50_1thread", [&] {
                sink = sink + xyt::sweepDesignSpace(live, wn50, kp50, o).feasibleCount;
            }, 10, 1.0);
        }
        // The same with the overshoot limit at 1 %, so that refinement runs too.
        problem.spec.maxOvershootPct = 1.0;
        benchmark(filter, "sweep_100x100_overshoot1pct_refined", [&] {
            const auto r = xyt::sweepDesignSpace(problem, wn, kp, {});
            sink = sink + r.feasibleCount;
        }, 3, 0.0);
        // 1,000 perturbed plants of the circle of Patrick, Ishak and Adnan (30 mm at 0.1 rad/s, one
        // revolution, both axes, every A and B coefficient +-10 %), each run with and without
        // the nominal ZPETC, all threads, no corners. Target under 1 s.
        {
            xyt::Session s;
            s.trajectory.kind = xyt::TrajectoryKind::Circle;
            s.trajectory.radius = 30.0;
            s.trajectory.omegaRadPerSec = 0.1;
            s.trajectory.rampInSeconds = 0.0;
            for (int axis = 0; axis < 2; ++axis) {
                const auto preset = *xyt::findPolePlacementPreset(axis == 0 ? "x-axis" : "y-axis");
                s.axes[static_cast<std::size_t>(axis)].method = xyt::DesignMethod::PolePlacementZpetc;
                s.axes[static_cast<std::size_t>(axis)].pp.a = preset.a.ascending();
                s.axes[static_cast<std::size_t>(axis)].pp.b = preset.b.ascending();
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
            benchmark(filter, "robustness_1000_plants_pp_circle_both_axes", [&] {
                for (const auto& p : problems)
                    sink = sink + xyt::analyzeRobustness(p, o).rmse.p50;
            }, 3, 0.0);
        }
        // Patrick, Ishak and Adnan: x-axis pole placement + ZPETC + one revolution of 30 sin(0.1 t) at 70 ms
        // (898 samples), all three structures.
        const xyt::PolePlacementPreset x = *xyt::findPolePlacementPreset("x-axis");
        xyt::Circle circle;
        circle.radius = 30.0;
        circle.omegaRadPerSec = 0.1;
        benchmark(filter, "pp_zpetc_revolution", [&] {
            const auto loop = xyt::designPolePlacement(x.a, x.b, x.t, x.tsSeconds);
            const auto zpetc = xyt::designZpetc(loop);
            const auto run =
                xyt::runZpetcTracking(loop, zpetc, circle.xAxis(), circle.periodSeconds());
            sink = sink + run.rmseWithFf;
        });
    }
    gcodeContour(filter);
    identification(filter);
    readCsv128MiB(filter);
    guiSliderToRepaint(filter, argc, argv);
    return 0;
}
