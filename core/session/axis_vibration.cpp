// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/axis_vibration.h"

#include "core/model/errors.h"
#include "core/model/math_constants.h"
#include "core/session/session_evaluation.h"

#include <algorithm>
#include <cmath>

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

AxisVibration analyzeAxisVibration(const Session& session, int axisIndex) {
    AxisVibration out;
    try {
        const AxisSettings& axis = session.axes.at(static_cast<std::size_t>(axisIndex));
        if (axis.method == DesignMethod::PolePlacementZpetc)
            throw InvalidInput("method", "a pole-placement axis runs its ARX model, which holds "
                                         "whatever mode its data showed: the flexible mode and "
                                         "the notch apply to continuous plants");
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
                throw InvalidInput("trajectory.shaping." + e.field(), e.reason());
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
        out.error = e.what();
    }
    return out;
}

} // namespace xyt
