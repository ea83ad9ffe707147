// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli_args.h"
#include "core/session/contour_run.h"
#include "core/session/coupled_digital_run.h"
#include "core/session/coupled_trajectory.h"
#include "core/session/coupling_sweep.h"
#include "core/session/session.h"

#include <QJsonValue>
#include <QStringList>

#include <optional>

namespace xyt::cli {

/// The cross-coupling's options of `contour`: --ccc-kp, --ccc-ki (both 0: off), --ccc-estimate.
extern const QStringList kCrossCouplingOptions;

/// The coupling the options ask for. @throws InvalidInput "--ccc-kp" / "--ccc-ki" for a gain that
/// is not a finite number >= 0, "--ccc-estimate" unless linear or circular.
CrossCoupling parseCrossCoupling(const CliArgs& args);

/// The coupled loop's stability as JSON: "line_loop" {period, lines_checked, ...}.
QJsonObject couplingStabilityJson(const CouplingStability& stability);

/// A program's "cross_coupling": the gains, the line loop, the independent axes' contour error
/// beside the coupled run and @p digital's (the digital implementations coupled, or null);
/// null when the coupling is off.
QJsonValue programCouplingJson(const Session& session, const ContourRun& run,
                               const DigitalContourRun* digital);

/// A trajectory's "cross_coupling" (the circle preset's): the gains, the line loop, the coupled
/// and the independent axes' contour error.
QJsonValue trajectoryCouplingJson(const Session& session, const CoupledTrajectoryRun& run);

/// The sweep's options of `contour --gcode`: --ccc-sweep (a flag), --ccc-sweep-kp, --ccc-sweep-ki.
extern const QStringList kCouplingSweepOptions;

/**
 * The grid --ccc-sweep asks for: defaultCouplingSweepGrid, with --ccc-sweep-kp / --ccc-sweep-ki
 * ("0,0.1,1": comma-separated gains) in place of either list; none without --ccc-sweep.
 * @throws InvalidInput "--ccc-sweep-kp" / "--ccc-sweep-ki" for a list that is empty, holds a
 *         word that is not a number, or a gain that is not finite or is negative, or one given
 *         without --ccc-sweep; "--ccc-sweep-kp" when the two make more than
 *         kMaxCouplingSweepCells pairs.
 */
std::optional<CouplingSweepGrid> parseCouplingSweepGrid(const CliArgs& args);

/// "cross_coupling_sweep": {estimate, grid {kp, ki}, independent_axes, cells [...], best (a
/// cell with its index and "among": robust, within_limit or saturating), rule, cancelled}; each
/// cell {kp, ki, status, contour_error {max, rms}, spectral_radius, disk_margin, saturated,
/// message, warning}.
QJsonObject couplingSweepJson(const CouplingSweepResult& sweep);

} // namespace xyt::cli
