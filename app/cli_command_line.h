// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

namespace xyt::cli {

/**
 * Runs xytune-cli with @p args (the arguments after the program name): the command's output on
 * stdout (JSON; report: text; new, export: the path written), bad input as one line on stderr
 * naming the argument. Returns the exit code: 0 success, 2 invalid input or a file that could
 * not be read or written, 1 an internal error. Needs a Q(Core)Application.
 */
int runCommandLine(QStringList args);

} // namespace xyt::cli
