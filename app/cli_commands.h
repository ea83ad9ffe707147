// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

namespace xyt::cli {

// Each command takes the arguments after its name and returns the process exit code. Invalid
// input is thrown as xyt::InvalidInput (main prints it and exits with 2).
int runGt(const QStringList& args);
int runSimulate(const QStringList& args);
int runReport(const QStringList& args);
int runNew(const QStringList& args);
int runExport(const QStringList& args);
/// The report of a saved session (xytune-cli report SESSION.json).
int runSessionReport(const QString& path);
int runRlocus(const QStringList& args);
int runSweep(const QStringList& args);
int runPp(const QStringList& args);
int runZpetc(const QStringList& args);
int runContour(const QStringList& args);
int runBode(const QStringList& args);
int runMargins(const QStringList& args);
int runRobustness(const QStringList& args);
int runIdentify(const QStringList& args);
int runExcite(const QStringList& args);
/// The power spectral densities of a Klipper accelerometer log (app/cli_psd.cpp).
int runPsd(const QStringList& args);
/// PID gains from a target crossover and phase margin, or from a relay experiment.
int runTune(const QStringList& args);
/// One input shaper: impulses, delay, Klipper's smoothing and max accel, sensitivity curve.
int runShaper(const QStringList& args);

} // namespace xyt::cli
