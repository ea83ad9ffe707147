// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/views/parameter_locus_view.h"

#include "ui/plots/parameter_locus_plot.h"
#include "ui/session/tuning_session.h"

namespace xyt::ui {

ParameterLocusView::ParameterLocusView(TuningSession* session, ParameterLocusPlot* plot)
    : PresenterView(session, plot), plot_(plot) {}

void ParameterLocusView::setSweptParameter(GtSweptParameter parameter) {
    swept_ = parameter;
    requestRedraw();
}

void ParameterLocusView::draw() {
    const int axis = session()->currentAxis();
    const AxisSettings& a = session()->session().axes.at(static_cast<std::size_t>(axis));
    const AxisEvaluation& e = session()->axisEvaluation(axis);
    const QString title = tr("Parameter locus of %1").arg(axisTitle());
    if (!e.ok) {
        plot_->showNoResult(title, noDesignReason(e));
        return;
    }
    if (a.method == DesignMethod::PolePlacementZpetc) {
        plot_->showNoResult(
            title, tr("The parameter locus sweeps ωn or kp of a Guillemin–Truxal axis. This axis "
                      "uses pole placement: its closed-loop poles are the roots of T = 1 + t1 z⁻¹ "
                      "(pole at z = %1), placed directly by t1.")
                       .arg(-a.pp.t1, 0, 'g', 4));
        return;
    }
    if (a.method != DesignMethod::GuilleminTruxal) {
        plot_->showNoResult(
            title, tr("The parameter locus sweeps ωn or kp of a Guillemin–Truxal axis. This axis "
                      "uses %1: the root locus shows its poles against the loop gain.")
                       .arg(methodDisplayName(a.method)));
        return;
    }
    std::vector<std::complex<double>> poles;
    try {
        poles = e.closedLoop().poles();
    } catch (const std::exception&) {
        poles.clear();
    }
    const bool kp = swept_ == GtSweptParameter::Kp;
    plot_->showLocus(session()->parameterLocus(axis, swept_), poles,
                     kp ? tr("Closed-loop poles as kp sweeps %1 … %2 (ωn = %3)")
                              .arg(a.gt.kp / 10, 0, 'g', 3)
                              .arg(a.gt.kp * 10, 0, 'g', 3)
                              .arg(a.gt.omegaNRadPerSec)
                        : tr("Closed-loop poles as ωn sweeps %1 … %2 rad/s (kp = %3)")
                              .arg(a.gt.omegaNRadPerSec / 10, 0, 'g', 3)
                              .arg(a.gt.omegaNRadPerSec * 10, 0, 'g', 3)
                              .arg(a.gt.kp));
}

} // namespace xyt::ui
