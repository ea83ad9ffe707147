// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/report/report_metrics.h"

#include "ui/panels/metrics_panel.h"
#include "ui/session/diagnostic_text.h"

#include <QStringList>

#include <cmath>
#include <optional>

namespace xyt::ui {

namespace {

/// One row of the table: the limit, each run's figure and, where the specification judges the
/// row, each run's verdict.
struct ReportMetricRow {
    int row = 0;
    QString limit, design, digital;
    std::optional<bool> designPass, digitalPass;
};

QString reportMark(const QString& figure, const std::optional<bool>& pass) {
    if (!pass)
        return figure.toHtmlEscaped();
    return QStringLiteral("%1 <span style='color:%2'>%3</span>")
        .arg(figure.toHtmlEscaped(), *pass ? QStringLiteral("#1b7f2a") : QStringLiteral("#c62828"),
             *pass ? QStringLiteral("✓") : QStringLiteral("✗"));
}

QString reportMarginText(double v) {
    return std::isinf(v) && v > 0 ? QStringLiteral("∞") : displayNumber(v);
}

QString reportSettleText(const MoveSettleMetrics& ms) {
    return ms.diverged ? ReportMetrics::tr("n/a")
           : ms.settleTimeSeconds
               ? displayNumber(*ms.settleTimeSeconds)
               : ReportMetrics::tr("> %1 (not settled in the run)")
                     .arg(displayNumber(std::max(0.0, ms.runEndSeconds - ms.moveEndSeconds)));
}

QString reportSaturatedText(const TrackingMetrics& m) {
    return m.diverged    ? ReportMetrics::tr("n/a")
           : m.saturated ? displayNumber(m.saturatedTimeSeconds)
                         : ReportMetrics::tr("no");
}

} // namespace

QString ReportMetrics::tableHtml(const Session& session, int axis, const AxisEvaluation& a) {
    using Row = MetricsPanel::Row;
    if (!a.ok)
        return tr("<p>No figures: the axis has no design (%1: %2).</p>")
            .arg(QString::fromStdString(a.errorField).toHtmlEscaped(),
                 diagnosticText(a.error).toHtmlEscaped());
    const Specification& spec = session.spec;
    const SpecificationCheck& d = a.designCheck;
    const std::optional<SpecificationCheck>& im = a.implementationCheck;
    const DigitalEvaluation* digital = a.digital.get();
    const TrackingMetrics& m = a.metrics;
    const auto judged = [&](bool SpecificationCheck::*criterion) {
        return std::pair<std::optional<bool>, std::optional<bool>>{
            d.*criterion, im ? std::optional<bool>((*im).*criterion) : std::nullopt};
    };
    const QString none = tr("—");
    std::vector<ReportMetricRow> rows;
    const auto add = [&](int row, const QString& limit, const QString& design,
                         const QString& digitalFigure,
                         std::pair<std::optional<bool>, std::optional<bool>> pass = {}) {
        rows.push_back({row, limit, design, digital ? digitalFigure : none, pass.first,
                        digital ? pass.second : std::nullopt});
    };
    const TrackingMetrics dm = digital ? digital->metrics : TrackingMetrics{};
    add(Row::Rmse, QString(), displayNumber(m.rmse), displayNumber(dm.rmse));
    add(Row::MaxError, QString(), displayNumber(m.maxAbsError), displayNumber(dm.maxAbsError));
    add(Row::MaxErrorPct, tr("≤ %1").arg(spec.maxErrorPct), displayNumber(m.maxAbsErrorPct),
        displayNumber(dm.maxAbsErrorPct), judged(&SpecificationCheck::trackingError));
    add(Row::MaxU, tr("≤ %1").arg(session.umaxVolts), displayNumber(m.maxAbsU),
        displayNumber(dm.maxAbsU), judged(&SpecificationCheck::noSaturation));
    // The discrete loop of Patrick, Ishak and Adnan is simulated without a limit: its clipped
    // time is flagged, not applied (as the panel's asterisk says).
    add(Row::Saturated, tr("no"),
        reportSaturatedText(m) + (a.pp && m.saturated ? tr(" (flagged, not applied)") : QString()),
        reportSaturatedText(dm), judged(&SpecificationCheck::noSaturation));
    add(Row::Itae, QString(), displayNumber(m.itae), displayNumber(dm.itae));
    if (a.zpetc && session.axes.at(static_cast<std::size_t>(axis)).pp.zpetcEnabled)
        add(Row::Improvement, QString(), displayNumber(a.improvementPct), none);
    if (a.moveSettle) {
        const std::optional<MoveSettleMetrics>& dms =
            digital ? digital->moveSettle : std::optional<MoveSettleMetrics>{};
        add(Row::SettleAfterMove, tr("≤ %1").arg(spec.maxSettleTimeSeconds),
            reportSettleText(*a.moveSettle), dms ? reportSettleText(*dms) : none,
            d.settleApplies ? judged(&SpecificationCheck::settle)
                            : std::pair<std::optional<bool>, std::optional<bool>>{});
        add(Row::FinalError, tr("|e| ≤ %1").arg(spec.inPositionWindowMm),
            displayNumber(a.moveSettle->finalErrorMm),
            dms ? displayNumber(dms->finalErrorMm) : none);
        add(Row::FinalOvershoot, QString(), displayNumber(a.moveSettle->finalOvershootMm),
            dms ? displayNumber(dms->finalOvershootMm) : none);
    }
    // The step and the margins belong to the design: the implementation's check takes them
    // from it, so its column repeats only the verdict.
    const QString same = tr("same step");
    add(Row::Settling, tr("≤ %1").arg(spec.maxSettlingTimeSeconds),
        a.step.stable ? displayNumber(a.step.settlingTimeSeconds) : tr("unstable"), same,
        judged(&SpecificationCheck::settlingTime));
    add(Row::Overshoot, tr("≤ %1").arg(spec.maxOvershootPct),
        a.step.stable ? displayNumber(a.step.overshootPct) : tr("unstable"), same,
        judged(&SpecificationCheck::overshoot));
    if (digital)
        add(Row::DigitalDamping, QString(), displayNumber(digital->designMinDamping, 3),
            displayNumber(digital->minDamping, 3));
    const bool margins = a.margins.has_value();
    const StabilityMargins mg = a.margins.value_or(StabilityMargins{});
    const bool robust = margins && mg.closedLoopStable;
    const QString sameLoop = tr("same loop");
    const auto marginPass = [&](bool SpecificationCheck::*criterion) {
        return margins && d.marginsApply ? judged(criterion)
                                         : std::pair<std::optional<bool>, std::optional<bool>>{};
    };
    add(Row::GainMargin, tr("≥ %1").arg(spec.minGainMarginDb),
        margins ? reportMarginText(mg.gainMarginDb) : none, sameLoop,
        marginPass(&SpecificationCheck::gainMargin));
    add(Row::PhaseMargin, tr("≥ %1").arg(spec.minPhaseMarginDeg),
        margins ? reportMarginText(mg.phaseMarginDeg) : none, sameLoop,
        marginPass(&SpecificationCheck::phaseMargin));
    add(Row::DelayMargin, QString(),
        robust    ? reportMarginText(mg.delayMarginSeconds)
        : margins ? tr("n/a")
                  : none,
        sameLoop);
    add(Row::PeakSensitivity, QString(),
        robust    ? reportMarginText(mg.peakSensitivity)
        : margins ? tr("n/a")
                  : none,
        sameLoop);

    QString html = QStringLiteral("<table width='100%' border='1' cellspacing='0' cellpadding='3' "
                                  "style='border-collapse:collapse; border-color:#999'>");
    html += tr("<tr style='background:#dddddd'><th align='left'>Figure</th><th>Limit</th>"
               "<th>As designed</th><th>As implemented%1</th></tr>")
                .arg(digital ? tr(" (digital, Ts = %1 s)").arg(digital->tsSeconds) : QString());
    int group = -1;
    for (const ReportMetricRow& r : rows) {
        // The group a row belongs to: the nearest group row above it in the panel's order.
        int g = r.row;
        while (g > 0 && !MetricsPanel::isGroupRow(g))
            --g;
        if (g != group) {
            group = g;
            html += QStringLiteral("<tr style='background:#eeeeee'><td colspan='4'><b>%1</b></td>"
                                   "</tr>")
                        .arg(MetricsPanel::groupTitle(g).toHtmlEscaped());
        }
        html += QStringLiteral("<tr><td>%1</td><td align='center'>%2</td><td align='right'>%3</td>"
                               "<td align='right'>%4</td></tr>")
                    .arg(MetricsPanel::rowTitle(r.row).toHtmlEscaped(), r.limit.toHtmlEscaped(),
                         reportMark(r.design, r.designPass), reportMark(r.digital, r.digitalPass));
    }
    html += QStringLiteral("</table>");
    return html;
}

} // namespace xyt::ui
