// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/zpetc.h"

#include "core/design/diophantine.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <cmath>
#include <numbers>

namespace xyt {

ZpetcDesign designZpetc(const PolePlacementDesign& loop, double margin) {
    requireFinite(margin, "margin");
    if (margin < 0.0 || margin >= 1.0)
        throw InvalidInput("margin", makeDiagnostic("in_zero_one_open_right"));
    ZpetcDesign z;
    z.delay = loop.delay;
    z.margin = margin;

    // Bc(z^-1) = Kf B(z^-1) / z^-d: drop the delay's leading zeros.
    const auto& c = loop.closedLoopNum.ascending();
    const Polynomial bc =
        Polynomial::fromAscending(std::vector<double>(c.begin() + loop.delay, c.end()), "b");
    std::vector<std::complex<double>> inside, outside;
    if (bc.degree() > 0) {
        for (const auto& root : zInverseRoots(bc)) {
            const bool cancel = std::abs(root) < 1.0 - margin;
            z.zeros.push_back({root, cancel});
            (cancel ? inside : outside).push_back(root);
        }
    }
    // prod (1 - z_i z^-1): the monic-in-z factor reversed into powers of z^-1. Conjugate zeros
    // have equal modulus, so both land on the same side and each factor stays real.
    z.bPlus = Polynomial::fromRoots(inside).reversed(static_cast<int>(inside.size()));
    z.bMinus = Polynomial::fromRoots(outside, bc.coefficient(0))
                   .reversed(static_cast<int>(outside.size()));
    const double bMinusAtOne = z.bMinus(1.0);
    if (std::abs(bMinusAtOne) <= 1e-12 * z.bMinus.maxAbsCoefficient())
        throw InvalidInput("b", makeDiagnostic("design_zpetc_b_minus_zero"));
    z.gainFactor = bMinusAtOne * bMinusAtOne;
    // The relative check above passes for a B- whose coefficients are all tiny (B-(1) ~ 2e-307):
    // the square then underflows to a subnormal or 0, and 1/[B-(1)]^2 to inf, so the filter
    // would hold NaN. Refuse a gain that is not a normal double with a finite inverse.
    if (!std::isnormal(z.gainFactor) || !std::isfinite(1.0 / z.gainFactor))
        throw InvalidInput("b", makeDiagnostic("design_zpetc_b_minus_out_of_range",
                                               {std::to_string(bMinusAtOne)}));
    const int s = z.bMinus.degree();
    z.previewSteps = z.delay + s;
    const Polynomial bMinusStar = z.bMinus.reversed(s);
    z.feedforwardNum = loop.closedLoopDen * bMinusStar;
    z.feedforwardDen = z.gainFactor * z.bPlus;
    z.overallFir = (1.0 / z.gainFactor) * (z.bMinus * bMinusStar);
    for (const Polynomial* p : {&z.feedforwardNum, &z.feedforwardDen, &z.overallFir})
        for (const double c : p->ascending())
            if (!std::isfinite(c))
                throw InvalidInput("b", makeDiagnostic("design_zpetc_overflow"));
    return z;
}

ZpetcFrequencyResponse zpetcFrequencyResponse(const PolePlacementDesign& loop,
                                              const ZpetcDesign& zpetc,
                                              const std::vector<double>& omegaRadPerSec) {
    ZpetcFrequencyResponse out;
    for (const double w : omegaRadPerSec) {
        requireFinite(w, "omega");
        if (w < 0.0)
            throw InvalidInput("omega", makeDiagnostic("not_negative"));
        const double theta = w * loop.tsSeconds;
        const std::complex<double> q = std::polar(1.0, -theta); // z^-1 on the unit circle
        const std::complex<double> closed = loop.closedLoopNum(q) / loop.closedLoopDen(q);
        const std::complex<double> preview = std::polar(1.0, theta * zpetc.previewSteps);
        const std::complex<double> withFf =
            closed * preview * zpetc.feedforwardNum(q) / zpetc.feedforwardDen(q);
        // A pole of the loop or of the feedforward on the unit circle at this frequency (or a
        // product beyond double range): no finite response exists there, so the frequency is
        // left out rather than given as NaN.
        if (!std::isfinite(closed.real()) || !std::isfinite(closed.imag()) ||
            !std::isfinite(withFf.real()) || !std::isfinite(withFf.imag())) {
            out.omittedOmegaRadPerSec.push_back(w);
            continue;
        }
        out.omegaRadPerSec.push_back(w);
        out.gainWithoutFf.push_back(std::abs(closed));
        out.gainWithFf.push_back(std::abs(withFf));
        out.phaseWithoutFfRad.push_back(std::arg(closed));
        out.phaseWithFfRad.push_back(std::arg(withFf));
    }
    return out;
}

std::vector<double> nyquistLogGrid(double tsSeconds, int points) {
    requirePositive(tsSeconds, "ts");
    if (points < 2)
        throw InvalidInput("points", makeDiagnostic("at_least", {"2"}));
    const double nyquist = std::numbers::pi / tsSeconds;
    std::vector<double> w(static_cast<std::size_t>(points));
    for (int i = 0; i < points; ++i)
        w[static_cast<std::size_t>(i)] =
            nyquist * std::pow(10.0, -3.0 + 3.0 * i / static_cast<double>(points - 1));
    return w;
}

} // namespace xyt
