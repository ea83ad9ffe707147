// SPDX-License-Identifier: GPL-3.0-or-later
// The user guide's tutorials followed in the window: the dialogs and views show the figures the
// tutorials state (docs/user-guide/*.md, the step named with each test), from the tutorials'
// own example sessions and commands. A tutorial's number is printed with 3 or 4 significant
// digits: each comparison allows half a unit of its last printed digit.
#include "core/study/robustness.h"
#include "tests/support/built_programs.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance.h"
#include "ui/files/session_file.h"
#include "ui/friction_curve_dialog.h"
#include "ui/main_window.h"
#include "ui/panels/flexible_mode_editor.h"
#include "ui/panels/number_field.h"
#include "ui/pid_tuning_dialog.h"
#include "ui/robustness_view.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// The example session @p name of resources/examples, as File › Open reads it.
Session exampleSession(const QString& name) {
    const files::SessionLoadResult r =
        files::loadSessionFile(QStringLiteral(XYT_SOURCE_DIR) + "/resources/examples/" + name);
    if (!r.ok)
        qFatal("%s: %s", qPrintable(name), qPrintable(r.message()));
    return r.session;
}

} // namespace

class TstTutorials : public QObject {
    Q_OBJECT

private slots:
    void pidTuningDialogGivesTheTutorialsGains();
    void frictionCurveOfTheTutorialsJogLog();
    void klippersRecommendationForTheTutorialsMode();
    void robustnessRunWithTheTutorialsRanges();
};

void TstTutorials::pidTuningDialogGivesTheTutorialsGains() {
    // feedforward.md, steps 9-11, on pid_feedforward.json.
    TuningSession session;
    session.reset(exampleSession("pid_feedforward.json"));
    PidTuningDialog dialog(&session, 0);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QCOMPARE(dialog.windowTitle(), QStringLiteral("Tune the PID of axis X"));
    QCOMPARE(dialog.crossoverField()->value(), 5.0);
    QCOMPARE(dialog.phaseMarginField()->value(), 60.0);
    QCOMPARE(dialog.relayField()->value(), 1.0);
    // "for a PI at 5 rad/s and 60°, P = 0.2227 V/mm and I = 0.4105 V/(mm s)"
    QVERIFY(dialog.proposal(0).ok);
    XYT_COMPARE_NEAR(dialog.proposal(0).p, 0.2227, 0.0, 0.00005);
    XYT_COMPARE_NEAR(dialog.proposal(0).i, 0.4105, 0.0, 0.00005);
    // "a limit cycle of period Tu = 0.1062 s gives P = 2.565, I = 28.97 (Ziegler–Nichols) and
    //  P = 1.781, I = 7.620 (Tyreus–Luyben)"
    QVERIFY2(dialog.relayText().contains(QStringLiteral("0.1062")), qPrintable(dialog.relayText()));
    XYT_COMPARE_NEAR(dialog.proposal(1).p, 2.565, 0.0, 0.0005);
    XYT_COMPARE_NEAR(dialog.proposal(1).i, 28.97, 0.0, 0.005);
    XYT_COMPARE_NEAR(dialog.proposal(2).p, 1.781, 0.0, 0.0005);
    XYT_COMPARE_NEAR(dialog.proposal(2).i, 7.620, 0.0, 0.0005);
    // Step 11: Apply sets P and I in one undo step; Undo returns to the example's gains.
    const double p0 = session.session().axes[0].parameters.at("p");
    const int steps = session.undoStack()->count();
    QTest::mouseClick(dialog.applyButton(0), Qt::LeftButton);
    QCOMPARE(session.undoStack()->count(), steps + 1);
    QCOMPARE(session.session().axes[0].parameters.at("p"), dialog.proposal(0).p);
    QCOMPARE(session.session().axes[0].parameters.at("i"), dialog.proposal(0).i);
    session.undoStack()->undo();
    QCOMPARE(session.session().axes[0].parameters.at("p"), p0);
}

void TstTutorials::frictionCurveOfTheTutorialsJogLog() {
    // friction.md, steps 8-11: the jog log made by the tutorial's command, read in
    // Design › Friction curve from a jog log.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString jog = dir.filePath("jog.csv");
    const test::CliRun made = test::runCli(
        {"excite", "--signal", "jog", "--speeds", "2,4,6,8", "--respond",
         QStringLiteral(XYT_SOURCE_DIR) + "/resources/examples/friction_quadrant_glitches.json",
         "--axis", "x", "--noise-std", "0.001", "--seed", "3", "-o", jog});
    QVERIFY2(made.finished && made.exitCode == 0, made.err.constData());
    QFile log(jog);
    QVERIFY(log.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(log.readAll()).trimmed().count('\n'), 5108); // 5108 samples
    TuningSession session;
    session.reset(exampleSession("friction_quadrant_glitches.json"));
    FrictionCurveDialog dialog(&session);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    dialog.loadFile(jog);
    QVERIFY2(dialog.estimate().has_value(), qPrintable(dialog.resultLabel()->text()));
    // "the Coulomb level 0.0197 V (the truth: 0.02 V) and the slope 0.04717 V per mm/s"
    XYT_COMPARE_NEAR(dialog.estimate()->coulombVolts, 0.0197, 0.0, 0.00005);
    XYT_COMPARE_NEAR(dialog.estimate()->viscousVoltsPerMmPerS, 0.04717, 0.0, 0.000005);
    QVERIFY2(dialog.resultLabel()->text().startsWith(QStringLiteral("Coulomb 0.0196")),
             qPrintable(dialog.resultLabel()->text())); // 0.019696 printed, 0.0197 rounded
    // Step 11: Use for the current axis, one undo step.
    const int steps = session.undoStack()->count();
    QTest::mouseClick(dialog.applyButton(), Qt::LeftButton);
    QCOMPARE(session.undoStack()->count(), steps + 1);
    QCOMPARE(session.session().axes[0].friction.coulombVolts, dialog.estimate()->coulombVolts);
}

void TstTutorials::klippersRecommendationForTheTutorialsMode() {
    // vibration.md, step 9, on vibration_notch_shaper.json (a 15 Hz mode, damping ratio 0.02):
    // ZVD at 17.2 Hz, the shapers designed for the mode's own damping ratio.
    TuningSession session;
    session.reset(exampleSession("vibration_notch_shaper.json"));
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    FlexibleModeEditor* editor = window.flexibleModeEditor();
    QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
    QTest::mouseClick(editor->recommendFromModeButton(), Qt::LeftButton);
    QCOMPARE(editor->adviceText(),
             QStringLiteral("Klipper's choice for the 15 Hz mode: ZVD at 17.2 Hz, 0 % vibration "
                            "left, smoothing 1.056 mm, max accel 400 mm/s²"));
    const ReferenceShaping& shaping = session.session().trajectory.shaping;
    QCOMPARE(shaping.type, ShaperType::Zvd);
    XYT_COMPARE_NEAR(shaping.frequencyHz, 17.2, 0.0, 0.05);
}

void TstTutorials::robustnessRunWithTheTutorialsRanges() {
    // design-space-and-robustness.md, steps 8-10, on braga_relaxed_spec.json.
    TuningSession session;
    session.reset(exampleSession("braga_relaxed_spec.json"));
    RobustnessView view(&session);
    view.resize(1200, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // Step 8: k0, a1, a2, each at 0 %.
    QCOMPARE(view.parameterNames().size(), 3);
    for (const QString& name : {"k0", "a1", "a2"}) {
        QVERIFY(view.rangeBox(name));
        QCOMPARE(view.rangeBox(name)->value(), 0.0);
    }
    // Step 9.
    view.rangeBox("k0")->setValue(20.0);
    view.rangeBox("a1")->setValue(10.0);
    view.rangeBox("a2")->setValue(10.0);
    QCOMPARE(view.samplesBox()->value(), 200);
    QCOMPARE(view.seedBox()->value(), 1);
    QVERIFY(view.cornersBox()->isChecked());
    QSignalSpy finished(&view, &RobustnessView::analysisFinished);
    QTest::mouseClick(view.runButton(), Qt::LeftButton);
    QVERIFY(finished.wait(120000));
    // Step 10.
    QVERIFY2(view.statusText().contains(QStringLiteral(
                 "200 plants + 8 corners: 0 % meet the spec (the nominal does not); 0 unstable.")),
             qPrintable(view.statusText()));
    const RobustnessResult& r = *view.result();
    XYT_COMPARE_NEAR(r.rmse.min, 2.51, 0.0, 0.005);
    XYT_COMPARE_NEAR(r.rmse.p50, 3.23, 0.0, 0.005);
    XYT_COMPARE_NEAR(r.rmse.max, 4.62, 0.0, 0.005);
    // The worst plant is a corner of the box: k0 - 20 %, a1 + 10 %, a2 + 10 % of Braga et al.'s
    // lower base (77.8, 125.3, 3665), so 62.24, 137.83, 4031.5 exactly but for round-off.
    QVERIFY(r.worst.has_value());
    const PlantRun& worst = r.runs[*r.worst];
    QVERIFY(worst.corner);
    XYT_COMPARE_NEAR(worst.values[0], 62.24, 1e-12, 0.0);
    XYT_COMPARE_NEAR(worst.values[1], 137.83, 1e-12, 0.0);
    XYT_COMPARE_NEAR(worst.values[2], 4031.5, 1e-12, 0.0);
    XYT_COMPARE_NEAR(worst.tracking.rmse, 4.62, 0.0, 0.005);
}

QTEST_MAIN(TstTutorials)
#include "tst_tutorials.moc"
