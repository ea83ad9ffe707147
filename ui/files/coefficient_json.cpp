// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/files/coefficient_json.h"

#include "core/session/design_method_module.h"
#include "ui/files/session_file.h"

#include <QJsonArray>

namespace xyt::files {

namespace {
/// Every number of the export passes exportableNumber: QJsonValue writes inf and NaN as null,
/// which firmware tooling reads as 0 or fails on. @p field names the session path it comes from.
double finite(double v, const std::string& field) {
    return exportableNumber(v, field);
}

QJsonArray array(const std::vector<double>& v, const std::string& field) {
    QJsonArray a;
    for (double x : v)
        a.append(finite(x, field));
    return a;
}

std::string axisField(int axisIndex, const std::string& part) {
    return "axes[" + std::to_string(axisIndex) + "]." + part;
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
        const FrictionCompensation& fc = settings.frictionCompensation;
        if (fc.percent != 0.0) {
            const std::string field = axisField(i, "friction");
            axis.insert(
                "friction_compensation",
                QJsonObject{{"scale", finite(fc.percent / 100.0, field + ".compensation.percent")},
                            {"coulomb", finite(settings.friction.coulombVolts, field + ".coulomb")},
                            {"viscous",
                             finite(settings.friction.viscousVoltsPerMmPerS, field + ".viscous")},
                            {"band", finite(fc.bandMmPerS, field + ".compensation.band")},
                            {"law",
                             "u_fc = scale (coulomb sat(v / band) + viscous v), v the reference "
                             "velocity, added to the controller's output before the limit"},
                            {"units", "coulomb in V, viscous in V per mm/s, band and v in mm/s"}});
        }
        const std::string ppField = axisField(i, "pp"), gtField = axisField(i, "gt");
        if (a.ok && a.pp) {
            axis.insert("position_unit", "mm (the ARX model's units)");
            axis.insert(
                "rst",
                QJsonObject{
                    {"F", array(a.pp->f.ascending(), ppField + " (F)")},
                    {"G", array(a.pp->g.ascending(), ppField + " (G)")},
                    {"Kf", finite(a.pp->kf, ppField + " (Kf)")},
                    {"T", array(a.pp->t.ascending(), ppField + ".t1")},
                    {"ts", finite(a.pp->tsSeconds, ppField + ".ts")},
                    {"order", "ascending powers of z^-1"},
                    {"law", "F(z^-1) u[k] = Kf w[k] - G(z^-1) y[k]; w = r, or the ZPETC output"},
                    {"units", "ts in s, u in the ARX model's input units"}});
            if (settings.pp.zpetcEnabled && a.zpetc)
                axis.insert(
                    "zpetc",
                    QJsonObject{{"num", array(a.zpetc->feedforwardNum.ascending(),
                                              ppField + ".zpetc (feedforward)")},
                                {"den", array(a.zpetc->feedforwardDen.ascending(),
                                              ppField + ".zpetc (feedforward)")},
                                {"preview_steps", a.zpetc->previewSteps},
                                {"gain_factor",
                                 finite(a.zpetc->gainFactor, ppField + ".zpetc (gain factor)")},
                                {"order", "ascending powers of z^-1"},
                                {"law", "den(z^-1) w[k] = num(z^-1) r[k + preview_steps]"}});
            axes.append(axis);
            continue;
        }
        if (a.ok && !a.gt) {
            // A registered method: the coefficients its module lists (its C export holds the
            // step the firmware runs).
            QJsonArray coefficients;
            for (const DesignCoefficient& c : designMethodModule(a.method).coefficients(a))
                coefficients.append(QJsonObject{
                    {"name", QString::fromStdString(c.name)},
                    {"value", finite(c.value, axisField(i, "parameters") + " (" + c.name + ")")},
                    {"unit", QString::fromStdString(c.unit)}});
            axis.insert("coefficients", coefficients);
            axes.append(axis);
            continue;
        }
        const DigitalController digital = axisDigitalController(session, evaluation, i, options);
        if (a.gt) {
            axis.insert("position_unit", QStringLiteral("model unit (%1 per mm of trajectory)")
                                             .arg(finite(settings.gt.modelUnitsPerPositionUnit,
                                                         gtField + ".model_unit_scale")));
            axis.insert(
                "continuous_pi",
                QJsonObject{{"kp", finite(a.gt->kp, gtField + ".kp")},
                            {"ki", finite(a.gt->ki, gtField + " (ki)")},
                            {"form", "u(s) = (kp + ki/s) e(s)"},
                            {"units", "kp in V per model unit, ki in V per model unit per s"}});
            axis.insert("reference_model",
                        QJsonObject{{"num", array(a.gt->referenceModel.num().descending(),
                                                  gtField + " (reference model)")},
                                    {"den", array(a.gt->referenceModel.den().descending(),
                                                  gtField + " (reference model)")},
                                    {"order", "descending powers of s"}});
            const NotchFilter& n = settings.gt.notch;
            if (n.present()) {
                const std::string f = gtField + ".notch";
                const Biquad b = discreteNotch(n, digital.tsSeconds, f + ".");
                axis.insert(
                    "notch",
                    QJsonObject{
                        {"centre_hz", finite(n.centreHz, f + ".centre")},
                        {"width_hz", finite(n.widthHz, f + ".width")},
                        {"depth_db", finite(n.depthDb, f + ".depth")},
                        {"continuous",
                         QJsonObject{{"num", array(n.transferFunction().num().descending(), f)},
                                     {"den", array(n.transferFunction().den().descending(), f)},
                                     {"order", "descending powers of s"}}},
                        {"biquad", QJsonObject{{"b", array({b.b0, b.b1, b.b2}, f)},
                                               {"a", array({1.0, b.a1, b.a2}, f)},
                                               {"ts", finite(digital.tsSeconds, "controller_ts")},
                                               {"order", "ascending powers of z^-1"}}},
                        {"discretization", "bilinear, prewarped at the centre"},
                        {"placement", "on the error e = r - y, ahead of the digital PI: the PI "
                                      "reads e_f = N(z) e"}});
            }
        }
        axis.insert(
            "digital_controller",
            QJsonObject{
                {"num", array(digital.num, gtField + " (digital PI at controller_ts)")},
                {"den", array(digital.den, gtField + " (digital PI at controller_ts)")},
                {"ts", finite(digital.tsSeconds, "controller_ts")},
                {"discretization", QString::fromStdString(discretizationName(options.piMethod))},
                {"order", "ascending powers of z^-1"},
                {"difference_equation",
                 "u[k] = sum_i num[i] e[k-i] - sum_{i>=1} den[i] u[k-i], e = r - y"},
                {"units", "ts in s, u in V"}});
        axes.append(axis);
    }
    // The implementation the controllers were checked with: the anti-windup travels
    // with the coefficients, since the same coefficients wind up without it.
    const ImplementationSettings& impl = session.implementation;
    const QJsonObject implementation{
        {"anti_windup", QString::fromStdString(antiWindupName(impl.antiWindup))},
        {"tracking_time", finite(impl.trackingTimeSeconds, "implementation.tracking_time")},
        {"delay_samples", impl.delaySamples},
        {"encoder_resolution_mm",
         finite(impl.encoderResolutionMm, "implementation.encoder_resolution")},
        {"dac_bits", impl.dacBits},
        {"note",
         "the PI runs in integrator form I[k] = I[k-1] + c0 e[k] + c1 e[k-1], u = sat(kp e + I), "
         "with this anti-windup; see the C export for the exact step"}};
    QJsonObject out{{"format", "xytune-coefficients"},
                    {"version", 1},
                    {"umax_volts", finite(session.umaxVolts, "umax")},
                    {"implementation", implementation},
                    {"axes", axes}};
    if (session.crossCoupling.active()) {
        // The cross-coupled controller over both axes (core/design/cross_coupling.h).
        const CrossCoupling& c = session.crossCoupling;
        out.insert(
            "cross_coupling",
            QJsonObject{{"kp", finite(c.kp, "cross_coupling.kp")},
                        {"ki", finite(c.ki, "cross_coupling.ki")},
                        {"estimate", contourEstimateName(c.estimate)},
                        {"corner_turn_rad", kCornerTurnRad},
                        {"units", "kp in V/mm, ki in V/(mm s), errors in mm"},
                        {"law",
                         "each period T: eps = -ex sin(theta) + ey cos(theta) (+ kappa tau^2 / 2, "
                         "tau = ex cos(theta) + ey sin(theta), circular); I+ = I + T eps; "
                         "uc = kp eps + ki I+; u_x += Cx uc, u_y += Cy uc (Cx, Cy = d eps / d "
                         "ex, d eps / d ey) before each axis' limit; I+ kept unless an axis "
                         "clips; I = 0 where theta turns by more than corner_turn_rad in one "
                         "period and on rapid moves"}});
    }
    return out;
}

} // namespace xyt::files
