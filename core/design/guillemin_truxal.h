// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/transfer_function.h"

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace xyt {

/// G(s) = k0 / (s^3 + a1 s^2 + a2 s), Braga et al. Eq. 9 (a DC motor base with an integrator).
struct ThirdOrderPlant {
    double k0 = 0.0;
    double a1 = 0.0;
    double a2 = 0.0;

    /// @throws InvalidInput "k0" (finite, nonzero), "a1", "a2" (finite).
    void validate() const;
    TransferFunction transferFunction() const;
    friend bool operator==(const ThirdOrderPlant&, const ThirdOrderPlant&) = default;
};

/**
 * The Guillemin-Truxal PI design of Braga et al. With the controller G_c = k (s + psi1)/(s + psi2)
 * (Eq. 8) the closed loop is Eq. 10; matching it to the type-2 reference model
 *   G_R(s) = (f3 wn^3 s + wn^4) / (s^4 + f1 wn s^3 + f2 wn^2 s^2 + f3 wn^3 s + wn^4)
 * (Eq. 7, whose s^2 the paper misprints as s) gives, by Eq. 11-18:
 *   psi2 = 0, f1 = a1/wn, f2 = a2/wn^2, f3 = kp k0/wn^3, psi1 = wn^4/(kp k0), ki = kp psi1,
 * so G_c(s) = kp + ki/s (Eq. 16) and the closed loop equals G_R exactly.
 */
struct GtDesign {
    ThirdOrderPlant plant;
    double omegaNRadPerSec = 0.0;
    double f1 = 0.0, f2 = 0.0, f3 = 0.0;
    double psi1 = 0.0, psi2 = 0.0;
    double kp = 0.0, ki = 0.0;
    TransferFunction referenceModel; ///< G_R(s), Eq. 7
    /// (kp s + ki)/s, Eq. 16; times the controller's filter (a notch) after withLoopElements
    TransferFunction controller;
    /// The plant the loop is closed around: plant's own G, or G times the factors
    /// withLoopElements adds (a flexible mode the design does not know of)
    TransferFunction loopPlant;
    TransferFunction openLoop;   ///< G_c G
    TransferFunction closedLoop; ///< feedback(G_c G), which equals G_R on the design's own plant
    std::vector<std::complex<double>> closedLoopPoles;
    bool stable = false; ///< an unstable result is returned, not thrown: a slider can reach it
};

/// @throws InvalidInput "wn" or "kp" unless finite and > 0, "wn" when wn^4 or a2/wn^2 is not a
///         finite nonzero double (wn beyond ~1e77 or below ~1e-154 rad/s), "kp" or "k0" when
///         kp k0, psi1 or ki overflows or vanishes (the factor farther from 1 in decades), and
///         the plant's fields.
GtDesign designGuilleminTruxal(const ThirdOrderPlant& plant, double omegaNRadPerSec, double kp);

/// openLoop, closedLoop, its poles and stable from @p design's controller and loopPlant.
void closeGtLoop(GtDesign& design);

/**
 * The design, made on its third-order plant, closed around that plant times @p plantFactor (a
 * flexible mode, core/model/flexible_mode.h) with its controller followed by @p
 * controllerFilter (a notch, core/design/notch_filter.h): what the table really does with the
 * controller the method designed. The design's own figures (f1..f3, psi, kp, ki, referenceModel)
 * are unchanged; closedLoop no longer equals referenceModel.
 */
GtDesign withLoopElements(GtDesign design, const TransferFunction& plantFactor,
                          const TransferFunction& controllerFilter);

/// A named plant and design of Braga et al.
struct GtPreset {
    std::string name;
    std::string description;
    ThirdOrderPlant plant;
    double omegaNRadPerSec;
    double kp;
    /// Model output units per trajectory unit: the paper's models are in metres and its
    /// trajectories in millimetres (see LoopSimulationOptions::modelUnitsPerPositionUnit).
    double modelUnitsPerPositionUnit;
};

/// "lower-base" (Eq. 2: k0 77.8, a1 125.3, a2 3665; wn 2, kp 30) and "upper-base" (Eq. 1:
/// k0 24.44, a1 68.18, a2 863; wn 1, kp 30).
const std::vector<GtPreset>& gtPresets();
std::optional<GtPreset> findGtPreset(const std::string& name);

} // namespace xyt
