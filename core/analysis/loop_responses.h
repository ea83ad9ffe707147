// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/analysis/frequency_response.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/transfer_function.h"

#include <vector>

namespace xyt {

/**
 * The transfer functions of one axis loop, all built from the polynomials (no cancellation):
 * open loop L, sensitivity S = 1/(1 + L), complementary sensitivity T = L/(1 + L) and input
 * sensitivity u/r (the actuator signal per unit reference).
 */
struct LoopTransferFunctions {
    TransferFunction openLoop;                 ///< L
    TransferFunction sensitivity;              ///< S = 1/(1 + L)
    TransferFunction complementarySensitivity; ///< T = L/(1 + L)
    TransferFunction inputSensitivity;         ///< u per r
};

/**
 * Guillemin-Truxal axis (Braga et al., unity feedback, G_c = (kp s + ki)/s ahead of
 * G = k0/(s^3 + a1 s^2 + a2 s)): with G_c = N_c/D_c and G = N/D,
 * L = N_c N/(D_c D), S = D_c D/(D_c D + N_c N), T = N_c N/(D_c D + N_c N),
 * u/r = G_c S = N_c D/(D_c D + N_c N). L has the double pole at s = 0.
 */
LoopTransferFunctions gtLoopTransferFunctions(const GtDesign& design);

/// Any continuous controller G_c ahead of a continuous plant G in unity feedback, with the
/// polynomials of gtLoopTransferFunctions (which is this loop for the PI it designs).
LoopTransferFunctions unityFeedbackLoop(const TransferFunction& controller,
                                        const TransferFunction& plant);

/**
 * Pole-placement (RST) axis (Patrick, Ishak and Adnan Fig. 9): F u = K_f r - G y, A y = B u, all in
 * z^-1. The loop broken at the plant input is L = B G/(A F); with P = A F + B G (= T of the design
 * up to the Diophantine residual, which is kept here so that T = L/(1 + L) exactly): S = A F/P, T =
 * B G/P, u/r = K_f A/P. Discrete in z with the design's Ts.
 */
LoopTransferFunctions rstLoopTransferFunctions(const PolePlacementDesign& design);

/**
 * Tracking from the desired output y_d to the output y of a pole-placement axis:
 * without feedforward y/y_d = K_f B/P (r = y_d drives the loop), and with the ZPETC ahead of it
 * y/y_d = z^p N_ff(z^-1)/D_ff(z^-1) K_f B/P (Patrick, Ishak and Adnan Eq. 6 and Fig. 8: zero phase
 * at every frequency, unity DC gain, a gain that falls away from 1 towards pi/Ts). The second has
 * more zeros than poles (the preview): a non-causal transfer function, for evaluation only.
 */
struct TrackingTransferFunctions {
    TransferFunction withoutFeedforward;
    TransferFunction withZpetc;
};
TrackingTransferFunctions zpetcTrackingTransferFunctions(const PolePlacementDesign& design,
                                                         const ZpetcDesign& zpetc);

/// The frequency responses of LoopTransferFunctions on one grid.
struct LoopFrequencyResponses {
    FrequencyResponse openLoop;
    FrequencyResponse sensitivity;
    FrequencyResponse complementarySensitivity;
    FrequencyResponse inputSensitivity;
};
/// @throws InvalidInput "omega" as frequencyResponse.
LoopFrequencyResponses loopFrequencyResponses(const LoopTransferFunctions& loop,
                                              const std::vector<double>& omegaRadPerSec);

/// The tracking responses with and without ZPETC on one grid (discrete, up to pi/Ts).
struct TrackingFrequencyResponses {
    FrequencyResponse withoutFeedforward;
    /// With the feedforward (ZPETC: phase ~ 0 from round-off, magnitude <= 0 dB; a PID's
    /// command feedforward from the exact model: 0 dB and 0 deg).
    FrequencyResponse withZpetc;
};
/// @throws InvalidInput "omega" as frequencyResponse.
TrackingFrequencyResponses
zpetcTrackingFrequencyResponses(const PolePlacementDesign& design, const ZpetcDesign& zpetc,
                                const std::vector<double>& omegaRadPerSec);

} // namespace xyt
