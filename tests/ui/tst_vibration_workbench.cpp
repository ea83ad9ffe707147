// SPDX-License-Identifier: GPL-3.0-or-later
// The flexible mode, the notch and the input shaper in the workbench, through the real widgets
// offscreen: the Mode fold beside the method box (fields, one undo step per edit, refusals at
// the field, the notch and the shaper designed from the mode, disabled where they do not apply),
// the Vibration view (what it draws against the core's AxisVibration and the resonant pair's
// closed-form peak) and the time plot's run without the shaper (the evaluation's own run).
#include "core/session/axis_vibration.h"
#include "tests/support/gui_checks.h"
#include "ui/main_window.h"
#include "ui/panels/flexible_mode_editor.h"
#include "ui/panels/number_field.h"
#include "ui/plots/time_response_plot.h"
#include "ui/plots/vibration_plot.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>
#include <qcustomplot.h>

#include <cmath>

using namespace xyt;
using namespace xyt::ui;

class TstVibrationWorkbench : public QObject {
    Q_OBJECT

private slots:
    void init() {
        QCoreApplication::setOrganizationName("xytune-tests");
        window_.reset(); // before its session
        session_ = std::make_unique<TuningSession>();
        window_ = std::make_unique<MainWindow>(session_.get());
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    void theFoldSetsTheModeAndTheViewDrawsIt() {
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        QToolButton* fold = editor->foldButton();
        QVERIFY(fold->isVisible() && !editor->isVisible());
        QTest::mouseClick(fold, Qt::LeftButton);
        QVERIFY(editor->isVisible());
        const int steps = session_->undoStack()->count();
        test::typeInto(editor->field("frequency"), "20");
        test::typeInto(editor->field("damping"), "0.05");
        const FlexibleMode& m = session_->session().axes[0].gt.flexibleMode;
        QCOMPARE(m.frequencyHz, 20.0);
        QCOMPARE(m.dampingRatio, 0.05);
        QCOMPARE(session_->undoStack()->count(), steps + 2);
        QVERIFY(fold->toolTip().contains(QStringLiteral("mode 20 Hz")));
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
        VibrationPlot* plot = window_->vibrationPlot();
        QVERIFY(plot->hasResult());
        QVERIFY(plot->plantGraph()->visible() && plot->plantGraph()->dataCount() > 100);
        QVERIFY(plot->markerTexts().contains(QStringLiteral("mode 20 Hz")));
        // The drawn peak above the rigid plant: 1 / (2 zeta sqrt(1 - zeta^2)) to the grid's
        // resolution (0.1 dB, tst_vibration_session).
        double peak = -1e300;
        auto rigid = plot->rigidGraph()->data()->constBegin();
        for (auto it = plot->plantGraph()->data()->constBegin();
             it != plot->plantGraph()->data()->constEnd(); ++it, ++rigid)
            peak = std::max(peak, it->value - rigid->value);
        const double expected = 20.0 * std::log10(1.0 / (2.0 * 0.05 * std::sqrt(1.0 - 0.0025)));
        QVERIFY2(std::abs(peak - expected) < 0.1, qPrintable(QString::number(peak)));
        // Undo goes back to the rigid table, and the view says so.
        session_->undoStack()->undo();
        session_->undoStack()->undo();
        QCOMPARE(session_->session().axes[0].gt.flexibleMode.frequencyHz, 0.0);
        QCOMPARE(editor->field("frequency")->value(), 0.0);
        QVERIFY(!plot->plantGraph()->visible());
        QVERIFY(plot->noticeText().contains(QStringLiteral("rigid")));
    }

    void theNotchAndTheShaperComeFromTheMode() {
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        test::typeInto(editor->field("frequency"), "20");
        test::typeInto(editor->field("damping"), "0.05");
        QTest::mouseClick(editor->notchFromModeButton(), Qt::LeftButton);
        const NotchFilter& n = session_->session().axes[0].gt.notch;
        QCOMPARE(n.centreHz, 20.0);
        QVERIFY(std::abs(n.depthDb - 20.0) < 1e-12); // 20 log10(1 / (2 * 0.05))
        QCOMPARE(editor->field("centre")->value(), 20.0);
        // The loop the views draw holds the mode and the notch: C G R N, of order 4 + 2 + 2.
        QCOMPARE(session_->frequencyAnalysis(0).loop.openLoop.den().degree(), 8);
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
        QVERIFY(window_->vibrationPlot()->notchGraph()->visible());
        // The shaper at the mode: ZV at 20 Hz, damping 0.05, on the trajectory (both axes).
        QTest::mouseClick(editor->shaperAtModeButton(), Qt::LeftButton);
        const ReferenceShaping& sh = session_->session().trajectory.shaping;
        QVERIFY(sh.active());
        QCOMPARE(sh.type, ShaperType::Zv);
        QCOMPARE(sh.frequencyHz, 20.0);
        QCOMPARE(sh.dampingRatio, 0.05);
        const AxisEvaluation& e = session_->axisEvaluation(0);
        QVERIFY(e.ok && e.shaping);
        VibrationPlot* plot = window_->vibrationPlot();
        QVERIFY(plot->sensitivityGraph()->dataCount() > 100);
        QVERIFY(plot->markerTexts().contains(QStringLiteral("0.0 % left at 20 Hz")));
        QVERIFY2(plot->summaryText().startsWith(QStringLiteral("ZV shaper: 2 impulses")),
                 qPrintable(plot->summaryText()));
        // The time plot draws the run without the shaper: the evaluation's, sample for sample.
        window_->lowerTabs()->setCurrentWidget(window_->timePlot());
        TimeResponsePlot* time = window_->timePlot();
        QVERIFY(time->unshapedOutputGraph()->visible());
        QVERIFY(test::sameSignal(time->unshapedOutputGraph()->data(), e.shaping->unshapedRun.t,
                                 e.shaping->unshapedRun.y));
        // Another type from the box, one undo step; "none" switches shaping off.
        const int steps = session_->undoStack()->count();
        editor->shaperTypeBox()->setCurrentIndex(editor->shaperTypeBox()->findText("EI"));
        emit editor->shaperTypeBox()->activated(editor->shaperTypeBox()->currentIndex());
        QCOMPARE(session_->session().trajectory.shaping.type, ShaperType::Ei);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        editor->shaperTypeBox()->setCurrentIndex(0);
        emit editor->shaperTypeBox()->activated(0);
        QVERIFY(!session_->session().trajectory.shaping.active());
        QVERIFY(!time->unshapedOutputGraph()->visible());
    }

    void refusedValuesStayAtTheField() {
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        test::typeInto(editor->field("frequency"), "20");
        const Session before = session_->session();
        test::typeInto(editor->field("damping"), "1.5");
        QVERIFY(editor->field("damping")->hasError() ||
                editor->field("damping")->toolTip().contains(QStringLiteral("[0, 1)")));
        QVERIFY(session_->session() == before);
        test::typeInto(editor->field("damping"), "0.1");
        test::typeInto(editor->field("anti_resonance"), "30");
        QCOMPARE(session_->session().axes[0].gt.flexibleMode.antiResonanceHz, 0.0); // above fr
        QVERIFY(editor->field("anti_resonance")->toolTip().contains(QStringLiteral("below")));
        // The notch above the controller's Nyquist frequency (controller_ts 10 ms: 50 Hz) is a
        // digital refusal the evaluation names; the continuous loop still runs.
        test::typeInto(editor->field("anti_resonance"), "0");
        test::typeInto(editor->field("centre"), "60");
        test::typeInto(editor->field("width"), "10");
        QCOMPARE(session_->session().axes[0].gt.notch.centreHz, 60.0);
        const AxisEvaluation& e = session_->axisEvaluation(0);
        QVERIFY(e.ok && !e.digital);
    }

    void aPolePlacementAxisSaysWhyNot() {
        session_->setMethod(1, DesignMethod::PolePlacementZpetc);
        session_->setCurrentAxis(1);
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        QVERIFY(!editor->field("frequency")->isEnabled());
        QVERIFY(!editor->notchFromModeButton()->isEnabled());
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
        QVERIFY(!window_->vibrationPlot()->hasResult());
        QVERIFY(window_->vibrationPlot()->noticeText().contains(QStringLiteral("ARX")));
        // A PID + feedforward axis has the mode but no notch stage.
        session_->setMethod(1, DesignMethod::PidFeedforward);
        QVERIFY(editor->field("frequency")->isEnabled());
        QVERIFY(!editor->field("centre")->isEnabled());
    }

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TstVibrationWorkbench)
#include "tst_vibration_workbench.moc"
