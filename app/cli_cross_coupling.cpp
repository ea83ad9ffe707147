// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_cross_coupling.h"

#include "app/cli_json.h"
#include "core/model/errors.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <numbers>

namespace xyt::cli {

const QStringList kCrossCouplingOptions = {"ccc-kp", "ccc-ki", "ccc-estimate"};

CrossCoupling parseCrossCoupling(const CliArgs& args) {
    CrossCoupling c;
    c.kp = args.number("ccc-kp", 0.0);
    c.ki = args.number("ccc-ki", 0.0);
    for (const auto& [option, value] :
         {std::pair<const char*, double>{"--ccc-kp", c.kp}, {"--ccc-ki", c.ki}})
        if (!std::isfinite(value) || value < 0.0)
            throw InvalidInput(option,
                               "must be a finite number >= 0 (0 switches the coupling off)");
    const QString estimate = args.text("ccc-estimate", "circular");
    if (!contourEstimateFromName(estimate.toStdString(), c.estimate))
        throw InvalidInput("--ccc-estimate",
                           "must be linear or circular, got '" + estimate.toStdString() + "'");
    return c;
}

QJsonObject couplingStabilityJson(const CouplingStability& st) {
    const CoupledLineLoop& w = st.worst;
    QJsonArray poles;
    for (const std::complex<double>& p : w.poles)
        poles.append(QJsonArray{number(p.real()), number(p.imag())});
    return {{"period", number(st.periodSeconds)},
            {"lines_checked", static_cast<qint64>(st.linesChecked)},
            {"frozen_directions", static_cast<qint64>(st.frozenDirections)},
            {"unbounded_frozen_directions", static_cast<qint64>(st.unboundedFrozenDirections)},
            {"worst_direction_deg", number(st.worstThetaRad * 180.0 / std::numbers::pi)},
            {"spectral_radius", number(w.spectralRadius)},
            {"hidden_integral_mode", w.hiddenIntegralMode},
            {"poles", poles},
            {"disk_margin", number(w.diskMargin)},
            {"disk_gain_margin_db", number(w.diskGainMarginDb)},
            {"disk_phase_margin_deg", number(w.diskPhaseMarginDeg)}};
}

namespace {

QJsonObject gains(const CrossCoupling& c) {
    return {
        {"kp", number(c.kp)}, {"ki", number(c.ki)}, {"estimate", contourEstimateName(c.estimate)}};
}

QJsonObject deviationJson(const ContourDeviation& d) {
    return {{"max", number(d.maxAbs)}, {"rms", number(d.rms)}};
}

} // namespace

QJsonValue trajectoryCouplingJson(const Session& session, const CoupledTrajectoryRun& run) {
    QJsonObject o = gains(session.crossCoupling);
    o.insert("line_loop", couplingStabilityJson(run.stability));
    o.insert("contour_error", deviationJson(run.coupledError));
    o.insert("independent_axes",
             QJsonObject{{"contour_error", deviationJson(run.independentError)}});
    return o;
}

} // namespace xyt::cli
