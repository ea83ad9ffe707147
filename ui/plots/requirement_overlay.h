// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/pole_requirements.h"

#include <qcustomplot.h>

#include <complex>
#include <limits>
#include <vector>

namespace xyt::ui {

/// What the overlay draws: the specification's step limits and, for a Guillemin-Truxal axis,
/// the design's omega_n (the specification has no omega_n requirement).
struct LocusRequirements {
    bool active = false;
    double maxOvershootPct = 0.0;
    double maxSettlingTimeSeconds = std::numeric_limits<double>::infinity();
    double designOmegaNRadPerSec = std::numeric_limits<double>::quiet_NaN(); ///< NaN: none
};

/**
 * The specification drawn on a root locus as Control System Designer does: the zeta
 * wedge of the overshoot limit, the settling line sigma = -4/ts (for a discrete loop their
 * images under z = exp(s Ts): the zeta spiral and the circle |z| = exp(-4 Ts/ts)), the
 * forbidden side of each shaded lightly, the reference model's omega_n circle (dashed, not
 * shaded: a design parameter, not a requirement, and not where the closed-loop poles sit), the
 * dominant closed-loop pair with its own omega_n and zeta, and a ring around every closed-loop
 * pole in a forbidden region. The positions
 * come from core/analysis (pole_requirements, damping_grid). Owns its plottables in @p plot.
 */
class RequirementOverlay {
public:
    explicit RequirementOverlay(QCustomPlot* plot);
    /// Redraws for a plane (@p tsSeconds 0: s) whose view spans about @p extent from the origin.
    void show(const LocusRequirements& requirements, double tsSeconds, double extent,
              const std::vector<std::complex<double>>& closedLoopPoles);
    void clear();

    /// The zeta boundary: upper end, origin (z = 1), lower end (s) or the spiral (z).
    QCPCurve* dampingBoundary() const { return damping_; }
    /// The settling boundary: the line Re s = sigma (two points) or the circle |z| = r.
    QCPCurve* settlingBoundary() const { return settling_; }
    QCPCurve* omegaCircle() const { return omega_; }
    QCPGraph* violatingPoles() const { return violating_; }
    /// The dominant closed-loop pole pair (the complex pair decaying slowest), its own omega_n
    /// and zeta in the legend: the reference model's omega_n is not where the poles sit.
    QCPGraph* dominantPoles() const { return dominant_; }

private:
    QCPCurve* damping_;
    QCPCurve* settling_;
    QCPCurve* omega_;
    QCPCurve* dampingShade_;
    QCPCurve* settlingShade_;
    QCPGraph* violating_;
    QCPGraph* dominant_;
};

} // namespace xyt::ui
