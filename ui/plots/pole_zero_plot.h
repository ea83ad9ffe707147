// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/pole_zero_map.h"
#include "ui/plots/plane_grid.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_widget.h"

#include <qcustomplot.h>

namespace xyt::ui {

/**
 * Pole-zero map of named sets (plant, controller, open loop, closed loop, reference model,
 * ZPETC): poles as crosses and zeros as circles in the set's colour, the zeta/omega_n grid (and
 * the unit circle in the z-plane). Clicking a legend entry hides or shows that set.
 */
class PoleZeroPlot : public PlotWidget {
    Q_OBJECT
public:
    explicit PoleZeroPlot(QWidget* parent = nullptr);
    void showSets(const std::vector<PoleZeroSet>& sets, const QString& title);
    /// The poles graph of set @p name (nullptr when absent); its zeros share the visibility.
    QCPGraph* polesGraph(const QString& name) const;
    QCPGraph* zerosGraph(const QString& name) const;
    void setSetVisible(const QString& name, bool visible);
    /// Clears the map and says why there is nothing to show (invalid or failed design).
    void showNoResult(const QString& title, const QString& reason);
    /// Lines said over the plane after showSets (what the poles mean: an integrator, an
    /// unstable or non-minimum-phase model); empty clears them.
    void setNotes(const QStringList& lines);
    bool hasResult() const { return !graphs_.isEmpty(); }
    QString noticeText() const { return notice_.text(); }

private:
    struct SetGraphs {
        QCPGraph* poles;
        QCPGraph* zeros;
    };
    QMap<QString, SetGraphs> graphs_;
    QSet<QString> hidden_;
    PlaneGrid grid_;
    QCPTextElement* title_;
    PlotNotice notice_;
    double lastTs_ = -1.0;
};

} // namespace xyt::ui
