// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The exported firmware code compiled and run as the firmware tests do: the header as xyt.h
// beside a harness.c in a folder, the project's C compiler (XYT_C_COMPILER) with the firmware
// flags (C99, every warning an error, no contraction of a * b + c into an fma, so the C
// arithmetic is the core's operation for operation), the harness run on an input.

#include "tests/support/built_programs.h"

#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <string>

namespace xyt::test {

/// What every firmware harness starts with: the headers, the generated xyt.h, and the hardware
/// both kinds share: read_number (stdin, exit 2 on bad input), encoder (round half up, as
/// encoderReading) and dac (the generated conversion when the header has a DAC).
inline constexpr const char* kCHarnessCommon = R"(#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "xyt.h"

#define MAX_STATES 64
#define MAX_DELAY 128

static double read_number(void) {
    double v;
    if (scanf("%lf", &v) != 1) {
        fprintf(stderr, "bad input\n");
        exit(2);
    }
    return v;
}

static double encoder(double y, double resolution) {
    return resolution == 0.0 ? y : resolution * floor(y / resolution + 0.5);
}

static double dac(xyt_real u) {
#ifdef XYT_DAC_BITS
    return (double)xyt_dac_volts(xyt_dac_code(u));
#else
    return (double)u;
#endif
}
)";

struct CHarnessRun {
    bool ok = false;
    QString error;     ///< why not, when !ok (the compiler's or the harness' stderr)
    QByteArray output; ///< the harness' stdout
};

/// Writes @p header as @p folder/xyt.h and @p source as harness.c, compiles them with the
/// firmware flags and @p extraFlags (e.g. -DSTEP=...), and runs the harness on @p input.
inline CHarnessRun runCHarness(const QString& folder, const std::string& header,
                               const QByteArray& source, const QByteArray& input,
                               const QStringList& extraFlags = {}) {
    CHarnessRun out;
    QFile h(folder + "/xyt.h"), c(folder + "/harness.c");
    if (!h.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        !c.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        out.error = QStringLiteral("cannot write the harness in ") + folder;
        return out;
    }
    h.write(QByteArray::fromStdString(header));
    c.write(source);
    h.close();
    c.close();
    QProcess compile;
    compile.setWorkingDirectory(folder);
    compile.start(
        QStringLiteral(XYT_C_COMPILER),
        QStringList{"-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-ffp-contract=off"} +
            extraFlags + QStringList{"harness.c", "-o", "harness", "-lm"});
    if (!compile.waitForFinished(120000) || compile.exitCode() != 0) {
        out.error = QStringLiteral("the harness did not compile: ") +
                    QString::fromLocal8Bit(compile.readAllStandardError());
        return out;
    }
    QProcess run;
    run.setWorkingDirectory(folder);
    run.start(folder + "/harness", {});
    run.write(input);
    run.closeWriteChannel();
    if (!run.waitForFinished(120000) || run.exitCode() != 0) {
        out.error = QStringLiteral("the harness failed: ") +
                    QString::fromLocal8Bit(run.readAllStandardError());
        return out;
    }
    out.ok = true;
    out.output = run.readAllStandardOutput();
    return out;
}

} // namespace xyt::test
