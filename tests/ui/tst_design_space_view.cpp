// SPDX-License-Identifier: GPL-3.0-or-later
// GUI tests of the design-space view: drive the real buttons and the plot offscreen; compare the
// heat map with the core's sweepDesignSpace called directly on the same problem.
#include "core/session/design_study.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"
#include "core/study/sweep_diagnosis.h"
#include "tests/support/tolerance.h"
#include "ui/design_space_view.h"
#include "ui/plots/design_space_plot.h"
#include "ui/session/tuning_session.h"

#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <bit>
#include <cmath>
#include <set>

using namespace xyt;
using namespace xyt::ui;

Q_DECLARE_METATYPE(std::vector<std::uint8_t>)
Q_DECLARE_METATYPE(xyt::ui::DesignSpaceView::StudyKind)

namespace {
// A study of a few thousand points takes seconds on the shared 2-core machine; leave room.
constexpr int kStudyTimeoutMs = 120000;

/// The problem the view must build for axis @p axis, assembled here from the session as the
/// issue describes it (independently of the view's code).
DesignProblem expectedProblem(const Session& s, int axis, double maxOvershootPct) {
    DesignProblem p;
    p.plant = s.axes[static_cast<std::size_t>(axis)].gt.plant;
    p.modelUnitsPerPositionUnit =
        s.axes[static_cast<std::size_t>(axis)].gt.modelUnitsPerPositionUnit;
    p.dtSeconds = s.trajectory.dtSeconds;
    // A cubic with the automatic duration is studied over its move plus twice the allowed
    // settle time, and judged on its move and settle (design_sweep.h, moveSweepDurationSeconds).
    const TrajectorySettings& t = s.trajectory;
    p.spec = s.spec;
    p.spec.umaxVolts = s.umaxVolts;
    p.spec.maxOvershootPct = maxOvershootPct;
    p.reference =
        sampled(axisReference(t, axis),
                sampleTimes(moveSweepDurationSeconds(t.tfSeconds, p.spec.maxSettleTimeSeconds),
                            t.dtSeconds));
    p.move = PointToPointMove{t.x0, t.xf, t.tfSeconds};
    return p;
}
} // namespace

class TstDesignSpaceView : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void defaultsFollowTheIssue();
    void heatMapHoldsTheCoreValues();
    void mapCellsLineUpWithTheLogGrid();
    void clickOnACellLoadsThatDesign();
    void hoverShowsTheFiguresAndFailures();
    void overshootOnlyFailureIsExplained();
    void marginsAreMappedAndTheirMinimumJudgesTheStudy();
    void bestOnTheEdgeIsWarned();
    void emptyMapBeforeTheFirstRun();
    void controlsStayInReachAndStill();
    void narrowViewGivesTheMapTheWidth();
    void wheelScrollsThePanelNotTheField();
    void cancelStopsAStudyAndKeepsTheWindowResponsive();
    void newRunReplacesARunningOne();
    void destroyingWhileRunningIsSafe();
    void currentDesignMarkerFollowsTheSession();
    void liveMapPreviewsThenStudiesInFull();
    void liveMapFollowsPlantTrajectoryAndLimits();
    void liveMapIgnoresTheDesignAndJudgesAgain();
    void liveOffOrHiddenComputesNothing();
    void liveMapSkipsAPolePlacementAxis();
    void outlineEnclosesTheFeasibleCells_data();
    void outlineEnclosesTheFeasibleCells();
    void cellEdgesAreMidpointsInTheAxisScale();

private:
    void setSmallGrid(int n, double overshootPct);
    void runAndWait();

    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<DesignSpaceView> view_;
};

void TstDesignSpaceView::init() {
    session_ = std::make_unique<TuningSession>();
    view_ = std::make_unique<DesignSpaceView>(session_.get());
    // The tests below drive the study by hand; the live map (on by default, checked by
    // defaultsFollowTheIssue) has its own tests, which turn it on.
    view_->liveBox()->setChecked(false);
    view_->resize(900, 600);
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
}

void TstDesignSpaceView::cleanup() {
    view_.reset();
    session_.reset();
}

void TstDesignSpaceView::setSmallGrid(int n, double overshootPct) {
    view_->wnCountBox()->setValue(n);
    view_->kpCountBox()->setValue(n);
    // The box edits the session's one specification when its editing finishes.
    view_->overshootBox()->setValue(overshootPct);
    emit view_->overshootBox()->editingFinished();
    QCOMPARE(session_->session().spec.maxOvershootPct, overshootPct);
}

void TstDesignSpaceView::runAndWait() {
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!view_->isRunning(), kStudyTimeoutMs);
    QVERIFY(view_->result().has_value());
    view_->plot()->replot(); // lay out the axes now, so that coordToPixel is current
}

void TstDesignSpaceView::defaultsFollowTheIssue() {
    // The defaults: wn 0.2-20 rad/s, kp 3-3000, 60 x 60, log grid; the paper's specification with
    // the session's actuator limit (Session holds no specification, so the overshoot limit is 0 %).
    QCOMPARE(view_->wnMinBox()->value(), 0.2);
    QCOMPARE(view_->wnMaxBox()->value(), 20.0);
    QCOMPARE(view_->kpMinBox()->value(), 3.0);
    QCOMPARE(view_->kpMaxBox()->value(), 3000.0);
    QCOMPARE(view_->wnCountBox()->value(), 60);
    QCOMPARE(view_->kpCountBox()->value(), 60);
    QVERIFY(view_->logGridBox()->isChecked());
    // The map is live by default (a view never shown computes nothing).
    const DesignSpaceView fresh(session_.get());
    QVERIFY(fresh.liveBox()->isChecked());
    QVERIFY(!fresh.isRunning());
    QCOMPARE(view_->settlingBox()->value(), 100.0);
    QCOMPARE(view_->overshootBox()->value(), 0.0);
    QCOMPARE(view_->errorBox()->value(), 2.0);
    QCOMPARE(view_->umaxBox()->value(), session_->session().umaxVolts);
    QVERIFY(!view_->cancelButton()->isEnabled());
}

void TstDesignSpaceView::heatMapHoldsTheCoreValues() {
    // Overshoot <= 2 %: the paper's lower-base design overshoots 0.997 % (specification.h), so
    // the grid has feasible designs and a best one.
    setSmallGrid(8, 2.0);
    runAndWait();
    QCOMPARE(view_->progressBar()->value(), 100);

    const DesignProblem problem = expectedProblem(session_->session(), 0, 2.0);
    const SweepAxis wn{0.2, 20.0, 8, true}, kp{3.0, 3000.0, 8, true};
    const DesignSweepResult expected = sweepDesignSpace(problem, wn, kp, {});
    const DesignSweepResult& actual = *view_->result();
    QCOMPARE(actual.status, SweepStatus::Completed);
    QCOMPARE(actual.feasibleCount, expected.feasibleCount);
    QVERIFY(expected.feasibleCount > 0);
    QVERIFY(expected.bestIndex.has_value());
    // Whatever the core's diagnosis says (e.g. the best design on the edge of the grid, with
    // the range to widen) is said in the status.
    const SweepDiagnosis d = diagnoseSweep(expected, problem.spec);
    for (const std::string& w : d.warnings)
        QVERIFY2(view_->statusText().contains(QString::fromStdString(w)), w.c_str());
    QVERIFY(!view_->relaxButton()->isVisible());

    QCPColorMapData* map = view_->plot()->colorMap()->data();
    QCPColorMapData* status = view_->plot()->statusMap()->data();
    QCOMPARE(map->keySize(), 8);
    QCOMPARE(map->valueSize(), 8);
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t j = 0; j < 8; ++j) {
            const DesignPoint& p = expected.at(i, j);
            const double value = criterionValue(p, SweepCriterion::Itae);
            const double cell = map->cell(static_cast<int>(i), static_cast<int>(j));
            // The core is deterministic bit for bit whatever the thread count (design_sweep.h),
            // so the map holds exactly the directly computed ITAE; non-finite ones are NaN (the
            // status layer draws them).
            if (std::isfinite(value))
                XYT_COMPARE_NEAR(cell, value, 0.0, 0.0);
            else
                QVERIFY(std::isnan(cell));
            const int expectedStatus = !p.stable || !p.metricsFinite ? DesignSpacePlot::Failed
                                       : p.feasible                  ? DesignSpacePlot::Feasible
                                                                     : DesignSpacePlot::Infeasible;
            QCOMPARE(static_cast<int>(status->cell(static_cast<int>(i), static_cast<int>(j))),
                     expectedStatus);
        }
    // The star sits on the core's best grid point, the diamond on its refined best.
    const DesignPoint& best = expected.points[*expected.bestIndex];
    QCOMPARE(view_->plot()->bestMarker()->dataCount(), 1);
    XYT_COMPARE_NEAR(view_->plot()->bestMarker()->data()->at(0)->key, best.wn, 0.0, 0.0);
    XYT_COMPARE_NEAR(view_->plot()->bestMarker()->data()->at(0)->value, best.kp, 0.0, 0.0);
    QVERIFY(expected.refined.has_value());
    QCOMPARE(view_->plot()->refinedMarker()->dataCount(), 1);
    XYT_COMPARE_NEAR(view_->plot()->refinedMarker()->data()->at(0)->key, expected.refined->point.wn,
                     0.0, 0.0);
    XYT_COMPARE_NEAR(view_->plot()->refinedMarker()->data()->at(0)->value,
                     expected.refined->point.kp, 0.0, 0.0);
    QVERIFY(view_->plot()->outlineCount() >= 1);
    QVERIFY2(view_->statusText().contains("feasible"), qPrintable(view_->statusText()));

    // The metric selector redraws the held result: max |u| of every point.
    view_->metricBox()->setCurrentIndex(3);
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t j = 0; j < 8; ++j) {
            const double value = criterionValue(expected.at(i, j), SweepCriterion::MaxU);
            if (std::isfinite(value))
                XYT_COMPARE_NEAR(map->cell(static_cast<int>(i), static_cast<int>(j)), value, 0.0,
                                 0.0);
        }
}

void TstDesignSpaceView::mapCellsLineUpWithTheLogGrid() {
    setSmallGrid(6, 2.0);
    runAndWait();
    DesignSpacePlot* plot = view_->plot();
    QCOMPARE(plot->xAxis->scaleType(), QCPAxis::stLogarithmic);
    QCOMPARE(plot->yAxis->scaleType(), QCPAxis::stLogarithmic);
    // Render the metric layer alone and read the colour at each grid point's pixel: it must be
    // the gradient's colour of that cell's value (a misaligned map shows a neighbour's colour).
    plot->statusMap()->setVisible(false);
    for (int i = 0; i < plot->outlineCount(); ++i)
        plot->outlineCurve(i)->setVisible(false);
    for (QCPGraph* g : {plot->bestMarker(), plot->refinedMarker(), plot->currentMarker()})
        g->setVisible(false);
    plot->legend->setVisible(false);
    plot->xAxis->grid()->setVisible(false);
    plot->yAxis->grid()->setVisible(false);
    plot->replot();
    const QImage image = plot->toPixmap(plot->width(), plot->height(), 1.0).toImage();
    const QCPColorMap* map = plot->colorMap();
    int checked = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const double v = map->data()->cell(i, j);
            if (std::isnan(v))
                continue;
            const QPoint px =
                plot->pixelOfCell(static_cast<std::size_t>(i), static_cast<std::size_t>(j))
                    .toPoint();
            const QColor want = QColor::fromRgba(map->gradient().color(v, map->dataRange(), true));
            const QColor got = image.pixelColor(px);
            // One unit per channel: the gradient's 256 levels are looked up identically, the
            // slack only covers the image's colour conversion.
            QVERIFY2(std::abs(got.red() - want.red()) <= 1 &&
                         std::abs(got.green() - want.green()) <= 1 &&
                         std::abs(got.blue() - want.blue()) <= 1,
                     qPrintable(QString("cell %1,%2: got %3 want %4")
                                    .arg(i)
                                    .arg(j)
                                    .arg(got.name(), want.name())));
            // And the cell lookup used for hover and click agrees.
            const auto cell = plot->cellAtPixel(px);
            QVERIFY(cell.has_value());
            QCOMPARE(cell->first, static_cast<std::size_t>(i));
            QCOMPARE(cell->second, static_cast<std::size_t>(j));
            ++checked;
        }
    QVERIFY(checked > 18);
}

void TstDesignSpaceView::clickOnACellLoadsThatDesign() {
    setSmallGrid(8, 2.0);
    runAndWait();
    const DesignSweepResult& r = *view_->result();
    const double wnBefore = session_->session().axes[0].gt.omegaNRadPerSec;
    const QPoint px = view_->plot()->pixelOfCell(5, 2).toPoint();
    QTest::mouseClick(view_->plot(), Qt::LeftButton, Qt::NoModifier, px);
    // The click copies the grid values into the session's current axis (x).
    QTRY_VERIFY(session_->session().axes[0].gt.omegaNRadPerSec != wnBefore);
    XYT_COMPARE_NEAR(session_->session().axes[0].gt.omegaNRadPerSec, r.wnValues[5], 0.0, 0.0);
    XYT_COMPARE_NEAR(session_->session().axes[0].gt.kp, r.kpValues[2], 0.0, 0.0);
    QCOMPARE(session_->undoStack()->undoText(), QString("Load design from the design space"));
    // The cross follows the session.
    XYT_COMPARE_NEAR(view_->plot()->currentMarker()->data()->at(0)->key, r.wnValues[5], 0.0, 0.0);
    session_->undoStack()->undo();
    XYT_COMPARE_NEAR(session_->session().axes[0].gt.omegaNRadPerSec, wnBefore, 0.0, 0.0);
}

void TstDesignSpaceView::hoverShowsTheFiguresAndFailures() {
    setSmallGrid(8, 0.0);
    runAndWait();
    const DesignSweepResult& r = *view_->result();
    QTest::mouseMove(view_->plot(), view_->plot()->pixelOfCell(4, 1).toPoint());
    QTRY_VERIFY(view_->readoutText().contains(
        QString("ωn = %1").arg(QString::number(r.wnValues[4], 'g', 4))));
    const QString text = view_->readoutText();
    QVERIFY2(text.contains(QString("kp = %1").arg(QString::number(r.kpValues[1], 'g', 4))),
             qPrintable(text));
    // With a 0 % limit no design is feasible (specification.h: G_R is type 2).
    QVERIFY2(text.contains("feasible: no") && text.contains("overshoot"), qPrintable(text));
}

void TstDesignSpaceView::bestOnTheEdgeIsWarned() {
    // kp only up to 30 at overshoot <= 2 %: the ITAE keeps falling with kp (Braga et al. Fig. 4),
    // so the best design sits on the upper kp edge and the optimum may lie beyond it.
    view_->wnMinBox()->setValue(0.2);
    view_->wnMaxBox()->setValue(20.0);
    view_->kpMinBox()->setValue(3.0);
    view_->kpMaxBox()->setValue(30.0);
    view_->wnCountBox()->setValue(6);
    view_->kpCountBox()->setValue(6);
    view_->overshootBox()->setValue(2.0);
    emit view_->overshootBox()->editingFinished();
    runAndWait();
    const DesignSweepResult& r = *view_->result();
    QVERIFY(r.bestIndex.has_value());
    Specification spec = session_->session().spec;
    spec.umaxVolts = session_->session().umaxVolts;
    const SweepDiagnosis d = diagnoseSweep(r, spec);
    QVERIFY(d.kpAtUpperEdge);
    QVERIFY2(view_->statusText().contains("upper end of the kp range"),
             qPrintable(view_->statusText()));
}

void TstDesignSpaceView::emptyMapBeforeTheFirstRun() {
    // Before the first run the map showed a stray coloured strip and an untitled 0-6 scale.
    QVERIFY(!view_->plot()->hasResult());
    QVERIFY(!view_->plot()->colorMap()->visible());
    QVERIFY(!view_->plot()->colorScale()->visible());
    QVERIFY(view_->plot()->noticeText().contains("Not computed yet"));
    setSmallGrid(4, 2.0);
    runAndWait();
    QVERIFY(view_->plot()->colorMap()->visible() && view_->plot()->colorScale()->visible());
    QVERIFY(view_->plot()->noticeText().isEmpty());
    QVERIFY(!view_->plot()->colorScale()->axis()->label().isEmpty());
    // The key says the colour is the metric's scale: it said "bright: feasible" while the
    // viridis map makes a high ITAE (the worst design) the brightest cell.
    const QString key = view_->plot()->toolTip();
    QVERIFY2(key.contains("colour: the metric") && !key.contains("bright"), qPrintable(key));
}

void TstDesignSpaceView::controlsStayInReachAndStill() {
    // At 1366x768 the tab is about 600 x 330 px: Run was below the visible area, and after a run
    // the status text moved the panel so that a click aimed at Cancel hit a spin box.
    view_->resize(600, 330);
    QTest::qWait(50);
    const QRect visible = view_->rect();
    for (QWidget* w :
         {static_cast<QWidget*>(view_->runButton()), static_cast<QWidget*>(view_->cancelButton()),
          static_cast<QWidget*>(view_->progressBar())})
        QVERIFY2(visible.contains(QRect(w->mapTo(view_.get(), QPoint(0, 0)), w->size())),
                 w->metaObject()->className());
    const QPoint cancelBefore = view_->cancelButton()->mapTo(view_.get(), QPoint(0, 0));
    const QRect mapBefore = view_->plot()->geometry();
    setSmallGrid(6, 0.0); // no feasible design: the longest status there is
    runAndWait();
    QVERIFY(view_->statusText().count('\n') >= 2);
    QCOMPARE(view_->cancelButton()->mapTo(view_.get(), QPoint(0, 0)), cancelBefore);
    QCOMPARE(view_->plot()->geometry(), mapBefore);
    // The status is longer than its strip: it scrolls there, whole, instead of being cut.
    auto* strip = qobject_cast<QScrollArea*>(view_->statusLabel()->parentWidget()->parentWidget());
    QVERIFY(strip);
    QVERIFY(strip->verticalScrollBar()->maximum() > 0);
    QVERIFY(view_->statusLabel()->height() >=
            view_->statusLabel()->heightForWidth(view_->statusLabel()->width()));
}

void TstDesignSpaceView::narrowViewGivesTheMapTheWidth() {
    // At 1366x768 the lower tab is about 600 px wide: the controls beside the map left it about
    // 80 x 150 px. Narrow, the controls are hidden until asked for, and the map takes the width.
    view_->resize(600, 330);
    QTest::qWait(50);
    QVERIFY(!view_->settingsButton()->isChecked());
    QVERIFY(!view_->controlPanel()->isVisible());
    QVERIFY2(view_->plot()->width() >= view_->width() - 40,
             qPrintable(QString::number(view_->plot()->width())));
    // Asked for, they are shown, and stay so when the view is resized (the user's choice).
    QTest::mouseClick(view_->settingsButton(), Qt::LeftButton);
    QVERIFY(view_->controlPanel()->isVisible());
    QVERIFY(view_->plot()->width() < view_->width() - view_->controlPanel()->width() + 1);
    view_->resize(580, 330);
    QTest::qWait(20);
    QVERIFY(view_->controlPanel()->isVisible());
    // Wide, a new view shows them beside the map.
    QTest::mouseClick(view_->settingsButton(), Qt::LeftButton);
    QVERIFY(!view_->controlPanel()->isVisible());
    view_->resize(900, 400);
    QTest::qWait(20);
    QVERIFY(!view_->controlPanel()->isVisible()); // still the user's choice
}

void TstDesignSpaceView::wheelScrollsThePanelNotTheField() {
    view_->resize(600, 330);
    QTest::qWait(50);
    QTest::mouseClick(view_->settingsButton(), Qt::LeftButton); // narrow: shown on request
    QDoubleSpinBox* box = view_->wnMaxBox();
    QScrollArea* panel = nullptr;
    for (QScrollArea* a : view_->findChildren<QScrollArea*>())
        if (a->widget()->isAncestorOf(box))
            panel = a;
    QVERIFY(panel && panel->verticalScrollBar()->maximum() > 0);
    const double before = box->value();
    const int scrolled = panel->verticalScrollBar()->value();
    const QPoint at = box->rect().center();
    QWheelEvent down(at, box->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton,
                     Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(box, &down);
    QCOMPARE(box->value(), before);                          // the field did not change
    QVERIFY(panel->verticalScrollBar()->value() > scrolled); // the panel scrolled
    // With focus, the wheel edits the field as usual.
    box->setFocus();
    QTRY_VERIFY(box->hasFocus());
    QWheelEvent up(at, box->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                   Qt::NoScrollPhase, false);
    QApplication::sendEvent(box, &up);
    QVERIFY(box->value() != before);
}

void TstDesignSpaceView::overshootOnlyFailureIsExplained() {
    setSmallGrid(8, 0.0);
    runAndWait();
    QCOMPARE(view_->result()->feasibleCount, 0);
    // The core's diagnosis: the criterion failing everywhere, its best value on the grid, and
    // the least-violating design, marked and offered as a relaxed specification.
    Specification spec = session_->session().spec;
    spec.umaxVolts = session_->session().umaxVolts;
    const SweepDiagnosis d = diagnoseSweep(*view_->result(), spec);
    QVERIFY(d.noneFeasible && !d.warnings.empty());
    for (const std::string& w : d.warnings)
        QVERIFY2(view_->statusText().contains(QString::fromStdString(w)), w.c_str());
    QVERIFY2(view_->statusText().contains("fails at every design of the grid") &&
                 view_->statusText().contains("Every GT design overshoots"),
             qPrintable(view_->statusText()));
    QCOMPARE(view_->plot()->bestMarker()->dataCount(), 0);
    QCOMPARE(view_->plot()->outlineCount(), 0);
    QCOMPARE(view_->plot()->leastViolatingMarker()->dataCount(), 1);
    QVERIFY(view_->relaxButton()->isVisible());
    // Relaxing sets the session's specification (one undoable step) and the same study, judged
    // again, has the least-violating design feasible.
    const int before = session_->undoStack()->count();
    QTest::mouseClick(view_->relaxButton(), Qt::LeftButton);
    QCOMPARE(session_->undoStack()->count(), before + 1);
    QVERIFY(session_->session().spec.maxOvershootPct > 0.0);
    QVERIFY2(view_->result()->feasibleCount >= 1, qPrintable(view_->statusText()));
    QCOMPARE(view_->plot()->leastViolatingMarker()->dataCount(), 0);
    session_->undoStack()->undo();
    QCOMPARE(session_->session().spec.maxOvershootPct, 0.0);
}

void TstDesignSpaceView::marginsAreMappedAndTheirMinimumJudgesTheStudy() {
    // The map shows the phase margin itself (deg, larger is better), and a minimum
    // set in the view is the session's (one undoable step) and judges the held study again.
    setSmallGrid(6, 2.0);
    runAndWait();
    const DesignSweepResult held = *view_->result();
    const int index = view_->metricBox()->findData(static_cast<int>(SweepCriterion::PhaseMargin));
    QVERIFY(index >= 0);
    view_->metricBox()->setCurrentIndex(index);
    QCPColorMapData* map = view_->plot()->colorMap()->data();
    std::vector<double> feasibleMargins;
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) {
            const DesignPoint& p = held.at(i, j);
            const double cell = map->cell(static_cast<int>(i), static_cast<int>(j));
            if (p.computed && p.metricsFinite && std::isfinite(p.phaseMarginDeg))
                QCOMPARE(cell, p.phaseMarginDeg);
            if (p.feasible)
                feasibleMargins.push_back(p.phaseMarginDeg);
        }
    QVERIFY(feasibleMargins.size() >= 2);
    std::sort(feasibleMargins.begin(), feasibleMargins.end());
    const double minimum = 0.5 * (feasibleMargins.front() + feasibleMargins.back());
    QVERIFY(feasibleMargins.front() < minimum);
    const int before = session_->undoStack()->count();
    view_->phaseMarginBox()->setValue(minimum);
    emit view_->phaseMarginBox()->editingFinished();
    QCOMPARE(session_->undoStack()->count(), before + 1);
    QCOMPARE(session_->session().spec.minPhaseMarginDeg, view_->phaseMarginBox()->value());
    for (const DesignPoint& p : view_->result()->points)
        if (p.feasible)
            QVERIFY(p.phaseMarginDeg >= session_->session().spec.minPhaseMarginDeg);
    QVERIFY(view_->result()->feasibleCount < static_cast<int>(feasibleMargins.size()));
    session_->undoStack()->undo();
    QCOMPARE(session_->session().spec.minPhaseMarginDeg, 0.0);
    QCOMPARE(view_->phaseMarginBox()->value(), 0.0);
    QCOMPARE(view_->result()->feasibleCount, held.feasibleCount);
}

void TstDesignSpaceView::cancelStopsAStudyAndKeepsTheWindowResponsive() {
    // 500 x 500 = 250000 designs: minutes of work, so the cancel surely comes first.
    setSmallGrid(500, 2.0);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    QVERIFY(view_->cancelButton()->isEnabled());
    // The event loop keeps turning while the workers run: progress arrives through it, and each
    // processEvents() returns.
    QElapsedTimer clock;
    clock.start();
    int turns = 0;
    while (view_->progressBar()->value() < 1 && clock.elapsed() < kStudyTimeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        ++turns;
    }
    QVERIFY(view_->progressBar()->value() >= 1);
    QVERIFY(turns > 1);
    QTest::mouseClick(view_->cancelButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view_->statusText().contains("Cancelled"), kStudyTimeoutMs);
    QVERIFY(!view_->isRunning());
    QCOMPARE(view_->result()->status, SweepStatus::Cancelled);
    QVERIFY(view_->result()->computedCount < 250000);
    QVERIFY(view_->progressBar()->value() < 100);
}

void TstDesignSpaceView::newRunReplacesARunningOne() {
    setSmallGrid(500, 2.0);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    setSmallGrid(5, 2.0);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view_->isRunning(), kStudyTimeoutMs);
    // Only the second study's result arrives.
    QCOMPARE(view_->result()->status, SweepStatus::Completed);
    QCOMPARE(view_->result()->points.size(), std::size_t(25));
    QCOMPARE(view_->progressBar()->value(), 100);
}

void TstDesignSpaceView::destroyingWhileRunningIsSafe() {
    setSmallGrid(500, 2.0);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    QTest::qWait(100);
    view_.reset(); // cancels and joins; queued progress events die with the widget
    QTest::qWait(100);
    QVERIFY(!view_);
}

void TstDesignSpaceView::currentDesignMarkerFollowsTheSession() {
    session_->setOmegaN(0, 3.5);
    QCOMPARE(view_->plot()->currentMarker()->dataCount(), 1);
    XYT_COMPARE_NEAR(view_->plot()->currentMarker()->data()->at(0)->key, 3.5, 0.0, 0.0);
}

namespace {
using Kind = DesignSpaceView::StudyKind;

/// Waits for the next studyFinished of @p spy (already holding @p seen signals), returns its kind.
Kind nextFinished(QSignalSpy& spy, int seen) {
    if (spy.count() <= seen)
        spy.wait(kStudyTimeoutMs);
    return spy.count() > seen ? spy.at(seen).at(0).value<Kind>() : Kind::Full;
}
} // namespace

void TstDesignSpaceView::liveMapPreviewsThenStudiesInFull() {
    setSmallGrid(6, 2.0);
    QSignalSpy spy(view_.get(), &DesignSpaceView::studyFinished);
    view_->liveBox()->setChecked(true); // visible, nothing shown yet: the preview starts at once
    QVERIFY(view_->isRunning());
    QVERIFY(view_->runningKind() == Kind::Preview);
    QVERIFY(nextFinished(spy, 0) == Kind::Preview);
    // The preview is the core's sweep of the session at the live fidelity (design_study.h):
    // 1,500 samples over tf + 2 x the settle limit, 100 samples per step-scan span, no refinement.
    const Session& s = session_->session();
    const DesignProblem preview = sessionDesignProblem(s, 0, kLivePreviewFidelity);
    QCOMPARE(view_->studiedProblem()->reference.size(), std::size_t(1500));
    QCOMPARE(view_->studiedProblem()->dtSeconds, preview.dtSeconds);
    QCOMPARE(view_->studiedProblem()->stepSamples, 100);
    SweepOptions o;
    o.refine = false;
    const SweepAxis wn{0.2, 20.0, 6, true}, kp{3.0, 3000.0, 6, true};
    const DesignSweepResult expected = sweepDesignSpace(preview, wn, kp, o);
    QCOMPARE(view_->result()->points.size(), expected.points.size());
    for (std::size_t i = 0; i < expected.points.size(); ++i)
        QCOMPARE(std::bit_cast<std::uint64_t>(view_->result()->points[i].tracking.itae),
                 std::bit_cast<std::uint64_t>(expected.points[i].tracking.itae));
    QVERIFY(view_->statusText().startsWith("Live preview (6 × 6 designs"));
    // Then, the inputs at rest, the full study: the grid at the session's dt, refined.
    QVERIFY(nextFinished(spy, 1) == Kind::Full);
    QVERIFY(!view_->resultIsPreview());
    QCOMPARE(view_->studiedProblem()->dtSeconds, s.trajectory.dtSeconds);
    QCOMPARE(view_->studiedProblem()->stepSamples, 500);
    QCOMPARE(view_->studiedProblem()->reference.size(),
             expectedProblem(s, 0, 2.0).reference.size());
    QVERIFY(view_->statusText().startsWith("Done"));
    // Nothing more: the map is up to date.
    QTest::qWait(DesignSpaceView::kLiveRestMs + 200);
    QCOMPARE(spy.count(), 2);
    QVERIFY(!view_->isRunning());
}

void TstDesignSpaceView::liveMapFollowsPlantTrajectoryAndLimits() {
    setSmallGrid(5, 2.0);
    QSignalSpy spy(view_.get(), &DesignSpaceView::studyFinished);
    view_->liveBox()->setChecked(true);
    QVERIFY(nextFinished(spy, 0) == Kind::Preview);
    QVERIFY(nextFinished(spy, 1) == Kind::Full);
    int seen = 2;
    const auto expectRestudy = [&](const char* what) {
        QVERIFY2(view_->isRunning() && view_->runningKind() == Kind::Preview, what);
        QVERIFY2(nextFinished(spy, seen) == Kind::Preview, what);
        QVERIFY2(nextFinished(spy, seen + 1) == Kind::Full, what);
        seen += 2;
    };
    ThirdOrderPlant plant = session_->session().axes[0].gt.plant;
    plant.k0 *= 1.5;
    session_->setPlant(0, plant);
    expectRestudy("plant");
    QVERIFY(view_->studiedProblem()->plant == plant);
    TrajectorySettings t = session_->session().trajectory;
    t.tfSeconds = 60.0;
    session_->setTrajectory(t);
    expectRestudy("trajectory");
    QCOMPARE(view_->studiedProblem()->move->endSeconds, 60.0);
    session_->setUmax(3.0);
    expectRestudy("actuator limit");
    QCOMPARE(view_->studiedProblem()->spec.umaxVolts, 3.0);
    Specification spec = session_->session().spec;
    spec.maxSettleTimeSeconds = 50.0; // the run lasts tf + 2 x it
    session_->setSpecification(spec);
    expectRestudy("settle limit");
    QCOMPARE(view_->studiedProblem()->reference.size(),
             std::size_t(std::floor((60.0 + 100.0) / 0.01 + 1e-9)) + 1);
    view_->wnCountBox()->setValue(4); // a new grid
    expectRestudy("grid");
    QCOMPARE(view_->result()->wnValues.size(), std::size_t(4));
    // Undo brings the earlier settings back: the map follows too.
    session_->undoStack()->undo();
    expectRestudy("undo");
    QCOMPARE(view_->studiedProblem()->spec.maxSettleTimeSeconds, 100.0);
}

void TstDesignSpaceView::liveMapIgnoresTheDesignAndJudgesAgain() {
    setSmallGrid(5, 2.0);
    QSignalSpy spy(view_.get(), &DesignSpaceView::studyFinished);
    view_->liveBox()->setChecked(true);
    QVERIFY(nextFinished(spy, 0) == Kind::Preview);
    QVERIFY(nextFinished(spy, 1) == Kind::Full);
    // wn and kp (the sliders) only move the marker: no study starts.
    session_->setOmegaN(0, 3.0);
    session_->setKp(0, 50.0);
    QVERIFY(!view_->isRunning());
    XYT_COMPARE_NEAR(view_->plot()->currentMarker()->data()->at(0)->key, 3.0, 0.0, 0.0);
    // A limit the runs do not depend on is judged again at once, without a study.
    Specification spec = session_->session().spec;
    spec.maxOvershootPct = 50.0;
    session_->setSpecification(spec);
    QVERIFY(!view_->isRunning());
    QCOMPARE(view_->studiedProblem()->spec.maxOvershootPct, 50.0);
    QTest::qWait(DesignSpaceView::kLiveRestMs + 200);
    QCOMPARE(spy.count(), 2);
}

void TstDesignSpaceView::liveOffOrHiddenComputesNothing() {
    setSmallGrid(4, 2.0);
    ThirdOrderPlant plant = session_->session().axes[0].gt.plant;
    plant.a1 *= 1.2;
    session_->setPlant(0, plant); // live off (init): nothing
    QVERIFY(!view_->isRunning());
    QVERIFY(!view_->result());
    // Hidden (another tab): live on computes nothing until shown.
    view_->hide();
    view_->liveBox()->setChecked(true);
    plant.a2 *= 1.2;
    session_->setPlant(0, plant);
    QVERIFY(!view_->isRunning());
    QSignalSpy spy(view_.get(), &DesignSpaceView::studyFinished);
    view_->show();
    QVERIFY(view_->isRunning() && view_->runningKind() == Kind::Preview);
    QVERIFY(nextFinished(spy, 0) == Kind::Preview);
    QVERIFY(view_->studiedProblem()->plant == plant);
    // Turning live off during the rest stops the full study from following.
    view_->liveBox()->setChecked(false);
    QTest::qWait(DesignSpaceView::kLiveRestMs + 200);
    QCOMPARE(spy.count(), 1);
    QVERIFY(view_->resultIsPreview());
    QVERIFY(!view_->isRunning());
}

void TstDesignSpaceView::liveMapSkipsAPolePlacementAxis() {
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    view_->liveBox()->setChecked(true);
    QVERIFY(!view_->isRunning()); // nothing to map for pole placement
    QVERIFY(!view_->result());
    QTest::mouseClick(view_->runButton(), Qt::LeftButton); // asked for: says why not
    QVERIFY(view_->statusText().contains("pole placement"));
    session_->setMethod(0, DesignMethod::GuilleminTruxal); // back to GT: the map follows
    QVERIFY(view_->isRunning() && view_->runningKind() == Kind::Preview);
}

void TstDesignSpaceView::outlineEnclosesTheFeasibleCells_data() {
    QTest::addColumn<int>("wnCount");
    QTest::addColumn<int>("kpCount");
    QTest::addColumn<std::vector<std::uint8_t>>("mask");
    QTest::addColumn<int>("loops");
    // Rows are wn, columns kp (DesignSweepResult indexing).
    QTest::newRow("one cell: one square")
        << 3 << 3 << std::vector<std::uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, 0} << 1;
    QTest::newRow("all feasible: the grid's border")
        << 2 << 3 << std::vector<std::uint8_t>(6, 1) << 1;
    QTest::newRow("ring: outer and inner loop")
        << 3 << 3 << std::vector<std::uint8_t>{1, 1, 1, 1, 0, 1, 1, 1, 1} << 2;
    QTest::newRow("two apart") << 1 << 3 << std::vector<std::uint8_t>{1, 0, 1} << 2;
    QTest::newRow("diagonal pair touching at a corner")
        << 2 << 2 << std::vector<std::uint8_t>{1, 0, 0, 1} << 2;
    QTest::newRow("none") << 2 << 2 << std::vector<std::uint8_t>(4, 0) << 0;
}

void TstDesignSpaceView::outlineEnclosesTheFeasibleCells() {
    QFETCH(int, wnCount);
    QFETCH(int, kpCount);
    QFETCH(std::vector<std::uint8_t>, mask);
    QFETCH(int, loops);
    const auto feasible = [&](int a, int b) {
        return a >= 0 && b >= 0 && a < wnCount && b < kpCount &&
               mask[static_cast<std::size_t>(a * kpCount + b)];
    };
    // Invariant: the outline's unit edges are exactly the sides between a feasible cell and a
    // non-feasible cell or the outside, each once, and every loop is closed.
    int perimeter = 0;
    for (int a = 0; a < wnCount; ++a)
        for (int b = 0; b < kpCount; ++b)
            if (feasible(a, b))
                perimeter += !feasible(a - 1, b) + !feasible(a + 1, b) + !feasible(a, b - 1) +
                             !feasible(a, b + 1);
    const auto outline = feasibleOutline(mask, wnCount, kpCount);
    QCOMPARE(static_cast<int>(outline.size()), loops);
    std::set<std::pair<std::pair<int, int>, std::pair<int, int>>> seen;
    int edges = 0;
    for (const auto& loop : outline) {
        QVERIFY(loop.size() >= 5);
        QVERIFY(loop.front() == loop.back());
        for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
            const int da = loop[k + 1].iWn - loop[k].iWn, db = loop[k + 1].iKp - loop[k].iKp;
            QCOMPARE(std::abs(da) + std::abs(db), 1);
            // The feasible cell lies on the left of the edge (counter-clockwise in wn x kp).
            const int a0 = loop[k].iWn, b0 = loop[k].iKp;
            const int cellA = da == 1 || db == -1 ? a0 : a0 - 1;
            const int cellB = da == 1 || db == 1 ? b0 : b0 - 1;
            QVERIFY2(feasible(cellA, cellB), qPrintable(QString("edge %1 of a loop").arg(k)));
            QVERIFY(seen.insert({{loop[k].iWn, loop[k].iKp}, {loop[k + 1].iWn, loop[k + 1].iKp}})
                        .second);
            ++edges;
        }
    }
    QCOMPARE(edges, perimeter);
}

void TstDesignSpaceView::cellEdgesAreMidpointsInTheAxisScale() {
    // Closed forms: log grid 1, 10, 100 -> geometric means sqrt(10), sqrt(1000) and mirrored
    // outer edges 1/sqrt(10), 1000/sqrt(10); linear grid 1, 2, 4 -> 1.5, 3 and 0.5, 5.
    const auto logEdges = cellEdges({1.0, 10.0, 100.0}, true);
    const std::vector<double> logExpected{1.0 / std::sqrt(10.0), std::sqrt(10.0), std::sqrt(1000.0),
                                          1000.0 / std::sqrt(10.0)};
    const auto linEdges = cellEdges({1.0, 2.0, 4.0}, false);
    const std::vector<double> linExpected{0.5, 1.5, 3.0, 5.0};
    QCOMPARE(logEdges.size(), std::size_t(4));
    QCOMPARE(linEdges.size(), std::size_t(4));
    for (std::size_t i = 0; i < 4; ++i) {
        // A square root and a division: a few ulps.
        XYT_COMPARE_NEAR(logEdges[i], logExpected[i], 1e-15, 0.0);
        XYT_COMPARE_NEAR(linEdges[i], linExpected[i], 1e-15, 0.0);
    }
}

QTEST_MAIN(TstDesignSpaceView)
#include "tst_design_space_view.moc"
