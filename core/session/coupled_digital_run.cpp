// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/session/coupled_digital_run.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"
#include "core/session/design_method_module.h"
#include "core/session/session.h"
#include "core/simulation/trajectory.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace xyt {

DigitalContourRun runDigitalProgramContour(const Session& session, const GcodeProgram& program,
                                           const ContourRunOptions& options) {
    FeedProfileOptions profileOptions = options.profile;
    profileOptions.maxSamples = std::min(profileOptions.maxSamples, sampleLimit());
    const FeedProfile p = planFeedProfile(
        program.path, programFeeds(program, options.profile.feedScale), profileOptions);
    std::array<std::unique_ptr<SampledLoopStepper>, 2> loops;
    for (int i = 0; i < 2; ++i)
        loops[static_cast<std::size_t>(i)] =
            designMethodModule(session.axes[static_cast<std::size_t>(i)].method)
                .steppedDigitalPath(session, i, p.t, i == 0 ? p.x : p.y);
    const double period = loops[0]->periodSeconds();
    if (std::abs(period - loops[1]->periodSeconds()) > 1e-9 * period)
        throw InvalidInput(
            "cross_coupling",
            makeDiagnostic("session_coupling_one_digital_period",
                           {formatNumber(period), formatNumber(loops[1]->periodSeconds())}));
    const std::size_t n = std::min(loops[0]->samples(), loops[1]->samples());
    if (loops[0]->samples() != loops[1]->samples())
        throw InvalidInput("cross_coupling", makeDiagnostic("session_digital_runs_samples"));
    const std::vector<bool> rapid = programRapidSegments(program);
    DigitalContourRun out;
    out.periodSeconds = period;
    out.directions = pathCouplingDirections(program.path, p, period, n, &rapid);
    if (session.crossCoupling.active()) {
        out.coupling = runCrossCoupled(*loops[0], *loops[1], out.directions, session.crossCoupling);
    } else {
        for (std::size_t k = 0; k < n; ++k)
            for (auto& loop : loops)
                loop->advance(0.0);
    }
    for (std::size_t i = 0; i < 2; ++i)
        out.axes[i] = loops[i]->takeRun();
    out.contour = contourError(program.path, out.axes[0].result.t, out.axes[0].result.y,
                               out.axes[1].result.y, programContourErrorOptions(program, options));
    return out;
}

} // namespace xyt
