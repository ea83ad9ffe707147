// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli's commands, their help and their exit codes (cli_main.cpp is the program around
// them).
#include "app/cli_command_line.h"

#include "app/cli_args.h"
#include "app/cli_commands.h"

#include "core/io/file_io.h"
#include "core/io/text_escape.h"
#include "core/model/errors.h"

#include <cstdio>
#include <functional>
#include <map>
#include <new>
#include <string>

namespace {

/// One command's entry of the help: its name and its lines (indented as in the general help).
struct CommandHelp {
    const char* name;
    const char* text;
};

constexpr CommandHelp kGtHelp[] = {
    {"gt", "  gt        Guillemin-Truxal PI design: [--preset lower-base|upper-base]\n"
           "            [--k0 K --a1 A --a2 A] --wn W --kp K\n"},
    {"simulate",
     "  simulate  the design on a trajectory: design options plus\n"
     "            --trajectory cubic|quintic --xf X --tf T [--x0 --t0 --v0 --vf]  or\n"
     "            --trajectory sine --amplitude A --omega W [--phase-deg P --ramp-in S]\n"
     "            [--duration S] [--dt 0.01] [--umax 2.5] [--in-position-window 0.01] [--csv "
     "FILE]\n"
     "            JSON: tracking {rmse, max_abs_error, ...}, step_response (unit step of the\n"
     "            closed loop), move_and_settle (cubic: settle_time after tf, final_error,\n"
     "            final_overshoot_mm; null for sine), duration_choice. Without --duration a\n"
     "            cubic runs past tf until it settles into the window (at most tf + 3 moves).\n"
     "            --digital [--controller-ts 0.01 --discretization tustin|backward-euler\n"
     "            --delay-samples N --encoder-resolution MM --dac-bits B\n"
     "            --anti-windup none|clamp|back-calculation --tracking-time S]: also the loop the\n"
     "            firmware runs (sampled-data PI, ZOH, quantization, anti-windup): JSON digital\n"
     "            {tracking, move_and_settle, poles (z-plane), min_damping, limit_cycle, "
     "warnings}.\n"
     "            --method pid-ff: LinuxCNC's pid with command feedforward (position in mm) on\n"
     "            the plant options, cubic or quintic only: [--p --i --d --ff0 --ff1 --ff2 --ff3\n"
     "            --bias --deadband --max-error-i --max-output (0: --umax) --derivative-filter]\n"
     "            (none negative), [--derivative-on-measurement] [--trajectory-derivatives (the\n"
     "            command's derivatives from the trajectory, else backward differences)]. Gains\n"
     "            not given: P, I the preset's PI (Braga et al.; the lower base's without\n"
     "            --preset), FF1..FF3 the plant's exact inverse (a2 u/k0, a1 u/k0, u/k0), else\n"
     "            0. --ff-from-model (any design): FF0 = 0 and FF1..FF3 the plant's inverse; a\n"
     "            Guillemin-Truxal design runs as its PI in mm units (P = kp u, I = ki u) on\n"
     "            pid-ff. Both run as the workbench runs a session axis; --digital takes\n"
     "            --controller-ts --delay-samples --encoder-resolution --dac-bits. JSON: method\n"
     "            \"pid-ff\", converted_from (\"guillemin-truxal\" or null), gains,\n"
     "            model_feedforward {ff1, ff2, ff3}, tracking, tracking_without_feedforward_rmse,\n"
     "            step_response, move_and_settle, margins, warnings, duration_choice, digital\n"
     "            {controller_ts, tracking, move_and_settle, poles, min_damping, limit_cycle}.\n"},
    {"report", "  report [SESSION.json]  text report of a session, or of the default design\n"
               "            (both bases of Braga et al.) when no file is given\n"},
    {"new", "  new -o FILE             write the default session (Braga et al.: x = lower base,\n"
            "            y = upper base, controller sample time 0.01 s); prints the path\n"},
    {"export",
     "  export SESSION.json --format json|c|m|csv|linuxcnc -o FILE [--discretization\n"
     "            tustin|backward-euler] [--precision double|float] [--ff-from-model]\n"
     "            controller coefficients (JSON, C header with the complete controller per axis\n"
     "            in double or float, Octave/MATLAB script), simulated signals (CSV) or\n"
     "            LinuxCNC's pid gains per joint (a HAL file of setp lines, position in mm, with\n"
     "            the INI's FERROR and MIN_FERROR as comments; a pole-placement axis is refused;\n"
     "            --ff-from-model: FF1..FF3 the plant's exact inverse); prints the path\n"},
    {"rlocus",
     "  rlocus    root locus of 1 + K N/D = 0: --num \"...\" --den \"...\" (descending powers of\n"
     "            s; with --ts T ascending powers of z^-1)  or  --gt-preset lower-base|upper-base\n"
     "            [--wn W --kp K] (K multiplies G_c G: K = 1 is the design)\n"
     "            [--kmax K] [--max-step 0.01 (fraction of the view)] [--max-points 5000]\n"},
    {"robustness",
     "  robustness SESSION.json [--samples 200] [--seed 1] [--range k0=10% ...] [--axis x|y|both]\n"
     "            [--no-corners] [--threads N] [--csv FILE]  plant-model mismatch: --samples "
     "random\n"
     "            plants (uniform within each --range, from --seed) and the 2^p corners of the\n"
     "            box, each run with the session's unchanged controller (ZPETC from the nominal\n"
     "            model). --range NAME=P% or NAME=FRACTION, repeatable, x.NAME / y.NAME for one\n"
     "            axis; names: k0, a1, a2 (Guillemin-Truxal), a1.., b1.. (ARX A, B). Instead of\n"
     "            ranges, --from-identification draws the plants from the covariance of the axis'\n"
     "            identified model (identify --session; the corners at 3 sigma). JSON per axis:\n"
     "            parameters, nominal, statistics {rmse, max_abs_error, max_abs_u, phase_margin,\n"
     "            gain_margin, rmse_without_ff} {count, min, p05, p50, p95, max, mean},\n"
     "            fraction_meeting_spec, unstable (listed, not in the statistics), worst (largest\n"
     "            RMSE). CSV: one row per plant. --sensitivity: for pole placement + ZPETC axes,\n"
     "            zpetc_sensitivity, the RMSE with and without feedforward at 0, 25, 50, 75 and\n"
     "            100 % of the ranges (same seed): where the feedforward stops paying off.\n"
     "            --contour (circle or G-code sessions): also \"xy\", pairs of plants drawn over\n"
     "            both axes' ranges (and the joint box's corners) tracing the contour together:\n"
     "            max and RMS contour error {count, min, p05, ...}, the worst pair; CSV rows "
     "\"xy\".\n"},
    {"identify",
     "  identify  --data FILE (CSV/TSV, .lvm, .mat) --input-col NAME --output-col NAME\n"
     "            [--time-col NAME | --ts S] (else the file's sample time, .lvm) [--segment N]\n"
     "            [--output-unit mm|m|counts [--mm-per-count X]] --structure arx|oe|bj|gt3\n"
     "            [--na 2 --nb 3 --nc 1 --nd 1 --nf 2 --nk 1] (0..100, nb 1..100: na 0 is FIR,\n"
     "            nk 0 a direct feedthrough) [--validate FILE2] [--range T0:T1]\n"
     "            [--detrend | --remove-means] [--decimate N] [--horizon 5] [--max-lag 25]\n"
     "            [--max-iterations 100] [--order-table NA0:NA1,NB0:NB1,NK0:NK1 (ARX loss, FPE,\n"
     "            AIC and validation loss of each order: order_table)]: the axis model from a\n"
     "            logged experiment. JSON: data,\n"
     "            model {structure, status, parameters {name: {value, std}}, polynomials a b c d "
     "f\n"
     "            (ascending z^-1), plant {k0, a1, a2, initial_position} for gt3 (y in mm; where "
     "the\n"
     "            table stood)}, fit {estimation,\n"
     "            validation: {simulation, prediction} %}, fpe, aic, residual_tests, poles, "
     "zeros,\n"
     "            stable, non_minimum_phase, warnings. Exit 3 when no estimate exists (status).\n"
     "            --session IN.json --axis x|y -o OUT.json: the session with the model as that\n"
     "            axis' plant (gt3: the Guillemin-Truxal plant; arx/oe/bj: the pole-placement "
     "model)\n"
     "            and where it came from (model_origin).\n"
     "            --structure frf [--segment-length M (default: the largest power of two <= 4096\n"
     "            giving 8 half-overlapping segments)] [--band F0:F1] [--mode-frequency HZ]: the\n"
     "            Welch H1 estimate (Hann, 50 % overlap, segment means removed). JSON: structure,\n"
     "            data, frequency, magnitude, phase_deg (unwrapped), coherence, relative_error\n"
     "            (Bendat and Piersol's sqrt(1 - g2) / (|g| sqrt(2 n_d))), magnitude_low/high\n"
     "            (|H| (1 -+ 2 relative_error)), band_sigmas, averages, equivalent_averages\n"
     "            (n_d), segment, window, overlap, resonance {frequency, peak, damping\n"
     "            (half-power; null when a crossing is outside the band), low/high_half_power,\n"
     "            note}, mode (the estimate at --mode-frequency; refused above the Nyquist\n"
     "            frequency).\n"},
    {"sweep",
     "  sweep     design-space study: the plant options, the trajectory options of simulate and\n"
     "            --wn MIN:MAX:N --kp MIN:MAX:N [--log] (N 1..500, --log: both axes log-spaced)\n"
     "            [--points] [--criterion "
     "itae|max_error|rmse|max_u|settle|phase_margin|gain_margin]\n"
     "            (the margins are maximized, the others minimized) [--threads N] [--csv FILE]\n"
     "            [--max-settling 100] [--max-overshoot 0] [--max-error 2]\n"
     "            [--max-settle-time 100] [--in-position-window 0.01]\n"
     "            [--min-phase-margin 0 (deg)] [--min-gain-margin 0 (dB)] (spec; --umax too).\n"
     "            A cubic without --duration runs tf + 2 x --max-settle-time.\n"
     "            JSON: best {wn, kp, ki, metrics, move_and_settle, phase_margin, gain_margin,\n"
     "            checks, index [i_wn, i_kp]}\n"
     "            and refined {...} (null when nothing is feasible), feasible_count, grid\n"
     "            {wn, kp}, with --points every point points[i_wn][i_kp] (rows over wn,\n"
     "            columns over kp; a 100 x 100 grid writes 13 MB), warnings and\n"
     "            diagnosis (criteria failing everywhere, least-violating design, relaxed\n"
     "            specification, best design on a grid edge). CSV: one row per point in\n"
     "            the same order (wn outer, kp inner); undefined metrics are empty fields.\n"},
};

constexpr CommandHelp kPpHelp[] = {
    {"pp", "  pp        RST design A F + B G = T, Kf = T(1)/B(1): [--preset x-axis|y-axis]\n"
           "            [--a A --b B] --t T [--ts 0.07]; A(0) != 1 is normalized (warning),\n"
           "            B(0) must be 0 (delay), T(0) must be 1. Keys F, G, Kf, residual,\n"
           "            closed_loop {num = Kf B, den = T}, plant_poles, plant_zeros, warnings\n"},
    {"zpetc",
     "  zpetc     pp options plus [--amplitude 30 --omega 0.1 --phase-deg 0 --duration S]\n"
     "            [--start reference|origin] [--margin 0.05] [--frequency-points N]:\n"
     "            reference amplitude sin(omega t + phase), one period by default. Zeros with\n"
     "            |z| < 1 - margin are cancelled (B+); the rest (B-) are listed in nmp_zeros.\n"
     "            feedforward {num, den}: u_ff(k) = num(z^-1)/den(z^-1) r(k + preview_steps),\n"
     "            u_ff is the loop's reference input; gain_factor = [B-(1)]^2;\n"
     "            metrics {rmse_without_ff, rmse_with_ff, improvement_pct}\n"},
    {"contour",
     "  contour   both axes on the circle: [--preset paper-zpetc] [--radius 30 --omega 0.1]\n"
     "            [--duration S --start reference|origin --margin 0.05]; per-axis metrics and\n"
     "            contour_error {without_ff, with_ff} {max, rms} (radial, mm); with [--ccc-kp\n"
     "            KP --ccc-ki KI (V/mm, V/(mm s); 0: off) --ccc-estimate circular|linear] also\n"
     "            cross_coupling {kp, ki, estimate, line_loop, contour_error, independent_axes}:\n"
     "            the same two axes (ZPETC at its default margin) on the circle from rest at\n"
     "            r(0), Koren's cross-coupled controller over both against independent axes\n"
     "  contour --gcode FILE [--feed-scale 1] [--max-accel 100 (mm/s^2)] [--max-jerk 0 (mm/s^3,\n"
     "            0: trapezoidal)] [--dt 0.001] [--rapid-feed 3000 (mm/min)] [--corner-angle 1\n"
     "            (deg)] [--corner-window 1 (mm)] [--method "
     "guillemin-truxal|pole-placement-zpetc]\n"
     "            [--csv FILE]  a G-code program (G0-G3, G17, G20/G21, G90/G91, F, N; Z, M, S, T\n"
     "            ignored with a warning) run by the default session's axes, both starting at\n"
     "            rest at the origin: Braga et al.'s Guillemin-Truxal PI (the default; x the "
     "lower\n"
     "            base, wn 2, kp 30; y the upper base, wn 1, kp 30; +-2.5 V: slow loops, built\n"
     "            for the paper's 130 s move) or Patrick, Ishak and Adnan's pole placement +\n"
     "            ZPETC (x-axis and y-axis models, Ts 70 ms, linear, |u| > 2.5 V flagged). The "
     "feed\n"
     "            profile stops at joins turning more than --corner-angle and keeps speed through\n"
     "            tangent ones, v^2/R <= --max-accel on arcs. JSON: profile, x_axis, y_axis "
     "(tracking),\n"
     "            contour_error {max, rms, max_at, corners} (signed, + left of travel, mm; G0\n"
     "            rapids left out), iso230_4 (a single full circle: the circle alone from rest,\n"
     "            both ways: G, F_max, F_min, H, G_bidirectional, reversal_spikes; else null),\n"
     "            warnings. --ccc-kp KP --ccc-ki KI (V/mm, V/(mm s); 0: off) [--ccc-estimate\n"
     "            circular|linear]: Koren's cross-coupled controller over both axes (off on G0\n"
     "            rapids); JSON cross_coupling {kp, ki, estimate, line_loop {spectral_radius,\n"
     "            poles, disk_margin, ... of the least stable line direction}, independent_axes\n"
     "            {contour_error, circular_deviation_g}, digital {period, contour_error}: the\n"
     "            axes' digital controllers (the C export's) coupled}; a line where the\n"
     "            coupled loop is unstable is refused naming the program line.\n"
     "            --ccc-sweep [--ccc-sweep-kp 0,0.03,0.1,0.3,1,3 --ccc-sweep-ki 0,0.1,0.3,1,3]\n"
     "            (comma-separated gains, at most 400 pairs): the program run once more for\n"
     "            every (kp, ki) with the --ccc-estimate, in parallel; JSON\n"
     "            cross_coupling_sweep {grid, independent_axes (the (0, 0) run), cells [{kp, ki,\n"
     "            status ok|unstable|failed, contour_error {max, rms}, spectral_radius,\n"
     "            disk_margin, saturated, message}], best (the smallest max contour error of\n"
     "            the cells whose axes stay inside the limit with the coupled loop stable at\n"
     "            every direction; failing those, inside the limit; failing those, any), rule}.\n"
     "            CSV: t,s,v,x_ref,y_ref,x,y,contour_error. A program error names the file,\n"
     "            line and column (--gcode part.nc: line 12: unknown word G5 at column 4)\n"},
};

constexpr CommandHelp kFrequencyHelp[] = {
    {"margins",
     "  margins   exact stability margins: gain_margin {factor, db, omega}, phase_margin {deg,\n"
     "            omega}, delay_margin, peak_sensitivity (Ms), peak_complementary_sensitivity\n"
     "            (Mt), bandwidth, every crossing, nyquist {encirclements, open/closed-loop\n"
     "            unstable poles}; an infinite margin is \"inf\"\n"},
    {"bode",
     "  bode      frequency, magnitude_db, phase_deg (unwrapped) on an adaptive grid holding the\n"
     "            crossovers, plus margins; pole placement adds tracking {without_ff, with_zpetc}\n"
     "            [--wmin W --wmax W --points-per-decade 10] [--csv FILE]\n"},
};

constexpr CommandHelp kIdentificationHelp[] = {
    {"psd",
     "  psd       --data FILE (Klipper's raw accelerometer CSV: #time,accel_x,accel_y,accel_z)\n"
     "            [--max-frequency 200] [--band F0:F1 (default 5 Hz to the maximum)]: the power\n"
     "            spectral densities as Klipper's shaper_calibrate.py computes them (fs = N / T,\n"
     "            0.5 s segments rounded up to a power of two, Kaiser window beta 6, 50 %\n"
     "            overlap). JSON: frequency, psd_x, psd_y, psd_z, psd_sum ((mm/s^2)^2/Hz),\n"
     "            sample_time, sampling_frequency, samples, segment, averages, window,\n"
     "            kaiser_beta, overlap, peak {frequency, peak, damping (half-power of psd_sum),\n"
     "            low/high_half_power, note}\n"},
    {"excite",
     "  excite    --signal square|prbs|chirp --ts S --duration S --amplitude V [--offset 0]\n"
     "            [--umax 2.5] -o FILE.csv|FILE.lvm, and per signal: square --period S;\n"
     "            prbs --clock N (samples per bit) --register N (2..31, maximal length:\n"
     "            period (2^N - 1) x clock samples); chirp --f0 HZ --f1 HZ (linear sweep over\n"
     "            the duration). |offset| + amplitude must not exceed --umax. Writes t,u (CSV)\n"
     "            or a LabVIEW Measurement file with Delta_X = ts, atomically; JSON: path,\n"
     "            samples, ts, duration, signal, description, max_abs_u, umax\n"},
};

constexpr CommandHelp kPidHelp[] = {
    {"tune",
     "  tune      PID gains in LinuxCNC's units (position in mm) for the plant options\n"
     "            [--model-unit-scale U] [--structure pid|pi (default pid, with Ti = 4 Td)]:\n"
     "            --crossover W (rad/s) --phase-margin DEG: the closed-form gains with\n"
     "            |L(jW)| = 1 and that margin, L = (P + I/s + D s) G / u. JSON: structure,\n"
     "            target {crossover, phase_margin}, status (\"ok\", or \"unreachable\" with exit\n"
     "            0 and gains null: reason says why), reason, gains {p, i, d, ti, td}, achieved\n"
     "            {crossover, phase_margin} (computed back from the gains), closed_loop_stable,\n"
     "            warnings.  Or --relay D (volts; exclusive with --crossover): the relay\n"
     "            experiment's exact limit cycle (Astrom and Hagglund): relay {amplitude,\n"
     "            period, ultimate_gain, limit_cycle_amplitude (mm)}, describing_function\n"
     "            {period, amplitude, ultimate_gain}, ziegler_nichols and tyreus_luyben\n"
     "            {p, i, d, ti, td} from the limit cycle's Ku and Tu\n"},
};

constexpr CommandHelp kShaperHelp[] = {
    {"shaper",
     "  shaper    one input shaper: --type zv|mzv|zvd|zvdd|ei|2hump_ei|3hump_ei --frequency HZ\n"
     "            [--damping 0.1 (the mode's damping ratio, Klipper's default)] [--points 251]\n"
     "            [--scv 5 (mm/s)]. JSON: type, frequency, damping, amplitudes, times (s),\n"
     "            duration (the last impulse: how much longer a shaped move lasts), delay (the\n"
     "            centroid sum A_i t_i: a shaped ramp's lag), scv, smoothing (mm, Klipper's\n"
     "            estimate at 5000 mm/s^2), max_accel (mm/s^2, Klipper's for 0.12 mm of\n"
     "            smoothing), sensitivity {damping, frequency (0 .. 2.5 HZ, --points values),\n"
     "            vibration (residual vibration as a fraction of the unshaped one)}\n"
     "  shaper --recommend (--data LOG.csv [--axis x|y|z|sum] | --mode-frequency HZ\n"
     "            [--mode-damping 0.05]) [--max-smoothing MM] [--klipper-shapers] [--damping 0.1]\n"
     "            [--scv 5]: Klipper's choice (find_best_shaper) over the spectrum of a Klipper\n"
     "            accelerometer log (normalized as Klipper does) or of a modelled mode. JSON:\n"
     "            source, recommended and shapers [{type, frequency, remaining_vibration,\n"
     "            smoothing, score, max_accel}], damping, scv\n"},
};

constexpr const char* kFrequencyLoops =
    "Frequency domain of a loop: --gt-preset lower-base|upper-base [--wn W --kp K], or\n"
    "--pp-preset x-axis|y-axis / --a A --b B --t T [--ts 0.07] (pole placement: L = BG/(AF)),\n"
    "or --num N --den D [--ts T] (L itself):\n";

constexpr const char* kExitCodes =
    "Exit codes: 0 success, 2 invalid input or a file that could not be read or written (one\n"
    "line naming the argument, with the path and the reason; an old file is unchanged), 1 an\n"
    "internal error.\n";

/// The general help: every command.
std::string generalUsage() {
    std::string u =
        "usage: xytune-cli COMMAND [OPTIONS]   (xytune-cli COMMAND --help: that command only)\n"
        "\n"
        "Commands (JSON on stdout unless said otherwise: report prints text, new and export\n"
        "the path written; polynomials of s in descending powers):\n";
    for (const CommandHelp& c : kGtHelp)
        u += c.text;
    u += "\nDiscrete pole placement and ZPETC of Patrick, Ishak and Adnan (polynomials of z^-1 in\n"
         "ascending powers, as space- or comma-separated lists, e.g. --a \"1 -1.6580 0.6583\"):\n";
    for (const CommandHelp& c : kPpHelp)
        u += c.text;
    u += "\nLinuxCNC's PID with command feedforward (simulate --method pid-ff, export --format\n"
         "linuxcnc):\n";
    for (const CommandHelp& c : kPidHelp)
        u += c.text;
    u += std::string("\n") + kFrequencyLoops;
    for (const CommandHelp& c : kFrequencyHelp)
        u += c.text;
    u += "\nInput shaping (Singer and Seering; Klipper's shaper set and estimates):\n";
    for (const CommandHelp& c : kShaperHelp)
        u += c.text;
    u += "\nSystem identification experiments:\n";
    for (const CommandHelp& c : kIdentificationHelp)
        u += c.text;
    return u + "\n" + kExitCodes;
}

/// The help of one command (its usage line, its entry, the exit codes), or "" if unknown.
std::string commandUsage(const std::string& name) {
    auto find = [&](const CommandHelp* begin, const CommandHelp* end) -> const CommandHelp* {
        for (const CommandHelp* c = begin; c != end; ++c)
            if (name == c->name)
                return c;
        return nullptr;
    };
    const CommandHelp* c = find(std::begin(kGtHelp), std::end(kGtHelp));
    if (!c)
        c = find(std::begin(kPpHelp), std::end(kPpHelp));
    if (!c)
        c = find(std::begin(kPidHelp), std::end(kPidHelp));
    if (!c)
        c = find(std::begin(kIdentificationHelp), std::end(kIdentificationHelp));
    if (!c)
        c = find(std::begin(kShaperHelp), std::end(kShaperHelp));
    std::string loops;
    if (!c && (c = find(std::begin(kFrequencyHelp), std::end(kFrequencyHelp))))
        loops = std::string(kFrequencyLoops) + "\n";
    if (!c)
        return {};
    return "usage: xytune-cli " + name + " [OPTIONS]\n\n" + loops + c->text + "\n" + kExitCodes;
}

/// The message as one printable line: arguments quoted in messages may hold newlines or other
/// control characters (a pasted list, a file name, a session label), and the contract is one
/// line on stderr that cannot drive the terminal.
std::string oneLine(const std::string& message) {
    return xyt::terminalText(message);
}

} // namespace

int xyt::cli::runCommandLine(QStringList args) {
    if (args.isEmpty() || args.first() == "--help" || args.first() == "-h" ||
        args.first() == "help") {
        std::fputs(generalUsage().c_str(), args.isEmpty() ? stderr : stdout);
        return args.isEmpty() ? 2 : 0;
    }
    const std::map<QString, std::function<int(const QStringList&)>> commands = {
        {"gt", xyt::cli::runGt},
        {"simulate", xyt::cli::runSimulate},
        {"report", xyt::cli::runReport},
        {"new", xyt::cli::runNew},
        {"export", xyt::cli::runExport},
        {"rlocus", xyt::cli::runRlocus},
        {"sweep", xyt::cli::runSweep},
        {"pp", xyt::cli::runPp},
        {"zpetc", xyt::cli::runZpetc},
        {"contour", xyt::cli::runContour},
        {"bode", xyt::cli::runBode},
        {"margins", xyt::cli::runMargins},
        {"robustness", xyt::cli::runRobustness},
        {"identify", xyt::cli::runIdentify},
        {"excite", xyt::cli::runExcite},
        {"psd", xyt::cli::runPsd},
        {"tune", xyt::cli::runTune},
        {"shaper", xyt::cli::runShaper},
    };
    const QString name = args.takeFirst();
    const auto it = commands.find(name);
    if (it == commands.end()) {
        std::fprintf(stderr, "xytune-cli: unknown command '%s' (see xytune-cli --help)\n",
                     oneLine(name.toStdString()).c_str());
        return 2;
    }
    if (args.contains("--help") || args.contains("-h")) {
        std::fputs(commandUsage(name.toStdString()).c_str(), stdout);
        return 0;
    }
    try {
        return it->second(args);
    } catch (const xyt::FileError& e) {
        // Every writer names its option (cannotWrite); this is the backstop for one that does
        // not. Every write is atomic (core/io/file_io.h): the old file is as it was.
        std::fprintf(
            stderr,
            "xytune-cli %s: cannot write %s; nothing was written, an existing file is unchanged\n",
            qPrintable(name), oneLine(e.what()).c_str());
        return 2;
    } catch (const xyt::InvalidInput& e) {
        std::fprintf(stderr, "xytune-cli %s: %s\n", qPrintable(name), oneLine(e.what()).c_str());
        return 2;
    } catch (const std::bad_alloc&) {
        // The readers say which file needs the memory; this catches what is left (a fit, a run).
        std::fprintf(stderr, "xytune-cli %s: the command needs more memory than is available\n",
                     qPrintable(name));
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "xytune-cli %s: internal error: %s\n", qPrintable(name),
                     oneLine(e.what()).c_str());
        return 1;
    }
}
