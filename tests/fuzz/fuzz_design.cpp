// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: plants and parameters decoded from the fuzz bytes through every design path
// a slider or a pasted coefficient list reaches. Invalid input must be rejected with
// xyt::InvalidInput; any other exception, a crash, a sanitizer report or NaN/inf in a result
// that was returned as valid aborts. Run times are bounded by construction (at most a few
// hundred samples per simulation, a few thousand locus points), so a hang is a real defect.
#include "tests/fuzz/fuzz_support.h"

#include "core/analysis/root_locus.h"
#include "core/design/diophantine.h"
#include "core/design/guillemin_truxal.h"
#include "core/design/pole_placement.h"
#include "core/design/zpetc.h"
#include "core/model/errors.h"
#include "core/simulation/simulation.h"
#include "core/simulation/trajectory.h"
#include "core/simulation/zpetc_tracking.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace {

using xyt::fuzz::FuzzInput;

void requireFiniteRun(const xyt::DiscreteRun& run) {
    XYT_FUZZ_REQUIRE_FINITE(run.y);
    XYT_FUZZ_REQUIRE_FINITE(run.u);
}

bool allStable(const std::vector<std::complex<double>>& roots, double tsSeconds) {
    return std::all_of(roots.begin(), roots.end(),
                       [&](std::complex<double> r) { return xyt::isStableRoot(r, tsSeconds); });
}

/// Braga et al.: Guillemin-Truxal PI design, its closed-loop simulation and its root locus.
void guilleminTruxal(FuzzInput& in) {
    const xyt::ThirdOrderPlant plant{in.number(77.8), in.number(125.3), in.number(3665.0)};
    const double wn = in.number(2.0), kp = in.number(30.0);
    const xyt::GtDesign d = xyt::designGuilleminTruxal(plant, wn, kp);
    XYT_FUZZ_REQUIRE_FINITE(d.f1);
    XYT_FUZZ_REQUIRE_FINITE(d.f2);
    XYT_FUZZ_REQUIRE_FINITE(d.f3);
    XYT_FUZZ_REQUIRE_FINITE(d.psi1);
    XYT_FUZZ_REQUIRE_FINITE(d.psi2);
    XYT_FUZZ_REQUIRE_FINITE(d.kp);
    XYT_FUZZ_REQUIRE_FINITE(d.ki);
    XYT_FUZZ_REQUIRE_FINITE(d.referenceModel);
    XYT_FUZZ_REQUIRE_FINITE(d.controller);
    XYT_FUZZ_REQUIRE_FINITE(d.openLoop);
    XYT_FUZZ_REQUIRE_FINITE(d.closedLoop);
    XYT_FUZZ_REQUIRE_FINITE(d.closedLoopPoles);

    // A cubic move sampled at most 400 times.
    const double dt = in.within(1e-4, 0.5);
    const double tf = dt * in.integer(1, 400);
    const xyt::CubicTrajectory cubic(0.0, in.within(-1000.0, 1000.0), 0.0, tf);
    const auto reference =
        xyt::sampled([&](double t) { return cubic.position(t); }, xyt::sampleTimes(tf, dt));
    xyt::LoopSimulationOptions options;
    options.dtSeconds = dt;
    options.umaxVolts =
        in.byte() % 2 ? in.within(1e-3, 100.0) : std::numeric_limits<double>::infinity();
    options.modelUnitsPerPositionUnit = in.byte() % 2 ? 0.001 : 1.0;
    const auto plantTf = plant.transferFunction();
    const auto run = xyt::simulateLoop(plantTf, d.controller, reference, options);
    XYT_FUZZ_REQUIRE(run.y.size() == reference.size());
    // A stable linear loop stays finite over a bounded time. With saturation the plant runs open
    // loop while clipped, so finiteness is only promised when the plant itself is not unstable.
    const auto plantPoles = plantTf.poles();
    const bool plantNotUnstable =
        std::all_of(plantPoles.begin(), plantPoles.end(),
                    [](std::complex<double> p) { return p.real() <= 0.0; });
    if (d.stable && (!std::isfinite(options.umaxVolts) || plantNotUnstable)) {
        XYT_FUZZ_REQUIRE_FINITE(run.y);
        XYT_FUZZ_REQUIRE_FINITE(run.u);
        XYT_FUZZ_REQUIRE_FINITE(run.e);
    }

    xyt::RootLocusOptions locusOptions;
    locusOptions.maxPoints = in.integer(10, 2000);
    const xyt::RootLocus locus = xyt::rootLocus(d.openLoop, locusOptions);
    XYT_FUZZ_REQUIRE_FINITE(locus.gains);
    for (const auto& branch : locus.branches)
        XYT_FUZZ_REQUIRE_FINITE(branch.roots);
}

xyt::Polynomial polynomial(const std::vector<double>& c, const char* field) {
    return xyt::Polynomial::fromAscending(c, field);
}

/// Patrick, Ishak and Adnan: the Diophantine equation, pole placement, ZPETC and the three tracking
/// runs.
void polePlacement(FuzzInput& in) {
    const auto a = polynomial(in.coefficients(1, 6), "a");
    std::vector<double> bc(static_cast<std::size_t>(in.integer(1, 3)), 0.0); // the delay
    for (double c : in.coefficients(1, 6))
        bc.push_back(c);
    if (in.byte() % 8 == 0)
        bc.front() = in.number(); // sometimes no delay: must be rejected, not crash
    const auto b = polynomial(bc, "b");
    std::vector<double> tc{1.0};
    for (double c : in.coefficients(0, 5))
        tc.push_back(c);
    const auto t = polynomial(tc, "t");

    if (in.byte() % 4 == 0) {
        const xyt::DiophantineSolution s = xyt::solveDiophantine(a, b, t);
        XYT_FUZZ_REQUIRE_FINITE(s.f);
        XYT_FUZZ_REQUIRE_FINITE(s.g);
        XYT_FUZZ_REQUIRE_FINITE(s.residual);
        return;
    }
    const double ts = in.number(0.07);
    const xyt::PolePlacementDesign loop = xyt::designPolePlacement(a, b, t, ts);
    XYT_FUZZ_REQUIRE_FINITE(loop.f);
    XYT_FUZZ_REQUIRE_FINITE(loop.g);
    XYT_FUZZ_REQUIRE_FINITE(loop.kf);
    XYT_FUZZ_REQUIRE_FINITE(loop.residual);
    XYT_FUZZ_REQUIRE_FINITE(loop.closedLoopNum);
    XYT_FUZZ_REQUIRE_FINITE(loop.closedLoopDen);
    XYT_FUZZ_REQUIRE_FINITE(loop.plantPoles);
    XYT_FUZZ_REQUIRE_FINITE(loop.plantZeros);

    const double margin = in.byte() % 2 ? xyt::kDefaultZpetcMargin : in.number(0.05);
    const xyt::ZpetcDesign zpetc = xyt::designZpetc(loop, margin);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.bPlus);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.bMinus);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.gainFactor);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.feedforwardNum);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.feedforwardDen);
    XYT_FUZZ_REQUIRE_FINITE(zpetc.overallFir);

    const auto response =
        xyt::zpetcFrequencyResponse(loop, zpetc, xyt::nyquistLogGrid(ts, in.integer(2, 50)));
    XYT_FUZZ_REQUIRE_FINITE(response.phaseWithFfRad);

    xyt::Sinusoid reference;
    reference.amplitude = in.within(0.0, 1000.0);
    reference.omegaRadPerSec = in.within(1e-3, 10.0);
    const double duration = ts * in.integer(0, 300);
    const auto start =
        in.byte() % 2 ? xyt::StartCondition::AtReference : xyt::StartCondition::AtOrigin;
    const xyt::ZpetcTrackingRun run =
        xyt::runZpetcTracking(loop, zpetc, reference, duration, start);
    // A stable closed loop (roots of T) and a stable feedforward (B+ holds only cancelled zeros)
    // keep every signal finite over a bounded time.
    if (allStable(loop.closedLoop().poles(), ts)) {
        requireFiniteRun(run.feedbackOnly);
        requireFiniteRun(run.withZpetc);
        requireFiniteRun(run.trajectoryZpetc);
        XYT_FUZZ_REQUIRE_FINITE(run.rmseWithoutFf);
        XYT_FUZZ_REQUIRE_FINITE(run.rmseWithFf);
    }
}

/// A root locus of an arbitrary proper loop N/D, continuous or discrete.
void rootLocusOfRandomLoop(FuzzInput& in) {
    const auto den = polynomial(in.coefficients(1, 7), "den");
    const auto num = polynomial(in.coefficients(1, 7), "num");
    const double ts = in.byte() % 2 ? 0.0 : in.number(0.1);
    xyt::RootLocusOptions options;
    options.maxPoints = in.integer(10, 2000);
    if (in.byte() % 4 == 0)
        options.kMax = in.number(100.0);
    if (in.byte() % 4 == 0)
        options.maxStepFraction = in.number(0.01);
    const xyt::RootLocus locus = xyt::rootLocus(num, den, ts, options);
    XYT_FUZZ_REQUIRE_FINITE(locus.gains);
    XYT_FUZZ_REQUIRE(locus.gains.size() <= static_cast<std::size_t>(options.maxPoints) + 2);
    for (const auto& branch : locus.branches) {
        XYT_FUZZ_REQUIRE_FINITE(branch.roots);
        XYT_FUZZ_REQUIRE(branch.roots.size() == locus.gains.size());
    }
    XYT_FUZZ_REQUIRE_FINITE(locus.poles);
    XYT_FUZZ_REQUIRE_FINITE(locus.zeros);
    if (locus.asymptotes.count > 0)
        XYT_FUZZ_REQUIRE_FINITE(locus.asymptotes.centroid);
    for (const auto& f : locus.breakaways) {
        XYT_FUZZ_REQUIRE_FINITE(f.point);
        XYT_FUZZ_REQUIRE_FINITE(f.gain);
    }
    for (const auto& f : locus.crossings) {
        XYT_FUZZ_REQUIRE_FINITE(f.point);
        XYT_FUZZ_REQUIRE_FINITE(f.gain);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzInput in(data, size);
    try {
        switch (in.byte() % 3) {
        case 0:
            guilleminTruxal(in);
            break;
        case 1:
            polePlacement(in);
            break;
        default:
            rootLocusOfRandomLoop(in);
            break;
        }
    } catch (const xyt::InvalidInput&) {
        // Rejected input, named: the expected outcome for nonsense.
    }
    return 0;
}
