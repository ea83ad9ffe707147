// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/simulation/stick_slip.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/number_format.h"

#include <algorithm>
#include <cstddef>

namespace xyt {

namespace {

/// The sign of the reference's change from sample k to k + 1 (0 at rest or at the end).
int referenceDirection(const std::vector<double>& r, std::size_t k) {
    if (k + 1 >= r.size())
        return 0;
    return r[k + 1] > r[k] ? 1 : (r[k + 1] < r[k] ? -1 : 0);
}

} // namespace

std::optional<StickSlipFindings> stickSlipFindings(const SimulationResult& run) {
    const std::vector<std::int8_t>& s = run.sliding;
    const std::size_t n = std::min(s.size(), run.r.size());
    if (n == 0)
        return std::nullopt;
    StickSlipFindings out;
    // The rest: from the last sample at which the reference still changed.
    std::size_t restStart = n;
    while (restStart > 1 && run.r[restStart - 1] == run.r[restStart - 2])
        --restStart;
    for (std::size_t k = 1; k < restStart; ++k) {
        if (!(s[k - 1] != 0 && s[k] == 0))
            continue;
        std::size_t end = k;
        while (end < n && s[end] == 0)
            ++end;
        const int before = referenceDirection(run.r, k - 1);
        bool sameWay = before != 0 && end < restStart;
        for (std::size_t j = k; sameWay && j <= end && j < restStart; ++j)
            sameWay = referenceDirection(run.r, j) == before;
        if (sameWay) {
            if (out.stopsDuringMove == 0)
                out.firstStopSeconds = run.t[k];
            ++out.stopsDuringMove;
        }
    }
    if (restStart < n) {
        double lo = run.y[restStart], hi = lo;
        for (std::size_t k = restStart + 1; k < n; ++k) {
            if (s[k - 1] == 0 && s[k] != 0)
                ++out.breakawaysAtRest;
            lo = std::min(lo, run.y[k]);
            hi = std::max(hi, run.y[k]);
        }
        out.restPeakToPeakMm = hi - lo;
    }
    return out;
}

std::vector<Diagnostic> stickSlipWarnings(const StickSlipFindings& f, StickSlipRun run) {
    std::vector<Diagnostic> out;
    const auto timesDiagnostic = [](int n) {
        return n == 1 ? makeDiagnostic("sim_once")
                      : makeDiagnostic("sim_times", {std::to_string(n)});
    };
    const auto ofRunDiagnostic = [run](Diagnostic finding) {
        return run == StickSlipRun::digitalImplementation
                   ? makeDiagnostic("sim_digital_implementation_finding", {std::move(finding)})
                   : finding;
    };
    if (f.stopsDuringMove > 0)
        out.push_back(ofRunDiagnostic(
            makeDiagnostic("sim_stick_slip_during_move", {timesDiagnostic(f.stopsDuringMove),
                                                          formatNumber(f.firstStopSeconds, 4)})));
    if (f.breakawaysAtRest >= 2)
        out.push_back(ofRunDiagnostic(
            makeDiagnostic("sim_hunting_at_rest", {timesDiagnostic(f.breakawaysAtRest),
                                                   formatNumber(1000.0 * f.restPeakToPeakMm, 3)})));
    return out;
}

} // namespace xyt
