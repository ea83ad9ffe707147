// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/session/tuning_session.h"
#include "tests/support/tolerance.h"

#include <QSignalSpy>
#include <QTest>

using namespace xyt;
using namespace xyt::ui;

class TstTuningSession : public QObject {
    Q_OBJECT
private slots:
    void startsWithThePaperDesign();
    void changeReevaluatesAndSignals();
    void undoRedo();
    void sliderDragMergesIntoOneStep();
    void differentParametersDoNotMerge();
    void invalidValueIsReportedNotThrown();
    void cleanState();
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

QTEST_MAIN(TstTuningSession)
#include "tst_tuning_session.moc"
