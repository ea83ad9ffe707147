// SPDX-License-Identifier: GPL-3.0-or-later
// xytune-cli: the headless face of XY Tune. JSON on stdout (report: text; new, export: the path
// written); bad input -> one line on stderr naming the argument, exit code 2.
#include "app/cli_args.h"
#include "app/cli_command_line.h"

#include <QCoreApplication>

int main(int argc, char* argv[]) {
    // The arguments decoded losslessly (file names may be any bytes), read before Qt sees argv.
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << xyt::cli::argumentText(argv[i]);
    QCoreApplication app(argc, argv);
    return xyt::cli::runCommandLine(args);
}
