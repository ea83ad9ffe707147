// SPDX-License-Identifier: GPL-3.0-or-later
// Results are never shown as the current design's when they are not: the job runner's life
// cycle (delivery with its stamp, replaced jobs dropped, cancel, failure, destruction while
// running) and the workbench cases a new user met: a robustness run finishing after the slider
// moved, ranges of the other axis, a design-space map of another method, File › New, and a
// G-code kind chosen before any program.
#include "core/model/errors.h"
#include "ui/design_space_view.h"
#include "ui/jobs/job_runner.h"
#include "ui/main_window.h"
#include "ui/panels/stale_veil.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/plots/design_space_plot.h"
#include "ui/robustness_view.h"
#include "ui/session/recovery_store.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QThread>
#include <QtTest>

#include <atomic>
#include <memory>

using namespace xyt;
using namespace xyt::ui;

namespace {

constexpr int kRunTimeoutMs = 120000;

/// A runner of ints stamped with ints, recording what reaches the GUI thread.
struct RecordingRunner {
    QObject context;
    QList<int> done;
    QList<int> stamps;
    QStringList failures;
    QList<double> progress;
    bool allOnGuiThread = true;
    std::unique_ptr<JobRunner<int, int>> runner;

    RecordingRunner() {
        runner = std::make_unique<JobRunner<int, int>>(
            &context, JobRunner<int, int>::Handlers{
                          [this](double f) {
                              progress << f;
                              allOnGuiThread &= QThread::currentThread() == qApp->thread();
                          },
                          [this](int&& value, const int& stamp) {
                              done << value;
                              stamps << stamp;
                              allOnGuiThread &= QThread::currentThread() == qApp->thread();
                          },
                          [this](const QString& error, const int& stamp) {
                              failures << error;
                              stamps << stamp;
                          }});
    }
};

/// Work that runs until it is cancelled (or 20 s pass), counting its items.
int untilCancelled(const JobProgress& progress, std::atomic<bool>* ended = nullptr) {
    int items = 0;
    QElapsedTimer timer;
    timer.start();
    while (progress(0.5) && timer.elapsed() < 20000) {
        ++items;
        QThread::msleep(2);
    }
    if (ended)
        *ended = true;
    return items;
}

/// With XYT_SCREENSHOT_DIR set, saves @p widget as NAME.png there, to look at.
void saveScreenshot(QWidget* widget, const QString& name) {
    const QString dir = qEnvironmentVariable("XYT_SCREENSHOT_DIR");
    if (dir.isEmpty())
        return;
    QTest::qWait(100); // the plots' queued replots
    widget->grab().save(dir + QStringLiteral("/%1.png").arg(name));
}

QString axisId(const TuningSession& s, int axis) {
    return QString::fromStdString(s.session().axes.at(static_cast<std::size_t>(axis)).id).toUpper();
}

} // namespace

class TstFreshResults : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();

    void runnerDeliversItsResultWithItsStamp();
    void replacedJobIsNeverDelivered();
    void cancelledJobDeliversWhatItHas();
    void failureIsDeliveredAsItsMessage();
    void destroyingTheRunnerStopsTheJob();
    void stampsFollowWhatAResultDependsOn();

    void robustnessRunEndingAfterAChangeIsVeiled();
    void robustnessRangesFollowTheSelectedAxis();
    void designSpaceMapOfAnotherMethodIsVeiled();
    void fileNewVeilsTheMapAndItsHover();
    void gcodeKindWithoutProgramIsSaid();

private:
    RobustnessView* robustness() const;
    DesignSpaceView* designSpace() const;

    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstFreshResults::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("xytune-tests");
}

void TstFreshResults::init() {
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->resize(1366, 768);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstFreshResults::cleanup() {
    window_->recovery()->discard();
    window_.reset();
    session_.reset();
}

RobustnessView* TstFreshResults::robustness() const {
    auto* view = window_->lowerTabs()->findChild<RobustnessView*>();
    window_->lowerTabs()->setCurrentWidget(view);
    return view;
}

DesignSpaceView* TstFreshResults::designSpace() const {
    return window_->lowerTabs()->findChild<DesignSpaceView*>();
}

// ---- The job runner -------------------------------------------------------------------------

void TstFreshResults::runnerDeliversItsResultWithItsStamp() {
    RecordingRunner r;
    r.runner->start(7, [](const JobProgress& progress) {
        for (int i = 1; i <= 4; ++i)
            progress(i / 4.0);
        return 42;
    });
    QVERIFY(r.runner->isRunning());
    QCOMPARE(r.runner->runningStamp(), 7);
    QTRY_COMPARE(r.done.size(), 1);
    QCOMPARE(r.done.front(), 42);
    QCOMPARE(r.stamps.front(), 7);
    QVERIFY(!r.runner->isRunning());
    QVERIFY(r.allOnGuiThread);
    // Progress is thinned, never invented: each reported value is the start (0) or one the work
    // gave, in order.
    double last = 0.0;
    for (double f : r.progress) {
        QVERIFY2(f == 0.0 || f == 0.25 || f == 0.5 || f == 0.75 || f == 1.0,
                 qPrintable(QString::number(f)));
        QVERIFY(f >= last);
        last = f;
    }
}

void TstFreshResults::replacedJobIsNeverDelivered() {
    RecordingRunner r;
    std::atomic<bool> firstEnded{false};
    r.runner->start(1,
                    [&firstEnded](const JobProgress& p) { return untilCancelled(p, &firstEnded); });
    r.runner->start(2, [](const JobProgress&) { return -2; });
    QTRY_COMPARE(r.done.size(), 1);
    QVERIFY(firstEnded.load()); // the first was cancelled (the pool runs one job at a time)
    QTest::qWait(50);           // and its result, posted or not, never arrives
    QCOMPARE(r.done, QList<int>{-2});
    QCOMPARE(r.stamps, QList<int>{2});
}

void TstFreshResults::cancelledJobDeliversWhatItHas() {
    RecordingRunner r;
    r.runner->start(3, [](const JobProgress& p) { return untilCancelled(p); });
    QTest::qWait(30);
    r.runner->cancel();
    QVERIFY(r.runner->isCancelling());
    QTRY_COMPARE(r.done.size(), 1);
    QVERIFY(r.done.front() >= 0); // the items it had computed: a partial result, delivered
    QCOMPARE(r.stamps.front(), 3);
    QVERIFY(!r.runner->isRunning());
}

void TstFreshResults::failureIsDeliveredAsItsMessage() {
    RecordingRunner r;
    r.runner->start(
        4, [](const JobProgress&) -> int { throw InvalidInput("samples", "must be at least 1"); });
    QTRY_COMPARE(r.failures.size(), 1);
    QVERIFY2(r.failures.front().contains("must be at least 1"), qPrintable(r.failures.front()));
    QCOMPARE(r.stamps.front(), 4);
    QVERIFY(r.done.isEmpty());
}

void TstFreshResults::destroyingTheRunnerStopsTheJob() {
    RecordingRunner r;
    std::atomic<bool> ended{false};
    r.runner->start(5, [&ended](const JobProgress& p) { return untilCancelled(p, &ended); });
    QTest::qWait(20);
    r.runner.reset(); // cancels and waits: the work has returned when this returns
    QVERIFY(ended.load());
    QTest::qWait(50);
    QVERIFY(r.done.isEmpty());
}

void TstFreshResults::stampsFollowWhatAResultDependsOn() {
    const ResultStamp design = session_->stamp(0, ResultScope::AxisDesign);
    const ResultStamp study = session_->stamp(0, ResultScope::AxisStudy);
    const ResultStamp both = session_->stamp(0, ResultScope::BothAxes);
    QCOMPARE(both.axis, -1);
    session_->setKp(0, 45.0);
    QVERIFY(!session_->isCurrent(design)); // the controller changed
    QVERIFY(session_->isCurrent(study));   // the map sweeps kp: still this axis' map
    QVERIFY(!session_->isCurrent(both));
    session_->setKp(1, 45.0);
    QVERIFY(!session_->isCurrent(design));
    session_->undoStack()->undo();
    session_->undoStack()->undo();
    QVERIFY(session_->isCurrent(design)); // back to the design it was computed for
    QVERIFY(session_->isCurrent(both));
    ThirdOrderPlant plant = session_->session().axes[0].gt.plant;
    plant.k0 *= 1.1;
    session_->setPlant(0, plant);
    QVERIFY(!session_->isCurrent(study));
    QVERIFY(session_->revision() > design.revision);
    const QString words = TuningSession::describe(design);
    QVERIFY2(
        words.contains(QString("ωn = %1 rad/s").arg(design.session.axes[0].gt.omegaNRadPerSec)) &&
            words.contains(QString("kp = %1").arg(design.session.axes[0].gt.kp)),
        qPrintable(words));
}

// ---- The workbench ----------------------------------------------------------------------------

void TstFreshResults::robustnessRunEndingAfterAChangeIsVeiled() {
    RobustnessView* view = robustness();
    view->samplesBox()->setValue(40);
    view->rangeBox("k0")->setValue(20.0);
    const double wn = session_->session().axes[0].gt.omegaNRadPerSec;
    QSignalSpy finished(view, &RobustnessView::analysisFinished);
    QTest::mouseClick(view->runButton(), Qt::LeftButton);
    QVERIFY(view->isRunning());
    // The slider moves while the run computes (before the event loop can deliver anything).
    session_->setOmegaN(0, 4.9);
    QVERIFY(finished.wait(kRunTimeoutMs));
    QVERIFY(view->result().has_value());
    QVERIFY(!view->resultIsCurrent());
    QVERIFY(view->veil()->isVeiled());
    const QString note = view->veil()->note();
    QVERIFY2(note.contains(QString("ωn = %1 rad/s").arg(wn)) && note.contains("changed"),
             qPrintable(note));
    QVERIFY(!view->worstButton()->isEnabled());
    saveScreenshot(window_.get(), "fresh_robustness_veiled");
    // Undone back to the analyzed design: the result is current again.
    session_->undoStack()->undo();
    QVERIFY(view->resultIsCurrent());
    QVERIFY(!view->veil()->isVeiled());
    QCOMPARE(view->worstButton()->isEnabled(), view->result()->worst.has_value());
}

void TstFreshResults::robustnessRangesFollowTheSelectedAxis() {
    RobustnessView* view = robustness();
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    session_->setCurrentAxis(1);
    QCOMPARE(view->parameterNames(), (QStringList{"a1", "a2", "k0"})); // Y's plant
    session_->setCurrentAxis(0);
    QVERIFY2(view->parameterNames().contains("b1") && !view->parameterNames().contains("k0"),
             qPrintable(view->parameterNames().join(',')));
    // A result for X, then the Y tab: veiled, saying which axis it was for.
    view->samplesBox()->setValue(5);
    QSignalSpy finished(view, &RobustnessView::analysisFinished);
    QTest::mouseClick(view->runButton(), Qt::LeftButton);
    QVERIFY(finished.wait(kRunTimeoutMs));
    QVERIFY(view->resultIsCurrent());
    QCOMPARE(view->analyzedAxis(), 0);
    session_->setCurrentAxis(1);
    QVERIFY(view->veil()->isVeiled());
    QVERIFY2(view->veil()->note().contains(QString("axis %1").arg(axisId(*session_, 0))) &&
                 view->veil()->note().contains(
                     QString("this tab shows axis %1").arg(axisId(*session_, 1))),
             qPrintable(view->veil()->note()));
    QCOMPARE(view->parameterNames(), (QStringList{"a1", "a2", "k0"}));
    session_->setCurrentAxis(0);
    QVERIFY(!view->veil()->isVeiled());
}

void TstFreshResults::designSpaceMapOfAnotherMethodIsVeiled() {
    DesignSpaceView* view = designSpace();
    view->liveBox()->setChecked(false);
    window_->lowerTabs()->setCurrentWidget(view);
    view->wnCountBox()->setValue(6);
    view->kpCountBox()->setValue(6);
    QTest::mouseClick(view->runButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isRunning(), kRunTimeoutMs);
    QVERIFY(view->resultIsCurrent());
    QVERIFY(!view->veil()->isVeiled());
    view->liveBox()->setChecked(true);
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    QVERIFY(!view->isRunning()); // nothing to map for pole placement
    QVERIFY(view->veil()->isVeiled());
    const QString note = view->veil()->note();
    QVERIFY2(note.contains("now uses pole placement") &&
                 note.contains(QString("axis %1").arg(axisId(*session_, 0))),
             qPrintable(note));
    // Back to Guillemin–Truxal: the map is that of the session again.
    session_->setMethod(0, DesignMethod::GuilleminTruxal);
    QVERIFY(view->resultIsCurrent() || view->isRunning());
}

void TstFreshResults::fileNewVeilsTheMapAndItsHover() {
    DesignSpaceView* view = designSpace();
    view->liveBox()->setChecked(false);
    window_->lowerTabs()->setCurrentWidget(view);
    ThirdOrderPlant plant = session_->session().axes[0].gt.plant;
    plant.k0 *= 1.5;
    session_->setPlant(0, plant);
    view->wnCountBox()->setValue(6);
    view->kpCountBox()->setValue(6);
    QTest::mouseClick(view->runButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isRunning(), kRunTimeoutMs);
    QVERIFY(view->resultIsCurrent());
    session_->markSaved(); // File › New asks nothing of a saved session
    window_->files()->newSession();
    QVERIFY(!view->resultIsCurrent());
    QVERIFY(view->veil()->isVeiled());
    QVERIFY2(view->veil()->note().contains(QString("k0 = %1").arg(plant.k0, 0, 'g', 5)),
             qPrintable(view->veil()->note()));
    saveScreenshot(window_.get(), "fresh_design_space_veiled");
    // The hover box describes no cell of a map that is not the session's.
    emit view->plot()->cellHovered(std::make_pair(std::size_t{2}, std::size_t{2}));
    QVERIFY2(view->readoutText().isEmpty(), qPrintable(view->readoutText()));
}

void TstFreshResults::gcodeKindWithoutProgramIsSaid() {
    TrajectorySettings circle = session_->session().trajectory;
    circle.kind = TrajectoryKind::Circle;
    session_->setTrajectory(circle);
    QVERIFY(!window_->timeVeil()->isVeiled());
    TrajectoryEditor* editor = window_->trajectoryEditor();
    QVERIFY(session_->session().trajectory.gcode.program.empty());
    editor->kindBox()->setCurrentIndex(2);
    emit editor->kindBox()->activated(2);
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Circle); // nothing applied
    for (StaleVeil* veil : {window_->timeVeil(), window_->contourVeil()}) {
        QVERIFY(veil->isVeiled());
        QVERIFY2(veil->note().contains("circle") && veil->note().contains("needs a program"),
                 qPrintable(veil->note()));
    }
    saveScreenshot(window_.get(), "fresh_gcode_without_program");
    // Back to the circle in the editor: the plots are the editor's again.
    editor->kindBox()->setCurrentIndex(1);
    emit editor->kindBox()->activated(1);
    QVERIFY(!window_->timeVeil()->isVeiled());
    QVERIFY(!window_->contourVeil()->isVeiled());
}

QTEST_MAIN(TstFreshResults)
#include "tst_fresh_results.moc"
