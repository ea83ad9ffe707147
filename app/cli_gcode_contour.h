// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli_args.h"

#include <QStringList>

namespace xyt::cli {

/// The options of `contour --gcode FILE`.
extern const QStringList kGcodeContourOptions;

/**
 * xytune-cli contour --gcode FILE: reads the program, plans its feed profile, runs both axes of
 * the default session (Braga et al.'s Guillemin-Truxal designs: x the lower base, y the upper
 * base) along it and prints the contour error, the ISO 230-4 figures of a single full circle
 * and the warnings as JSON; --csv writes the time series.
 */
int runGcodeContour(const CliArgs& args);

} // namespace xyt::cli
