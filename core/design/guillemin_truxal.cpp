// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/guillemin_truxal.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/model/translatable_text.h"

#include <algorithm>
#include <cmath>

namespace xyt {

void ThirdOrderPlant::validate() const {
    requireNonZero(k0, "k0");
    requireFinite(a1, "a1");
    requireFinite(a2, "a2");
}

TransferFunction ThirdOrderPlant::transferFunction() const {
    validate();
    return TransferFunction::fromDescending({k0}, {1.0, a1, a2, 0.0});
}

GtDesign designGuilleminTruxal(const ThirdOrderPlant& plant, double omegaNRadPerSec, double kp) {
    plant.validate();
    requirePositive(omegaNRadPerSec, "wn");
    requirePositive(kp, "kp");
    const double wn = omegaNRadPerSec;
    const double wn2 = wn * wn, wn3 = wn2 * wn, wn4 = wn2 * wn2;
    GtDesign d;
    d.plant = plant;
    d.omegaNRadPerSec = wn;
    d.kp = kp;
    d.f1 = plant.a1 / wn;           // Eq. 17 (Eq. 14 with psi2 = 0)
    d.f2 = plant.a2 / wn2;          // Eq. 18
    d.f3 = kp * plant.k0 / wn3;     // Eq. 15
    d.psi2 = 0.0;                   // Eq. 12 with Eq. 15
    d.psi1 = wn4 / (kp * plant.k0); // Eq. 11
    d.ki = kp * d.psi1;             // Eq. 16
    // omega_n enters as wn^4 (Eq. 11) and as a1/wn, a2/wn^2 (Eq. 17-18): above ~1e77 rad/s wn^4
    // overflows, below ~1e-154 rad/s wn^2 underflows to 0 and f2 overflows. Refuse naming the
    // input instead of handing inf/NaN coefficients on ("den[2]: must be a number, got NaN" was
    // the message for wn = 1e300). What still overflows with a representable wn is kp's doing
    // (kp k0, or wn^4/(kp k0) for a tiny kp).
    const auto representable = [](double v) { return std::isfinite(v) && v != 0.0; };
    if (!representable(wn4) || !std::isfinite(d.f1) || !std::isfinite(d.f2))
        throw InvalidInput(
            "wn", makeDiagnostic("design_gt_wn_out_of_range",
                                 {formatNumber(wn), formatNumber(wn4), formatNumber(d.f2)}));
    if (!std::isfinite(d.f3) || !representable(d.psi1) || !representable(d.ki) ||
        !std::isfinite(d.f3 * wn3)) {
        // kp and k0 enter as their product: name the factor that is out of all proportion (the
        // one farther from 1 in decades), so that a plant gain of 1e308 typed with kp = 460 is
        // not reported as kp's fault.
        const std::vector<Diagnostic> why = {formatNumber(kp * plant.k0), formatNumber(d.psi1),
                                             formatNumber(d.ki)};
        if (std::abs(std::log10(std::abs(plant.k0))) > std::abs(std::log10(kp)))
            throw InvalidInput("k0", makeDiagnostic("design_gt_k0_out_of_range",
                                                    {formatNumber(plant.k0), formatNumber(kp),
                                                     formatNumber(wn), why[0], why[1], why[2]}));
        throw InvalidInput("kp", makeDiagnostic("design_gt_kp_out_of_range",
                                                {formatNumber(kp), formatNumber(plant.k0),
                                                 formatNumber(wn), why[0], why[1], why[2]}));
    }
    d.referenceModel = TransferFunction::fromDescending(
        {d.f3 * wn3, wn4}, {1.0, d.f1 * wn, d.f2 * wn2, d.f3 * wn3, wn4});
    d.controller = TransferFunction::fromDescending({kp, d.ki}, {1.0, 0.0});
    d.loopPlant = plant.transferFunction();
    closeGtLoop(d);
    return d;
}

void closeGtLoop(GtDesign& d) {
    d.openLoop = series(d.controller, d.loopPlant);
    d.closedLoop = feedback(d.openLoop);
    d.closedLoopPoles = d.closedLoop.poles();
    // TransferFunction::isStable on the poles just found (not finding them again).
    d.stable = std::all_of(d.closedLoopPoles.begin(), d.closedLoopPoles.end(),
                           [](std::complex<double> p) { return isStableRoot(p, 0.0); });
}

GtDesign withLoopElements(GtDesign design, const TransferFunction& plantFactor,
                          const TransferFunction& controllerFilter) {
    design.loopPlant = series(design.loopPlant, plantFactor);
    design.controller = series(design.controller, controllerFilter);
    closeGtLoop(design);
    return design;
}

const std::vector<GtPreset>& gtPresets() {
    static const std::vector<GtPreset> presets = {
        {XYT_TRANSLATE_NOOP("xyt::PresetName", "lower-base"),
         "Lower base, Braga et al. Eq. 2 (design of Sec. 3.1)",
         {77.8, 125.3, 3665.0},
         2.0,
         30.0,
         0.001},
        {XYT_TRANSLATE_NOOP("xyt::PresetName", "upper-base"),
         "Upper base, Braga et al. Eq. 1 (design of Sec. 3.2)",
         {24.44, 68.18, 863.0},
         1.0,
         30.0,
         0.001},
    };
    return presets;
}

std::optional<GtPreset> findGtPreset(const std::string& name) {
    for (const auto& p : gtPresets())
        if (p.name == name)
            return p;
    return std::nullopt;
}

} // namespace xyt
