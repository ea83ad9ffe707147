// SPDX-License-Identifier: GPL-3.0-or-later
// GUI tests: drive the real widgets offscreen and assert on the presenter's state and the plots'
// data, not on pixels.
#include "ui/contour_plot.h"
#include "ui/equations_panel.h"
#include "ui/main_window.h"
#include "ui/number_field.h"
#include "ui/parameter_slider.h"
#include "ui/plant_editor.h"
#include "ui/time_response_plot.h"
#include "ui/trajectory_editor.h"
#include "ui/tuning_session.h"
#include "tests/support/tolerance.h"

#include <QComboBox>
#include <QSlider>
#include <QTest>

using namespace xyt;
using namespace xyt::ui;

class TstMainWindow : public QObject {
    Q_OBJECT
private slots:
    void init();
    void omegaNSliderUpdatesKi();
    void kpSpinBoxUpdatesDesign();
    void invalidPlantValueIsRejectedAtTheField();
    void validPlantValueIsApplied();
    void contourPlotHoldsTheSimulatedData();
    void timePlotShowsTheRun();
    void undoRestoresTheSlider();

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstMainWindow::init() {
    QCoreApplication::setOrganizationName("xytune-tests");
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstMainWindow::omegaNSliderUpdatesKi() {
    QSlider* slider = window_->omegaNSlider()->slider();
    slider->setFocus();
    const int before = slider->value();
    QTest::keyClick(slider, Qt::Key_PageUp);
    QVERIFY(slider->value() != before);
    const double wn = session_->session().axes[0].gt.omegaNRadPerSec;
    QVERIFY(wn > 2.0);
    // Core value (Eq. 11, 16): ki = kp * wn^4 / (kp k0) = wn^4 / k0.
    const double ki = session_->axisEvaluation(0).gt->ki;
    XYT_COMPARE_NEAR(ki, std::pow(wn, 4) / 77.8, 1e-13, 0.0);
    QVERIFY2(window_->equationsPanel()->text().contains(QString::number(ki, 'g', 6)),
             qPrintable(window_->equationsPanel()->text()));
}

void TstMainWindow::kpSpinBoxUpdatesDesign() {
    auto* spin = window_->kpSlider()->spinBox();
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, "45");
    QTest::keyClick(spin, Qt::Key_Return);
    QTRY_COMPARE(session_->session().axes[0].gt.kp, 45.0);
    XYT_COMPARE_NEAR(session_->axisEvaluation(0).gt->f3, 45.0 * 77.8 / 8.0, 1e-14, 0.0);
}

void TstMainWindow::invalidPlantValueIsRejectedAtTheField() {
    NumberField* k0 = window_->plantEditor()->k0Field();
    k0->setFocus();
    k0->selectAll();
    QTest::keyClicks(k0, "abc");
    QTest::keyClick(k0, Qt::Key_Return);
    QVERIFY(k0->hasError());
    QVERIFY2(k0->toolTip().contains("k0") && k0->toolTip().contains("not a number"),
             qPrintable(k0->toolTip()));
    QCOMPARE(session_->session().axes[0].gt.plant.k0, 77.8); // not applied
    QCOMPARE(session_->undoStack()->count(), 0);
    k0->selectAll();
    QTest::keyClicks(k0, "0");
    QTest::keyClick(k0, Qt::Key_Return);
    QVERIFY(k0->hasError());
    QVERIFY(k0->toolTip().contains("nonzero"));
    QCOMPARE(session_->session().axes[0].gt.plant.k0, 77.8);
}

void TstMainWindow::validPlantValueIsApplied() {
    NumberField* a2 = window_->plantEditor()->a2Field();
    a2->setFocus();
    a2->selectAll();
    QTest::keyClicks(a2, "4000");
    QTest::keyClick(a2, Qt::Key_Return);
    QVERIFY(!a2->hasError());
    QCOMPARE(session_->session().axes[0].gt.plant.a2, 4000.0);
    // f2 = a2 / wn^2 (Eq. 18).
    XYT_COMPARE_NEAR(session_->axisEvaluation(0).gt->f2, 1000.0, 1e-14, 0.0);
    QCOMPARE(window_->plantEditor()->presetBox()->currentText(), QString("custom"));
}

void TstMainWindow::contourPlotHoldsTheSimulatedData() {
    QComboBox* kind = window_->trajectoryEditor()->kindBox();
    kind->setFocus();
    QTest::keyClick(kind, Qt::Key_Down); // cubic -> circle
    QTRY_VERIFY(session_->session().trajectory.kind == TrajectoryKind::Circle);
    const auto& x = session_->axisEvaluation(0).run;
    const auto& y = session_->axisEvaluation(1).run;
    QCPCurve* traced = window_->contourPlot()->tracedCurve();
    QCOMPARE(traced->data()->size(), static_cast<int>(x.t.size()));
    // Both axes share dt here, so the traced point k is (x_k, y_k) exactly.
    for (int k : {0, 1000, static_cast<int>(x.t.size()) - 1}) {
        const auto point = traced->data()->at(k);
        XYT_COMPARE_NEAR(point->key, x.y[static_cast<std::size_t>(k)], 0.0, 0.0);
        XYT_COMPARE_NEAR(point->value, y.y[static_cast<std::size_t>(k)], 0.0, 0.0);
    }
}

void TstMainWindow::timePlotShowsTheRun() {
    const auto& run = session_->axisEvaluation(0).run;
    QCOMPARE(window_->timePlot()->outputGraph()->data()->size(), static_cast<int>(run.t.size()));
    QCOMPARE(window_->timePlot()->controlGraph()->data()->at(100)->value, run.u[100]);
}

void TstMainWindow::undoRestoresTheSlider() {
    window_->omegaNSlider()->spinBox()->setValue(3.0);
    QCOMPARE(session_->session().axes[0].gt.omegaNRadPerSec, 3.0);
    session_->undoStack()->undo();
    QCOMPARE(window_->omegaNSlider()->value(), 2.0);
    QCOMPARE(window_->omegaNSlider()->spinBox()->value(), 2.0);
}

QTEST_MAIN(TstMainWindow)
#include "tst_main_window.moc"
