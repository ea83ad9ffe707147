// SPDX-License-Identifier: GPL-3.0-or-later
// The robustness view drives the core's analyzeRobustness: what it draws is the
// core's result for the same problem (computed here again), the worst case loads as one undo
// step, a design change clears a result that no longer applies, and a run can be cancelled or
// outlived by the view. In XY-contour mode it drives analyzeContourRobustness the same way: the
// envelope, histogram and XY band drawn are the core's joint result, the worst pair loads into
// both axes as one undo step, and the mode follows the trajectory (no contour for a cubic).
#include "core/session/robustness_problem.h"
#include "tests/support/plot_layout_checks.h"
#include "tests/support/tolerance.h"
#include "ui/panels/stale_veil.h"
#include "ui/plots/contour_band_plot.h"
#include "ui/plots/envelope_plot.h"
#include "ui/plots/histogram_plot.h"
#include "ui/plots/sensitivity_plot.h"
#include "ui/robustness_view.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using namespace xyt;
using namespace xyt::ui;

namespace {
constexpr int kTimeoutMs = 120000;
}

class TstRobustnessView : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void drawsTheCoresResult();
    void worstCaseLoadsAsOneUndoStep();
    void designChangeVeilsTheResult();
    void polePlacementAxisHasItsCoefficients();
    void cancelAndDestroyWhileRunning();
    void contourModeDrawsTheCoresJointResult();
    void contourWorstPairLoadsBothAxesInOneStep();
    void contourModeFollowsTheTrajectory();
    void computedResultsAreReadable_data();
    void computedResultsAreReadable();

private:
    void runAndWait();
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<RobustnessView> view_;
};

void TstRobustnessView::init() {
    session_ = std::make_unique<TuningSession>();
    view_ = std::make_unique<RobustnessView>(session_.get());
    view_->resize(1000, 500);
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
}

void TstRobustnessView::cleanup() {
    view_.reset();
    session_.reset();
}

void TstRobustnessView::runAndWait() {
    QSignalSpy spy(view_.get(), &RobustnessView::analysisFinished);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    QVERIFY(spy.wait(kTimeoutMs));
}

void TstRobustnessView::drawsTheCoresResult() {
    QCOMPARE(view_->parameterNames().size(), 3); // k0, a1, a2 of the GT plant
    QVERIFY(!view_->envelopePlot()->hasResult());
    view_->rangeBox("k0")->setValue(10.0);
    view_->rangeBox("a2")->setValue(5.0);
    view_->samplesBox()->setValue(30);
    view_->seedBox()->setValue(4);
    runAndWait();
    RobustnessProblem p = sessionRobustnessProblem(session_->session(), 0);
    setRelativeRange(p.parameters, "k0", 0.10);
    setRelativeRange(p.parameters, "a2", 0.05);
    RobustnessOptions o;
    o.samples = 30;
    o.seed = 4;
    const RobustnessResult r = analyzeRobustness(p, o);
    QCOMPARE(view_->result()->runs.size(), std::size_t(34)); // 30 and 4 corners
    // The envelope drawn is the core's (error by default), point for point.
    const auto* maxData = view_->envelopePlot()->maxGraph()->data().data();
    QCOMPARE(maxData->size(), static_cast<int>(r.error.t.size()));
    for (int i = 0; i < maxData->size(); i += 37) {
        QCOMPARE(maxData->at(i)->key, r.error.t[static_cast<std::size_t>(i)]);
        QCOMPARE(maxData->at(i)->value, r.error.max[static_cast<std::size_t>(i)]);
        QCOMPARE(view_->envelopePlot()->nominalGraph()->data()->at(i)->value,
                 r.error.nominal[static_cast<std::size_t>(i)]);
    }
    // The histogram counts every stable plant once; max |u| has the actuator limit drawn.
    view_->figureBox()->setCurrentIndex(2);
    double total = 0.0;
    for (auto it = view_->histogramPlot()->bars()->data()->constBegin();
         it != view_->histogramPlot()->bars()->data()->constEnd(); ++it)
        total += it->value;
    QCOMPARE(static_cast<int>(total), r.maxAbsU.count);
    QCOMPARE(view_->histogramPlot()->limitDrawn(), session_->session().umaxVolts);
    QCOMPARE(view_->histogramPlot()->nominalDrawn(), r.nominal.tracking.maxAbsU);
    // The other signals and figures come from the same result.
    view_->signalBox()->setCurrentIndex(2);
    QCOMPARE(view_->envelopePlot()->minGraph()->data()->at(0)->value, r.command.min[0]);
    QVERIFY(view_->statusText().contains(QString::number(100.0 * r.fractionMeetingSpec, 'g', 3) +
                                         " % meet"));
    // A Guillemin-Truxal axis has no ZPETC: the sensitivity choice says so.
    view_->figureBox()->setCurrentIndex(3);
    QVERIFY(!view_->sensitivityPlot()->hasResult());
    QVERIFY(view_->sensitivityPlot()->noticeText().contains("ZPETC"));
    QVERIFY(view_->sensitivityCurve().empty());
    QVERIFY(view_->worstButton()->isEnabled());
}

void TstRobustnessView::worstCaseLoadsAsOneUndoStep() {
    view_->rangeBox("k0")->setValue(20.0);
    view_->samplesBox()->setValue(10);
    view_->cornersBox()->setChecked(false);
    runAndWait();
    const ThirdOrderPlant before = session_->session().axes[0].gt.plant;
    const std::vector<double> worst = view_->result()->runs[*view_->result()->worst].values;
    QTest::mouseClick(view_->worstButton(), Qt::LeftButton);
    const ThirdOrderPlant after = session_->session().axes[0].gt.plant;
    QCOMPARE(after.k0, worst[0]);
    QCOMPARE(after.a1, before.a1);
    QCOMPARE(after.a2, before.a2);
    // The analysis was of the old nominal plant: veiled, and the button off.
    QVERIFY(!view_->resultIsCurrent() && view_->veil()->isVeiled());
    QVERIFY(!view_->worstButton()->isEnabled());
    session_->undoStack()->undo();
    QVERIFY(session_->session().axes[0].gt.plant == before);
    QVERIFY(view_->resultIsCurrent()); // of this plant again
}

void TstRobustnessView::designChangeVeilsTheResult() {
    view_->samplesBox()->setValue(5);
    runAndWait();
    QVERIFY(view_->envelopePlot()->hasResult());
    QVERIFY(!view_->veil()->isVeiled());
    const double kp = session_->session().axes[0].gt.kp;
    session_->setKp(0, 40.0); // another controller: the result no longer applies
    // Kept under a veil that says what it was computed for, never shown as this design's.
    QVERIFY(view_->result().has_value());
    QVERIFY(!view_->resultIsCurrent());
    QVERIFY(view_->veil()->isVeiled());
    QVERIFY2(view_->veil()->note().contains(QString("kp = %1").arg(kp)) &&
                 view_->veil()->note().contains("design has changed"),
             qPrintable(view_->veil()->note()));
    QVERIFY(!view_->worstButton()->isEnabled());
    // A change of the other axis leaves it alone.
    runAndWait();
    QVERIFY(!view_->veil()->isVeiled());
    session_->setKp(1, 45.0);
    QVERIFY(view_->result().has_value());
    QVERIFY(view_->resultIsCurrent());
    QVERIFY(!view_->veil()->isVeiled());
}

void TstRobustnessView::polePlacementAxisHasItsCoefficients() {
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    // Patrick, Ishak and Adnan's x-axis model: A = 1 + a1 z^-1 + a2 z^-2, B = b1 z^-1 + b2 z^-2 +
    // b3 z^-3.
    QCOMPARE(view_->parameterNames(), (QStringList{"a1", "a2", "b1", "b2", "b3"}));
    view_->rangeBox("b1")->setValue(20.0);
    view_->samplesBox()->setValue(8);
    runAndWait();
    QCOMPARE(view_->result()->runs.size(), std::size_t(10));
    QVERIFY(view_->result()->rmseWithoutFf.count > 0);
    // The ZPETC sensitivity curve is the core's at 0, 25, 50, 75 and 100 % of the ranges.
    RobustnessProblem p = sessionRobustnessProblem(session_->session(), 0);
    setRelativeRange(p.parameters, "b1", 0.2);
    RobustnessOptions o;
    o.samples = 8;
    const auto curve = zpetcSensitivity(p, RobustnessView::sensitivityScales(), o);
    view_->figureBox()->setCurrentIndex(3);
    QVERIFY(view_->sensitivityPlot()->isVisible());
    QVERIFY(view_->sensitivityPlot()->hasResult());
    QCOMPARE(view_->sensitivityPlot()->withFfGraph()->data()->size(), 5);
    for (int i = 0; i < 5; ++i) {
        QCOMPARE(view_->sensitivityPlot()->withFfGraph()->data()->at(i)->value,
                 curve[static_cast<std::size_t>(i)].rmseWithFf.p50);
        QCOMPARE(view_->sensitivityPlot()->withoutFfGraph()->data()->at(i)->value,
                 curve[static_cast<std::size_t>(i)].rmseWithoutFf.p50);
    }
    QVERIFY(curve.back().medianImprovementPct < curve.front().medianImprovementPct);
    const std::vector<double> worst = view_->result()->runs[*view_->result()->worst].values;
    view_->loadWorstCase();
    QCOMPARE(session_->session().axes[0].pp.b[1], worst[2]);
    QCOMPARE(session_->session().axes[0].method, DesignMethod::PolePlacementZpetc);
}

void TstRobustnessView::cancelAndDestroyWhileRunning() {
    view_->rangeBox("k0")->setValue(10.0);
    view_->samplesBox()->setValue(100000);
    QSignalSpy spy(view_.get(), &RobustnessView::analysisFinished);
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QTest::qWait(100);
    QTest::mouseClick(view_->cancelButton(), Qt::LeftButton);
    QVERIFY(spy.wait(kTimeoutMs));
    QVERIFY(view_->statusText().startsWith("Cancelled after"));
    QVERIFY(view_->result()->computedCount < 100000);
    // Destroying the view while a run is under way joins it (no crash, no late callback).
    QTest::mouseClick(view_->runButton(), Qt::LeftButton);
    QVERIFY(view_->isRunning());
    view_.reset();
    QTest::qWait(50);
}

void TstRobustnessView::contourModeDrawsTheCoresJointResult() {
    QVERIFY(!view_->contourBox()->isEnabled()); // the paper's cubic: no contour
    TrajectorySettings t = session_->session().trajectory;
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    QVERIFY(view_->contourBox()->isEnabled());
    view_->contourBox()->setChecked(true);
    // Both axes are Guillemin-Truxal: one row per name, applied to both.
    QCOMPARE(view_->parameterNames().size(), 3);
    QCOMPARE(view_->figureBox()->count(), 2);
    QCOMPARE(view_->signalBox()->currentText(), QString("contour error"));
    view_->rangeBox("k0")->setValue(10.0);
    view_->samplesBox()->setValue(12);
    view_->seedBox()->setValue(9);
    runAndWait();
    QVERIFY(!view_->result()); // the joint result replaces the axis one
    QVERIFY(view_->contourResult().has_value());
    ContourRobustnessProblem p = sessionContourRobustnessProblem(session_->session());
    setRelativeRange(p.x.parameters, "k0", 0.1);
    setRelativeRange(p.y.parameters, "k0", 0.1);
    RobustnessOptions o;
    o.samples = 12;
    o.seed = 9;
    const ContourRobustnessResult r = analyzeContourRobustness(p, o);
    QCOMPARE(view_->contourResult()->runs.size(),
             std::size_t(12 + 4)); // 2 uncertain parameters: 4 corners
    QCOMPARE(view_->contourResult()->maxAbsContourError.p95, r.maxAbsContourError.p95);
    // The envelope is the contour error's, point for point.
    const auto* maxData = view_->envelopePlot()->maxGraph()->data().data();
    QCOMPARE(maxData->size(), static_cast<int>(r.error.t.size()));
    for (int i = 0; i < maxData->size(); i += 41)
        QCOMPARE(maxData->at(i)->value, r.error.max[static_cast<std::size_t>(i)]);
    // The XY band (the default figure): one piece for the circle, drawn magnified about it.
    ContourBandPlot* band = view_->bandPlot();
    QVERIFY(band->isVisible());
    QVERIFY(band->hasResult());
    QCOMPARE(band->innerBands().size(), std::size_t(1));
    const double m = band->magnification();
    QVERIFY(m >= 1.0);
    QVERIFY(band->titleText().contains(QString::number(m, 'g', 4)));
    const auto* nominal = band->nominalCurves().front()->data().data();
    QCOMPARE(nominal->size(), static_cast<int>(r.base.size()));
    for (int j = 0; j < nominal->size(); j += 53) {
        const auto k = static_cast<std::size_t>(j);
        QVERIFY(test::near(nominal->at(j)->key,
                           r.base[k].x + m * r.error.nominal[k] * r.normal[k].x, 1e-12, 1e-12));
        QVERIFY(test::near(nominal->at(j)->value,
                           r.base[k].y + m * r.error.nominal[k] * r.normal[k].y, 1e-12, 1e-12));
    }
    // The 5-95 % polygon: its upper edge forward, its lower edge back.
    const auto* inner = band->innerBands().front()->data().data();
    QCOMPARE(inner->size(), 2 * static_cast<int>(r.base.size()));
    // The histogram counts every stable pair once.
    view_->figureBox()->setCurrentIndex(0);
    QVERIFY(view_->histogramPlot()->isVisible());
    double total = 0.0;
    for (auto it = view_->histogramPlot()->bars()->data()->constBegin();
         it != view_->histogramPlot()->bars()->data()->constEnd(); ++it)
        total += it->value;
    QCOMPARE(static_cast<int>(total), r.maxAbsContourError.count);
    QCOMPARE(view_->histogramPlot()->nominalDrawn(), r.nominal.maxAbsContourError);
    QVERIFY(view_->statusText().contains("plant pairs"));
    QVERIFY(view_->statusText().contains("x.k0 = "));
    if (qEnvironmentVariableIsSet("XYT_SCREENSHOT_DIR")) { // to look at it (not an assertion)
        view_->figureBox()->setCurrentIndex(1);
        for (const QSize size : {QSize(1340, 330), QSize(1000, 500)}) {
            view_->resize(size);
            QTest::qWait(50);
            view_->grab().save(qEnvironmentVariable("XYT_SCREENSHOT_DIR") +
                               QStringLiteral("/robustness_contour_%1.png").arg(size.width()));
        }
        view_->figureBox()->setCurrentIndex(0);
    }
    // A change of either axis veils the joint result, naming both axes' designs it was for.
    const double kpY = session_->session().axes[1].gt.kp;
    session_->setKp(1, 45.0);
    QVERIFY(view_->contourResult().has_value());
    QVERIFY(!view_->resultIsCurrent());
    QVERIFY(view_->veil()->isVeiled());
    QVERIFY2(view_->veil()->note().contains(QString("kp = %1").arg(kpY)) &&
                 view_->veil()->note().contains("design has changed"),
             qPrintable(view_->veil()->note()));
    QVERIFY(!view_->worstButton()->isEnabled());
}

void TstRobustnessView::contourWorstPairLoadsBothAxesInOneStep() {
    TrajectorySettings t = session_->session().trajectory;
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    session_->setMethod(
        0,
        DesignMethod::PolePlacementZpetc); // Patrick, Ishak and Adnan's circle, x by pole placement
    view_->contourBox()->setChecked(true);
    // The union of both axes' names: the ARX a1, a2, b1..b3 and the plant's k0 (a1, a2 shared).
    QCOMPARE(view_->parameterNames().size(), 6);
    view_->rangeBox("b1")->setValue(10.0);
    view_->rangeBox("k0")->setValue(10.0);
    view_->samplesBox()->setValue(6);
    view_->cornersBox()->setChecked(false);
    runAndWait();
    const ContourRobustnessResult r =
        *view_->contourResult(); // (a copy: loading clears the view's)
    const std::vector<double> worst = r.runs[*r.worst].values;
    const std::size_t steps = static_cast<std::size_t>(session_->undoStack()->count());
    const Session before = session_->session();
    QTest::mouseClick(view_->worstButton(), Qt::LeftButton);
    QCOMPARE(static_cast<std::size_t>(session_->undoStack()->count()), steps + 1);
    const auto at = [&](const std::string& name) {
        const auto it = std::find(r.parameterNames.begin(), r.parameterNames.end(), name);
        return worst[static_cast<std::size_t>(it - r.parameterNames.begin())];
    };
    QCOMPARE(session_->session().axes[0].pp.b[1], at("x.b1"));
    QCOMPARE(session_->session().axes[1].gt.plant.k0, at("y.k0"));
    QCOMPARE(session_->session().axes[1].gt.plant.a1, before.axes[1].gt.plant.a1);
    session_->undoStack()->undo();
    QVERIFY(session_->session().axes == before.axes);
}

void TstRobustnessView::contourModeFollowsTheTrajectory() {
    TrajectorySettings t = session_->session().trajectory;
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    view_->contourBox()->setChecked(true);
    view_->samplesBox()->setValue(3);
    runAndWait();
    QVERIFY(view_->contourResult().has_value());
    // Back to the cubic: no contour to analyze; the mode and its result go.
    t.kind = TrajectoryKind::Cubic;
    session_->setTrajectory(t);
    QVERIFY(!view_->contourBox()->isEnabled());
    QVERIFY(!view_->contourBox()->isChecked());
    QVERIFY(!view_->contourResult());
    QCOMPARE(view_->figureBox()->count(), 4);
    QVERIFY(!view_->bandPlot()->hasResult());
    // Switching modes by hand clears the other mode's result too.
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    runAndWait();
    QVERIFY(view_->result().has_value());
    view_->contourBox()->setChecked(true);
    QVERIFY(!view_->result());
    QVERIFY(!view_->envelopePlot()->hasResult());
}

void TstRobustnessView::computedResultsAreReadable_data() {
    QTest::addColumn<bool>("contour");
    QTest::addColumn<double>("rangePct");
    QTest::newRow("axis, no uncertainty") << false << 0.0; // every plant the nominal one
    QTest::newRow("axis, k0 20 %") << false << 20.0;
    QTest::newRow("contour, no uncertainty") << true << 0.0;
    QTest::newRow("contour, k0 20 %") << true << 20.0;
}

void TstRobustnessView::computedResultsAreReadable() {
    // Each plot of a computed result, in each figure, at the sizes the tab has in a 1366x768
    // and a 1600x1000 window: annotations inside and apart, legends whole, tick labels apart.
    // With every plant the nominal one the histogram's range was a round-off wide and its
    // tick labels ran together ("3.34853.3486...").
    QFETCH(bool, contour);
    QFETCH(double, rangePct);
    if (contour) {
        TrajectorySettings t = session_->session().trajectory;
        t.kind = TrajectoryKind::Circle;
        session_->setTrajectory(t);
        view_->contourBox()->setChecked(true);
    }
    view_->rangeBox("k0")->setValue(rangePct);
    view_->samplesBox()->setValue(24);
    view_->seedBox()->setValue(3);
    runAndWait();
    QVERIFY(contour ? view_->contourResult().has_value() : view_->result().has_value());
    QStringList problems;
    for (const QSize size : {QSize(560, 390), QSize(800, 480)}) {
        view_->resize(size);
        for (int figure = 0; figure < view_->figureBox()->count(); ++figure) {
            view_->figureBox()->setCurrentIndex(figure);
            QTest::qWait(20);
            for (auto* plot : view_->findChildren<QCustomPlot*>()) {
                if (!plot->isVisible())
                    continue;
                plot->replot(QCustomPlot::rpImmediateRefresh);
                plot->replot(
                    QCustomPlot::rpImmediateRefresh); // as shown: after the guard's re-layout
                for (const QString& p : test::annotationProblems(plot))
                    problems << QString("%1x%2, %3: %4")
                                    .arg(size.width())
                                    .arg(size.height())
                                    .arg(view_->figureBox()->currentText(), p);
            }
        }
    }
    problems.removeDuplicates();
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
}

QTEST_MAIN(TstRobustnessView)
#include "tst_robustness_view.moc"
