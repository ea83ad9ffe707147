// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/tolerance.h"
#include "ui/session/tuning_session.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <complex>

using namespace xyt;
using namespace xyt::ui;

class TstTuningSession : public QObject {
    Q_OBJECT
private slots:
    void snapshotEvaluationIsComputedOncePerInput();
    void startsWithThePaperDesign();
    void changeReevaluatesAndSignals();
    void undoRedo();
    void sliderDragMergesIntoOneStep();
    void differentParametersDoNotMerge();
    void invalidValueIsReportedNotThrown();
    void cleanState();
    void viewChangesAreOneStepEach();
    void loopGainScalesTheWholeLoop();
    void loopGainRefusesWhatItCannotApply();
};

void TstTuningSession::startsWithThePaperDesign() {
    TuningSession s;
    QVERIFY(s.session() == Session::paperDefault());
    QVERIFY(s.axisEvaluation(0).ok);
    // Braga et al. Eq. 20: ki = kp psi1 = 16/77.8 (closed form).
    XYT_COMPARE_NEAR(s.axisEvaluation(0).gt->ki, 16.0 / 77.8, 1e-14, 0.0);
}

void TstTuningSession::changeReevaluatesAndSignals() {
    TuningSession s;
    QSignalSpy spy(&s, &TuningSession::designChanged);
    s.setOmegaN(0, 3.0);
    QCOMPARE(spy.count(), 1);
    // ki = wn^4 / k0 (kp cancels): 81 / 77.8.
    XYT_COMPARE_NEAR(s.axisEvaluation(0).gt->ki, 81.0 / 77.8, 1e-14, 0.0);
}

void TstTuningSession::undoRedo() {
    TuningSession s;
    s.setKp(1, 50.0);
    s.setUmax(5.0);
    QCOMPARE(s.undoStack()->count(), 2);
    s.undoStack()->undo();
    QCOMPARE(s.session().umaxVolts, 2.5);
    QCOMPARE(s.session().axes[1].gt.kp, 50.0);
    s.undoStack()->undo();
    QVERIFY(s.session() == Session::paperDefault());
    s.undoStack()->redo();
    s.undoStack()->redo();
    QCOMPARE(s.session().umaxVolts, 5.0);
    QCOMPARE(s.session().axes[1].gt.kp, 50.0);
}

void TstTuningSession::sliderDragMergesIntoOneStep() {
    TuningSession s;
    for (double wn = 2.0; wn <= 3.0; wn += 0.1)
        s.setOmegaN(0, wn);
    QCOMPARE(s.undoStack()->count(), 1);
    s.undoStack()->undo();
    QCOMPARE(s.session().axes[0].gt.omegaNRadPerSec, 2.0);
}

void TstTuningSession::differentParametersDoNotMerge() {
    TuningSession s;
    s.setOmegaN(0, 2.5);
    s.setOmegaN(1, 1.5); // other axis
    s.setKp(0, 20.0);
    QCOMPARE(s.undoStack()->count(), 3);
}

void TstTuningSession::invalidValueIsReportedNotThrown() {
    TuningSession s;
    s.setKp(0, -1.0); // a programmatic bad value: the evaluation names the field
    QVERIFY(!s.axisEvaluation(0).ok);
    // The session path (AxisEvaluation::errorField), as for every field.
    QCOMPARE(QString::fromStdString(s.axisEvaluation(0).errorField), QString("axes[0].gt.kp"));
    QVERIFY(s.axisEvaluation(1).ok);
}

void TstTuningSession::cleanState() {
    TuningSession s;
    QVERIFY(!s.isModified());
    s.setKp(0, 31.0);
    QVERIFY(s.isModified());
    s.markSaved();
    QVERIFY(!s.isModified());
    s.undoStack()->undo();
    QVERIFY(s.isModified());
    s.reset(Session::paperDefault());
    QVERIFY(!s.isModified());
    QCOMPARE(s.undoStack()->count(), 0);
}

void TstTuningSession::viewChangesAreOneStepEach() {
    // Every change a view makes goes through the presenter: one undo step each, named, and
    // none for a change that changes nothing; undo restores the session exactly (invariant).
    TuningSession s;
    const Session start = s.session();
    ImplementationSettings implementation;
    implementation.dacBits = 12;
    s.setImplementation(implementation);
    s.setControllerTs(0.002);
    s.setPiDiscretization(PiDiscretization::BackwardEuler);
    Specification spec = start.spec;
    spec.maxOvershootPct = 5.0;
    s.setSpecificationAndLimit(spec, 3.0);
    GtAxisSettings gt = start.axes[1].gt;
    gt.omegaNRadPerSec = 1.5;
    gt.kp = 20.0;
    s.setGt(1, gt, "Load design from the design space");
    AxisSettings identified = start.axes[0];
    identified.method = DesignMethod::PolePlacementZpetc;
    QVERIFY(s.setAxis(0, identified, "Use the identified ARX(2,3,1) for axis X"));
    std::array<AxisSettings, 2> pair = s.session().axes;
    pair[0].pp.a[1] = -1.7;
    pair[1].gt.plant.k0 = 80.0;
    s.setAxes(pair, "Load the worst plant pair");
    s.storeSnapshot("tuned");
    QCOMPARE(s.undoStack()->count(), 8);
    QCOMPARE(s.undoStack()->text(4), QString("Load design from the design space"));
    QCOMPARE(s.undoStack()->text(7), QString("Store snapshot tuned"));
    const Session end = s.session();
    QCOMPARE(end.implementation.dacBits, 12);
    QCOMPARE(end.controllerTsSeconds, 0.002);
    QCOMPARE(end.piDiscretization, PiDiscretization::BackwardEuler);
    QCOMPARE(end.spec.maxOvershootPct, 5.0);
    QCOMPARE(end.umaxVolts, 3.0);
    QVERIFY(end.axes[1].gt.omegaNRadPerSec == 1.5 && end.axes[1].gt.plant.k0 == 80.0);
    QCOMPARE(end.axes[0].method, DesignMethod::PolePlacementZpetc);
    QCOMPARE(end.snapshots.size(), std::size_t{1});
    QCOMPARE(end.snapshots[0].name, std::string("tuned"));

    // The same values again: no step.
    s.setImplementation(implementation);
    s.setControllerTs(0.002);
    s.setPiDiscretization(PiDiscretization::BackwardEuler);
    s.setSpecificationAndLimit(spec, 3.0);
    s.setAxes(pair, "again");
    QVERIFY(!s.setAxis(0, end.axes[0], "again"));
    QCOMPARE(s.undoStack()->count(), 8);
    for (int i = 0; i < 8; ++i)
        s.undoStack()->undo();
    QVERIFY(s.session() == start);
}

void TstTuningSession::loopGainScalesTheWholeLoop() {
    // Closed form (guillemin_truxal.h): the loop is L = (kp s + ki)/s k0/(s^3 + a1 s^2 + a2 s)
    // with ki = kp psi1 = wn^4 / k0, so the integral gain goes as wn^4. A root-locus gain K
    // (L -> K L) is kp -> K kp and ki -> K ki, i.e. wn -> K^(1/4) wn, psi1 = wn^4/(kp k0)
    // unchanged. K = 16: wn 2 -> 4 rad/s, kp 30 -> 480, ki 16/77.8 -> 256/77.8, L' = 16 L at every
    // frequency.
    TuningSession s;
    const GtDesign before = *s.axisEvaluation(0).gt;
    QSignalSpy spy(&s, &TuningSession::designChanged);
    QVERIFY(s.applyLoopGain(0, 16.0));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(s.undoStack()->count(), 1);
    const GtAxisSettings& gt = s.session().axes[0].gt;
    XYT_COMPARE_NEAR(gt.omegaNRadPerSec, 4.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(gt.kp, 480.0, 1e-15, 0.0);
    const GtDesign after = *s.axisEvaluation(0).gt;
    XYT_COMPARE_NEAR(after.ki, 256.0 / 77.8, 1e-14, 0.0);
    XYT_COMPARE_NEAR(after.psi1, before.psi1, 1e-14, 0.0);
    for (double w : {0.01, 0.3, 2.0, 40.0}) {
        const std::complex<double> ratio =
            after.openLoop.frequencyResponse(w) / before.openLoop.frequencyResponse(w);
        XYT_COMPARE_NEAR(ratio.real(), 16.0, 1e-12, 0.0);
        XYT_COMPARE_NEAR(ratio.imag(), 0.0, 0.0, 1e-10);
    }
    // The other axis is untouched, and one undo step restores the design.
    QVERIFY(s.session().axes[1] == Session::paperDefault().axes[1]);
    s.undoStack()->undo();
    QVERIFY(s.session() == Session::paperDefault());
    // A gain below 1 lowers both: K = 1/81, wn -> wn / 3 and kp -> kp / 81 (the y axis).
    const GtAxisSettings y = s.session().axes[1].gt;
    QVERIFY(s.applyLoopGain(1, 1.0 / 81.0));
    XYT_COMPARE_NEAR(s.session().axes[1].gt.omegaNRadPerSec, y.omegaNRadPerSec / 3.0, 1e-15, 0.0);
    XYT_COMPARE_NEAR(s.session().axes[1].gt.kp, y.kp / 81.0, 1e-15, 0.0);
}

void TstTuningSession::loopGainRefusesWhatItCannotApply() {
    // Only a finite K > 0 on a Guillemin-Truxal axis is a loop gain to apply; nothing changes
    // otherwise (no undo step, no signal).
    TuningSession s;
    QSignalSpy spy(&s, &TuningSession::designChanged);
    for (double k : {0.0, -2.0, std::nan(""), HUGE_VAL})
        QVERIFY(!s.applyLoopGain(0, k));
    s.setMethod(1, DesignMethod::PolePlacementZpetc);
    QCOMPARE(spy.count(), 1);
    QVERIFY(!s.applyLoopGain(1, 2.0));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(s.undoStack()->count(), 1);
}

// The overlay's evaluation equals the core's for the snapshot's design in this session, and is
// computed again only when what it depends on changes (not on a slider step of the design).
void TstTuningSession::snapshotEvaluationIsComputedOncePerInput() {
    TuningSession s;
    s.storeSnapshot("before");
    s.setKp(0, 45.0);
    const auto expected = [&s] {
        QString ignored;
        Session e =
            TuningSession::liveSessionOf(s.session().withDesign(s.session().snapshots[0]), ignored);
        return evaluateAxis(e, 0);
    };
    const AxisEvaluation& first = s.snapshotEvaluation(0, 0);
    QCOMPARE(s.snapshotEvaluationsComputed(), std::size_t{1});
    QVERIFY(first.ok);
    QCOMPARE(first.run.y, expected().run.y); // the same computation: bit for bit
    s.setKp(0, 50.0);                        // the current design, not the snapshot's
    s.setOmegaN(0, 3.0);
    QCOMPARE(s.snapshotEvaluation(0, 0).run.y, expected().run.y);
    QCOMPARE(s.snapshotEvaluationsComputed(), std::size_t{1});
    Specification spec = s.session().spec;
    spec.maxSettleTimeSeconds = 50.0; // sets the run's length: the overlay depends on it
    s.setSpecification(spec);
    QCOMPARE(s.snapshotEvaluation(0, 0).run.y, expected().run.y);
    QCOMPARE(s.snapshotEvaluationsComputed(), std::size_t{2});
    s.snapshotEvaluation(0, 1); // the other axis
    QCOMPARE(s.snapshotEvaluationsComputed(), std::size_t{3});
}

QTEST_MAIN(TstTuningSession)
#include "tst_tuning_session.moc"
