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
    const auto broken = [](const std::optional<AxisBrokenLoop>& b) {
        if (!b)
            return QJsonValue();
        return QJsonValue(QJsonObject{{"gain_margin_db", number(b->gainMarginDb)},
                                      {"phase_margin_deg", number(b->phaseMarginDeg)}});
    };
    return {{"period", number(st.periodSeconds)},
            {"broken_at_x", broken(w.brokenAtX)},
            {"broken_at_y", broken(w.brokenAtY)},
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

const QStringList kCouplingSweepOptions = {"ccc-sweep", "ccc-sweep-kp", "ccc-sweep-ki"};

namespace {

/// A comma-separated list of gains, refused naming @p option.
std::vector<double> gainList(const QString& text, const std::string& option) {
    std::vector<double> out;
    for (const QString& word : text.split(',')) {
        const QString w = word.trimmed();
        bool ok = false;
        const double v = w.toDouble(&ok);
        if (!ok)
            throw InvalidInput(option, "'" + w.toStdString() +
                                           "' is not a number (a comma-separated list of gains, "
                                           "e.g. 0,0.1,1)");
        out.push_back(v);
    }
    return out;
}

QJsonObject sweepCellJson(const CouplingSweepCell& c) {
    const bool ok = c.status == CouplingCellStatus::Ok;
    QJsonObject o{{"kp", number(c.coupling.kp)},
                  {"ki", number(c.coupling.ki)},
                  {"status", couplingCellStatusName(c.status)},
                  {"contour_error", ok ? QJsonValue(QJsonObject{{"max", number(c.maxAbsMm)},
                                                                {"rms", number(c.rmsMm)}})
                                       : QJsonValue()},
                  {"spectral_radius", ok ? number(c.spectralRadius) : QJsonValue()},
                  {"disk_margin", ok ? number(c.diskMargin) : QJsonValue()},
                  {"saturated", ok ? QJsonValue(c.saturated) : QJsonValue()}};
    if (!c.message.text.empty())
        o.insert("message", QString::fromStdString(c.message));
    if (!c.warning.text.empty())
        o.insert("warning", QString::fromStdString(c.warning));
    return o;
}

} // namespace

std::optional<CouplingSweepGrid> parseCouplingSweepGrid(const CliArgs& args) {
    if (!args.flag("ccc-sweep")) {
        for (const char* option : {"ccc-sweep-kp", "ccc-sweep-ki"})
            if (args.has(option))
                throw InvalidInput(CliArgs::field(option), "needs --ccc-sweep");
        return std::nullopt;
    }
    CouplingSweepGrid grid = defaultCouplingSweepGrid();
    if (const auto kp = args.value("ccc-sweep-kp"))
        grid.kpVoltsPerMm = gainList(*kp, "--ccc-sweep-kp");
    if (const auto ki = args.value("ccc-sweep-ki"))
        grid.kiVoltsPerMmSecond = gainList(*ki, "--ccc-sweep-ki");
    try {
        return normalizedCouplingSweepGrid(grid);
    } catch (const InvalidInput& e) {
        if (e.field() == "ki")
            throw InvalidInput("--ccc-sweep-ki", e.reason());
        throw InvalidInput("--ccc-sweep-kp", // "kp", or the pairs of both lists ("grid")
                           e.field() == "grid" ? "with --ccc-sweep-ki: " + e.reason() : e.reason());
    }
}

QJsonObject couplingSweepJson(const CouplingSweepResult& sweep) {
    QJsonArray cells;
    for (const CouplingSweepCell& c : sweep.cells)
        cells.append(sweepCellJson(c));
    QJsonValue best;
    if (sweep.best) {
        QJsonObject b = sweepCellJson(sweep.cells[*sweep.best]);
        b.insert("index", static_cast<qint64>(*sweep.best));
        b.insert("among", sweep.bestBasis == CouplingBestBasis::Robust        ? "robust"
                          : sweep.bestBasis == CouplingBestBasis::WithinLimit ? "within_limit"
                                                                              : "saturating");
        best = b;
    }
    QJsonObject independent = sweepCellJson(sweep.independent);
    for (const char* key : {"kp", "ki", "spectral_radius", "disk_margin"})
        independent.remove(key);
    return {{"estimate", contourEstimateName(sweep.estimate)},
            {"grid", QJsonObject{{"kp", numbers(sweep.grid.kpVoltsPerMm)},
                                 {"ki", numbers(sweep.grid.kiVoltsPerMmSecond)}}},
            {"independent_axes", independent},
            {"cells", cells},
            {"best", best},
            {"rule", kBestCouplingRule},
            {"cancelled", sweep.cancelled}};
}

QJsonValue trajectoryCouplingJson(const Session& session, const CoupledTrajectoryRun& run) {
    QJsonObject o = gains(session.crossCoupling);
    o.insert("line_loop", couplingStabilityJson(run.stability));
    o.insert("contour_error", deviationJson(run.coupledError));
    o.insert("independent_axes",
             QJsonObject{{"contour_error", deviationJson(run.independentError)}});
    return o;
}

} // namespace xyt::cli
