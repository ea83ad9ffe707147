// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QJsonArray>
#include <QTest>

class TstCliGt : public QObject {
    Q_OBJECT
private slots:
    void gtLowerBaseKeys();
    void badArgumentExitsWithTwo();
};

void TstCliGt::gtLowerBaseKeys() {
    const auto run = xyt::test::runCli({"gt", "--preset", "lower-base", "--wn", "2", "--kp", "30"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    for (const char* key : {"f1", "f2", "f3", "psi1", "psi2", "kp", "ki", "reference_model",
                            "controller", "closed_loop"})
        QVERIFY2(o.contains(key), key);
    // Paper 000 Eq. 20: ki = 30 * 2^4 / (30 * 77.8) = 0.205656 (printed 0.20566, 5 digits).
    XYT_COMPARE_NEAR(o["ki"].toDouble(), 16.0 / 77.8, 1e-12, 0.0);
    QCOMPARE(o["closed_loop"].toObject()["poles"].toArray().size(), 4);
}

void TstCliGt::badArgumentExitsWithTwo() {
    const auto run = xyt::test::runCli({"gt", "--preset", "lower-base", "--wn", "-1"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("--wn"), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.out.isEmpty());
}

QTEST_APPLESS_MAIN(TstCliGt)
#include "tst_cli_gt.moc"
