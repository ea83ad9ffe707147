// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_vibration.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/session/session_evaluation.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace xyt {

namespace {

/// 20 log10 |H(j 2 pi f)|.
double magnitudeDb(const TransferFunction& h, double hz) {
    return 20.0 * std::log10(std::abs(h.frequencyResponse(kTwoPi * hz)));
}

} // namespace

std::optional<ResonancePick> measuredModePick(const FrequencyResponseEstimate& measured,
                                              const GtAxisSettings& gt, double minCoherence) {
    try {
        const TransferFunction rigid = gt.plant.transferFunction();
        requirePositive(gt.modelUnitsPerPositionUnit, "model_unit_scale");
        std::vector<double> f, ratio;
        for (std::size_t i = 0; i < measured.frequencyHz.size(); ++i) {
            const double hz = measured.frequencyHz[i];
            if (!(hz > 0.0) || !(measured.coherence[i] >= minCoherence))
                continue;
            const double model =
                std::abs(rigid.frequencyResponse(kTwoPi * hz)) / gt.modelUnitsPerPositionUnit;
            if (model > 0.0 && std::isfinite(model)) {
                f.push_back(hz);
                ratio.push_back(measured.magnitude[i] / model);
            }
        }
        if (f.size() < 3)
            return std::nullopt;
        return pickResonance(f, ratio, ResonanceQuantity::Magnitude);
    } catch (const InvalidInput&) {
        return std::nullopt;
    }
}

MeasuredOpenLoop measuredOpenLoop(const FrequencyResponseEstimate& measured,
                                  const TransferFunction& controller, double modelUnitsPerMm,
                                  const FrequencyResponse& model, double minCoherence) {
    if (controller.tsSeconds() > 0.0)
        throw InvalidInput("controller", makeDiagnostic("session_controller_continuous"));
    requirePositive(modelUnitsPerMm, "model_unit_scale");
    MeasuredOpenLoop out;
    for (std::size_t i = 0; i < measured.frequencyHz.size(); ++i) {
        const double w = kTwoPi * measured.frequencyHz[i];
        if (!(w > 0.0) || !(measured.coherence[i] >= minCoherence) ||
            !(measured.magnitude[i] > 0.0))
            continue;
        const std::complex<double> c = controller.frequencyResponse(w);
        out.omegaRadPerSec.push_back(w);
        out.magnitudeDb.push_back(
            20.0 * std::log10(std::abs(c) * measured.magnitude[i] * modelUnitsPerMm));
        out.phaseDeg.push_back((measured.phaseRad[i] + std::arg(c)) * 180.0 / kPi);
    }
    // One branch with the model: whole turns that bring the first bin within 180 degrees of
    // the model's phase there (interpolated on the model's grid).
    if (!out.phaseDeg.empty() && model.omegaRadPerSec.size() > 1) {
        const auto& mw = model.omegaRadPerSec;
        const double w0 = out.omegaRadPerSec.front();
        const auto it = std::lower_bound(mw.begin(), mw.end(), w0);
        const std::size_t j =
            it == mw.end() ? mw.size() - 1 : static_cast<std::size_t>(it - mw.begin());
        const double reference = model.phaseDeg[j];
        const double turns = std::round((reference - out.phaseDeg.front()) / 360.0);
        for (double& p : out.phaseDeg)
            p += 360.0 * turns;
    }
    return out;
}

AxisVibration analyzeAxisVibration(const Session& session, int axisIndex) {
    AxisVibration out;
    try {
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        if (axis.method == DesignMethod::PolePlacementZpetc)
            throw InvalidInput("method", makeDiagnostic("session_vibration_arx_axis"));
        const GtAxisSettings& gt = axis.gt;
        const TransferFunction rigid = gt.plant.transferFunction();
        const TransferFunction plant = axisPlantTransferFunction(gt, axisIndex);
        const TransferFunction notch = notchTransferFunction(gt, axisIndex);
        out.modeHz = gt.flexibleMode.frequencyHz;
        out.notchHz = gt.notch.centreHz;
        if (session.trajectory.shaping.active()) {
            const ReferenceShaping& s = session.trajectory.shaping;
            try {
                out.shaper = designInputShaper(s.type, s.frequencyHz, s.dampingRatio);
            } catch (const InvalidInput& e) {
                throw InvalidInput("trajectory.shaping." + e.field(), e.reasonDiagnostic());
            }
        }
        // The grid: three decades below the highest frequency of interest up to 3 times it.
        double top = std::max({out.modeHz, out.notchHz, out.shaper ? out.shaper->frequencyHz : 0.0,
                               std::sqrt(std::abs(gt.plant.a2)) / kTwoPi});
        if (!(top > 0.0))
            top = 10.0;
        const double lo = top / 1000.0, hi = 3.0 * top;
        constexpr int kPoints = 600;
        requirePositive(gt.modelUnitsPerPositionUnit, "gt.model_unit_scale");
        const double unitDb = 20.0 * std::log10(gt.modelUnitsPerPositionUnit);
        for (int i = 0; i < kPoints; ++i) {
            const double f = lo * std::pow(hi / lo, static_cast<double>(i) / (kPoints - 1));
            out.frequencyHz.push_back(f);
            out.rigidDb.push_back(magnitudeDb(rigid, f) - unitDb);
            out.plantDb.push_back(magnitudeDb(plant, f) - unitDb);
            if (gt.notch.present())
                out.notchDb.push_back(magnitudeDb(notch, f));
        }
        if (out.shaper) {
            const double at = out.modeHz > 0.0 ? out.modeHz : out.shaper->frequencyHz;
            const double zeta =
                out.modeHz > 0.0 ? gt.flexibleMode.dampingRatio : out.shaper->dampingRatio;
            out.sensitivity = shaperSensitivity(*out.shaper, 401,
                                                2.5 * std::max(at, out.shaper->frequencyHz) /
                                                    out.shaper->frequencyHz);
            out.residualAtModePercent = 100.0 * residualVibration(*out.shaper, at, zeta);
        }
        out.ok = true;
    } catch (const InvalidInput& e) {
        out = {};
        out.error = makeDiagnostic("field_reason", {e.field(), e.reasonDiagnostic()});
    }
    return out;
}

} // namespace xyt
