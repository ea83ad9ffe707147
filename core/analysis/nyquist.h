// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic.h"
#include "core/model/transfer_function.h"

#include <complex>
#include <string>
#include <vector>

namespace xyt {

struct NyquistOptions {
    /// Radius of the indentations around open-loop poles on the stability boundary: this
    /// fraction of |omega_p| (of the geometric mean of the pole and zero frequencies for
    /// s = 0) in the s-plane, or this radius itself in the z-plane. A closed-loop pole closer
    /// than that to an indented open-loop pole is not counted (a loop that close to the
    /// boundary is marginal anyway).
    double indentationRelativeRadius = 1e-6;
    /// Sampling bound: between consecutive samples neither arg(1 + L) nor arg L turns by more
    /// than this, and |1 + L| changes by at most a factor 2 (so a pass near -1 is resolved).
    double maxArgStepDeg = 15.0;
    /// Bound on the number of samples (a warning says when it is reached; the count is then
    /// not trusted).
    int maxPoints = 200000;
};

/// An indentation of the contour around an open-loop pole on the boundary (j omega_p, or
/// e^{j omega_p Ts}), passing on its stable side: to the right in the s-plane, outside the unit
/// circle in the z-plane. The pole is thereby treated as stable (not in P).
struct NyquistIndentation {
    double omegaRadPerSec = 0.0; ///< 0 for integrators, pi/Ts for a pole at z = -1
    int order = 0;               ///< multiplicity: the curve turns k half-circles at infinity
    double radius = 0.0;         ///< in the s-plane (rad/s) or the z-plane
};

/**
 * The Nyquist curve of L and the encirclement count of -1.
 *
 * The contour (clockwise around the unstable region): continuous, up the imaginary axis and
 * back along an infinite half circle on which L tends to its (finite, L proper) limit;
 * discrete, the unit circle counterclockwise (whose exterior, with infinity, is the unstable
 * region: the argument principle for it gives the same formula). Both with the indentations.
 * Only the upper half is sampled (s = j omega, omega from 0 to infinity; z = e^{j theta},
 * theta from 0 to pi); the lower half is its complex conjugate, so the total turn of
 * arg(1 + L) is twice that of the upper half (which starts and ends on the real axis).
 *
 * Nyquist criterion: Z = N + P, with N the clockwise encirclements of -1 by L, P the open-loop
 * poles in the unstable region (boundary poles excluded, see NyquistIndentation) and Z the
 * closed-loop poles there.
 *
 * N is counted by summing the turn of arg(1 + L) between samples of an adaptive sampling that
 * bounds each turn (NyquistOptions::maxArgStepDeg), not from the closed-loop poles.
 */
struct NyquistCurve {
    double tsSeconds = 0.0;
    /// L along the upper half of the contour, in order (indentations included).
    std::vector<std::complex<double>> points;
    /// The frequency of each point: omega on the axis (inf at the end of a continuous contour),
    /// the indented pole's frequency on an indentation.
    std::vector<double> omegaRadPerSec;
    /// -1 for a point on the boundary itself, else the index into indentations.
    std::vector<int> indentationIndex;
    std::vector<NyquistIndentation> indentations; ///< at omega >= 0, increasing
    int clockwiseEncirclements = 0;               ///< N
    int openLoopUnstablePoles = 0;                ///< P
    int closedLoopUnstablePoles = 0;              ///< Z = N + P
    /// True when a sample lies within 1e-9 of -1 (a closed-loop pole on the boundary): N is
    /// then not defined.
    bool passesThroughMinusOne = false;
    std::vector<Diagnostic> warnings;
};

/// @throws InvalidInput "num" for an improper loop, and "indentationRelativeRadius" (in (0, 0.1)),
///         "maxArgStepDeg" (in (0, 90]), "maxPoints" (>= 100) when out of range.
NyquistCurve nyquistCurve(const TransferFunction& openLoop, const NyquistOptions& options = {});

} // namespace xyt
