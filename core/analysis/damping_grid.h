// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <complex>
#include <vector>

namespace xyt {

/// Damping ratio and natural frequency of one pole.
struct DampingAndFrequency {
    double zeta = 0.0;            ///< -Re(s)/|s|, in [-1, 1]; 1 for a pole at s = 0
    double omegaNRadPerSec = 0.0; ///< |s| in rad/s; +infinity for z = 0 (s = -infinity)
};

/**
 * zeta and omega_n of a pole: for a continuous pole s directly, omega_n = |s|,
 * zeta = -Re(s)/|s|; for a discrete pole z (tsSeconds > 0) through the equivalent s-plane pole
 *   s = ln(z) / Ts   (principal logarithm, so |Im s| <= pi/Ts, the Nyquist frequency),
 * the inverse of z = exp(s Ts). A pole at s = 0 has zeta = 1, omega_n = 0 (a pure integrator);
 * z = 0 maps to s = -infinity: zeta = 1, omega_n = +infinity.
 * @throws InvalidInput "tsSeconds" when negative or not finite, "root" when not finite.
 */
DampingAndFrequency dampingOf(std::complex<double> root, double tsSeconds = 0.0);

/// One line of a damping grid, as a polyline in the s- or z-plane.
struct GridLine {
    double value = 0.0; ///< the zeta or the omega_n (rad/s) the line stands for
    std::vector<std::complex<double>> points;
};

/// Constant-zeta and constant-omega_n lines for a pole-zero map or a root locus.
struct DampingGrid {
    double tsSeconds = 0.0;
    std::vector<GridLine> dampingLines;   ///< one per zeta, both half planes in one polyline
    std::vector<GridLine> frequencyLines; ///< one per omega_n
};

/**
 * The s-plane grid: for each zeta a ray pair s = r(-zeta +- j sqrt(1 - zeta^2)),
 * 0 <= r <= radius, drawn as one polyline from the upper end through the origin to the lower
 * end; for each omega_n the left half circle s = omega_n e^{j theta}, pi/2 <= theta <= 3pi/2.
 * @param zetas each in [0, 1]; @param omegasRadPerSec each > 0; @param radius > 0 (rad/s);
 * @param pointsPerLine >= 2.
 * @throws InvalidInput naming the offending argument.
 */
DampingGrid sPlaneDampingGrid(const std::vector<double>& zetas,
                              const std::vector<double>& omegasRadPerSec, double radius,
                              int pointsPerLine = 61);

/**
 * The z-plane grid inside the unit circle, the image of the s-plane grid under z = exp(s Ts):
 * for each zeta the spiral z = exp(Ts omega (-zeta +- j sqrt(1 - zeta^2))) for omega from 0
 * until the damped frequency omega sqrt(1 - zeta^2) reaches the Nyquist frequency pi/Ts (for
 * zeta = 1 the real segment from z = 1 to z = exp(-pi)); for each omega_n the curve
 * z = exp(Ts omega_n e^{j theta}), pi/2 <= theta <= 3pi/2 (omega_n <= pi/Ts keeps |Im s| within
 * the Nyquist band, so the curve stays inside the unit circle and ends on the real axis).
 * @param zetas each in [0, 1]; @param omegasRadPerSec each in (0, pi/Ts];
 * @param tsSeconds > 0; @param pointsPerLine >= 2 (points per half of a line).
 * @throws InvalidInput naming the offending argument.
 */
DampingGrid zPlaneDampingGrid(const std::vector<double>& zetas,
                              const std::vector<double>& omegasRadPerSec, double tsSeconds,
                              int pointsPerLine = 61);

/// zeta = 0, 0.1, ..., 0.9, 1: the usual grid lines.
std::vector<double> defaultGridZetas();
/**
 * "Nice" natural frequencies (1, 2, 5 times a power of ten) up to @p maxRadPerSec, at most
 * about @p count of them, for the s-plane grid of a view of that radius.
 * @throws InvalidInput unless maxRadPerSec > 0 and count >= 1.
 */
std::vector<double> niceGridFrequencies(double maxRadPerSec, int count = 6);
/// omega_n = k/10 * pi/Ts, k = 1..10: the usual z-plane frequency lines (fractions of Nyquist).
std::vector<double> defaultZGridFrequencies(double tsSeconds);

} // namespace xyt
