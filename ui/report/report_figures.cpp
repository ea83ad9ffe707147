// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/report/report_figures.h"

#include "core/analysis/root_locus.h"
#include "core/session/axis_frequency.h"
#include "core/session/design_method_module.h"
#include "core/simulation/step_view.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/step_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/diagnostic_text.h"

#include <QCoreApplication>
#include <QPixmap>

namespace xyt::ui {

namespace {

/**
 * Draws @p plot, made by @p fill, at kReportFigureWidth x @p height. The plot is shown (never on
 * screen: Qt::WA_DontShowOnScreen) so that it lays itself out as in the window: its titles,
 * legends and notice boxes are placed on resize and in a queued pass after it, which the posted
 * events let run. The picture is QCustomPlot's own drawing at kReportFigureScale, not a grab of
 * the screen's pixels.
 */
template <class Plot, class Fill>
ReportFigure reportFigure(const QString& name, const QString& caption, int height, Fill fill,
                          const QString& hoverHint = QString()) {
    Plot plot;
    plot.setAttribute(Qt::WA_DontShowOnScreen);
    plot.resize(kReportFigureWidth, height);
    plot.show();
    fill(plot);
    // The readout's "hover ..." hint asks for a mouse a page does not have: left out.
    if (!hoverHint.isEmpty())
        for (QCPLayoutElement* element : plot.plotLayout()->elements(true))
            if (auto* text = qobject_cast<QCPTextElement*>(element);
                text && text->text() == hoverHint)
                text->setText(QString());
    for (int pass = 0; pass < 3; ++pass) // the queued layout passes (legend columns, titles)
        QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    ReportFigure figure;
    figure.name = QStringLiteral("xyt-figure:") + name;
    figure.caption = caption;
    figure.logicalWidth = kReportFigureWidth;
    figure.logicalHeight = height;
    figure.image = plot.toPixmap(kReportFigureWidth, height, kReportFigureScale).toImage();
    figure.image.setDevicePixelRatio(kReportFigureScale);
    return figure;
}

QString reportAxisTitle(const AxisSettings& a) {
    const QString id = QString::fromStdString(a.id).toUpper();
    return a.label.empty()
               ? QCoreApplication::translate("xyt::ui::ReportFigures", "Axis %1").arg(id)
               : QCoreApplication::translate("xyt::ui::ReportFigures", "Axis %1 (%2)")
                     .arg(id, QString::fromStdString(a.label));
}

QString noDesignText(const AxisEvaluation& e) {
    return QCoreApplication::translate("xyt::ui::ReportFigures", "No design: %1: %2")
        .arg(QString::fromStdString(e.errorField), diagnosticText(e.error));
}

// The four plots of an axis, each fed as its view feeds it (ui/views/*_view.cpp), from the
// report's evaluation instead of the presenter's live one.

ReportFigure rootLocusFigure(const Session& s, const AxisEvaluation& e, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    const QString id = QString::fromStdString(a.id);
    const QString title = QCoreApplication::translate("xyt::ui::ReportFigures",
                                                      "Root locus of %1 (K = 1: the design)")
                              .arg(reportAxisTitle(a));
    return reportFigure<RootLocusPlot>(
        id + "-root-locus",
        QCoreApplication::translate("xyt::ui::ReportFigures",
                                    "Root locus of the loop 1 + K L = 0; the closed-loop poles of "
                                    "the design (K = 1) are marked, with the region the "
                                    "specification allows."),
        400,
        [&](RootLocusPlot& plot) {
            if (!e.ok) {
                plot.showNoResult(title, noDesignText(e));
                return;
            }
            plot.setRequirements(axisLocusRequirements(s, axis));
            const std::optional<LoopTransferFunctions> loop = axisLoop(e);
            plot.showLocus(loop ? rootLocus(loop->openLoop) : RootLocus{}, designClosedLoopPoles(e),
                           title);
        },
        RootLocusPlot::readoutHint());
}

ReportFigure bodeFigure(const Session& s, const AxisEvaluation& e, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    const QString title =
        QCoreApplication::translate("xyt::ui::ReportFigures", "Bode diagram of %1")
            .arg(reportAxisTitle(a));
    return reportFigure<BodePlot>(
        QString::fromStdString(a.id) + "-bode",
        QCoreApplication::translate("xyt::ui::ReportFigures",
                                    "Bode diagram of the open loop L with the gain and phase "
                                    "margins, and the closed loop."),
        460,
        [&](BodePlot& plot) {
            if (!e.ok) {
                plot.showNoResult(title, noDesignText(e));
                return;
            }
            const AxisFrequencyAnalysis f = analyzeAxisFrequency(s, e);
            if (!f.ok) {
                plot.showNoResult(title, QCoreApplication::translate("xyt::ui::ReportFigures",
                                                                     "No frequency analysis: %1")
                                             .arg(diagnosticText(f.error)));
                return;
            }
            plot.showAnalysis(f, a.method != DesignMethod::PolePlacementZpetc || a.pp.zpetcEnabled,
                              title,
                              {s.spec.minPhaseMarginDeg, s.spec.minGainMarginDb,
                               e.check.phaseMargin, e.check.gainMargin});
        },
        BodePlot::readoutHint());
}

ReportFigure stepFigure(const Session& s, const AxisEvaluation& e, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    const QString title = QCoreApplication::translate("xyt::ui::ReportFigures", "Unit step of %1")
                              .arg(reportAxisTitle(a));
    return reportFigure<StepPlot>(
        QString::fromStdString(a.id) + "-step",
        QCoreApplication::translate("xyt::ui::ReportFigures",
                                    "Unit step of the closed loop, with the specification's "
                                    "overshoot and settling limits."),
        320,
        [&](StepPlot& plot) {
            if (!e.ok) {
                plot.showNoResult(title, noDesignText(e));
                return;
            }
            try {
                const bool pp = e.pp && e.zpetc;
                plot.showView(stepView(e.closedLoop(), e.step, specificationEnvelope(s.spec),
                                       pp ? &*e.pp : nullptr, pp ? &*e.zpetc : nullptr,
                                       pp && a.pp.zpetcEnabled),
                              title);
            } catch (const std::exception& ex) {
                plot.showNoResult(title, QCoreApplication::translate("xyt::ui::ReportFigures",
                                                                     "No step response: %1")
                                             .arg(exceptionText(ex)));
            }
        },
        StepPlot::readoutHint());
}

ReportFigure timeFigure(const Session& s, const AxisEvaluation& e, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    return reportFigure<TimeResponsePlot>(
        QString::fromStdString(a.id) + "-time",
        QCoreApplication::translate("xyt::ui::ReportFigures",
                                    "Response to the trajectory: reference and output, tracking "
                                    "error, control voltage; the digital implementation "
                                    "overlaid."),
        640, [&](TimeResponsePlot& plot) {
            plot.setDigitalVisible(true); // the window's default (View › Show the digital ...)
            plot.showAxis(e, reportAxisTitle(a), s.umaxVolts);
        });
}

} // namespace

std::vector<ReportFigure> axisFigures(const Session& session, const SessionEvaluation& evaluation,
                                      int axis) {
    const AxisEvaluation& e = evaluation.axes.at(static_cast<std::size_t>(axis));
    return {rootLocusFigure(session, e, axis), bodeFigure(session, e, axis),
            stepFigure(session, e, axis), timeFigure(session, e, axis)};
}

std::vector<ReportFigure> contourFigures(const Session& session,
                                         const SessionEvaluation& evaluation) {
    std::vector<ReportFigure> figures;
    bool polar = false;
    figures.push_back(reportFigure<ContourPlot>(
        "contour",
        QCoreApplication::translate("xyt::ui::ReportFigures",
                                    "The XY contour: commanded and traced path, the error "
                                    "magnified about the path."),
        600, [&](ContourPlot& plot) {
            plot.showSession(session, evaluation);
            polar = plot.polarAvailable();
        }));
    if (polar)
        figures.push_back(reportFigure<ContourPlot>(
            "ballbar",
            QCoreApplication::translate("xyt::ui::ReportFigures",
                                        "Ballbar view of the circle (ISO 230-4): the radial "
                                        "deviation magnified about the nominal centre."),
            600, [&](ContourPlot& plot) {
                plot.showSession(session, evaluation);
                plot.setPolar(true);
            }));
    return figures;
}

} // namespace xyt::ui
