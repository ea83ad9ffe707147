// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Runs the built xytune-cli (path from the generated built_programs.h) and captures what
// it printed, for the CLI contract tests.

#include "tests/support/built_programs.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace xyt::test {

struct CliRun {
    int exitCode = -1;
    bool finished = false; ///< false when it crashed or did not finish within the time bound
    QByteArray out;
    QByteArray err;
    /// stdout parsed as a JSON object (empty when it is not one).
    QJsonObject json() const { return QJsonDocument::fromJson(out).object(); }
};

/// @param environment added to the test's own (e.g. XYT_TEST_FAIL_WRITE=write).
inline CliRun runCli(const QStringList& args, int timeoutMs = 60000,
                     const QStringList& environment = {}) {
    QProcess p;
    if (!environment.isEmpty()) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const QString& e : environment)
            env.insert(e.section('=', 0, 0), e.section('=', 1));
        p.setProcessEnvironment(env);
    }
    p.start(QStringLiteral(XYT_CLI_PATH), args);
    CliRun r;
    if (!p.waitForStarted(10000))
        return r;
    r.finished = p.waitForFinished(timeoutMs) && p.exitStatus() == QProcess::NormalExit;
    if (!r.finished)
        p.kill();
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

} // namespace xyt::test
