// SPDX-License-Identifier: GPL-3.0-or-later
// The table's friction in the workbench, through its real widgets offscreen: the Friction fold
// beside the method box (fields, one undo step per edit, refusals at the field, disabled on a
// pole-placement axis), and the ballbar view's compensated/uncompensated comparison with the
// reversal spikes in the metrics panel. Each value is checked against the presenter's
// evaluation (the core's numbers).
#include "tests/support/gui_checks.h"
#include "ui/main_window.h"
#include "ui/panels/friction_editor.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QTabWidget>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>
#include <qcustomplot.h>

#include <algorithm>
#include <cstdint>

using namespace xyt;
using namespace xyt::ui;

class TstFrictionWorkbench : public QObject {
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

    void theFoldEditsTheTableAsOneUndoStep() {
        FrictionEditor* editor = window_->frictionEditor();
        QToolButton* fold = editor->foldButton();
        QVERIFY(fold->isVisible() && fold->isEnabled());
        QVERIFY(!editor->isVisible()); // folded
        QTest::mouseClick(fold, Qt::LeftButton);
        QVERIFY(editor->isVisible());
        const int steps = session_->undoStack()->count();
        test::typeInto(editor->field("coulomb"), "0.02");
        QCOMPARE(session_->session().axes[0].friction.coulombVolts, 0.02);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        QVERIFY(fold->text().contains(QStringLiteral("●")));
        QVERIFY(fold->toolTip().contains(QStringLiteral("Coulomb 0.02 V")));
        // The run now sticks: the evaluation's run has the table's sliding flags, and the time
        // plot shades the stuck samples over the error (none drawn where the table slides).
        const std::vector<std::int8_t>& sliding = session_->axisEvaluation(0).run.sliding;
        QVERIFY(!sliding.empty());
        QVERIFY(std::count(sliding.begin(), sliding.end(), std::int8_t{0}) > 0);
        window_->lowerTabs()->setCurrentWidget(window_->timePlot());
        QVERIFY(window_->timePlot()->stuckGraph()->dataCount() > 0);
        test::typeInto(editor->field("percent"), "100");
        QCOMPARE(session_->session().axes[0].frictionCompensation.percent, 100.0);
        session_->undoStack()->undo();
        QCOMPARE(session_->session().axes[0].frictionCompensation.percent, 0.0);
        QCOMPARE(editor->field("percent")->value(), 0.0);
        session_->undoStack()->undo();
        QCOMPARE(session_->session().axes[0].friction.coulombVolts, 0.0);
        QCOMPARE(editor->field("coulomb")->value(), 0.0);
        QVERIFY(session_->axisEvaluation(0).run.sliding.empty()); // the linear table again
        QCOMPARE(window_->timePlot()->stuckGraph()->dataCount(), 0);
        // The other axis has its own table: y is untouched, and its fields show its values.
        session_->setCurrentAxis(1);
        QCOMPARE(editor->field("coulomb")->value(), 0.0);
    }

    void refusedValuesStayAtTheField() {
        FrictionEditor* editor = window_->frictionEditor();
        QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        test::typeInto(editor->field("backlash"), "-0.01");
        QVERIFY(editor->field("backlash")->hasError());
        QCOMPARE(session_->session().axes[0].friction.backlashMm, 0.0);
        test::typeInto(editor->field("backlash"), "0");
        test::typeInto(editor->field("coulomb"), "0.02");
        const int steps = session_->undoStack()->count();
        // A static level below the Coulomb level: refused at the static field by the core's rule.
        test::typeInto(editor->field("static"), "0.01");
        QVERIFY(editor->field("static")->toolTip().contains(QStringLiteral("Coulomb")));
        QCOMPARE(session_->session().axes[0].friction.staticVolts, 0.0);
        QCOMPARE(session_->undoStack()->count(), steps);
        // Above it without a Stribeck velocity: refused at that field.
        test::typeInto(editor->field("static"), "0.05");
        QVERIFY(editor->field("stribeck_velocity")->toolTip().contains(QStringLiteral("> 0")));
        QCOMPARE(session_->session().axes[0].friction.staticVolts, 0.0);
        test::typeInto(editor->field("stribeck_velocity"), "0.5");
        QCOMPARE(session_->session().axes[0].friction.staticVolts, 0.05);
        QCOMPARE(session_->session().axes[0].friction.stribeckVelocityMmPerS, 0.5);
    }

    void aPolePlacementAxisTakesAnInputDeadZone() {
        // An ARX model has no moving mass: the fold offers the Coulomb level and the amplifier
        // deadband only (its input dead zone), the other fields disabled saying why.
        session_->setMethod(0, DesignMethod::PolePlacementZpetc);
        FrictionEditor* editor = window_->frictionEditor();
        QVERIFY(editor->foldButton()->isEnabled());
        QVERIFY(editor->field("coulomb")->isEnabled());
        QVERIFY(editor->field("amplifier_deadband")->isEnabled());
        for (const char* name : {"static", "stribeck_velocity", "viscous", "backlash", "percent"}) {
            QVERIFY(!editor->field(name)->isEnabled());
            QVERIFY(editor->field(name)->toolTip().contains(QStringLiteral("ARX")));
        }
        QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        test::typeInto(editor->field("coulomb"), "0.5");
        QCOMPARE(session_->session().axes[0].friction.coulombVolts, 0.5);
        const AxisEvaluation& a = session_->axisEvaluation(0);
        QVERIFY2(a.ok, a.error.text.c_str());
        session_->setMethod(0, DesignMethod::GuilleminTruxal);
        QVERIFY(editor->field("backlash")->isEnabled());
    }

    void theBallbarComparesTheCompensation() {
        Session s = session_->session();
        for (AxisSettings& a : s.axes) {
            a.method = DesignMethod::PidFeedforward;
            a.friction.coulombVolts = 0.02;
            a.frictionCompensation.percent = 100.0;
        }
        s.trajectory.kind = TrajectoryKind::Gcode;
        s.trajectory.gcode.fileName = "ballbar.nc";
        s.trajectory.gcode.program = "G21 G90 G17\nG0 X25 Y0\nG2 X25 Y0 I-25 J0 F150\n";
        session_->apply(s, QStringLiteral("ballbar"));
        const auto& program = session_->evaluation().program;
        QVERIFY(program && program->circular && program->circular->uncompensatedIso);
        const ContourCircularTest& test = *program->circular;
        // The compensation removes what the friction adds: G without it is larger.
        QVERIFY(test.uncompensatedIso->circularDeviationG > test.iso.circularDeviationG);
        window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
        ContourPlot* plot = window_->contourPlot();
        plot->setPolar(true);
        QCOMPARE(plot->uncompensatedCurve()->data()->size(),
                 static_cast<int>(test.uncompensatedX.size()));
        QVERIFY(plot->uncompensatedCurve()->name().contains(QStringLiteral("without")));
        // The metrics panel: the largest spike on the ISO line, each one and G without the
        // compensation in its tooltip.
        double largest = 0.0;
        for (const ReversalSpike& spike : test.iso.reversalSpikes)
            largest = std::max(largest, std::abs(spike.heightMm));
        const QString figures = window_->metricsPanel()->contourText();
        QVERIFY2(figures.contains(QStringLiteral("spikes ≤ %1 mm").arg(largest, 0, 'f', 4)),
                 qPrintable(figures));
        const QString tip = window_->metricsPanel()->contourToolTip();
        QVERIFY2(tip.contains(QStringLiteral("G %1 mm").arg(
                     test.uncompensatedIso->circularDeviationG, 0, 'f', 4)),
                 qPrintable(tip));
        QVERIFY(tip.contains(
            QStringLiteral("0° %1").arg(test.iso.reversalSpikes[0].heightMm, 0, 'f', 4)));
        // The ballbar view's figures name G without the compensation too.
        QVERIFY(plot->figuresText().contains(QStringLiteral("without friction compensation G")));
        // Without the compensation there is nothing to compare.
        for (AxisSettings& a : s.axes)
            a.frictionCompensation.percent = 0.0;
        session_->apply(s, QStringLiteral("no compensation"));
        QVERIFY(!session_->evaluation().program->circular->uncompensatedIso);
        QCOMPARE(plot->uncompensatedCurve()->data()->size(), 0);
    }

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TstFrictionWorkbench)
#include "tst_friction_workbench.moc"
