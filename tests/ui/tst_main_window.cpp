// SPDX-License-Identifier: GPL-3.0-or-later
// GUI tests: drive the real widgets offscreen and assert on the presenter's state and the plots'
// data, not on pixels.
#include "tests/support/gui_checks.h"
#include "tests/support/tolerance.h"
#include "ui/files/session_file.h"
#include "ui/main_window.h"
#include "ui/panels/equations_panel.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/parameter_slider.h"
#include "ui/panels/plant_editor.h"
#include "ui/panels/pp_editor.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/tuning_session.h"
#include "ui/views/step_response_view.h"
#include "ui/views/time_response_view.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QTableWidget>
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
    void clickOnRootLocusSetsTheGain();
    void switchingToPolePlacement();
    void invalidCoefficientListIsRejectedAtTheField();
    void sliderStepRelaysNoSplitter();
    void manyWarningsFitA1366x768Window();
    void programWithFrictionFitsA1366x768Window();
    void viewsObserveThePresenter();

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
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    QComboBox* kind = window_->trajectoryEditor()->kindBox();
    kind->setFocus();
    QTest::keyClick(kind, Qt::Key_Down); // cubic -> circle
    QTRY_VERIFY(session_->session().trajectory.kind == TrajectoryKind::Circle);
    const auto& x = session_->axisEvaluation(0).run;
    const auto& y = session_->axisEvaluation(1).run;
    QCPCurve* traced = window_->contourPlot()->tracedCurve();
    QCOMPARE(traced->data()->size(), static_cast<int>(x.t.size()));
    // The magnified path of a circle is R + factor (rho - R) along each traced point's angle.
    auto* factor =
        window_->lowerTabs()->cornerWidget(Qt::TopRightCorner)->findChild<QDoubleSpinBox*>();
    if (!factor)
        factor =
            qobject_cast<QDoubleSpinBox*>(window_->lowerTabs()->cornerWidget(Qt::TopRightCorner));
    QVERIFY(factor);
    factor->setValue(50.0);
    {
        const std::size_t k = x.t.size() - 1;
        const double rho = std::hypot(x.y[k], y.y[k]);
        const double expected = 25.0 + 50.0 * (rho - 25.0);
        const auto m = window_->contourPlot()->magnifiedCurve()->data()->at(static_cast<int>(k));
        XYT_COMPARE_NEAR(std::hypot(m->key, m->value), expected, 1e-12, 1e-12);
    }
    // Both axes share dt here, so the traced point k is (x_k, y_k) exactly.
    for (int k : {0, 1000, static_cast<int>(x.t.size()) - 1}) {
        const auto point = traced->data()->at(k);
        XYT_COMPARE_NEAR(point->key, x.y[static_cast<std::size_t>(k)], 0.0, 0.0);
        XYT_COMPARE_NEAR(point->value, y.y[static_cast<std::size_t>(k)], 0.0, 0.0);
    }
}

void TstMainWindow::timePlotShowsTheRun() {
    const auto& run = session_->axisEvaluation(0).run;
    // Every drawn point is a sample of the run (decimated to its extremes beyond 16 384 samples).
    QVERIFY(test::sameSignal(window_->timePlot()->outputGraph()->data(), run.t, run.y));
    QVERIFY(test::sameSignal(window_->timePlot()->controlGraph()->data(), run.t, run.u));
}

void TstMainWindow::undoRestoresTheSlider() {
    window_->omegaNSlider()->spinBox()->setValue(3.0);
    QCOMPARE(session_->session().axes[0].gt.omegaNRadPerSec, 3.0);
    session_->undoStack()->undo();
    QCOMPARE(window_->omegaNSlider()->value(), 2.0);
    QCOMPARE(window_->omegaNSlider()->spinBox()->value(), 2.0);
}

void TstMainWindow::clickOnRootLocusSetsTheGain() {
    RootLocusPlot* plot = window_->rootLocusPlot();
    window_->upperTabs()->setCurrentWidget(plot);
    plot->replot();
    // A point on the branch that leaves the origin pole pair, about a third of the way along:
    // click exactly on its pixel (the plot's own axes convert coordinates to pixels).
    const RootLocus& locus = plot->locus();
    QVERIFY(!locus.branches.empty());
    std::size_t branch = 0, index = 0;
    double best = -1.0;
    for (std::size_t b = 0; b < locus.branches.size(); ++b)
        for (std::size_t i = 0; i < locus.branches[b].roots.size(); ++i) {
            const auto r = locus.branches[b].roots[i];
            const double g = locus.gains[i];
            if (plot->xAxis->range().contains(r.real()) &&
                plot->yAxis->range().contains(r.imag()) && std::abs(r.imag()) > 20 && g > best &&
                g < 50) {
                best = g;
                branch = b;
                index = i;
            }
        }
    QVERIFY2(best > 0, "no visible complex locus point");
    const auto point = locus.branches[branch].roots[index];
    const QPoint pixel(qRound(plot->xAxis->coordToPixel(point.real())),
                       qRound(plot->yAxis->coordToPixel(point.imag())));
    const auto pick = plot->pickAtPixel(pixel);
    QVERIFY(pick.has_value());
    const double gain = pick->gain;
    QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, pixel);
    // The controller becomes K (kp + ki/s): kp' = K kp, wn' = K^(1/4) wn (ki = wn^4/k0).
    XYT_COMPARE_NEAR(session_->session().axes[0].gt.kp, 30.0 * gain, 1e-12, 0.0);
    XYT_COMPARE_NEAR(session_->session().axes[0].gt.omegaNRadPerSec, 2.0 * std::pow(gain, 0.25),
                     1e-12, 0.0);
    // Invariant: the picked point is now a closed-loop pole of the new design.
    double nearest = 1e300;
    for (const auto& p : session_->axisEvaluation(0).gt->closedLoopPoles)
        nearest = std::min(nearest, std::abs(p - pick->point));
    QVERIFY2(nearest < 1e-6 * std::abs(pick->point), qPrintable(QString::number(nearest)));
}

void TstMainWindow::switchingToPolePlacement() {
    session_->setCurrentAxis(1);
    QComboBox* method = window_->methodBox();
    method->setFocus();
    QTest::keyClick(method, Qt::Key_Down);
    QTRY_VERIFY(session_->session().axes[1].method == DesignMethod::PolePlacementZpetc);
    const AxisEvaluation& e = session_->axisEvaluation(1);
    QVERIFY(e.ok);
    QVERIFY(e.pp.has_value());
    // T(1)/B(1) = 0.8 / (0.0352 + 0.0599 - 0.0067) (Patrick, Ishak and Adnan Eq. 7, y-axis B).
    XYT_COMPARE_NEAR(e.pp->kf, 0.8 / 0.0884, 1e-12, 0.0);
    // The t1 slider is a design parameter: moving it re-solves the Diophantine equation.
    window_->ppEditor()->t1Slider()->spinBox()->setValue(-0.5);
    QCOMPARE(session_->session().axes[1].pp.t1, -0.5);
    XYT_COMPARE_NEAR(session_->axisEvaluation(1).pp->kf, 0.5 / 0.0884, 1e-12, 0.0);
    QCOMPARE(window_->rootLocusPlot()->locus().tsSeconds, 0.07);
}

void TstMainWindow::invalidCoefficientListIsRejectedAtTheField() {
    session_->setMethod(0, DesignMethod::PolePlacementZpetc);
    QLineEdit* a = window_->ppEditor()->aField();
    const auto before = session_->session().axes[0].pp;
    a->setFocus();
    a->selectAll();
    QTest::keyClicks(a, "1 -1.658 x");
    QTest::keyClick(a, Qt::Key_Return);
    QVERIFY2(a->toolTip().contains("A[2]") && a->toolTip().contains("not a number"),
             qPrintable(a->toolTip()));
    QVERIFY(session_->session().axes[0].pp == before);
}

namespace {
/// Counts the layout requests that reach the watched widgets.
class LayoutRequestCounter : public QObject {
public:
    int count = 0;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::LayoutRequest)
            ++count;
        return QObject::eventFilter(watched, event);
    }
};
} // namespace

void TstMainWindow::sliderStepRelaysNoSplitter() {
    // A slider step changes figures in the metrics table and the plots, never the size of
    // anything: a layout request reaching a splitter makes Qt ask every tab page, hidden ones
    // too, for its size hints, which cost a seventh of a slider step (xytune-bench
    // gui_slider_to_repaint). The metrics table's rows and height are fixed, its columns resized
    // only when a figure needs it, and the plots' hints constant (PlotWidget).
    window_->resize(1366, 768);
    QSlider* slider = window_->omegaNSlider()->slider();
    // First visits of the two positions may size the columns to their new figures.
    for (int delta : {1, -1}) {
        slider->setValue(slider->value() + delta);
        QCoreApplication::processEvents();
    }
    LayoutRequestCounter counter;
    for (QSplitter* splitter : window_->findChildren<QSplitter*>())
        splitter->installEventFilter(&counter);
    const double before = session_->session().axes[0].gt.omegaNRadPerSec;
    for (int step = 0; step < 4; ++step) {
        slider->setValue(slider->value() + (step % 2 ? -1 : 1));
        QCoreApplication::processEvents();
        QVERIFY(session_->session().axes[0].gt.omegaNRadPerSec != before || step % 2); // it moved
    }
    QCOMPARE(counter.count, 0);
}

void TstMainWindow::programWithFrictionFitsA1366x768Window() {
    // The friction tutorial's session: a G-code circle (contour and ISO 230-4 figures under the
    // metrics table) with stick-slip and saturation warnings on both axes. The side column
    // needed 792 px and the window grew taller than a 1366x768 screen; it now scrolls.
    const auto loaded = xyt::files::loadSessionFile(
        QStringLiteral(XYT_SOURCE_DIR "/resources/examples/friction_quadrant_glitches.json"));
    QVERIFY2(loaded.ok, qPrintable(loaded.message()));
    session_->reset(loaded.session);
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    window_->resize(1366, 768);
    QTest::qWait(50);
    QVERIFY(!window_->metricsPanel()->noticeText().isEmpty());
    QVERIFY2(window_->minimumSizeHint().height() <= 768,
             qPrintable(QString::number(window_->minimumSizeHint().height())));
    QCOMPARE(window_->height(), 768);
    // The contour keeps one scale on both axes once laid out (a circle stays round): mm per
    // pixel equal within 1 % (a pixel of rounding in an axis rect about 250 px tall is 0.4 %).
    ContourPlot* plot = window_->contourPlot();
    plot->replot();
    const QRect rect = plot->axisRect()->rect();
    const double xScale = plot->xAxis->range().size() / rect.width();
    const double yScale = plot->yAxis->range().size() / rect.height();
    QVERIFY2(std::abs(xScale / yScale - 1.0) < 0.01,
             qPrintable(QStringLiteral("x %1 mm/px, y %2 mm/px").arg(xScale).arg(yScale)));
}

void TstMainWindow::manyWarningsFitA1366x768Window() {
    // Both axes pole placement on the 600 mm cubic: six warnings in the metrics panel (out of
    // reach, unclipped |u|, the implementation's verdict, for each axis). They made the window
    // at least 790 px tall and covered the table's margin rows.
    Session s = Session::paperDefault();
    for (AxisSettings& a : s.axes)
        a.method = DesignMethod::PolePlacementZpetc;
    session_->reset(s);
    window_->resize(1366, 768);
    QTest::qWait(20);
    QVERIFY2(window_->minimumSizeHint().height() <= 768,
             qPrintable(QString::number(window_->minimumSizeHint().height())));
    QCOMPARE(window_->height(), 768);
    QVERIFY(!window_->metricsPanel()->noticeText().isEmpty());
    auto* table = window_->metricsPanel()->findChild<QTableWidget*>();
    QVERIFY(table);
    const QRect tableRect(table->mapTo(window_.get(), QPoint(0, 0)), table->size());
    for (QScrollArea* area : window_->metricsPanel()->findChildren<QScrollArea*>()) {
        if (!area->isVisible())
            continue;
        const QRect r(area->mapTo(window_.get(), QPoint(0, 0)), area->size());
        QVERIFY2(!r.intersects(tableRect), "the warnings cover the metrics table");
        QVERIFY(window_->rect().contains(r));
    }
}

void TstMainWindow::viewsObserveThePresenter() {
    // Each plot is drawn by its view, which observes the presenter: a change through the
    // presenter alone (no window call) redraws what is on screen, marks a view on a hidden tab
    // stale without drawing it, and the hidden view is drawn when its tab is shown.
    window_->resize(1366, 768);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    window_->lowerTabs()->setCurrentWidget(window_->timePlot());
    StepResponseView* step = nullptr;
    TimeResponseView* time = nullptr;
    for (PresenterView* view : window_->views()) {
        step = step ? step : qobject_cast<StepResponseView*>(view);
        time = time ? time : qobject_cast<TimeResponseView*>(view);
    }
    QVERIFY(step && time);
    QCOMPARE(window_->views().size(), std::size_t(11)); // every plot and both panels
    const auto settling = [&] {
        return window_->stepPlot()->settlingMarker()->data()->isEmpty()
                   ? -1.0
                   : window_->stepPlot()->settlingMarker()->data()->at(0)->key;
    };
    const double before = settling();
    session_->setOmegaN(0, 3.0);
    QVERIFY(time->isCurrent());
    QVERIFY(test::sameSignal(window_->timePlot()->outputGraph()->data(),
                             session_->axisEvaluation(0).run.t, session_->axisEvaluation(0).run.y));
    QVERIFY(!step->isCurrent());
    QCOMPARE(settling(), before); // not drawn while hidden
    window_->lowerTabs()->setCurrentWidget(window_->stepPlot());
    QVERIFY(step->isCurrent());
    QCOMPARE(settling(), session_->axisEvaluation(0).step.settlingTimeSeconds);
    QCOMPARE(test::plotsMismatch(window_.get(), session_.get()), QString());
}

QTEST_MAIN(TstMainWindow)
#include "tst_main_window.moc"
