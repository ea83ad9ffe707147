// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <complex>
#include <functional>
#include <vector>

namespace xyt::ui {

class DampingLabels;

/**
 * The constant-damping / constant-frequency grid behind the s- or z-plane plots (and the unit
 * circle for the z-plane), drawn from the core's DampingGrid. Owns its curves in @p plot.
 */
class PlaneGrid {
public:
    explicit PlaneGrid(QCustomPlot* plot);
    /// Rebuilds the grid for the sample time (0: s-plane) and the largest frequency shown.
    void show(double tsSeconds, double maxOmegaRadPerSec);
    void setVisible(bool visible);

private:
    void clear();
    QCustomPlot* plot_;
    std::vector<QCPCurve*> curves_;
    DampingLabels* labels_ = nullptr;
    double ts_ = -1.0;
    double maxOmega_ = -1.0;
    bool visible_ = true;
};

/// A polyline of complex points as a curve (real part horizontal).
QCPCurve* addComplexCurve(QCustomPlot* plot, const std::vector<std::complex<double>>& points,
                          const QPen& pen);
/**
 * Shows one curve per branch of complex points in @p curves (created or removed as the branch
 * count changes; @p penFor gives the pen of the curve with that index).
 */
void showBranches(QCustomPlot* plot, std::vector<QCPCurve*>& curves,
                  const std::vector<std::vector<std::complex<double>>>& branches,
                  const std::function<QPen(std::size_t)>& penFor);

/// The rectangle of the complex plane a view should show.
struct PlaneBox {
    double reMin = 0.0, reMax = 0.0, imMin = 0.0, imMax = 0.0;
};

/// True when some finite point of @p points lies outside the plot's current view.
bool anyOutsideView(const QCustomPlot* plot, const std::vector<std::complex<double>>& points);

/**
 * The box around @p base and every finite point of @p points, with 8 % margins on each side
 * (and at least a small extent, so a single point gets a readable view).
 */
PlaneBox fittedBox(PlaneBox base, const std::vector<std::complex<double>>& points);

/**
 * Sets the plot's view to the smallest equal-aspect view around @p box (one unit spans as many
 * pixels on both axes: circles stay circles), kept so when the plot is resized.
 */
void setView(QCustomPlot* plot, const PlaneBox& box);

/// Returns to the last box given to setView (false for a plot that never had one).
bool resetPlaneView(QCustomPlot* plot);

/// Replaces the data of a point graph with the complex points.
void setComplexPoints(QCPGraph* graph, const std::vector<std::complex<double>>& points);

} // namespace xyt::ui
