// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli_args.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/session.h"

#include <QJsonValue>
#include <QStringList>

namespace xyt::cli {

/// The cross-coupling's options of `contour`: --ccc-kp, --ccc-ki (both 0: off), --ccc-estimate.
extern const QStringList kCrossCouplingOptions;

/// The coupling the options ask for. @throws InvalidInput "--ccc-kp" / "--ccc-ki" for a gain that
/// is not a finite number >= 0, "--ccc-estimate" unless linear or circular.
CrossCoupling parseCrossCoupling(const CliArgs& args);

/// The coupled loop's stability as JSON: "line_loop" {period, lines_checked, ...}.
QJsonObject couplingStabilityJson(const CouplingStability& stability);

/// A program's "cross_coupling": the gains, the line loop and the independent axes' contour
/// error beside the coupled run; null when the coupling is off.
QJsonValue programCouplingJson(const Session& session, const ContourRun& run);

/// A trajectory's "cross_coupling" (the circle preset's): the gains, the line loop, the coupled
/// and the independent axes' contour error.
QJsonValue trajectoryCouplingJson(const Session& session, const CoupledTrajectoryRun& run);

} // namespace xyt::cli
