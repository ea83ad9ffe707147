// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_json.h"

#include <QJsonDocument>

#include <cmath>
#include <cstdio>

namespace xyt::cli {

QJsonValue number(double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); }

QJsonArray numbers(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(number(x));
    return a;
}

QJsonArray descending(const Polynomial& p) { return numbers(p.descending()); }

QJsonArray ascending(const Polynomial& p) { return numbers(p.ascending()); }

QJsonArray complexPairs(const std::vector<std::complex<double>>& roots) {
    QJsonArray a;
    for (const auto& r : roots)
        a.append(QJsonArray{number(r.real()), number(r.imag())});
    return a;
}

QJsonObject continuousTf(const TransferFunction& tf) {
    return {{"num", descending(tf.num())}, {"den", descending(tf.den())}};
}

QJsonObject metricsJson(const TrackingMetrics& m, const StepCharacteristics& step) {
    return {{"rmse", number(m.rmse)},
            {"max_abs_error", number(m.maxAbsError)},
            {"max_abs_error_pct", number(m.maxAbsErrorPct)},
            {"max_abs_u", number(m.maxAbsU)},
            {"saturated", m.diverged ? QJsonValue() : QJsonValue(m.saturated)},
            {"diverged", m.diverged},
            {"saturated_time", number(m.saturatedTimeSeconds)},
            {"settling_time", step.stable ? number(step.settlingTimeSeconds) : QJsonValue()},
            {"overshoot_pct", step.stable ? number(step.overshootPct) : QJsonValue()},
            {"itae", number(m.itae)}};
}

void print(const QJsonObject& object) {
    const QByteArray bytes = QJsonDocument(object).toJson(QJsonDocument::Indented);
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
    std::fflush(stdout);
}

} // namespace xyt::cli
