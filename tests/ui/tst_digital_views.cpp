// SPDX-License-Identifier: GPL-3.0-or-later
// The digital implementation in the workbench: the time plots overlay the loop the
// firmware runs, the metrics panel shows its figures (marked where they differ from the
// design's), the pole-zero map shows its z-plane poles, and the implementation fields edit the
// session with field-level errors. Assertions on the presenter's values and the plots' data;
// the expected values are the core's (AxisEvaluation::digital).
#include "tests/support/tolerance.h"
#include "ui/main_window.h"
#include "ui/panels/implementation_editor.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/tuning_session.h"

#include <QAction>
#include <QComboBox>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>

#include <qcustomplot.h>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// Braga et al.'s session on a move that saturates (600 mm in 10 s), with a coarse encoder, a
/// 10-bit DAC, one sample of delay and no anti-windup: the digital loop differs visibly.
Session quantizedSession() {
    Session s = Session::paperDefault();
    s.trajectory.tfSeconds = 10.0;
    s.trajectory.durationSeconds = 60.0;
    s.implementation.encoderResolutionMm = 0.05;
    s.implementation.dacBits = 10;
    s.implementation.delaySamples = 1;
    s.implementation.antiWindup = AntiWindup::None;
    return s;
}

} // namespace

class TstDigitalViews : public QObject {
    Q_OBJECT
private slots:
    void init();
    void timePlotOverlaysTheDigitalRun();
    void overlayFollowsTheViewAction();
    void metricsShowTheDigitalFigures();
    void poleZeroMapShowsTheDigitalLoopInTheZPlane();
    void implementationFieldsEditTheSession();
    void invalidImplementationValueStaysAtTheField();

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstDigitalViews::init() {
    QCoreApplication::setOrganizationName("xytune-tests");
    session_ = std::make_unique<TuningSession>();
    session_->reset(quantizedSession());
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstDigitalViews::timePlotOverlaysTheDigitalRun() {
    window_->lowerTabs()->setCurrentWidget(window_->timePlot());
    const AxisEvaluation& e = session_->axisEvaluation(0);
    QVERIFY(e.digital != nullptr);
    const SampledDataRun& run = e.digital->run;
    TimeResponsePlot* plot = window_->timePlot();
    QVERIFY(plot->digitalOutputGraph()->visible());
    // The graph holds the core's samples (decimated only beyond a few thousand points: 6001 here
    // are drawn min/max per bucket, so the first and last samples and the extremes are exact).
    QCPGraphDataContainer& y = *plot->digitalOutputGraph()->data();
    QVERIFY(!y.isEmpty());
    QCOMPARE(y.constBegin()->key, run.result.t.front());
    QCOMPARE((y.constEnd() - 1)->value, run.result.y.back());
    double top = -1e300;
    for (auto it = y.constBegin(); it != y.constEnd(); ++it)
        top = std::max(top, it->value);
    QCOMPARE(top, *std::max_element(run.result.y.begin(), run.result.y.end()));
    // The command is the one the plant received: DAC levels, held between samples.
    QCOMPARE(plot->digitalControlGraph()->lineStyle(), QCPGraph::lsStepLeft);
    const double lsb = 2.0 * 2.5 / 1024.0;
    for (auto it = plot->digitalControlGraph()->data()->constBegin();
         it != plot->digitalControlGraph()->data()->constEnd(); ++it)
        QVERIFY2(std::abs(it->value / lsb - std::round(it->value / lsb)) < 1e-9,
                 qPrintable(QString::number(it->value)));
    QVERIFY(plot->positionLegend()->hasItemWithPlottable(plot->digitalOutputGraph()));
}

void TstDigitalViews::overlayFollowsTheViewAction() {
    QAction* action = window_->digitalOverlayAction();
    QVERIFY(action->isCheckable() && action->isChecked());
    action->trigger();
    TimeResponsePlot* plot = window_->timePlot();
    QVERIFY(!plot->digitalOutputGraph()->visible());
    QVERIFY(plot->digitalOutputGraph()->data()->isEmpty());
    QVERIFY(!plot->positionLegend()->hasItemWithPlottable(plot->digitalOutputGraph()));
    action->trigger();
    QVERIFY(plot->digitalOutputGraph()->visible());
    QVERIFY(!plot->digitalOutputGraph()->data()->isEmpty());
}

void TstDigitalViews::metricsShowTheDigitalFigures() {
    QTableWidget* table = window_->metricsPanel()->table();
    QCOMPARE(table->item(MetricsPanel::DigitalGroup, 0)->text(), QString("Digital implementation"));
    for (int c = 0; c < 2; ++c) {
        const AxisEvaluation& e = session_->axisEvaluation(c);
        QCOMPARE(table->item(MetricsPanel::DigitalRmse, c)->text(),
                 displayNumber(e.digital->metrics.rmse));
        QCOMPARE(table->item(MetricsPanel::DigitalMaxError, c)->text(),
                 displayNumber(e.digital->metrics.maxAbsError));
        QCOMPARE(table->item(MetricsPanel::DigitalDamping, c)->text(),
                 displayNumber(e.digital->minDamping, 3));
        QVERIFY(table->item(MetricsPanel::DigitalRmse, c)
                    ->toolTip()
                    .startsWith("design " + displayNumber(e.metrics.rmse)));
    }
    // Where the digital figure differs from the design's by more than 5 %, it is marked; the
    // ideal implementation at 10 ms on the paper's slow cubic differs by far less.
    Session ideal = Session::paperDefault();
    session_->apply(ideal, "ideal");
    const AxisEvaluation& e = session_->axisEvaluation(0);
    QVERIFY(std::abs(e.digital->metrics.rmse - e.metrics.rmse) < 0.05 * e.metrics.rmse);
    QCOMPARE(table->item(MetricsPanel::DigitalRmse, 0)->foreground().color().isValid() &&
                 table->item(MetricsPanel::DigitalRmse, 0)->foreground().style() != Qt::NoBrush,
             false);
    // A slow controller with 1.5 s of delay (the loop's delay margin is 2.4 s) on a 20 s move:
    // the digital loop is lightly damped, and its RMSE differs from the design's by 6 %.
    ideal.trajectory.tfSeconds = 20.0;
    ideal.trajectory.durationSeconds = 80.0;
    ideal.controllerTsSeconds = 0.1;
    ideal.implementation.delaySamples = 15;
    session_->apply(ideal, "slow controller");
    const AxisEvaluation& slow = session_->axisEvaluation(0);
    QVERIFY(std::abs(slow.digital->metrics.rmse - slow.metrics.rmse) > 0.05 * slow.metrics.rmse);
    QCOMPARE(table->item(MetricsPanel::DigitalRmse, 0)->foreground().color(), QColor(0xffb26a00));
    QVERIFY(
        table->item(MetricsPanel::DigitalRmse, 0)->toolTip().contains("differs by more than 5 %"));
    // Its least-damped pole is far below the design's: red, and the warning says why.
    QVERIFY(slow.digital->minDamping < 0.8 * slow.digital->designMinDamping);
    QCOMPARE(table->item(MetricsPanel::DigitalDamping, 0)->foreground().color(),
             QColor(0xffc62828));
    QVERIFY(window_->metricsPanel()->noticeText().contains("much less damped than the design"));
}

void TstDigitalViews::poleZeroMapShowsTheDigitalLoopInTheZPlane() {
    window_->upperTabs()->setCurrentWidget(window_->poleZeroPlot());
    PoleZeroPlot* plot = window_->poleZeroPlot();
    QVERIFY(plot->polesGraph("closed loop")); // the s-plane map by default
    QVERIFY(!window_->zPlaneAction()->isChecked());
    window_->zPlaneAction()->trigger();
    const AxisEvaluation& e = session_->axisEvaluation(0);
    QCPGraph* digital = plot->polesGraph("digital loop");
    QVERIFY(digital);
    QVERIFY(plot->polesGraph("design at Ts"));
    QVERIFY(!plot->polesGraph("closed loop"));
    QCOMPARE(static_cast<std::size_t>(digital->data()->size()), e.digital->poles.size());
    // 3 plant states, the PI's integrator and past error, one sample of delay.
    QCOMPARE(e.digital->poles.size(), std::size_t(6));
    for (auto it = digital->data()->constBegin(); it != digital->data()->constEnd(); ++it)
        QVERIFY(std::abs(std::complex<double>(it->key, it->value)) < 1.0); // a stable digital loop
    window_->zPlaneAction()->trigger();
    QVERIFY(plot->polesGraph("closed loop"));
}

void TstDigitalViews::implementationFieldsEditTheSession() {
    ImplementationEditor* editor = window_->implementationEditor();
    QVERIFY(!editor->isVisible()); // folded by default
    QTest::mouseClick(window_->implementationToggle(), Qt::LeftButton);
    QTRY_VERIFY(editor->isVisible());
    QVERIFY(window_->implementationToggle()->text().contains("quantized"));
    NumberField* dac = editor->dacBitsField();
    dac->setFocus();
    dac->selectAll();
    QTest::keyClicks(dac, "12");
    QTest::keyClick(dac, Qt::Key_Return);
    QTRY_COMPARE(session_->session().implementation.dacBits, 12);
    QComboBox* antiWindup = editor->antiWindupBox();
    antiWindup->setCurrentIndex(1);
    emit antiWindup->activated(1);
    QCOMPARE(session_->session().implementation.antiWindup, AntiWindup::BackCalculation);
    QVERIFY(editor->trackingTimeField()->isEnabled());
    QVERIFY(window_->implementationToggle()->text().contains("back-calc."));
    // Each edit is one undo step.
    session_->undoStack()->undo();
    QCOMPARE(session_->session().implementation.antiWindup, AntiWindup::None);
    session_->undoStack()->undo();
    QCOMPARE(session_->session().implementation.dacBits, 10);
    QCOMPARE(editor->dacBitsField()->value(), 10.0);
}

void TstDigitalViews::invalidImplementationValueStaysAtTheField() {
    QTest::mouseClick(window_->implementationToggle(), Qt::LeftButton);
    for (const auto& [field, text, message] :
         {std::tuple{window_->implementationEditor()->dacBitsField(), "40",
                     "implementation.dac_bits: must be an integer in 0..32 (0: ideal DAC)"},
          std::tuple{window_->implementationEditor()->delayField(), "1.5",
                     "implementation.delay_samples: must be an integer in 0..100"},
          std::tuple{window_->implementationEditor()->encoderField(), "-0.01",
                     "implementation.encoder_resolution: must be a finite number >= 0 (mm per "
                     "count; 0: ideal)"}}) {
        const ImplementationSettings before = session_->session().implementation;
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
        QVERIFY(field->hasError());
        QCOMPARE(field->errorText(), QString(message));
        QVERIFY(session_->session().implementation == before);
    }
}

QTEST_MAIN(TstDigitalViews)
#include "tst_digital_views.moc"
