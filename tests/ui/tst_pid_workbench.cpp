// SPDX-License-Identifier: GPL-3.0-or-later
// The PID + feedforward method in the workbench, driven through its real widgets offscreen:
// its editor (the feedforward sliders in percent of the model, "From model", the derivative
// source, a slider drag as one undo step), the time plot's split of u, the Bode view's tracking
// with the feedforward, the quintic profile, Design › Add feedforward from the model and the
// tuning dialog. Each value is checked against the core (the presenter's evaluation, or the
// core function the widget shows).
#include "core/design/model_feedforward.h"
#include "core/design/pid_tuning.h"
#include "core/design/relay_experiment.h"
#include "core/session/pid_feedforward_method.h"
#include "tests/support/gui_checks.h"
#include "tests/support/tolerance.h"
#include "ui/design_space_view.h"
#include "ui/main_window.h"
#include "ui/panels/method_parameter_editor.h"
#include "ui/panels/number_field.h"
#include "ui/panels/parameter_slider.h"
#include "ui/panels/pid_feedforward_editor.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/pid_tuning_dialog.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/design_space_plot.h"
#include "ui/plots/number_text.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/robustness_view.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

#include <qcustomplot.h>

using namespace xyt;
using namespace xyt::ui;

class TstPidWorkbench : public QObject {
    Q_OBJECT
private slots:
    void init();
    void choosingTheMethodShowsItsEditor();
    void feedforwardSlidersAreInPercentOfTheModel();
    void timePlotSplitsTheCommand();
    void bodeShowsTrackingWithTheFeedforward();
    void quinticProfileIsChosenBesideTheKind();
    void addFeedforwardTurnsThePaperPiIntoPiPlusFeedforward();
    void tuningDialogAppliesEachRule();
    void draggingAZeroOnTheRootLocusMovesIt();
    void robustnessSaysWhatTheFeedforwardStillGains();
    void designSpaceMapsThePiAndLoadsACell();
    void draggingAPoleAlongTheLocusSetsTheGain();

private:
    PidFeedforwardEditor* editor() const { return window_->findChild<PidFeedforwardEditor*>(); }
    void choosePid();

    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstPidWorkbench::init() {
    QCoreApplication::setOrganizationName("xytune-tests");
    window_.reset(); // before its session
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstPidWorkbench::choosePid() {
    QComboBox* method = window_->methodBox();
    const int index = method->findText(QStringLiteral("PID + feedforward"));
    QVERIFY(index >= 0);
    method->setCurrentIndex(index);
    emit method->activated(index);
    QCOMPARE(session_->session().axes[0].method, DesignMethod::PidFeedforward);
}

void TstPidWorkbench::choosingTheMethodShowsItsEditor() {
    choosePid();
    QVERIFY(editor() && editor()->isVisible());
    // The defaults: Braga et al.'s PI in mm units and the model's feedforward at 100 %.
    QCOMPARE(editor()->gainsEditor()->field("p")->value(), 0.03);
    for (int k = 1; k <= 3; ++k)
        XYT_COMPARE_NEAR(editor()->feedforwardSlider(k)->value(), 100.0, 1e-12, 0.0);
    QVERIFY(!editor()->derivativeOnMeasurementBox()->isChecked());
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
    // A refused value at the field: a negative D.
    test::typeInto(editor()->gainsEditor()->field("d"), "-1");
    QVERIFY(editor()->gainsEditor()->field("d")->hasError());
    QCOMPARE(session_->session().axes[0].parameters.count("d"), std::size_t{0});
    // The same editor shows the other axis' settings when it is chosen (after switching it too).
    session_->setCurrentAxis(1);
    QVERIFY(!editor()->isVisible()); // y is still Guillemin-Truxal
    session_->setCurrentAxis(0);
    QVERIFY(editor()->isVisible());
}

void TstPidWorkbench::feedforwardSlidersAreInPercentOfTheModel() {
    choosePid();
    const ModelFeedforwardGains model = modelFeedforwardGains({77.8, 125.3, 3665.0}, 0.001);
    ParameterSlider* ff1 = editor()->feedforwardSlider(1);
    const int steps = session_->undoStack()->count();
    // A drag: several values, one undo step, the last value kept.
    for (double percent : {90.0, 70.0, 50.0})
        emit ff1->valueChanged(percent);
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    XYT_COMPARE_NEAR(session_->session().axes[0].parameters.at("ff1"), 0.5 * model.ff1, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ff1->value(), 50.0, 1e-12, 0.0);
    // Half the velocity feedforward costs tracking: the RMSE grows (the design's run).
    const double rmseHalf = session_->axisEvaluation(0).metrics.rmse;
    QTest::mouseClick(editor()->fromModelButton(), Qt::LeftButton);
    XYT_COMPARE_NEAR(session_->session().axes[0].parameters.at("ff1"), model.ff1, 1e-15, 0.0);
    XYT_COMPARE_NEAR(ff1->value(), 100.0, 1e-12, 0.0);
    QVERIFY(session_->axisEvaluation(0).metrics.rmse < 1e-3 * rmseHalf);
    // The derivative source and the D-on-measurement choice are one step each.
    QComboBox* source = editor()->derivativeSourceBox();
    source->setCurrentIndex(1);
    emit source->activated(1);
    QCOMPARE(session_->session().axes[0].parameters.at("command_derivatives"), 1.0);
    QTest::mouseClick(editor()->derivativeOnMeasurementBox(), Qt::LeftButton);
    QCOMPARE(session_->session().axes[0].parameters.at("derivative_on_measurement"), 1.0);
    session_->undoStack()->undo();
    QVERIFY(!editor()->derivativeOnMeasurementBox()->isChecked());
    // A plant without an inverse (k0 = 0 is refused by the plant editor, so the model text is
    // checked on a plant the editor is given directly).
    AxisSettings broken = session_->session().axes[0];
    broken.gt.plant.k0 = 0.0;
    editor()->setSettings(broken);
    QVERIFY(!editor()->fromModelButton()->isEnabled());
    QVERIFY(editor()->modelText().contains("no usable inverse"));
    editor()->setSettings(session_->session().axes[0]);
    QVERIFY(editor()->fromModelButton()->isEnabled());
}

void TstPidWorkbench::timePlotSplitsTheCommand() {
    choosePid();
    window_->lowerTabs()->setCurrentWidget(window_->timePlot());
    QApplication::processEvents();
    TimeResponsePlot* time = window_->timePlot();
    const SimulationResult& run = session_->axisEvaluation(0).run;
    QVERIFY(time->feedforwardGraph()->visible());
    QVERIFY(time->controlLegend()->visible());
    QVERIFY(test::sameSignal(time->feedforwardGraph()->data(), run.t, run.uFeedforward));
    std::vector<double> rest(run.u.size());
    for (std::size_t k = 0; k < rest.size(); ++k)
        rest[k] = run.u[k] - run.uFeedforward[k];
    QVERIFY(test::sameSignal(time->feedbackPartGraph()->data(), run.t, rest));
    // Back to the Guillemin-Truxal PI: no feedforward, no split.
    QComboBox* method = window_->methodBox();
    method->setCurrentIndex(0);
    emit method->activated(0);
    QApplication::processEvents();
    QVERIFY(!time->feedforwardGraph()->visible());
    QVERIFY(!time->controlLegend()->visible());
}

void TstPidWorkbench::bodeShowsTrackingWithTheFeedforward() {
    choosePid();
    window_->upperTabs()->setCurrentWidget(window_->bodePlot());
    QApplication::processEvents();
    // With the model's exact inverse the tracking r -> y is 0 dB at every frequency
    // (T + S F G/u = 1): every drawn point within 1e-6 dB.
    const QCPGraph* with =
        window_->bodePlot()->magnitudeGraph(QStringLiteral("tracking with feedforward"));
    QVERIFY(with && !with->data()->isEmpty());
    for (auto it = with->data()->constBegin(); it != with->data()->constEnd(); ++it)
        QVERIFY2(std::abs(it->value) < 1e-6, qPrintable(QString::number(it->value)));
    QVERIFY(window_->bodePlot()->magnitudeGraph(QStringLiteral("tracking, loop alone")));
    // Half the feedforward: no longer flat.
    emit editor()->feedforwardSlider(1)->valueChanged(50.0);
    QApplication::processEvents();
    with = window_->bodePlot()->magnitudeGraph(QStringLiteral("tracking with feedforward"));
    double largest = 0.0;
    for (auto it = with->data()->constBegin(); it != with->data()->constEnd(); ++it)
        largest = std::max(largest, std::abs(it->value));
    QVERIFY(largest > 1.0);
    // A Guillemin-Truxal axis has no tracking curves.
    session_->setCurrentAxis(1);
    QApplication::processEvents();
    QVERIFY(!window_->bodePlot()->magnitudeGraph(QStringLiteral("tracking with feedforward")));
}

void TstPidWorkbench::quinticProfileIsChosenBesideTheKind() {
    TrajectoryEditor* trajectory = window_->trajectoryEditor();
    QComboBox* profile = trajectory->profileBox();
    QVERIFY(profile->isVisible());
    profile->setCurrentIndex(1);
    emit profile->activated(1);
    QCOMPARE(session_->session().trajectory.profile, MoveProfile::Quintic);
    // The reference is the quintic: half way it is half way, a quarter in it is 600 (10/64 -
    // 15/256 + 6/1024) = 600 * 0.103515625 mm.
    const SimulationResult& run = session_->axisEvaluation(0).run;
    XYT_COMPARE_NEAR(run.r[3250], 600.0 * 0.103515625, 1e-12, 0.0);
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
    // The circle has no profile to choose.
    QComboBox* kind = trajectory->kindBox();
    kind->setCurrentIndex(1);
    emit kind->activated(1);
    QVERIFY(!profile->isVisible());
    session_->undoStack()->undo();
    QVERIFY(profile->isVisible());
    QCOMPARE(profile->currentIndex(), 1);
}

void TstPidWorkbench::addFeedforwardTurnsThePaperPiIntoPiPlusFeedforward() {
    QAction* add =
        test::findMenuAction(window_->menuBar(), "Design/Add feedforward from the model");
    QVERIFY(add && add->isEnabled());
    QVERIFY(!window_->tuneAction()->isEnabled()); // a Guillemin-Truxal axis
    const GtDesign gt = *session_->axisEvaluation(0).gt;
    add->trigger();
    const AxisSettings& x = session_->session().axes[0];
    QCOMPARE(x.method, DesignMethod::PidFeedforward);
    QCOMPARE(x.parameters.at("p"), gt.kp * 0.001);
    QCOMPARE(x.parameters.at("i"), gt.ki * 0.001);
    QCOMPARE(x.parameters.at("ff1"), modelFeedforwardGains(x.gt.plant, 0.001).ff1);
    QVERIFY(window_->tuneAction()->isEnabled());
    QCOMPARE(window_->methodBox()->currentText(), QStringLiteral("PID + feedforward"));
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
    session_->undoStack()->undo();
    QCOMPARE(session_->session().axes[0].method, DesignMethod::GuilleminTruxal);
    // A pole-placement axis: the action is disabled.
    session_->setCurrentAxis(1);
    Session next = session_->session();
    next.axes[1].method = DesignMethod::PolePlacementZpetc;
    session_->apply(next, "pole placement");
    QVERIFY(!add->isEnabled());
}

void TstPidWorkbench::tuningDialogAppliesEachRule() {
    choosePid();
    PidTuningDialog dialog(session_.get(), 0, window_.get());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    // Row 0 is the core's closed form for the fields' target (PI, 5 rad/s, 60 deg).
    const ThirdOrderPlant plant{77.8, 125.3, 3665.0};
    PidTuningResult expected = tunePidForMargin(plant, 0.001, PidStructure::Pi, 5.0, 60.0);
    QVERIFY(dialog.proposal(0).ok);
    QCOMPARE(dialog.proposal(0).p, expected.p);
    XYT_COMPARE_NEAR(dialog.proposal(0).phaseMarginDeg, 60.0, 0.0, 1e-6);
    // PID and another target through the widgets.
    dialog.structureBox()->setCurrentIndex(1);
    emit dialog.structureBox()->activated(1);
    test::typeInto(dialog.crossoverField(), "10");
    expected = tunePidForMargin(plant, 0.001, PidStructure::Pid, 10.0, 60.0);
    QCOMPARE(dialog.proposal(0).d, expected.d);
    // The relay rows: the exact limit cycle's Ku and Tu through the rules.
    const RelayLimitCycle cycle = relayLimitCycle(plant, 0.001, 1.0);
    const UltimateCycleGains zn =
        ultimateCycleGains(cycle.ultimateGainVoltsPerMm, cycle.periodSeconds,
                           UltimateCycleRule::ZieglerNichols, PidStructure::Pid);
    QCOMPARE(dialog.proposal(1).p, zn.p);
    QCOMPARE(dialog.proposal(1).d, zn.d);
    QVERIFY(dialog.relayText().contains(significant(cycle.periodSeconds, 4)));
    QVERIFY(!dialog.relayPlot()->graph(0)->data()->isEmpty());
    // Apply Tyreus-Luyben: P, I, D of the axis, the feedforward kept, one undo step.
    const int steps = session_->undoStack()->count();
    const double ff1 = session_->session().axes[0].parameters.count("ff1")
                           ? session_->session().axes[0].parameters.at("ff1")
                           : pidFeedforwardParameters()[4].defaultValue;
    QTest::mouseClick(dialog.applyButton(2), Qt::LeftButton);
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    const AxisSettings& x = session_->session().axes[0];
    QCOMPARE(x.parameters.at("p"), dialog.proposal(2).p);
    QCOMPARE(x.parameters.at("d"), dialog.proposal(2).d);
    QCOMPARE(pidFeedforwardDesign(session_->axisEvaluation(0)).gains.ff1, ff1);
    QCOMPARE(editor()->gainsEditor()->field("p")->value(), dialog.proposal(2).p);
    // An unreachable target: the row says why and cannot be applied.
    dialog.structureBox()->setCurrentIndex(0);
    emit dialog.structureBox()->activated(0);
    test::typeInto(dialog.phaseMarginField(), "120");
    QVERIFY(!dialog.proposal(0).ok);
    QVERIFY(!dialog.applyButton(0)->isEnabled());
    // A refused relay amplitude stays at the field.
    test::typeInto(dialog.relayField(), "-1");
    QVERIFY(dialog.relayField()->hasError());
}

void TstPidWorkbench::draggingAZeroOnTheRootLocusMovesIt() {
    RootLocusPlot* locus = window_->rootLocusPlot();
    window_->upperTabs()->setCurrentWidget(locus);
    QVERIFY(!locus->zerosDraggable()); // the Guillemin-Truxal PI: its zero is not the user's
    choosePid();
    QApplication::processEvents();
    QVERIFY(locus->zerosDraggable());
    QCOMPARE(locus->locus().zeros.size(), std::size_t{1}); // the PI's -I/P
    const std::complex<double> zero = locus->locus().zeros.front();
    XYT_COMPARE_NEAR(zero.real(), -pidFeedforwardDesign(session_->axisEvaluation(0)).gains.i / 0.03,
                     1e-9, 0.0);
    // Press on the zero, drag it left in three moves, release: one undo step, and the
    // controller's zero where it was released (the pixel's coordinate in the view as it is at
    // the release; I' = -P Re(s)).
    const auto pixel = [&](std::complex<double> s) {
        return QPoint(qRound(locus->xAxis->coordToPixel(s.real())),
                      qRound(locus->yAxis->coordToPixel(s.imag())));
    };
    const QCPRange before = locus->xAxis->range();
    const int steps = session_->undoStack()->count();
    const QPoint start = pixel(zero);
    QTest::mousePress(locus, Qt::LeftButton, {}, start);
    for (int dx : {-10, -20, -30}) {
        QMouseEvent move(QEvent::MouseMove, start + QPoint(dx, 0), locus->mapToGlobal(start),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(locus, &move);
    }
    const QPoint end = start + QPoint(-30, 0);
    const double expected = locus->xAxis->pixelToCoord(end.x());
    QTest::mouseRelease(locus, Qt::LeftButton, {}, end);
    QApplication::processEvents();
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    const ServoPidGains& g = pidFeedforwardDesign(session_->axisEvaluation(0)).gains;
    XYT_COMPARE_NEAR(-g.i / g.p, expected, 1e-12, 0.0);
    QVERIFY(locus->locus().zeros.front().real() < zero.real());
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
    // Into the right half plane: refused, the design unchanged, the status bar says why.
    const double iBefore = g.i;
    const QPoint moved = pixel(locus->locus().zeros.front());
    QTest::mousePress(locus, Qt::LeftButton, {}, moved);
    QTest::mouseRelease(locus, Qt::LeftButton, {}, pixel({0.5 * before.upper, 0.0}));
    QCOMPARE(pidFeedforwardDesign(session_->axisEvaluation(0)).gains.i, iBefore);
    QVERIFY(window_->statusBar()->currentMessage().contains("right half plane"));
    // Picking a gain on a branch scales P, I and D.
    const double p = pidFeedforwardDesign(session_->axisEvaluation(0)).gains.p;
    emit locus->gainPicked(2.0);
    XYT_COMPARE_NEAR(pidFeedforwardDesign(session_->axisEvaluation(0)).gains.p, 2.0 * p, 1e-15,
                     0.0);
}

void TstPidWorkbench::robustnessSaysWhatTheFeedforwardStillGains() {
    // The robustness tab on a PID + feedforward axis, k0 +-10 %: its summary gives the ratio of
    // the feedback's RMSE alone to the RMSE with the feedforward on the median plant, from the
    // core's result (Distribution p50s).
    choosePid();
    RobustnessView* view = window_->findChild<RobustnessView*>();
    QVERIFY(view);
    window_->lowerTabs()->setCurrentWidget(view);
    QApplication::processEvents();
    view->rangeBox("k0")->setValue(10.0);
    view->samplesBox()->setValue(8);
    QSignalSpy spy(view, &RobustnessView::analysisFinished);
    QTest::mouseClick(view->runButton(), Qt::LeftButton);
    QVERIFY(spy.wait(60000));
    QVERIFY(view->result());
    const RobustnessResult& r = *view->result();
    QVERIFY(r.rmseWithoutFf.count > 0);
    const double gain = r.rmseWithoutFf.p50 / r.rmse.p50;
    QVERIFY(gain > 5.0); // the requirement: at least 5x with k0 10 % off
    QVERIFY2(view->statusText().contains(
                 QStringLiteral("divides the RMSE by %1").arg(significant(gain, 3))),
             qPrintable(view->statusText()));
}

void TstPidWorkbench::designSpaceMapsThePiAndLoadsACell() {
    // The design-space tab on a PID + feedforward axis without D: a study of its PI over
    // (wn, kp) with the feedforward fixed; a clicked cell sets P = kp u and I = ki u (one undo
    // step), the feedforward kept; P and I edits leave the map current (only the marker moves);
    // a D refuses the study at the status line.
    choosePid();
    TrajectorySettings t = session_->session().trajectory;
    t.durationSeconds = 130.0; // the study's runs and the evaluation's then have one length
    session_->setTrajectory(t);
    DesignSpaceView* view = window_->findChild<DesignSpaceView*>();
    QVERIFY(view);
    view->liveBox()->setChecked(false);
    window_->lowerTabs()->setCurrentWidget(view);
    QApplication::processEvents();
    view->wnCountBox()->setValue(4);
    view->kpCountBox()->setValue(4);
    QSignalSpy spy(view, &DesignSpaceView::studyFinished);
    view->run();
    QVERIFY(spy.wait(60000));
    QVERIFY(view->result() && view->resultIsCurrent());
    QVERIFY(!view->studiedProblem()->feedforwardVolts.empty());
    const DesignPoint& cell = view->result()->at(1, 2);
    const double ff1 = pidFeedforwardDesign(session_->axisEvaluation(0)).gains.ff1;
    const int steps = session_->undoStack()->count();
    emit view->plot()->cellClicked(1, 2);
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    const PidFeedforwardDesign& d = pidFeedforwardDesign(session_->axisEvaluation(0));
    QCOMPARE(d.gains.p, cell.kp * 0.001);
    QCOMPARE(d.gains.i, cell.ki * 0.001);
    QCOMPARE(d.gains.ff1, ff1);
    QVERIFY(view->resultIsCurrent());
    // The cell's figures are the evaluation's (the design's run, 1e-9: the round trip).
    XYT_COMPARE_NEAR(session_->axisEvaluation(0).metrics.rmse, cell.tracking.rmse, 1e-9, 0.0);
    // A feedforward change stales the map; a D refuses a new study.
    emit editor()->feedforwardSlider(1)->valueChanged(80.0);
    QVERIFY(!view->resultIsCurrent());
    test::typeInto(editor()->gainsEditor()->field("d"), "0.001");
    view->run();
    QVERIFY(view->statusLabel()->text().contains("set D to 0"));
}

void TstPidWorkbench::draggingAPoleAlongTheLocusSetsTheGain() {
    // Press on a closed-loop pole of the design, drag it along the locus in three moves,
    // release: the loop gain of the release point on the locus as it was at the press
    // (pickLocusPoint of that locus) multiplies P, I and D of the design before the drag, once
    // (the moves do not compound), as one undo step; the feedforward stays.
    choosePid();
    RootLocusPlot* plot = window_->rootLocusPlot();
    window_->upperTabs()->setCurrentWidget(plot);
    QApplication::processEvents();
    const RootLocus before = plot->locus();
    const PidFeedforwardDesign design = pidFeedforwardDesign(session_->axisEvaluation(0));
    // A closed-loop pole of the design in view, and a point of its branch at least 20 px away.
    const auto pixel = [&](std::complex<double> s) {
        return QPoint(qRound(plot->xAxis->coordToPixel(s.real())),
                      qRound(plot->yAxis->coordToPixel(s.imag())));
    };
    const QRect area = plot->axisRect()->rect();
    QPoint from, to;
    for (const std::complex<double>& pole : design.closedLoopPoles) {
        const LocusPick start = *pickLocusPoint(before, pole);
        const auto& roots = before.branches[start.branch].roots;
        for (std::size_t k = 0; k < roots.size() && to.isNull(); ++k) {
            const QPoint a = pixel(start.point), b = pixel(roots[k]);
            if (area.contains(a) && area.contains(b) && (b - a).manhattanLength() > 20 &&
                (b - a).manhattanLength() < 60) {
                from = a;
                to = b;
            }
        }
        if (!to.isNull())
            break;
    }
    QVERIFY(!to.isNull());
    const int steps = session_->undoStack()->count();
    QTest::mousePress(plot, Qt::LeftButton, {}, from);
    for (int k = 1; k <= 3; ++k) {
        const QPoint at = from + (to - from) * k / 3;
        QMouseEvent move(QEvent::MouseMove, at, plot->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QApplication::sendEvent(plot, &move);
    }
    // The gain the release reads: the pixel's coordinate in the view at the release, on the
    // locus of the press.
    const auto expected = pickLocusPoint(
        before, {plot->xAxis->pixelToCoord(to.x()), plot->yAxis->pixelToCoord(to.y())});
    QVERIFY(expected && expected->gain != 1.0);
    QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
    QApplication::processEvents();
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    const PidFeedforwardDesign& after = pidFeedforwardDesign(session_->axisEvaluation(0));
    XYT_COMPARE_NEAR(after.gains.p, expected->gain * design.gains.p, 1e-15, 0.0);
    XYT_COMPARE_NEAR(after.gains.i, expected->gain * design.gains.i, 1e-15, 0.0);
    QCOMPARE(after.gains.ff1, design.gains.ff1);
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
}

QTEST_MAIN(TstPidWorkbench)
#include "tst_pid_workbench.moc"
