// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/coefficient_json.h"

#include "ui/session_file.h"

#include <QJsonArray>

namespace xyt::ui {

namespace {
QJsonArray array(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}
} // namespace

QJsonObject coefficientsJson(const Session& session, const SessionEvaluation& evaluation,
                             const ExportOptions& options) {
    QJsonArray axes;
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& settings = session.axes[static_cast<std::size_t>(i)];
        const DigitalController digital = axisDigitalController(session, evaluation, i, options);
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        QJsonObject axis{{"id", QString::fromStdString(settings.id)},
                         {"label", QString::fromStdString(settings.label)},
                         {"method", methodName(settings.method)}};
        if (a.gt) {
            axis.insert("position_unit", QStringLiteral("model unit (%1 per mm of trajectory)")
                                             .arg(settings.gt.modelUnitsPerPositionUnit));
            axis.insert("continuous_pi",
                        QJsonObject{{"kp", a.gt->kp},
                                    {"ki", a.gt->ki},
                                    {"form", "u(s) = (kp + ki/s) e(s)"},
                                    {"units", "kp in V per model unit, ki in V per model unit per s"}});
            axis.insert("reference_model",
                        QJsonObject{{"num", array(a.gt->referenceModel.num().descending())},
                                    {"den", array(a.gt->referenceModel.den().descending())},
                                    {"order", "descending powers of s"}});
        }
        axis.insert("digital_controller",
                    QJsonObject{{"num", array(digital.num)},
                                {"den", array(digital.den)},
                                {"ts", digital.tsSeconds},
                                {"discretization", QString::fromStdString(discretizationName(options.piMethod))},
                                {"order", "ascending powers of z^-1"},
                                {"difference_equation",
                                 "u[k] = sum_i num[i] e[k-i] - sum_{i>=1} den[i] u[k-i], e = r - y"},
                                {"units", "ts in s, u in V"}});
        axes.append(axis);
    }
    return {{"format", "xytune-coefficients"},
            {"version", 1},
            {"umax_volts", session.umaxVolts},
            {"axes", axes}};
}

} // namespace xyt::ui
