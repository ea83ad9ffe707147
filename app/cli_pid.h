// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// simulate's run of the PID with command feedforward (LinuxCNC's pid) through a session, the
// path taken by --method pid-ff and --ff-from-model (cli_pid.cpp).

#include "app/cli_args.h"

#include <QSet>
#include <QStringList>

namespace xyt::cli {

/// The PID's gains and limits, each a number (--p ... --derivative-filter).
extern const QStringList kPidGainOptions;
/// The PID's switches, which take no value.
extern const QStringList kPidFlags;
/// Every flag of simulate (for CliArgs::parse).
QSet<QString> simulateFlags();

/// Whether simulate runs through the session: --method pid-ff or --ff-from-model. Refuses an
/// unknown --method naming it.
bool simulatesThroughSession(const CliArgs& args);

/**
 * simulate --method pid-ff, or any design with --ff-from-model: axis 0 of Session::paperDefault()
 * set from the arguments (axis 1 a copy, so that an automatic duration is this axis' own) and
 * evaluated by evaluateAxis, the run the workbench makes. A refusal of the core names the option
 * ("axes[0].parameters.max_error_i" -> --max-error-i).
 */
int simulateThroughSession(const CliArgs& args);

} // namespace xyt::cli
