// SPDX-License-Identifier: GPL-3.0-or-later
// The flexible mode, the notch and the input shaper in the workbench, through the real widgets
// offscreen: the Mode fold beside the method box (fields, one undo step per edit, refusals at
// the field, the notch and the shaper designed from the mode, disabled where they do not apply),
// the Vibration view (what it draws against the core's AxisVibration and the resonant pair's
// closed-form peak) and the time plot's run without the shaper (the evaluation's own run).
#include "core/identification/accelerometer_log.h"
#include "core/identification/spectral_estimate.h"
#include "core/session/axis_vibration.h"
#include "core/session/shaper_advice.h"
#include "tests/support/gui_checks.h"
#include "ui/main_window.h"
#include "ui/panels/flexible_mode_editor.h"
#include "ui/panels/number_field.h"
#include "ui/plots/bode_plot.h"
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
#include <random>

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
        // The Bode view draws L without the notch beside L, named with its phase margin.
        window_->upperTabs()->setCurrentWidget(window_->bodePlot());
        QCPGraph* withoutNotch =
            window_->bodePlot()->magnitudeGraph(QStringLiteral("L without the notch"));
        QVERIFY(withoutNotch && withoutNotch->dataCount() > 0);
        QVERIFY(withoutNotch->name().contains(QStringLiteral("PM")));
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
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

    /// Klipper's recommendation from the mode and from a log: the shaper the core's
    /// recommendShaper picks on the same spectrum, applied as one undo step; a bad log is
    /// reported and changes nothing.
    void theRecommendationIsTheCoresAndApplies() {
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        test::typeInto(editor->field("frequency"), "47");
        test::typeInto(editor->field("damping"), "0.04");
        const int steps = session_->undoStack()->count();
        QTest::mouseClick(editor->recommendFromModeButton(), Qt::LeftButton);
        ShaperRecommendationOptions options;
        options.dampingRatio = 0.04;
        const ShaperFit model =
            recommendShaper(flexibleModeSpectrum({47.0, 0.04, 0.0, 0.02}), options).best();
        const ReferenceShaping& sh = session_->session().trajectory.shaping;
        QCOMPARE(sh.type, model.shaper.type);
        QCOMPARE(sh.frequencyHz, model.shaper.frequencyHz);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        QVERIFY2(
            editor->adviceText().startsWith(QStringLiteral("Klipper's choice for the 47 Hz mode")),
            qPrintable(editor->adviceText()));
        const QString log = QStringLiteral(XYT_TEST_DATA_DIR) + "/klipper_accel_raw.csv";
        editor->recommendFromLog(log);
        const ShaperFit measured =
            recommendShaper(
                accelerometerShaperSpectrum(
                    accelerometerSpectra(readAccelerometerLogFile(log.toStdString()), 200.0),
                    "sum"))
                .best();
        QCOMPARE(session_->session().trajectory.shaping.type, measured.shaper.type);
        QCOMPARE(session_->session().trajectory.shaping.frequencyHz, measured.shaper.frequencyHz);
        QVERIFY(editor->adviceText().contains(QStringLiteral("klipper_accel_raw.csv")));
        const Session before = session_->session();
        editor->recommendFromLog(QStringLiteral(XYT_TEST_DATA_DIR) + "/README.md");
        QVERIFY(editor->adviceText().startsWith(QStringLiteral("No recommendation:")));
        QVERIFY(session_->session() == before);
    }

    /// Measurements over the model: a frequency-response estimate set for x is drawn where its
    /// coherence is at least kMinCoherence, as 20 log10 |H| (mm/V), point for point; the
    /// accelerometer log read for a recommendation is drawn as its PSD sum in dB re its peak.
    void measurementsAreDrawnOverTheModel() {
        std::mt19937_64 random(20261126);
        std::normal_distribution<double> normal;
        const double ts = 0.001;
        std::vector<double> u(20000), y(u.size());
        double state = 0.0;
        for (std::size_t k = 0; k < u.size(); ++k) {
            u[k] = normal(random);
            y[k] = state + 0.01 * normal(random);
            state = 0.95 * state + 0.05 * u[k]; // a first-order lag, 1 mm/V at DC
        }
        auto measured = std::make_shared<TuningSession::MeasuredResponse>();
        measured->estimate = estimateFrequencyResponse(u, y, ts);
        measured->source = QStringLiteral("simulated");
        const FrequencyResponseEstimate expected = measured->estimate;
        session_->setMeasuredResponse(0, measured);
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
        QCPGraph* drawn = window_->vibrationPlot()->measuredGraph();
        QVERIFY(drawn->visible());
        int k = 0;
        auto it = drawn->data()->constBegin();
        for (std::size_t i = 0; i < expected.frequencyHz.size(); ++i) {
            if (!(expected.frequencyHz[i] > 0.0 && expected.magnitude[i] > 0.0 &&
                  expected.coherence[i] >= VibrationPlot::kMinCoherence))
                continue;
            QVERIFY(it != drawn->data()->constEnd());
            QCOMPARE(it->key, expected.frequencyHz[i]);
            QCOMPARE(it->value, 20.0 * std::log10(expected.magnitude[i]));
            ++it;
            ++k;
        }
        QVERIFY(k > 10);
        QVERIFY(it == drawn->data()->constEnd());
        // The Bode view draws the loop it makes with the axis' controller: one dot per drawn bin.
        window_->upperTabs()->setCurrentWidget(window_->bodePlot());
        QCPGraph* loop = window_->bodePlot()->measuredMagnitudeGraph();
        QVERIFY(loop && loop->visible());
        QCOMPARE(loop->dataCount(), k);
        window_->upperTabs()->setCurrentWidget(window_->vibrationPlot());
        session_->setMeasuredResponse(0, nullptr);
        QVERIFY(!drawn->visible());
        FlexibleModeEditor* editor = window_->flexibleModeEditor();
        editor->recommendFromLog(QStringLiteral(XYT_TEST_DATA_DIR) + "/klipper_accel_raw.csv");
        QCPGraph* psd = window_->vibrationPlot()->accelerationGraph();
        QVERIFY(psd->visible() && psd->dataCount() > 10);
        double top = -1e300;
        for (auto p = psd->data()->constBegin(); p != psd->data()->constEnd(); ++p)
            top = std::max(top, p->value);
        QVERIFY(std::abs(top) < 1e-12); // dB re its own peak
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
