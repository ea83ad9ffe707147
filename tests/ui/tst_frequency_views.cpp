// SPDX-License-Identifier: GPL-3.0-or-later
// The frequency domain in the workbench: the Bode and Nyquist tabs and the margins in the metrics
// panel draw what the core computed, follow the sliders, and say so when there is nothing to draw.
#include "core/analysis/stability_margins.h"
#include "tests/support/tolerance.h"
#include "ui/main_window.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/parameter_slider.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/nyquist_plot.h"
#include "ui/session/recovery_store.h"
#include "ui/session/tuning_session.h"

#include <QDoubleSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>

#include <cmath>
#include <memory>

using namespace xyt;
using namespace xyt::ui;

class TstFrequencyViews : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void bodeDrawsTheCoreResponseAndMargins();
    void kpSliderMovesThePhaseMarginShown();
    void marginMinimaAreJudgedOnThePanel();
    void polePlacementAxisShowsTheTrackingWithAndWithoutZpetc();
    void legendClickHidesACurve();
    void nyquistStatesTheCriterion();
    void invalidAxisHasNoFrequencyView();
    void nyquistPlaneHasEqualAspect();

private:
    QString cell(int row, int column) const {
        return window_->metricsPanel()->table()->item(row, column)->text();
    }
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstFrequencyViews::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("xytune-tests");
}

void TstFrequencyViews::init() {
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->resize(1366, 768);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstFrequencyViews::cleanup() {
    window_->recovery()->discard();
    window_.reset();
    session_.reset();
}

void TstFrequencyViews::bodeDrawsTheCoreResponseAndMargins() {
    window_->upperTabs()->setCurrentWidget(window_->bodePlot());
    BodePlot* plot = window_->bodePlot();
    QVERIFY(plot->hasResult());
    const AxisFrequencyAnalysis& f = session_->frequencyAnalysis(0);
    QVERIFY(f.ok);
    // The drawn curve is the core's response, point for point.
    QCPGraph* mag = plot->magnitudeGraph("open loop L");
    QCPGraph* phase = plot->phaseGraph("open loop L");
    QVERIFY(mag && phase);
    QCOMPARE(mag->dataCount(), static_cast<int>(f.responses.openLoop.omegaRadPerSec.size()));
    for (int i = 0; i < mag->dataCount(); i += 17) {
        QCOMPARE(mag->data()->at(i)->key,
                 f.responses.openLoop.omegaRadPerSec[static_cast<std::size_t>(i)]);
        QCOMPARE(mag->data()->at(i)->value,
                 f.responses.openLoop.magnitudeDb[static_cast<std::size_t>(i)]);
        QCOMPARE(phase->data()->at(i)->value,
                 f.responses.openLoop.phaseDeg[static_cast<std::size_t>(i)]);
    }
    // The margins drawn and listed are the core's exact ones.
    const StabilityMargins& m = f.margins;
    const QStringList marks = plot->markerTexts();
    QVERIFY2(marks.contains(QString("GM %1 dB at %2 rad/s")
                                .arg(QString::number(m.gainMarginDb, 'g', 3),
                                     QString::number(m.gainMarginOmegaRadPerSec, 'g', 3))),
             qPrintable(marks.join(" | ")));
    QVERIFY(marks.contains(QString("PM %1° at %2 rad/s")
                               .arg(QString::number(m.phaseMarginDeg, 'g', 3),
                                    QString::number(m.phaseMarginOmegaRadPerSec, 'g', 3))));
    // Judged against the (default, zero) minima: both pass.
    QCOMPARE(cell(MetricsPanel::GainMargin, 0), displayNumber(m.gainMarginDb) + " ✓");
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 0), displayNumber(m.phaseMarginDeg) + " ✓");
    QCOMPARE(cell(MetricsPanel::DelayMargin, 0), displayNumber(m.delayMarginSeconds));
    QCOMPARE(cell(MetricsPanel::PeakSensitivity, 0), displayNumber(m.peakSensitivity));
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 1),
             displayNumber(session_->frequencyAnalysis(1).margins.phaseMarginDeg) + " ✓");
    // The GT loop's gain margin equals the gain at which its root locus crosses into the right
    // half-plane (cross-feature invariant, checked in the core; here only that both tabs agree).
    QVERIFY(m.gainMarginDb > 0.0 && std::isfinite(m.gainMarginDb));
    // Hover readout at the phase crossover names the frequency.
    const QPoint at(static_cast<int>(plot->magnitudeRect()
                                         ->axis(QCPAxis::atBottom)
                                         ->coordToPixel(m.gainMarginOmegaRadPerSec)),
                    plot->magnitudeRect()->center().y());
    QTest::mouseMove(plot, at);
    QTRY_VERIFY(plot->readoutText().startsWith("ω = "));
}

void TstFrequencyViews::kpSliderMovesThePhaseMarginShown() {
    // The GUI test: moving kp changes the phase margin on the panel to the core's value.
    window_->upperTabs()->setCurrentWidget(window_->bodePlot());
    const QString before = cell(MetricsPanel::PhaseMargin, 0);
    window_->kpSlider()->spinBox()->setValue(80.0);
    QCOMPARE(session_->session().axes[0].gt.kp, 80.0);
    const StabilityMargins expected = stabilityMargins(session_->axisEvaluation(0).gt->openLoop);
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 0), displayNumber(expected.phaseMarginDeg) + " ✓");
    QVERIFY(cell(MetricsPanel::PhaseMargin, 0) != before);
    QVERIFY(window_->bodePlot()->markerTexts().filter("PM ").first().startsWith(
        QString("PM %1°").arg(QString::number(expected.phaseMarginDeg, 'g', 3))));
}

void TstFrequencyViews::marginMinimaAreJudgedOnThePanel() {
    // The specification's minimum phase and gain margins: edited at the panel (one undoable
    // step), quoted in its limit column and judged per axis against the core's margins.
    const double pmX = session_->frequencyAnalysis(0).margins.phaseMarginDeg;
    const double pmY = session_->frequencyAnalysis(1).margins.phaseMarginDeg;
    const double gmX = session_->frequencyAnalysis(0).margins.gainMarginDb;
    QVERIFY(pmX > pmY); // Braga et al.: 88.1 deg (lower base) and 86.1 deg (upper base)
    auto* phase = window_->metricsPanel()->specField("phase_margin");
    auto* gain = window_->metricsPanel()->specField("gain_margin");
    QVERIFY(phase && gain);
    const double between = 0.5 * (pmX + pmY);
    phase->setValue(between);
    emit phase->valueAccepted(between);
    QCOMPARE(session_->session().spec.minPhaseMarginDeg, between);
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 0), displayNumber(pmX) + " ✓");
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 1), displayNumber(pmY) + " ✗");
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 2), QString("≥ %1").arg(between));
    QVERIFY(!session_->axisEvaluation(1).check.allPassed());
    gain->setValue(gmX + 1.0);
    emit gain->valueAccepted(gmX + 1.0);
    QCOMPARE(cell(MetricsPanel::GainMargin, 0), displayNumber(gmX) + " ✗");
    // Undo takes the gain minimum back, then the phase minimum.
    session_->undoStack()->undo();
    QCOMPARE(session_->session().spec.minGainMarginDb, 0.0);
    QCOMPARE(cell(MetricsPanel::GainMargin, 0), displayNumber(gmX) + " ✓");
    session_->undoStack()->undo();
    QCOMPARE(session_->session().spec.minPhaseMarginDeg, 0.0);
    QCOMPARE(cell(MetricsPanel::PhaseMargin, 1), displayNumber(pmY) + " ✓");
    // A value out of range is refused at the field, naming it; the session keeps its minimum.
    phase->setText("200");
    QVERIFY(!phase->commit());
    QVERIFY2(phase->errorText().contains("min phase margin"), qPrintable(phase->errorText()));
    QCOMPARE(session_->session().spec.minPhaseMarginDeg, 0.0);
}

void TstFrequencyViews::polePlacementAxisShowsTheTrackingWithAndWithoutZpetc() {
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    TrajectorySettings t = session_->session().trajectory;
    t.kind = TrajectoryKind::Circle;
    t.omegaRadPerSec = 0.1;
    session_->setTrajectory(t);
    window_->upperTabs()->setCurrentWidget(window_->bodePlot());
    BodePlot* plot = window_->bodePlot();
    QVERIFY(plot->magnitudeGraph("tracking with ZPETC"));
    QVERIFY(plot->magnitudeGraph("tracking, loop alone"));
    // Zero phase with ZPETC (Patrick, Ishak and Adnan): every drawn phase sample within round-off
    // of 0.
    QCPGraph* phase = plot->phaseGraph("tracking with ZPETC");
    for (auto it = phase->data()->constBegin(); it != phase->data()->constEnd(); ++it)
        QVERIFY(std::abs(it->value) < 1e-6);
    QVERIFY(plot->markerTexts().contains("reference ω = 0.1"));
    QVERIFY(plot->markerTexts().contains("Nyquist π/Ts"));
    PpAxisSettings pp = session_->session().axes[0].pp;
    pp.zpetcEnabled = false;
    session_->setPp(0, pp);
    QVERIFY(!plot->magnitudeGraph("tracking with ZPETC"));
    QVERIFY(plot->magnitudeGraph("tracking, loop alone"));
}

void TstFrequencyViews::legendClickHidesACurve() {
    window_->upperTabs()->setCurrentWidget(window_->bodePlot());
    BodePlot* plot = window_->bodePlot();
    plot->replot(QCustomPlot::rpImmediateRefresh);
    QCPGraph* s = plot->magnitudeGraph("|S| sensitivity");
    QVERIFY(s && s->visible());
    QCPAbstractLegendItem* item = nullptr;
    for (QCPLegend* legend : plot->findChildren<QCPLegend*>())
        if (auto* found = legend->itemWithPlottable(s))
            item = found;
    QVERIFY(item);
    QTest::mouseClick(plot, Qt::LeftButton, {}, item->rect().center());
    QVERIFY(!s->visible());
    QTest::mouseClick(plot, Qt::LeftButton, {}, item->rect().center());
    QVERIFY(s->visible());
}

void TstFrequencyViews::nyquistStatesTheCriterion() {
    window_->upperTabs()->setCurrentWidget(window_->nyquistPlot());
    NyquistPlot* plot = window_->nyquistPlot();
    const NyquistCurve& c = session_->frequencyAnalysis(0).nyquist;
    QVERIFY(plot->criterionText().contains(QString("N = %1").arg(c.clockwiseEncirclements)));
    QVERIFY(plot->criterionText().contains("Z = N + P = 0: closed loop stable"));
    // Unstable: kp far beyond the Routh bound of the lower base at wn = 2 (c (a1 a2 - c) >
    // a1^2 wn^4 fails for kp k0 > a1 a2, i.e. kp > 5900): Z = 2 on the plot and GM < 0 dB.
    session_->setKp(0, 7000.0);
    const AxisFrequencyAnalysis& f = session_->frequencyAnalysis(0);
    QCOMPARE(f.nyquist.closedLoopUnstablePoles, 2);
    QVERIFY(plot->criterionText().contains("Z = N + P = 2"));
    QVERIFY(!f.margins.closedLoopStable);
    QCOMPARE(
        window_->metricsPanel()->table()->item(MetricsPanel::GainMargin, 0)->foreground().color(),
        QColor(0xc6, 0x28, 0x28));
}

void TstFrequencyViews::invalidAxisHasNoFrequencyView() {
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    PpAxisSettings pp = session_->session().axes[0].pp;
    pp.b = {0.0, 0.0, 0.0}; // B = 0: no design
    session_->setPp(0, pp);
    QVERIFY(!session_->axisEvaluation(0).ok);
    for (QWidget* tab : {static_cast<QWidget*>(window_->bodePlot()),
                         static_cast<QWidget*>(window_->nyquistPlot())}) {
        window_->upperTabs()->setCurrentWidget(tab);
        QVERIFY(!window_->bodePlot()->hasResult() || tab != window_->bodePlot());
    }
    QVERIFY(!window_->nyquistPlot()->hasResult());
    QVERIFY(window_->nyquistPlot()->noticeText().startsWith("No design"));
    QVERIFY(window_->bodePlot()->noticeText().startsWith("No design"));
    QCOMPARE(cell(MetricsPanel::GainMargin, 0), QString("—"));
    // Back to a valid plant: the views return (never the old curves in between).
    session_->undoStack()->undo();
    QVERIFY(window_->nyquistPlot()->hasResult());
}

void TstFrequencyViews::nyquistPlaneHasEqualAspect() {
    window_->upperTabs()->setCurrentWidget(window_->nyquistPlot());
    NyquistPlot* plot = window_->nyquistPlot();
    for (const QSize size : {QSize(1366, 768), QSize(1600, 1000)}) {
        window_->resize(size);
        QTest::qWait(50);
        plot->replot(QCustomPlot::rpImmediateRefresh);
        const double px = plot->axisRect()->width() / plot->xAxis->range().size();
        const double py = plot->axisRect()->height() / plot->yAxis->range().size();
        QVERIFY2(std::abs(px / py - 1.0) < 0.01, qPrintable(QString("%1 vs %2").arg(px).arg(py)));
        QVERIFY(plot->xAxis->range().contains(-1.0));
    }
}

QTEST_MAIN(TstFrequencyViews)
#include "tst_frequency_views.moc"
