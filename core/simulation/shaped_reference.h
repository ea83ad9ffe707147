// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/design/input_shaper.h"

#include <cstddef>
#include <vector>

namespace xyt {

/**
 * A reference shaped by an input shaper: r_s(t) = sum_i A_i r(t - t_i), on the same time grid
 * t_k = t0 + k dt as the reference it came from, and longer than it by addedSamples =
 * ceil(duration / dt) samples so that the shaped move ends (its last impulse, t_n after the
 * reference's end, reaches the reference's final value). The caller extends its time vector by
 * those samples (t_k = t0 + k dt for every k < values.size()).
 */
struct ShapedReference {
    std::vector<double> values;
    std::size_t addedSamples = 0;
};

/**
 * r_s(t_k) = sum_i A_i r(t_k - t_i) for the reference @p r sampled every @p dtSeconds.
 *  - Between samples r is interpolated linearly: the reference is a sampled trajectory whose
 *    samples are exact, linear interpolation is second order (error <= dt^2/8 max|r''|), never
 *    overshoots the samples (each r_s is a convex combination of them, amplitudes > 0) and is
 *    exact on any piecewise-linear reference whose breakpoints are samples (a ramp, a corner).
 *    An impulse time that is a whole number of samples (to 1e-9 of a sample) reads that sample
 *    directly, so a shaper whose times are multiples of dt is applied exactly.
 *  - Before the first sample r holds r(t0) (the table is at rest there), after the last it
 *    holds the last sample (the move has ended).
 * Since the amplitudes sum to 1, the shaped reference ends at the reference's final value.
 * @param moveSeconds the reference's moving time (the caller's move, e.g. tf - t0 of a
 *   point-to-point trajectory).
 * @throws InvalidInput "shaper.frequency" when the shaper lasts longer than the move (it would
 *   smear the whole move: "the shaper lasts X s, longer than the move of Y s"); "dt" unless > 0;
 *   "move" unless > 0; "reference" when empty or not finite; "shaper" when its amplitudes and
 *   times differ in size, are empty, or its times do not start at 0 and increase.
 */
ShapedReference shapeReference(const InputShaper& shaper, const std::vector<double>& r,
                               double dtSeconds, double moveSeconds);

/// The shaped command of a 2-D path: x and y shaped by the same shaper (shapeReference each).
struct ShapedPath {
    std::vector<double> x, y;
    std::size_t addedSamples = 0;
};

/// @throws InvalidInput "y" when x and y differ in size; otherwise as shapeReference.
ShapedPath shapePath(const InputShaper& shaper, const std::vector<double>& x,
                     const std::vector<double>& y, double dtSeconds, double moveSeconds);

/**
 * How far a shaped path strays from the programmed one (Klipper's "smoothing": the shaper rounds
 * corners and shrinks curves). For each shaped point k, its distance to the programmed
 * polyline's segments between samples k - m - 1 and k, m = ceil(duration / dt) (the part of the
 * path the shaper blended into that point; a path that comes back near itself later is not
 * mistaken for the nearest); the largest of these.
 */
struct PathDeviation {
    double maxMm = 0.0;
    std::size_t index = 0; ///< the shaped sample where it occurs
};

/// @p shaped as shapePath returns it for @p x, @p y and @p shaper.
/// @throws InvalidInput "x" / "y" when sizes disagree or are empty, "dt" unless > 0.
PathDeviation shapedPathDeviation(const ShapedPath& shaped, const std::vector<double>& x,
                                  const std::vector<double>& y, const InputShaper& shaper,
                                  double dtSeconds);

/**
 * The shaper's gain on a circle: a circle of radius R traced at angular speed omega, z(t) =
 * R e^{j omega t}, shaped is sum_i A_i R e^{j omega (t - t_i)} = z(t) H(omega) with H(omega) =
 * sum_i A_i e^{-j omega t_i}: once the shaper's duration has passed, a circle of radius
 * R |H(omega)|, lagging by arg H. Its deviation from the programmed circle is R (1 - |H|).
 */
double shapedCircleRadiusRatio(const InputShaper& shaper, double omegaRadPerSec);

} // namespace xyt
