// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/loop_responses.h"

namespace xyt {

LoopTransferFunctions gtLoopTransferFunctions(const GtDesign& design) {
    return unityFeedbackLoop(design.controller, design.loopPlant);
}

LoopTransferFunctions unityFeedbackLoop(const TransferFunction& controller,
                                        const TransferFunction& plant) {
    const Polynomial& nc = controller.num();
    const Polynomial& dc = controller.den();
    const Polynomial& ng = plant.num();
    const Polynomial& dg = plant.den();
    const Polynomial open = dc * dg;
    const Polynomial closed = open + nc * ng;
    LoopTransferFunctions out;
    out.openLoop = TransferFunction(nc * ng, open);
    out.sensitivity = TransferFunction(open, closed);
    out.complementarySensitivity = TransferFunction(nc * ng, closed);
    out.inputSensitivity = TransferFunction(nc * dg, closed);
    return out;
}

LoopTransferFunctions rstLoopTransferFunctions(const PolePlacementDesign& design) {
    const Polynomial af = design.a * design.f;
    const Polynomial bg = design.b * design.g;
    const Polynomial p = af + bg;
    const double ts = design.tsSeconds;
    LoopTransferFunctions out;
    out.openLoop = TransferFunction::fromZInverse(bg, af, ts);
    out.sensitivity = TransferFunction::fromZInverse(af, p, ts);
    out.complementarySensitivity = TransferFunction::fromZInverse(bg, p, ts);
    out.inputSensitivity = TransferFunction::fromZInverse(design.kf * design.a, p, ts);
    return out;
}

TrackingTransferFunctions zpetcTrackingTransferFunctions(const PolePlacementDesign& design,
                                                         const ZpetcDesign& zpetc) {
    const Polynomial p = design.a * design.f + design.b * design.g;
    TrackingTransferFunctions out;
    out.withoutFeedforward =
        TransferFunction::fromZInverse(design.kf * design.b, p, design.tsSeconds);
    // z^p N_ff(z^-1)/D_ff(z^-1) = z^(p - a + b) N~(z)/D~(z), N~ and D~ the reversed polynomials
    // (a = deg N_ff, b = deg D_ff; D_ff(0) != 0, so D~ has degree b).
    const int a = zpetc.feedforwardNum.degree();
    const int b = zpetc.feedforwardDen.degree();
    const int e = zpetc.previewSteps - a + b;
    Polynomial num = zpetc.feedforwardNum.reversed(a);
    Polynomial den = zpetc.feedforwardDen.reversed(b);
    std::vector<double> shift(static_cast<std::size_t>(std::abs(e)) + 1, 0.0);
    shift.back() = 1.0;
    const Polynomial zPower = Polynomial::fromAscending(shift);
    if (e >= 0)
        num = num * zPower;
    else
        den = den * zPower;
    out.withZpetc = series(TransferFunction(num, den, design.tsSeconds), out.withoutFeedforward);
    return out;
}

LoopFrequencyResponses loopFrequencyResponses(const LoopTransferFunctions& loop,
                                              const std::vector<double>& omegaRadPerSec) {
    return {frequencyResponse(loop.openLoop, omegaRadPerSec),
            frequencyResponse(loop.sensitivity, omegaRadPerSec),
            frequencyResponse(loop.complementarySensitivity, omegaRadPerSec),
            frequencyResponse(loop.inputSensitivity, omegaRadPerSec)};
}

TrackingFrequencyResponses
zpetcTrackingFrequencyResponses(const PolePlacementDesign& design, const ZpetcDesign& zpetc,
                                const std::vector<double>& omegaRadPerSec) {
    const TrackingTransferFunctions tf = zpetcTrackingTransferFunctions(design, zpetc);
    return {frequencyResponse(tf.withoutFeedforward, omegaRadPerSec),
            frequencyResponse(tf.withZpetc, omegaRadPerSec)};
}

} // namespace xyt
