// SPDX-License-Identifier: GPL-3.0-or-later
// The friction compensation in the exports (core/session/friction_export.h): the C header's
// xyt_<id>_friction_ff compiled with the project's C compiler (-ffp-contract=off, as the
// firmware loop test) equals the core's frictionCompensationVolts bit for bit at velocities
// across the band, at its edges and beyond; the LinuxCNC export gives the same numbers for a
// separate component; an axis without compensation writes nothing.
#include "core/session/export_text.h"
#include "core/session/linuxcnc_export.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "tests/support/c_harness.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>
#include <vector>

using namespace xyt;

namespace {

constexpr const char* kHarness = R"(#include <stdio.h>
#include "xyt.h"
int main(void) {
    double v;
    while (scanf("%lf", &v) == 1)
        printf("%.17g\n", (double)xyt_x_friction_ff((xyt_real)v));
    return 0;
}
)";

Session compensatedSession() {
    Session s = Session::paperDefault();
    for (AxisSettings& a : s.axes)
        a.method = DesignMethod::PidFeedforward;
    AxisSettings& x = s.axes[0];
    x.friction.coulombVolts = 0.0213;
    x.friction.viscousVoltsPerMmPerS = 0.0071;
    x.frictionCompensation.percent = 87.5;
    x.frictionCompensation.bandMmPerS = 0.05;
    return s;
}

const std::vector<double> kVelocities{-30.0, -0.05,  -0.0371, -1e-9, 0.0, 1e-9,
                                      0.01,  0.0499, 0.05,    0.051, 2.5, 100.0};

} // namespace

class TstFrictionExport : public QObject {
    Q_OBJECT

private slots:
    void theFirmwareFunctionIsTheCoresBitForBit() {
        const Session s = compensatedSession();
        const SessionEvaluation e = evaluateSession(s);
        const std::string header = exportCHeader(s, e, {});
        QVERIFY(header.find("xyt_x_friction_ff") != std::string::npos);
        QVERIFY(header.find("xyt_y_friction_ff") == std::string::npos); // y has none
        QTemporaryDir dir;
        QByteArray input;
        char buf[40];
        for (double v : kVelocities) {
            std::snprintf(buf, sizeof buf, "%.17g\n", v);
            input += buf;
        }
        const test::CHarnessRun run = test::runCHarness(dir.path(), header, kHarness, input);
        QVERIFY2(run.ok, qPrintable(run.error));
        const QList<QByteArray> lines = run.output.trimmed().split('\n');
        QCOMPARE(lines.size(), static_cast<qsizetype>(kVelocities.size()));
        for (std::size_t i = 0; i < kVelocities.size(); ++i) {
            const double expected = frictionCompensationVolts(
                s.axes[0].friction, s.axes[0].frictionCompensation, kVelocities[i]);
            QCOMPARE(lines[static_cast<qsizetype>(i)].toDouble(), expected);
        }
    }

    void linuxCncGetsTheValuesForAComponent() {
        const Session s = compensatedSession();
        const std::string hal = exportLinuxCnc(s, evaluateSession(s));
        const auto at = hal.find("# Friction compensation of joint 0");
        QVERIFY(at != std::string::npos);
        QVERIFY(hal.find("# Friction compensation of joint 1") == std::string::npos);
        // The numbers as %.17g writes them (exact round trip), read back.
        const QString note = QString::fromStdString(hal.substr(at));
        const auto value = [&](const QString& name) {
            const QRegularExpressionMatch m =
                QRegularExpression(name + " = ([-+0-9.eE]+)").match(note);
            return m.hasMatch() ? m.captured(1).toDouble() : -1.0;
        };
        QCOMPARE(value("S"), 0.875);
        QCOMPARE(value("Fc"), 0.0213);
        QCOMPARE(value("bv"), 0.0071);
        QCOMPARE(value("w"), 0.05);
    }
};

QTEST_APPLESS_MAIN(TstFrictionExport)
#include "tst_friction_export.moc"
