// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"

#include <QJsonArray>
#include <QTest>

#include <cmath>

class TstCliRlocus : public QObject {
    Q_OBJECT
private slots:
    void continuousTypeOneLoop();
    void discretePaperXAxisLoop();
    void gtPresetDesignPoint();
    void badInputExitsWithTwo_data();
    void badInputExitsWithTwo();
};

void TstCliRlocus::continuousTypeOneLoop() {
    const auto run = xyt::test::runCli({"rlocus", "--num", "1", "--den", "1 3 2 0"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    QVERIFY(!run.out.contains("nan") && !run.out.contains("inf"));
    const QJsonObject o = run.json();
    const QJsonArray branches = o["branches"].toArray();
    QCOMPARE(branches.size(), 3);
    for (const QJsonValue& b : branches) {
        const QJsonArray first = b.toArray().first().toArray();
        QCOMPARE(first.size(), 3);                            // [k, re, im]
        XYT_COMPARE_NEAR(first[0].toDouble(), 0.0, 0.0, 0.0); // starts at K = 0
    }
    // Closed forms for 1/(s(s+1)(s+2)): centroid -1, angles 60/180/300; breakaway
    // -1 + 1/sqrt(3) at K = 2/(3 sqrt 3); Routh crossing K = 6 at omega = sqrt(2). JSON prints
    // shortest round-trip doubles: the core's 1e-10 accuracy is what is checked.
    const QJsonObject asym = o["asymptotes"].toObject();
    XYT_COMPARE_NEAR(asym["centroid"].toDouble(), -1.0, 1e-14, 0.0);
    QCOMPARE(asym["angles_deg"].toArray().size(), 3);
    const QJsonArray br = o["breakaway"].toArray().first().toArray(); // [re, im, k]
    XYT_COMPARE_NEAR(br[0].toDouble(), -1.0 + 1.0 / std::sqrt(3.0), 1e-10, 0.0);
    XYT_COMPARE_NEAR(br[2].toDouble(), 2.0 / (3.0 * std::sqrt(3.0)), 1e-10, 0.0);
    const QJsonArray cr = o["crossings"].toArray().first().toArray(); // [k, re, im]
    XYT_COMPARE_NEAR(cr[0].toDouble(), 6.0, 1e-10, 0.0);
    XYT_COMPARE_NEAR(std::abs(cr[2].toDouble()), std::sqrt(2.0), 1e-10, 0.0);
}

void TstCliRlocus::discretePaperXAxisLoop() {
    // Patrick, Ishak and Adnan Eq. 1, typed as in the paper (ascending powers of z^-1), Ts 0.07 s.
    // Unit-circle crossing where 1 - a0^2 - a1 + a0 a2 = 0 (Jury/Schur-Cohn for the cubic A z + K
    // B), the root of 0.3417 + 0.0124732 K - 0.00397250 K^2 (see tst_root_locus).
    const auto run = xyt::test::runCli({"rlocus", "--num", "0 0.0421 0.0628 -0.0454", "--den",
                                        "1 -1.6580 0.6583", "--ts", "0.07", "--kmax", "50"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    QCOMPARE(o["ts"].toDouble(), 0.07);
    QCOMPARE(o["branches"].toArray().size(), 3);
    const QJsonArray last = o["branches"].toArray().first().toArray().last().toArray();
    XYT_COMPARE_NEAR(last[0].toDouble(), 50.0, 0.0, 0.0); // --kmax ends the trace exactly
    const double qa = -(0.0454 * 0.0454 + 0.0454 * 0.0421), qb = 0.0454 * 1.658 - 0.0628,
                 qc = 1.0 - 0.6583;
    const double k = (-qb - std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
    const QJsonArray cr = o["crossings"].toArray().first().toArray();
    XYT_COMPARE_NEAR(cr[0].toDouble(), k, 1e-9, 0.0);
    const double re = cr[1].toDouble(), im = cr[2].toDouble();
    XYT_COMPARE_NEAR(std::hypot(re, im), 1.0, 1e-12, 0.0); // on the unit circle
}

void TstCliRlocus::gtPresetDesignPoint() {
    const auto run =
        xyt::test::runCli({"rlocus", "--gt-preset", "lower-base", "--wn", "2", "--kp", "30"});
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = run.json();
    QCOMPARE(o["branches"].toArray().size(), 4);
    QCOMPARE(o["design_gain"].toDouble(), 1.0);
    // The design's closed-loop poles: the roots of G_R's denominator (Eq. 19:
    // s^4 + 125.3 s^3 + 3665 s^2 + 2334 s + 16); their product is wn^4 = 16 (Vieta).
    const QJsonArray poles = o["design_poles"].toArray();
    QCOMPARE(poles.size(), 4);
    double product = 1.0;
    for (const QJsonValue& p : poles) {
        XYT_COMPARE_NEAR(p.toArray()[1].toDouble(), 0.0, 0.0, 1e-9); // all real for this design
        product *= p.toArray()[0].toDouble();
    }
    XYT_COMPARE_NEAR(product, 16.0, 1e-9, 0.0);
    // Routh gain margin: K = (a1 a2 kp - a1^2 ki)/(k0 kp^2), ki = 16/77.8.
    const double a1 = 125.3, a2 = 3665.0, k0 = 77.8, kp = 30.0, ki = 16.0 / 77.8;
    const QJsonArray cr = o["crossings"].toArray().first().toArray();
    XYT_COMPARE_NEAR(cr[0].toDouble(), (a1 * a2 * kp - a1 * a1 * ki) / (k0 * kp * kp), 1e-9, 0.0);
}

void TstCliRlocus::badInputExitsWithTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("argument");
    QTest::newRow("empty num") << QStringList{"--num", "", "--den", "1 1"} << "--num";
    QTest::newRow("text in den") << QStringList{"--num", "1", "--den", "1 x"} << "--den";
    QTest::newRow("improper") << QStringList{"--num", "1 2 3", "--den", "1 1"} << "--num";
    QTest::newRow("constant den") << QStringList{"--num", "1", "--den", "5"} << "--den";
    QTest::newRow("missing den") << QStringList{"--num", "1"} << "--den";
    QTest::newRow("negative ts") << QStringList{"--num", "1", "--den", "1 0.5", "--ts", "-1"}
                                 << "--ts";
    QTest::newRow("z^0 of den zero")
        << QStringList{"--num", "1", "--den", "0 1", "--ts", "0.1"} << "--den";
    QTest::newRow("kmax zero") << QStringList{"--num", "1", "--den", "1 1", "--kmax", "0"}
                               << "--kmax";
    QTest::newRow("unknown preset") << QStringList{"--gt-preset", "middle"} << "--gt-preset";
    QTest::newRow("wn negative") << QStringList{"--gt-preset", "lower-base", "--wn", "-2"}
                                 << "--wn";
    QTest::newRow("num with preset")
        << QStringList{"--gt-preset", "lower-base", "--num", "1"} << "--num";
    QTest::newRow("unknown option")
        << QStringList{"--num", "1", "--den", "1 1", "--bogus", "1"} << "--bogus";
}

void TstCliRlocus::badInputExitsWithTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, argument);
    const auto run = xyt::test::runCli(QStringList{"rlocus"} + args);
    QVERIFY(run.finished);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(argument.toUtf8()), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.out.isEmpty());
}

QTEST_APPLESS_MAIN(TstCliRlocus)
#include "tst_cli_rlocus.moc"
