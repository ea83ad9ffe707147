// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli: the headless face of XY Tune. JSON on stdout; bad input -> one line on stderr
// naming the argument, exit code 2.
#include "app/cli_commands.h"

#include "core/model/errors.h"
#include "core/io/file_io.h"
#include "core/io/text_escape.h"

#include <QCoreApplication>

#include <cstdio>
#include <functional>
#include <map>
#include <string>

namespace {

constexpr const char* kUsage =
    "usage: xytune-cli COMMAND [OPTIONS]\n"
    "\n"
    "Commands (JSON on stdout; polynomials of s in descending powers):\n"
    "  gt        Guillemin-Truxal PI design: [--preset lower-base|upper-base]\n"
    "            [--k0 K --a1 A --a2 A] --wn W --kp K\n"
    "  simulate  the design on a trajectory: design options plus\n"
    "            --trajectory cubic --xf X --tf T [--x0 --t0 --v0 --vf]  or\n"
    "            --trajectory sine --amplitude A --omega W [--phase-deg P --ramp-in S]\n"
    "            [--duration S] [--dt 0.01] [--umax 2.5] [--csv FILE]\n"
    "  report [SESSION.json]  text report of a session, or of the default design\n"
    "            (both bases of paper 000) when no file is given\n"
    "  new -o FILE             write the default session (paper 000: x = lower base,\n"
    "            y = upper base, controller sample time 0.01 s)\n"
    "  export SESSION.json --format json|c|m|csv -o FILE [--discretization\n"
    "            tustin|backward-euler]  controller coefficients (JSON, C header,\n"
    "            Octave/MATLAB script) or simulated signals (CSV)\n"
    "  rlocus    root locus of 1 + K N/D = 0: --num \"...\" --den \"...\" (descending powers of\n"
    "            s; with --ts T ascending powers of z^-1)  or  --gt-preset lower-base|upper-base\n"
    "            [--wn W --kp K] (K multiplies G_c G: K = 1 is the design)\n"
    "            [--kmax K] [--max-step 0.01 (fraction of the view)] [--max-points 5000]\n"
    "  sweep     design-space study: the plant options, the trajectory options of simulate and\n"
    "            --wn MIN:MAX:N --kp MIN:MAX:N [--log] (N 1..500, --log: both axes log-spaced)\n"
    "            [--criterion itae|max_error|rmse|max_u] [--threads N] [--csv FILE]\n"
    "            [--max-settling 100] [--max-overshoot 0] [--max-error 2] (spec; --umax too).\n"
    "            JSON: best {wn, kp, ki, metrics, checks, index [i_wn, i_kp]} and refined\n"
    "            {...} (null when nothing is feasible), feasible_count, grid {wn, kp},\n"
    "            points[i_wn][i_kp] (rows over wn, columns over kp). CSV: one row per point in\n"
    "            the same order (wn outer, kp inner); undefined metrics are empty fields.\n"
    "\n"
    "Discrete pole placement and ZPETC of paper 001 (polynomials of z^-1 in ascending powers,\n"
    "as space- or comma-separated lists, e.g. --a \"1 -1.6580 0.6583\"):\n"
    "  pp        RST design A F + B G = T, Kf = T(1)/B(1): [--preset x-axis|y-axis]\n"
    "            [--a A --b B] --t T [--ts 0.07]; A(0) != 1 is normalized (warning),\n"
    "            B(0) must be 0 (delay), T(0) must be 1. Keys F, G, Kf, residual,\n"
    "            closed_loop {num = Kf B, den = T}, plant_poles, plant_zeros, warnings\n"
    "  zpetc     pp options plus [--amplitude 30 --omega 0.1 --phase-deg 0 --duration S]\n"
    "            [--start reference|origin] [--margin 0.05] [--frequency-points N]:\n"
    "            reference amplitude sin(omega t + phase), one period by default. Zeros with\n"
    "            |z| < 1 - margin are cancelled (B+); the rest (B-) are listed in nmp_zeros.\n"
    "            feedforward {num, den}: u_ff(k) = num(z^-1)/den(z^-1) r(k + preview_steps),\n"
    "            u_ff is the loop's reference input; gain_factor = [B-(1)]^2;\n"
    "            metrics {rmse_without_ff, rmse_with_ff, improvement_pct}\n"
    "  contour   both axes on the circle: [--preset paper-zpetc] [--radius 30 --omega 0.1]\n"
    "            [--duration S --start reference|origin --margin 0.05]; per-axis metrics and\n"
    "            contour_error {without_ff, with_ff} {max, rms} (radial, mm)\n"
    "\n"
    "Frequency domain of a loop: --gt-preset lower-base|upper-base [--wn W --kp K], or\n"
    "--pp-preset x-axis|y-axis / --a A --b B --t T [--ts 0.07] (pole placement: L = BG/(AF)),\n"
    "or --num N --den D [--ts T] (L itself):\n"
    "  margins   exact stability margins: gain_margin {factor, db, omega}, phase_margin {deg,\n"
    "            omega}, delay_margin, peak_sensitivity (Ms), peak_complementary_sensitivity\n"
    "            (Mt), bandwidth, every crossing, nyquist {encirclements, open/closed-loop\n"
    "            unstable poles}; an infinite margin is \"inf\"\n"
    "  bode      frequency, magnitude_db, phase_deg (unwrapped) on an adaptive grid holding the\n"
    "            crossovers, plus margins; pole placement adds tracking {without_ff, with_zpetc}\n"
    "            [--wmin W --wmax W --points-per-decade 10] [--csv FILE]\n"
    "\n"
    "Exit codes: 0 success, 2 invalid input (message names the argument), 1 a file that\n"
    "could not be written (path and system reason; the old file is unchanged) or an internal\n"
    "error.\n";

/// The message as one printable line: arguments quoted in messages may hold newlines or other
/// control characters (a pasted list, a file name, a session label), and the contract is one
/// line on stderr that cannot drive the terminal.
std::string oneLine(const std::string& message) { return xyt::terminalText(message); }

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QStringList args = QCoreApplication::arguments().mid(1);
    if (args.isEmpty() || args.first() == "--help" || args.first() == "-h" ||
        args.first() == "help") {
        std::fputs(kUsage, args.isEmpty() ? stderr : stdout);
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
    };
    const QString name = args.takeFirst();
    const auto it = commands.find(name);
    if (it == commands.end()) {
        std::fprintf(stderr, "xytune-cli: unknown command '%s' (see xytune-cli --help)\n",
                     oneLine(name.toStdString()).c_str());
        return 2;
    }
    if (args.contains("--help")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    try {
        return it->second(args);
    } catch (const xyt::FileError& e) {
        // Every write is atomic (core/io/file_io.h): a failed one leaves any old file as it was.
        std::fprintf(stderr, "xytune-cli %s: cannot write %s; nothing was written, an existing file is unchanged\n",
                     qPrintable(name), oneLine(e.what()).c_str());
        return 1;
    } catch (const xyt::InvalidInput& e) {
        std::fprintf(stderr, "xytune-cli %s: %s\n", qPrintable(name), oneLine(e.what()).c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "xytune-cli %s: internal error: %s\n", qPrintable(name),
                     oneLine(e.what()).c_str());
        return 1;
    }
}
