// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/coefficient_json.h"

#include "ui/session/session_file.h"

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
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        QJsonObject axis{{"id", QString::fromStdString(settings.id)},
                         {"label", QString::fromStdString(settings.label)},
                         {"method", methodName(settings.method)}};
        if (a.ok && a.pp) {
            axis.insert("position_unit", "mm (the ARX model's units)");
            axis.insert("rst", QJsonObject{
                {"F", array(a.pp->f.ascending())},
                {"G", array(a.pp->g.ascending())},
                {"Kf", a.pp->kf},
                {"T", array(a.pp->t.ascending())},
                {"ts", a.pp->tsSeconds},
                {"order", "ascending powers of z^-1"},
                {"law", "F(z^-1) u[k] = Kf w[k] - G(z^-1) y[k]; w = r, or the ZPETC output"},
                {"units", "ts in s, u in the ARX model's input units"}});
            if (settings.pp.zpetcEnabled && a.zpetc)
                axis.insert("zpetc", QJsonObject{
                    {"num", array(a.zpetc->feedforwardNum.ascending())},
                    {"den", array(a.zpetc->feedforwardDen.ascending())},
                    {"preview_steps", a.zpetc->previewSteps},
                    {"gain_factor", a.zpetc->gainFactor},
                    {"order", "ascending powers of z^-1"},
                    {"law", "den(z^-1) w[k] = num(z^-1) r[k + preview_steps]"}});
            axes.append(axis);
            continue;
        }
        const DigitalController digital = axisDigitalController(session, evaluation, i, options);
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
