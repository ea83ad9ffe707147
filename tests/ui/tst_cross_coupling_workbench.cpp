// SPDX-License-Identifier: GPL-3.0-or-later
// Cross-coupled contouring in the workbench, through its real widgets offscreen: the
// Cross-coupling fold of the trajectory box (fields, one undo step per edit, refusals at the
// field), the XY contour view comparing the coupled run with the independent axes on a program,
// in the ballbar view and on the circle preset, and the refusal of axes at two periods shown
// at the fold. Each drawn value is checked against the presenter's evaluation (the core's).
#include "tests/support/gui_checks.h"
#include "ui/main_window.h"
#include "ui/panels/cross_coupling_editor.h"
#include "ui/panels/number_field.h"
#include "ui/plots/contour_plot.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QLabel>
#include <QTabWidget>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>
#include <qcustomplot.h>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// Braga et al.'s check circle as a program: 25 mm at 90 mm/min from rest at the origin.
Session circleProgramSession(Session s) {
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "paper_circle.nc";
    s.trajectory.gcode.program = "F90\nG3 X0 Y0 I-25 J0\n";
    return s;
}

} // namespace

class TstCrossCouplingWorkbench : public QObject {
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

    void theFoldEditsTheCouplingAsOneUndoStep() {
        CrossCouplingEditor* editor = window_->crossCouplingEditor();
        QToolButton* fold = editor->foldButton();
        QVERIFY(fold->isVisible());
        QVERIFY(!editor->kpField()->isVisible()); // folded
        QTest::mouseClick(fold, Qt::LeftButton);
        QVERIFY(editor->kpField()->isVisible());
        QVERIFY(!fold->text().contains(QStringLiteral("●")));
        const int steps = session_->undoStack()->count();
        test::typeInto(editor->kpField(), "0.1");
        QCOMPARE(session_->session().crossCoupling.kp, 0.1);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        QVERIFY(fold->text().contains(QStringLiteral("●")));
        editor->estimateBox()->setCurrentIndex(1);
        emit editor->estimateBox()->activated(1);
        QCOMPARE(session_->session().crossCoupling.estimate, ContourEstimateKind::Linear);
        QCOMPARE(session_->undoStack()->count(), steps + 2);
        // A negative gain is refused at its field; nothing changes.
        test::typeInto(editor->kiField(), "-1");
        QVERIFY(editor->kiField()->hasError());
        QVERIFY(editor->kiField()->toolTip().contains(QStringLiteral(">= 0")));
        QCOMPARE(session_->session().crossCoupling.ki, 0.0);
        QCOMPARE(session_->undoStack()->count(), steps + 2);
        session_->undoStack()->undo();
        session_->undoStack()->undo();
        QCOMPARE(session_->session().crossCoupling, CrossCoupling{});
        QCOMPARE(editor->kpField()->value(), 0.0);
        QVERIFY(!fold->text().contains(QStringLiteral("●")));
    }

    void aProgramIsComparedWithTheIndependentAxes() {
        Session s = circleProgramSession(session_->session());
        session_->apply(s, QStringLiteral("circle program"));
        ContourPlot* plot = window_->contourPlot();
        window_->lowerTabs()->setCurrentWidget(plot);
        QCOMPARE(plot->independentCurve()->data()->size(), 0);
        const double alone = session_->evaluation().program->contour.maxAbs;
        s.crossCoupling = {0.1, 1.0, ContourEstimateKind::Circular};
        session_->apply(s, QStringLiteral("couple"));
        const auto& program = session_->evaluation().program;
        QVERIFY(program && program->independent);
        // The comparison is the uncoupled run, and the coupling cuts the error (the core's
        // tests state how much).
        QCOMPARE(program->independent->contour.maxAbs, alone);
        QVERIFY(program->contour.maxAbs < 0.5 * alone);
        QCOMPARE(plot->independentCurve()->data()->size(),
                 static_cast<int>(program->independent->contour.error.size()));
        QVERIFY(plot->figuresText().startsWith(QStringLiteral("Cross-coupled")));
        QVERIFY(plot->figuresText().contains(
            QStringLiteral("independent axes: max %1 mm").arg(QString::number(alone, 'g', 3))));
        QVERIFY(window_->crossCouplingEditor()->stabilityLabel()->text().contains(
            QString::number(alone, 'g', 3)));
        // The coupled loop's stability as the evaluation found it: the least stable direction's
        // spectral radius and the phase margin broken at each axis' input.
        const CouplingStability& st = *program->couplingStability;
        const QString status = window_->crossCouplingEditor()->stabilityLabel()->text();
        QVERIFY2(status.contains(QString::number(st.worst.spectralRadius, 'g', 6)),
                 qPrintable(status));
        QVERIFY(st.worst.brokenAtX && st.worst.brokenAtY);
        QVERIFY2(status.contains(QStringLiteral("at the x input: phase margin %1°")
                                     .arg(st.worst.brokenAtX->phaseMarginDeg, 0, 'f', 1)),
                 qPrintable(status));
        // The ballbar view: the program is one full circle, run alone for ISO 230-4; the
        // independent axes' run beside the coupled one, with its G.
        plot->setPolar(true);
        QVERIFY(program->independent->iso);
        QCOMPARE(plot->independentCurve()->data()->size(),
                 static_cast<int>(program->independent->circleX.size()));
        QVERIFY(plot->figuresText().contains(QStringLiteral("independent axes G")));
        plot->setPolar(false);
        // Off again: nothing to compare.
        session_->setCrossCoupling({});
        QVERIFY(!session_->evaluation().program->independent);
        QCOMPARE(plot->independentCurve()->data()->size(), 0);
        QVERIFY(window_->crossCouplingEditor()->stabilityLabel()->isHidden());
    }

    void polePlacementAxesAlsoShowTheFeedbackAlone() {
        // Axes with a ZPETC: the contour and ballbar views add the feedback alone (the core's
        // feedbackOnly run) beside the independent axes.
        Session s = circleProgramSession(session_->session());
        for (AxisSettings& a : s.axes)
            a.method = DesignMethod::PolePlacementZpetc;
        s.crossCoupling = {3.0, 1.0, ContourEstimateKind::Circular};
        session_->apply(s, QStringLiteral("pp coupled"));
        const auto& program = session_->evaluation().program;
        QVERIFY(program && program->feedbackOnly && program->feedbackOnly->iso);
        ContourPlot* plot = window_->contourPlot();
        window_->lowerTabs()->setCurrentWidget(plot);
        QCOMPARE(plot->feedbackOnlyCurve()->data()->size(),
                 static_cast<int>(program->feedbackOnly->contour.error.size()));
        QVERIFY(plot->figuresText().contains(
            QStringLiteral("without feedforward: max %1 mm")
                .arg(QString::number(program->feedbackOnly->contour.maxAbs, 'g', 3))));
        plot->setPolar(true);
        QCOMPARE(plot->feedbackOnlyCurve()->data()->size(),
                 static_cast<int>(program->feedbackOnly->circleX.size()));
        QVERIFY(plot->figuresText().contains(QStringLiteral("without feedforward G")));
        plot->setPolar(false);
    }

    void theCirclePresetRunsCoupled() {
        Session s = session_->session();
        s.trajectory.kind = TrajectoryKind::Circle;
        s.crossCoupling = {0.1, 0.0, ContourEstimateKind::Circular};
        session_->apply(s, QStringLiteral("circle"));
        const auto& coupled = session_->evaluation().coupledTrajectory;
        QVERIFY(coupled);
        ContourPlot* plot = window_->contourPlot();
        window_->lowerTabs()->setCurrentWidget(plot);
        // The traced curve is the coupled run; the dotted one the independent axes'.
        QCOMPARE(plot->tracedCurve()->data()->size(), static_cast<int>(coupled->t.size()));
        QCOMPARE(plot->tracedCurve()->data()->at(100)->key, coupled->coupled[0].y[100]);
        QCOMPARE(plot->tracedCurve()->data()->at(100)->value, coupled->coupled[1].y[100]);
        QCOMPARE(plot->independentCurve()->data()->size(), static_cast<int>(coupled->t.size()));
        QVERIFY(plot->figuresText().contains(
            QStringLiteral("independent axes: max %1 mm")
                .arg(QString::number(coupled->independentError.maxAbs, 'f', 4))));
    }

    void axesAtTwoPeriodsAreRefusedAtTheFold() {
        Session s = circleProgramSession(session_->session());
        s.axes[1].method = DesignMethod::PolePlacementZpetc; // 70 ms beside the 10 ms step
        s.crossCoupling = {0.1, 0.0, ContourEstimateKind::Circular};
        session_->apply(s, QStringLiteral("mixed"));
        const SessionEvaluation& ev = session_->evaluation();
        QVERIFY(!ev.couplingError.text.empty());
        QLabel* label = window_->crossCouplingEditor()->stabilityLabel();
        QVERIFY(!label->isHidden());
        QCOMPARE(label->text(), QString::fromStdString(ev.couplingError));
        QVERIFY(label->text().contains(QStringLiteral("one controller period")));
        QVERIFY(label->styleSheet().contains(QStringLiteral("color")));
    }

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TstCrossCouplingWorkbench)
#include "tst_cross_coupling_workbench.moc"
