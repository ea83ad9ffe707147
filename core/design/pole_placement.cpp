// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/pole_placement.h"

#include "core/design/diophantine.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/model/translatable_text.h"

#include <cmath>

namespace xyt {

TransferFunction PolePlacementDesign::closedLoop() const {
    return TransferFunction::fromZInverse(closedLoopNum, closedLoopDen, tsSeconds);
}

PolePlacementDesign designPolePlacement(const Polynomial& aTyped, const Polynomial& bTyped,
                                        const Polynomial& t, double tsSeconds) {
    requirePositive(tsSeconds, "ts");
    if (aTyped.isZero() || aTyped.coefficient(0) == 0.0)
        throw InvalidInput("a", makeDiagnostic("design_z0_nonzero"));
    if (bTyped.isZero())
        throw InvalidInput("b", makeDiagnostic("zero"));
    if (bTyped.coefficient(0) != 0.0)
        throw InvalidInput("b", makeDiagnostic("design_b0_not_zero"));
    if (t.isZero() || t.coefficient(0) != 1.0)
        throw InvalidInput("t", makeDiagnostic("design_t0_not_one"));
    for (const auto& r : zInverseRoots(t))
        if (!(std::abs(r) < 1.0))
            throw InvalidInput("t", makeDiagnostic("design_t_root_outside", {formatComplex(r)}));

    PolePlacementDesign d;
    const double a0 = aTyped.coefficient(0);
    d.a = aTyped;
    d.b = bTyped;
    if (a0 != 1.0) {
        d.a = (1.0 / a0) * aTyped;
        d.b = (1.0 / a0) * bTyped;
        d.warnings.push_back(makeDiagnostic("design_a0_normalized", {formatNumber(a0)}));
    }
    d.t = t;
    d.tsSeconds = tsSeconds;
    if (d.b.isZero())
        throw InvalidInput("b", makeDiagnostic("design_b_zero"));
    while (d.delay < d.b.degree() && d.b.coefficient(d.delay) == 0.0)
        ++d.delay;
    const double b1 = d.b(1.0);
    if (std::abs(b1) <= 1e-12 * d.b.maxAbsCoefficient())
        throw InvalidInput("b", makeDiagnostic("design_b1_zero"));

    DiophantineSolution s = solveDiophantine(d.a, d.b, d.t);
    d.f = s.f;
    d.g = s.g;
    d.residual = s.residual;
    d.conditionNumber = s.conditionNumber;
    d.warnings.insert(d.warnings.end(), s.warnings.begin(), s.warnings.end());
    d.kf = d.t(1.0) / b1;
    // B(1) can be nonzero relative to B's coefficients and still so small (B ~ 1e-313 after
    // the division by A(0)) that Kf overflows (found by fuzz_design, regression input
    // tests/fuzz/corpus/fuzz_design/crash-kf-overflow).
    if (!std::isfinite(d.kf))
        throw InvalidInput("b", makeDiagnostic("design_b1_too_small", {formatNumber(b1)}));
    // Finite is not enough: with B scaled down to ~1e-307 (A(0) = -DBL_MAX) Kf and G reach
    // ~1e306, and Kf r or G y overflow within a few samples of a stable loop (found by
    // fuzz_design, regression input tests/fuzz/corpus/fuzz_design/crash-kf-command-overflow).
    // No physical axis needs a gain beyond 1e100: that still leaves 200 decades of headroom for
    // references up to 1e6 mm and the loop's transient growth.
    constexpr double kMaxGain = 1e100;
    if (std::abs(d.kf) > kMaxGain || d.g.maxAbsCoefficient() > kMaxGain ||
        d.f.maxAbsCoefficient() > kMaxGain)
        throw InvalidInput(
            "b", makeDiagnostic("design_b1_negligible", {formatNumber(b1), formatNumber(d.kf)}));
    d.closedLoopNum = d.kf * d.b;
    d.closedLoopDen = d.t;
    if (d.a.degree() > 0)
        d.plantPoles = zInverseRoots(d.a);
    if (d.b.degree() > d.delay)
        d.plantZeros = zInverseRoots(d.b);
    return d;
}

std::vector<PolePlacementPreset> polePlacementPresets() {
    const Polynomial t = Polynomial::fromAscending({1.0, -0.2}); // Eq. 9-10, t1 = -0.2
    return {
        {XYT_TRANSLATE_NOOP("xyt::PresetName", "x-axis"),
         "X axis, ARX231 at 70 ms (Patrick, Ishak and Adnan Eq. 1)",
         Polynomial::fromAscending({1.0, -1.6580, 0.6583}),
         Polynomial::fromAscending({0.0, 0.0421, 0.0628, -0.0454}), t, 0.07},
        {XYT_TRANSLATE_NOOP("xyt::PresetName", "y-axis"),
         "Y axis, ARX231 at 70 ms (Patrick, Ishak and Adnan Eq. 3)",
         Polynomial::fromAscending({1.0, -1.4590, 0.4587}),
         Polynomial::fromAscending({0.0, 0.0352, 0.0599, -0.0067}), t, 0.07},
    };
}

std::optional<PolePlacementPreset> findPolePlacementPreset(const std::string& name) {
    for (auto& p : polePlacementPresets())
        if (p.name == name)
            return p;
    return std::nullopt;
}

} // namespace xyt
