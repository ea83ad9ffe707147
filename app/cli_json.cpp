// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_json.h"

#include "app/cli_design_args.h"

#include <QJsonDocument>

#include <cmath>
#include <cstdio>

namespace xyt::cli {

QJsonValue number(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QJsonArray numbers(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(number(x));
    return a;
}

QJsonArray descending(const Polynomial& p) {
    return numbers(p.descending());
}

QJsonArray ascending(const Polynomial& p) {
    return numbers(p.ascending());
}

QJsonArray complexPairs(const std::vector<std::complex<double>>& roots) {
    QJsonArray a;
    for (const auto& r : roots)
        a.append(QJsonArray{number(r.real()), number(r.imag())});
    return a;
}

QJsonObject continuousTf(const TransferFunction& tf) {
    return {{"num", descending(tf.num())}, {"den", descending(tf.den())}};
}

QJsonObject trackingJson(const TrackingMetrics& m) {
    return {{"rmse", number(m.rmse)},
            {"max_abs_error", number(m.maxAbsError)},
            {"max_abs_error_pct", number(m.maxAbsErrorPct)},
            {"max_abs_u", number(m.maxAbsU)},
            {"saturated", m.diverged ? QJsonValue() : QJsonValue(m.saturated)},
            {"diverged", m.diverged},
            {"saturated_time", number(m.saturatedTimeSeconds)},
            {"itae", number(m.itae)}};
}

QJsonObject metricsJson(const TrackingMetrics& m, const StepCharacteristics& step) {
    QJsonObject o = trackingJson(m);
    o.insert("settling_time", step.stable ? number(step.settlingTimeSeconds) : QJsonValue());
    o.insert("overshoot_pct", step.stable ? number(step.overshootPct) : QJsonValue());
    return o;
}

QJsonObject stepResponseJson(const StepCharacteristics& step) {
    auto defined = [&](double v) { return step.stable ? number(v) : QJsonValue(); };
    return {{"stable", step.stable},
            {"final_value", defined(step.finalValue)},
            {"settling_time", defined(step.settlingTimeSeconds)},
            {"settling_band_pct", 2.0},
            {"overshoot_pct", defined(step.overshootPct)},
            {"peak_time", defined(step.peakTimeSeconds)}};
}

QJsonObject moveSettleJson(const MoveSettleMetrics& m) {
    return {{"window_mm", number(m.windowMm)},
            {"move_end", number(m.moveEndSeconds)},
            {"run_end", number(m.runEndSeconds)},
            {"reached_move_end", m.reachedMoveEnd},
            {"settled", m.settled},
            {"settle_time", m.settleTimeSeconds ? number(*m.settleTimeSeconds) : QJsonValue()},
            {"final_error", number(m.finalErrorMm)},
            {"final_overshoot_mm", number(m.finalOvershootMm)},
            {"diverged", m.diverged}};
}

QJsonObject marginsJson(const StabilityMargins& m, const NyquistCurve& n) {
    QJsonArray gains, phases;
    for (const GainMarginCrossing& c : m.gainMargins)
        gains.append(QJsonObject{{"omega", number(c.omegaRadPerSec)},
                                 {"gain_factor", number(c.gainFactor)},
                                 {"gain_db", number(c.gainDb)}});
    for (const PhaseMarginCrossing& c : m.phaseMargins)
        phases.append(QJsonObject{{"omega", number(c.omegaRadPerSec)},
                                  {"phase_margin_deg", number(c.phaseMarginDeg)},
                                  {"delay_margin_s", number(c.delayMarginSeconds)}});
    QJsonArray warnings;
    for (const std::string& w : m.warnings)
        warnings.append(QString::fromStdString(w));
    // number() writes null for a non-finite value; an infinite margin is said in words.
    const auto margin = [](double v) {
        return std::isinf(v) && v > 0 ? QJsonValue("inf") : number(v);
    };
    return {
        {"gain_margin", QJsonObject{{"factor", margin(m.gainMarginFactor)},
                                    {"db", margin(m.gainMarginDb)},
                                    {"omega", number(m.gainMarginOmegaRadPerSec)}}},
        {"phase_margin", QJsonObject{{"deg", margin(m.phaseMarginDeg)},
                                     {"omega", number(m.phaseMarginOmegaRadPerSec)}}},
        {"delay_margin",
         QJsonObject{{"s", margin(m.delayMarginSeconds)},
                     {"samples", m.tsSeconds > 0.0 ? margin(m.delayMarginSamples) : QJsonValue()}}},
        {"peak_sensitivity", QJsonObject{{"ms", margin(m.peakSensitivity)},
                                         {"omega", number(m.peakSensitivityOmegaRadPerSec)}}},
        {"peak_complementary_sensitivity",
         QJsonObject{{"mt", margin(m.peakComplementarySensitivity)},
                     {"omega", number(m.peakComplementarySensitivityOmegaRadPerSec)}}},
        {"bandwidth", margin(m.bandwidthRadPerSec)},
        {"closed_loop_stable", m.closedLoopStable},
        {"gain_margin_crossings", gains},   // at every phase crossover
        {"phase_margin_crossings", phases}, // at every gain crossover
        {"nyquist", QJsonObject{{"encirclements", n.clockwiseEncirclements},
                                {"open_loop_unstable_poles", n.openLoopUnstablePoles},
                                {"closed_loop_unstable_poles", n.closedLoopUnstablePoles}}},
        {"ts", number(m.tsSeconds)},
        {"warnings", warnings}};
}

void print(const QJsonObject& object) {
    const QByteArray bytes = QJsonDocument(object).toJson(QJsonDocument::Indented);
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
    std::fflush(stdout);
}

} // namespace xyt::cli

namespace xyt::cli {

QString marginsText(const StabilityMargins& m) {
    const auto v = [](double x) {
        return std::isinf(x) && x > 0 ? QStringLiteral("inf") : QString::number(x, 'g', 3);
    };
    QString text = QStringLiteral("GM %1 dB").arg(v(m.gainMarginDb));
    if (std::isfinite(m.gainMarginOmegaRadPerSec))
        text += QStringLiteral(" at %1 rad/s").arg(v(m.gainMarginOmegaRadPerSec));
    text += QStringLiteral(", PM %1 deg").arg(v(m.phaseMarginDeg));
    if (std::isfinite(m.phaseMarginOmegaRadPerSec))
        text += QStringLiteral(" at %1 rad/s").arg(v(m.phaseMarginOmegaRadPerSec));
    text += QStringLiteral(", delay margin %1 s, Ms %2")
                .arg(v(m.delayMarginSeconds), v(m.peakSensitivity));
    if (!m.closedLoopStable)
        text += QStringLiteral(" (closed loop UNSTABLE: not robustness measures)");
    return text;
}

} // namespace xyt::cli
