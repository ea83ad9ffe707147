// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace xyt {

/// The input shapers machine firmware ships (Klipper's set, and Marlin's and RepRapFirmware's).
enum class ShaperType { Zv, Zvd, Zvdd, Mzv, Ei, TwoHumpEi, ThreeHumpEi };

/// The name a session, the CLI and Klipper use ("zv", "mzv", "2hump_ei"); and back (false:
/// unknown).
const char* shaperName(ShaperType type);
bool shaperFromName(const std::string& name, ShaperType& type);

/**
 * An input shaper: the reference convolved with impulses of @c amplitudes (summing to 1) at
 * @c times (s, the first 0). Applied to a command it cancels (ZV, ZVD, ZVDD at the design
 * frequency exactly) or bounds (MZV, the EI family over a band) the residual vibration of a
 * mode of frequency f and damping ratio zeta, at the price of delaying and smoothing the
 * command by up to duration().
 */
struct InputShaper {
    ShaperType type = ShaperType::Zv;
    double frequencyHz = 0.0;
    double dampingRatio = 0.0;
    std::vector<double> amplitudes, times;
    double duration() const { return times.empty() ? 0.0 : times.back(); }
};

/// The vibration tolerance the EI family is designed for: 5 % (Klipper's
/// SHAPER_VIBRATION_REDUCTION of 20).
inline constexpr double kShaperVibrationTolerance = 0.05;

/**
 * The shaper @p type for a mode of @p frequencyHz and @p dampingRatio. With the damped period
 * td = 1 / (f sqrt(1 - zeta^2)) and K = exp(-zeta pi / sqrt(1 - zeta^2)), before normalizing
 * the amplitudes to sum 1:
 *  - ZV, ZVD, ZVDD (Singer and Seering 1990): amplitudes the binomial coefficients of
 *    (1 + K q)^n, n = 1, 2, 3, at times 0, td/2, ..., n td/2;
 *  - MZV (Klipper's): K' = exp(-0.75 zeta pi / sqrt(1 - zeta^2)), amplitudes
 *    a1 = 1 - 1/sqrt(2), (sqrt(2) - 1) K', a1 K'^2 at 0, 0.375 td, 0.75 td;
 *  - EI, 2-hump EI, 3-hump EI (Singhose, Seering and Singer's extra-insensitive shapers for the
 *    tolerance V = kShaperVibrationTolerance, in the closed forms of Klipper's shaper_defs.py
 *    as of 2020-2021; later Klipper fits the EI family's amplitudes and times as polynomials
 *    in the damping ratio, which this does not follow): EI
 *    0.25 (1 + V), 0.5 (1 - V) K, 0.25 (1 + V) K^2 at 0, td/2, td; 2-hump with
 *    X = (V^2 (sqrt(1 - V^2) + 1))^(1/3), a1 = (3 X^2 + 2 X + 3 V^2) / (16 X),
 *    a2 = (0.5 - a1) K, a3 = a2 K, a4 = a1 K^3 at 0 .. 1.5 td; 3-hump with
 *    a1 = (1 + 3 V + 2 sqrt(2 (V + 1) V)) / 16, a2 = 0.25 (1 - V) K,
 *    a3 = (0.5 (1 + V) - 2 a1) K^2, a4 = a2 K^2, a5 = a1 K^4 at 0 .. 2 td.
 * @throws InvalidInput "frequency" unless finite and > 0, "damping" unless in [0, 1).
 */
InputShaper designInputShaper(ShaperType type, double frequencyHz, double dampingRatio);

/**
 * The residual vibration of a mode of @p frequencyHz and @p dampingRatio after the shaper, as a
 * fraction of the unshaped command's (Singer and Seering): with w = 2 pi f, wd = w sqrt(1 -
 * zeta^2) and the impulses (A_i, t_i), V = exp(-zeta w t_n) |sum A_i exp(zeta w t_i) e^{j wd t_i}|
 * (0: cancelled, 1: as unshaped; at f = 0 the sum of the amplitudes, 1).
 * @throws InvalidInput "frequency" unless finite and >= 0, "damping" unless in [0, 1).
 */
double residualVibration(const InputShaper& shaper, double frequencyHz, double dampingRatio);

} // namespace xyt
