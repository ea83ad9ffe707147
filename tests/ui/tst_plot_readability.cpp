// SPDX-License-Identifier: GPL-3.0-or-later
// What a new user sees on the plots: planes at equal aspect, legends and hints that
// hide nothing, a parameter locus framed on the poles that move with the stability boundary
// marked, distinguishable pole sets, controls only on the tabs they act on, panels without
// gaps and axes without crowded ticks. Each test drives the real window at 1366x768 and, where
// it matters, at 1600x1000.
#include "core/design/guillemin_truxal.h"
#include "tests/support/plot_layout_checks.h"
#include "tests/support/tolerance.h"
#include "ui/main_window.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/damping_labels.h"
#include "ui/plots/parameter_locus_plot.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/step_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/session/recovery_store.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>

#include <cmath>
#include <memory>

using namespace xyt;
using namespace xyt::ui;

Q_DECLARE_METATYPE(xyt::Session)

namespace {

/// The states whose plots are checked for their layout: each method, an invalid design, a
/// diverging run, a G-code program, the circle (its polar, ballbar-like view) and a move back.
QList<QPair<const char*, Session>> layoutStates() {
    Session pp = Session::paperDefault();
    for (AxisSettings& a : pp.axes)
        a.method = DesignMethod::PolePlacementZpetc;
    Session invalid = Session::paperDefault();
    invalid.axes[1].method = DesignMethod::PolePlacementZpetc;
    invalid.axes[1].pp.b = {0.0, 0.0, 0.0}; // B = 0: no design
    Session unstable = Session::paperDefault();
    unstable.axes[0].gt.plant.a1 = -100.0; // the closed loop diverges
    Session gcode = Session::paperDefault();
    gcode.trajectory.kind = TrajectoryKind::Gcode;
    gcode.trajectory.gcode.fileName = "square.nc";
    gcode.trajectory.gcode.program =
        "G21 G90\nG1 X20 Y0 F600\nX20 Y15\nG3 X15 Y20 I-5 J0\nG1 X0 Y20\nX0 Y0\n";
    Session circle = Session::paperDefault();
    circle.trajectory.kind = TrajectoryKind::Circle;
    Session back = Session::paperDefault(); // 600 mm back to 0: the traces end where the legend was
    back.trajectory.x0 = 600.0;
    back.trajectory.xf = 0.0;
    return {{"default", Session::paperDefault()},
            {"pole placement", pp},
            {"one axis invalid", invalid},
            {"unstable", unstable},
            {"gcode", gcode},
            {"circle", circle},
            {"move back", back}};
}

/// Draws @p plot as a user sees it: the guard may re-lay it out once (a wrapped title, a
/// legend in fewer columns) and queue the drawing that shows it.
void drawSettled(QCustomPlot* plot) {
    plot->replot(QCustomPlot::rpImmediateRefresh);
    plot->replot(QCustomPlot::rpImmediateRefresh);
}

} // namespace

class TstPlotReadability : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void planesHaveEqualAspect_data();
    void planesHaveEqualAspect();
    void legendsAndHintSitOutsideThePlane();
    void zPlaneDampingLabelsDoNotPileUp();
    void sPlaneDampingLabelsStayApartWhenZoomed_data();
    void sPlaneDampingLabelsStayApartWhenZoomed();
    void annotationsStayInsideAndApart_data();
    void annotationsStayInsideAndApart();
    void legendGivesWayToANoticeAndReturns();
    void plotsSettleAfterADesignChange_data();
    void plotsSettleAfterADesignChange();
    void parameterLocusFramesTheMovingPolesAndMarksTheBoundary();
    void parameterLocusBoundaryFollowsKp();
    void coincidentPoleSetsAreDistinguishable();
    void zpetcLeavesTheLegendWhenSwitchedOff();
    void cornerControlsOnlyOnTheirTab();
    void leftPanelHasNoGapForTheShortPage();
    void leftPanelFitsA1366x768Window();
    void valueTicksFitTheirPanel();
    void displayNumberHasSignificantDigits();
    void moveAndSettleRowsShowTheCoreFigures();
    void metricsAreGroupedAndNeverCut_data();
    void metricsAreGroupedAndNeverCut();

private:
    void usePolePlacement(int axis);
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

void TstPlotReadability::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("xytune-tests");
}

void TstPlotReadability::init() {
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->resize(1366, 768);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TstPlotReadability::cleanup() {
    window_->recovery()->discard();
    window_.reset();
    session_.reset();
}

void TstPlotReadability::usePolePlacement(int axis) {
    session_->setCurrentAxis(axis);
    session_->setMethod(axis, DesignMethod::PolePlacementZpetc);
}

namespace {
/// Pixels per unit along x and y of a plot's main axes, after a synchronous replot.
std::pair<double, double> pixelsPerUnit(QCustomPlot* plot) {
    plot->replot(QCustomPlot::rpImmediateRefresh);
    const QCPRange x = plot->xAxis->range(), y = plot->yAxis->range();
    return {plot->axisRect()->width() / x.size(), plot->axisRect()->height() / y.size()};
}
} // namespace

void TstPlotReadability::planesHaveEqualAspect_data() {
    QTest::addColumn<int>("tab");
    QTest::addColumn<bool>("discrete");
    QTest::newRow("root locus, s-plane") << 0 << false;
    QTest::newRow("root locus, z-plane") << 0 << true;
    QTest::newRow("parameter locus") << 1 << false;
    QTest::newRow("pole-zero, s-plane") << 2 << false;
    QTest::newRow("pole-zero, z-plane") << 2 << true;
}

void TstPlotReadability::planesHaveEqualAspect() {
    // The z-plane's unit circle was drawn as an ellipse: a unit must span as many pixels on
    // both axes (to the pixel rounding of the axis rect, < 1 %), at both window sizes.
    QFETCH(int, tab);
    QFETCH(bool, discrete);
    if (discrete)
        usePolePlacement(0);
    window_->upperTabs()->setCurrentIndex(tab);
    auto* plot = qobject_cast<QCustomPlot*>(window_->upperTabs()->currentWidget());
    QVERIFY(plot);
    for (const QSize size : {QSize(1366, 768), QSize(1600, 1000), QSize(1366, 768)}) {
        window_->resize(size);
        QTest::qWait(50);
        const auto [px, py] = pixelsPerUnit(plot);
        QVERIFY2(std::abs(px / py - 1.0) < 0.01, qPrintable(QString("%1x%2: %3 vs %4 px per unit")
                                                                .arg(size.width())
                                                                .arg(size.height())
                                                                .arg(px)
                                                                .arg(py)));
        // The z-plane's unit circle (the stability boundary) whole in the view: it was cut.
        if (discrete)
            for (const QCPRange r : {plot->xAxis->range(), plot->yAxis->range()})
                QVERIFY2(r.lower < -1.0 && r.upper > 1.0,
                         qPrintable(QString("%1 .. %2").arg(r.lower).arg(r.upper)));
    }
    // The reset view (double click, context menu) keeps it.
    plot->xAxis->setRange(-1, 100);
    QTest::mouseDClick(plot, Qt::LeftButton, {}, plot->axisRect()->center());
    const auto [px, py] = pixelsPerUnit(plot);
    QVERIFY2(std::abs(px / py - 1.0) < 0.01, qPrintable(QString("%1 vs %2").arg(px).arg(py)));
}

void TstPlotReadability::legendsAndHintSitOutsideThePlane() {
    // The locus legend hid the lower branch, and the hover hint sat on the damping labels:
    // both now live in rows under the plane, so no pixel of the axis rect is theirs.
    for (int tab = 0; tab < 3; ++tab) {
        window_->upperTabs()->setCurrentIndex(tab);
        auto* plot = qobject_cast<QCustomPlot*>(window_->upperTabs()->currentWidget());
        plot->replot(QCustomPlot::rpImmediateRefresh);
        QVERIFY(plot->legend->visible());
        QVERIFY2(!plot->legend->outerRect().intersects(
                     plot->axisRect()->outerRect().adjusted(0, 0, 0, -1)),
                 qPrintable(plot->objectName()));
        QVERIFY(plot->legend->outerRect().top() >= plot->axisRect()->outerRect().bottom() - 1);
    }
    // The step view likewise (its legend carries the envelope and the markers).
    window_->lowerTabs()->setCurrentWidget(window_->stepPlot());
    StepPlot* step = window_->stepPlot();
    step->replot(QCustomPlot::rpImmediateRefresh);
    QVERIFY(step->legend->visible());
    QVERIFY(step->legend->outerRect().top() >= step->axisRect()->outerRect().bottom() - 1);
    QVERIFY(step->axisRect()->height() > 150); // the plane keeps most of the tab at 1366x768
    RootLocusPlot* rl = window_->rootLocusPlot();
    auto* hint = qobject_cast<QCPTextElement*>(rl->plotLayout()->element(3, 0));
    QVERIFY(hint);
    QCOMPARE(hint->text(), RootLocusPlot::readoutHint());
    QVERIFY(hint->outerRect().top() >= rl->legend->outerRect().bottom() - 1);
}

namespace {

/// The ζ labels of @p plot as last drawn.
std::vector<DampingLabels::Placed> dampingLabels(QCustomPlot* plot) {
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto* labels = dynamic_cast<DampingLabels*>(plot->item(i)))
            return labels->placed();
    return {};
}

/// Fails unless every label lies inside the plot's axis rect and no two overlap.
void requireLabelsInsideApart(QCustomPlot* plot, const std::vector<DampingLabels::Placed>& labels) {
    const QRectF area = plot->axisRect()->rect();
    for (std::size_t i = 0; i < labels.size(); ++i) {
        QVERIFY2(area.contains(labels[i].rect),
                 qPrintable(labels[i].text + " leaves the axis rect"));
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            QVERIFY2(!labels[i].rect.intersects(labels[j].rect),
                     qPrintable(labels[i].text + " overlaps " + labels[j].text));
    }
}

} // namespace

void TstPlotReadability::zPlaneDampingLabelsDoNotPileUp() {
    // Every z-plane damping line starts at z = 1, where all the ζ labels used to sit; each now
    // sits above the top of its own spiral, inside the unit disc's view, none on another.
    usePolePlacement(0);
    window_->upperTabs()->setCurrentIndex(0);
    RootLocusPlot* plot = window_->rootLocusPlot();
    plot->replot(QCustomPlot::rpImmediateRefresh);
    // The default view holds the model's zero near z = -18, so the unit disc is small: the
    // labels that fit are placed apart, the rest left out.
    requireLabelsInsideApart(plot, dampingLabels(plot));
    // Zoomed on the unit disc, at least five of the nine have room.
    plot->xAxis->setRange(-1.3, 1.3);
    plot->yAxis->setRange(-1.3, 1.3);
    plot->replot(QCustomPlot::rpImmediateRefresh);
    const auto labels = dampingLabels(plot);
    QVERIFY2(labels.size() >= 5, qPrintable(QString::number(labels.size())));
    requireLabelsInsideApart(plot, labels);
}

void TstPlotReadability::sPlaneDampingLabelsStayApartWhenZoomed_data() {
    QTest::addColumn<QSize>("size");
    QTest::newRow("1366x768") << QSize(1366, 768);
    QTest::newRow("1600x1000") << QSize(1600, 1000);
}

void TstPlotReadability::sPlaneDampingLabelsStayApartWhenZoomed() {
    // The light-damping rays converge on the imaginary axis: their labels used to stack at the
    // top of the plane. Each is placed where its ray leaves the view, or left out.
    QFETCH(QSize, size);
    window_->resize(size);
    window_->upperTabs()->setCurrentIndex(0);
    RootLocusPlot* plot = window_->rootLocusPlot();
    QTest::qWait(50);
    plot->replot(QCustomPlot::rpImmediateRefresh);
    auto labels = dampingLabels(plot);
    QVERIFY2(labels.size() >= 4, qPrintable(QString::number(labels.size())));
    requireLabelsInsideApart(plot, labels);
    // Zoomed on the origin (a fifth of the view): the rays leave a smaller view, still labelled.
    plot->xAxis->scaleRange(0.2, 0.0);
    plot->yAxis->scaleRange(0.2, 0.0);
    plot->replot(QCustomPlot::rpImmediateRefresh);
    labels = dampingLabels(plot);
    QVERIFY2(labels.size() >= 4, qPrintable(QString::number(labels.size())));
    requireLabelsInsideApart(plot, labels);
}

void TstPlotReadability::annotationsStayInsideAndApart_data() {
    QTest::addColumn<Session>("state");
    QTest::addColumn<QSize>("size");
    for (const auto& [name, state] : layoutStates())
        for (const QSize size : {QSize(1366, 768), QSize(1600, 1000)})
            QTest::addRow("%s, %dx%d", name, size.width(), size.height()) << state << size;
}

void TstPlotReadability::annotationsStayInsideAndApart() {
    // Every plot of every tab, for both axes: marker labels, notices and ζ labels inside their
    // axis rect and none on another, legends set in a plane inside it, titles whole. Before,
    // the step view's peak and settling labels overlapped, notices were cut at the left and an
    // invalid design's title on both sides.
    QFETCH(Session, state);
    QFETCH(QSize, size);
    session_->reset(state);
    window_->resize(size);
    QStringList problems;
    for (int axis : {0, 1}) {
        session_->setCurrentAxis(axis);
        for (QTabWidget* tabs : {window_->upperTabs(), window_->lowerTabs()})
            for (int i = 0; i < tabs->count(); ++i) {
                tabs->setCurrentIndex(i);
                QTest::qWait(1);
                for (auto* plot : tabs->currentWidget()->findChildren<QCustomPlot*>()) {
                    if (!plot->isVisible())
                        continue;
                    drawSettled(plot);
                    for (const QString& p : test::annotationProblems(plot))
                        problems << QString("axis %1, %2: %3")
                                        .arg(axis)
                                        .arg(tabs->tabText(i).remove('&'), p);
                }
                if (auto* plot = qobject_cast<QCustomPlot*>(tabs->currentWidget())) {
                    drawSettled(plot);
                    for (const QString& p : test::annotationProblems(plot))
                        problems << QString("axis %1, %2: %3")
                                        .arg(axis)
                                        .arg(tabs->tabText(i).remove('&'), p);
                }
            }
    }
    problems.removeDuplicates();
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
}

void TstPlotReadability::legendGivesWayToANoticeAndReturns() {
    // The unstable loop's notice spans the position plane at 1366x768: every corner for the
    // legend holds text, so the legend waits hidden; back to a stable design, it returns.
    window_->resize(1366, 768);
    window_->lowerTabs()->setCurrentIndex(0);
    auto* plot = qobject_cast<QCustomPlot*>(window_->lowerTabs()->currentWidget());
    QVERIFY(plot);
    const auto insetLegend = [plot]() -> QCPLegend* {
        for (QCPAxisRect* rect : plot->axisRects())
            for (int k = 0; k < rect->insetLayout()->elementCount(); ++k)
                if (auto* legend = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(k)))
                    return legend;
        return nullptr;
    };
    QVERIFY(insetLegend());
    drawSettled(plot);
    QVERIFY(insetLegend()->visible());
    Session unstable = Session::paperDefault();
    unstable.axes[0].gt.plant.a1 = -100.0;
    session_->reset(unstable);
    drawSettled(plot);
    QVERIFY(!insetLegend()->visible());
    QVERIFY(test::annotationProblems(plot).isEmpty());
    session_->reset(Session::paperDefault());
    drawSettled(plot);
    QVERIFY(insetLegend()->visible());
    QVERIFY2(test::annotationProblems(plot).isEmpty(),
             qPrintable(test::annotationProblems(plot).join('\n')));
}

void TstPlotReadability::plotsSettleAfterADesignChange_data() {
    QTest::addColumn<Session>("session");
    for (const auto& [name, state] : layoutStates())
        QTest::newRow(name) << state;
}

void TstPlotReadability::plotsSettleAfterADesignChange() {
    // A slider step draws each visible plot once, and once more at most when the layout guard
    // changed the layout (a legend entry came or went, a tick count or a title). A guard step
    // that undid the plot's own setting (the time plot's value ticks) or counted the empty
    // cells of a legend's last row as gaps redrew the plot on every pass of the event loop.
    QFETCH(Session, session);
    session_->apply(session, "state");
    QTest::qWait(50);
    QMap<QCustomPlot*, int> drawings;
    for (QCustomPlot* plot : window_->findChildren<QCustomPlot*>())
        connect(plot, &QCustomPlot::afterReplot, this, [plot, &drawings] { ++drawings[plot]; });
    constexpr int kSteps = 4;
    constexpr int kPasses =
        8; ///< event-loop passes after each step: a plot redrawing without end shows 8
    for (int step = 0; step < kSteps; ++step) {
        Session next = session; // a new design for either method: ωn, or T's root
        next.axes[0].gt.omegaNRadPerSec *= step % 2 ? 1.0 : 1.1;
        next.axes[0].pp.t1 *= step % 2 ? 1.0 : 1.1;
        session_->apply(next, "step");
        for (int pass = 0; pass < kPasses; ++pass)
            QCoreApplication::processEvents();
    }
    QVERIFY(!drawings.isEmpty()); // the visible plots were drawn
    for (auto it = drawings.cbegin(); it != drawings.cend(); ++it)
        QVERIFY2(it.value() <= 2 * kSteps, qPrintable(QString("%1 drawn %2 times in %3 steps")
                                                          .arg(it.key()->metaObject()->className())
                                                          .arg(it.value())
                                                          .arg(kSteps)));
}

void TstPlotReadability::parameterLocusFramesTheMovingPolesAndMarksTheBoundary() {
    // Default session, X axis: wn sweeps 0.2 ... 20 rad/s at kp = 30 (Braga et al.'s lower base).
    // Routh on s^4 + a1 s^3 + a2 s^2 + kp k0 s + wn^4: unstable above
    // wn* = (c (a1 a2 - c) / a1^2)^(1/4), c = kp k0, crossing at omega = sqrt(c / a1).
    window_->upperTabs()->setCurrentIndex(1);
    ParameterLocusPlot* plot = window_->parameterLocusPlot();
    plot->replot(QCustomPlot::rpImmediateRefresh);
    const ThirdOrderPlant p = session_->session().axes[0].gt.plant;
    const double c = session_->session().axes[0].gt.kp * p.k0;
    const double wnStar = std::pow(c * (p.a1 * p.a2 - c) / (p.a1 * p.a1), 0.25);
    QCOMPARE(plot->boundaryGraph()->data()->size(), 2);
    const double omegaCross = std::sqrt(c / p.a1);
    XYT_COMPARE_NEAR(std::abs(plot->boundaryGraph()->data()->at(0)->value), omegaCross, 1e-6, 0.0);
    QVERIFY2(plot->labelTexts().contains(
                 QString("unstable above ωn = %1").arg(QString::number(wnStar, 'g', 3))),
             qPrintable(plot->labelTexts().join(" | ")));
    // Framed on the two dominant branches (the plant's fast poles barely move), with both
    // half-planes and the crossing in view.
    QCOMPARE(plot->framedBranchCount(), 2);
    QVERIFY(plot->xAxis->range().lower < 0.0 && plot->xAxis->range().upper > 0.0);
    QVERIFY(plot->yAxis->range().contains(omegaCross));
    // The dominant poles of the design take more than a pixel: the view spans tens of rad/s,
    // not the 80 of the fast plant pole.
    QVERIFY2(plot->xAxis->range().size() < 0.8 * 80.0,
             qPrintable(QString::number(plot->xAxis->range().size())));
    QVERIFY(plot->noticeText().contains("barely move"));
    // A few parameter values are written along the branches.
    int valueLabels = 0;
    for (const QString& t : plot->labelTexts())
        valueLabels += t.startsWith("ωn=") ? 1 : 0;
    QVERIFY2(valueLabels >= 2, qPrintable(plot->labelTexts().join(" | ")));
}

void TstPlotReadability::parameterLocusBoundaryFollowsKp() {
    // kp sweeping (kp/10 ... 10 kp around kp = 30) at wn = 10: Routh gives a stable loop for
    // c = kp k0 between the roots of c^2 - a1 a2 c + a1^2 wn^4 = 0, i.e. kp in about
    // (4.4, 5900) V/m for the lower base: one boundary inside the sweep, at the lower root.
    window_->upperTabs()->setCurrentIndex(1);
    QComboBox* swept = nullptr;
    for (QComboBox* box : window_->findChildren<QComboBox*>())
        if (box->accessibleName() == "Swept parameter")
            swept = box;
    QVERIFY(swept && swept->isVisible());
    session_->setOmegaN(0, 10.0);
    swept->setCurrentIndex(1);
    ParameterLocusPlot* plot = window_->parameterLocusPlot();
    const ThirdOrderPlant p = session_->session().axes[0].gt.plant;
    const double a = p.a1, b = p.a2, d = 1e4;
    const double kpLow = 0.5 * (a * b - std::sqrt(a * a * b * b - 4 * a * a * d)) / p.k0;
    QVERIFY(kpLow > 3.0 && kpLow < 300.0);
    QStringList boundary;
    for (const QString& t : plot->labelTexts())
        if (t.startsWith("unstable"))
            boundary << t;
    QCOMPARE(boundary,
             QStringList{QString("unstable below kp = %1").arg(QString::number(kpLow, 'g', 3))});
    QCOMPARE(plot->boundaryGraph()->data()->size(), 2);
}

void TstPlotReadability::coincidentPoleSetsAreDistinguishable() {
    // The GT closed loop equals the reference model (Braga et al. Eq. 3): their poles coincide, so
    // the two sets must differ in shape, not only in colour, or one hides under the other.
    window_->upperTabs()->setCurrentIndex(2);
    PoleZeroPlot* plot = window_->poleZeroPlot();
    QCPGraph* closed = plot->polesGraph("closed loop");
    QCPGraph* model = plot->polesGraph("reference model");
    QVERIFY(closed && model);
    QCOMPARE(closed->data()->size(), model->data()->size());
    QVERIFY(closed->scatterStyle().shape() != model->scatterStyle().shape());
    // Every set has a pole mark of its own (shape and size).
    QSet<QString> marks;
    for (const char* name :
         {"plant", "controller", "open loop", "closed loop", "reference model"}) {
        QCPGraph* g = plot->polesGraph(name);
        QVERIFY2(g, qPrintable(name));
        marks.insert(QString("%1/%2").arg(g->scatterStyle().shape()).arg(g->scatterStyle().size()));
    }
    QCOMPARE(marks.size(), 5);
}

void TstPlotReadability::zpetcLeavesTheLegendWhenSwitchedOff() {
    usePolePlacement(0);
    window_->upperTabs()->setCurrentIndex(2);
    PoleZeroPlot* plot = window_->poleZeroPlot();
    const auto legendNames = [plot] {
        QStringList names;
        for (int i = 0; i < plot->legend->itemCount(); ++i)
            if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->legend->item(i)))
                names << item->plottable()->name();
        return names;
    };
    QVERIFY(legendNames().contains("ZPETC feedforward"));
    PpAxisSettings pp = session_->session().axes[0].pp;
    pp.zpetcEnabled = false;
    session_->setPp(0, pp);
    QVERIFY2(!legendNames().contains("ZPETC feedforward"), qPrintable(legendNames().join(", ")));
    QVERIFY(plot->polesGraph("ZPETC feedforward") == nullptr);
    session_->undoStack()->undo();
    QVERIFY(legendNames().contains("ZPETC feedforward"));
}

void TstPlotReadability::cornerControlsOnlyOnTheirTab() {
    // "sweep ωn" acts on the parameter locus, "error × N" on the XY contour: elsewhere they
    // did nothing and confused.
    QComboBox* swept = nullptr;
    for (QComboBox* box : window_->findChildren<QComboBox*>())
        if (box->accessibleName() == "Swept parameter")
            swept = box;
    QDoubleSpinBox* magnification = nullptr;
    for (QDoubleSpinBox* box : window_->findChildren<QDoubleSpinBox*>())
        if (box->accessibleName() == "Contour error magnification")
            magnification = box;
    QVERIFY(swept && magnification);
    for (int upper = 0; upper < window_->upperTabs()->count(); ++upper)
        for (int lower = 0; lower < window_->lowerTabs()->count(); ++lower) {
            window_->upperTabs()->setCurrentIndex(upper);
            window_->lowerTabs()->setCurrentIndex(lower);
            QCOMPARE(swept->isVisible(),
                     window_->upperTabs()->currentWidget() == window_->parameterLocusPlot());
            QCOMPARE(magnification->isVisible(),
                     window_->lowerTabs()->currentWidget() == window_->contourPlot());
        }
    // On a pole-placement axis the parameter locus has no parameter to sweep: shown, disabled.
    usePolePlacement(0);
    window_->upperTabs()->setCurrentIndex(1);
    QVERIFY(swept->isVisible());
    QVERIFY(!swept->isEnabled());
}

void TstPlotReadability::leftPanelHasNoGapForTheShortPage() {
    // The circle's three fields sat above an empty gap as tall as the cubic's six.
    TrajectoryEditor* editor = window_->trajectoryEditor();
    auto* pages = editor->findChild<QStackedWidget*>();
    QVERIFY(pages);
    TrajectorySettings t = session_->session().trajectory;
    const int cubicHeight = pages->sizeHint().height();
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    const int circleHeight = pages->sizeHint().height();
    QCOMPARE(circleHeight, pages->currentWidget()->sizeHint().height());
    QVERIFY2(circleHeight < cubicHeight,
             qPrintable(QString("%1 vs %2").arg(circleHeight).arg(cubicHeight)));
    // The width stays that of the widest page, so nothing is clipped on either.
    QVERIFY(pages->sizeHint().width() >= pages->widget(0)->sizeHint().width());
    // The design stack too: the pole-placement page is shorter than the GT page.
    usePolePlacement(0);
    for (QStackedWidget* stack : window_->findChildren<QStackedWidget*>())
        if (stack != pages && stack->count() == 2 && stack->currentIndex() == 1 &&
            stack->currentWidget()->metaObject()->className() == QByteArray("xyt::ui::PpEditor"))
            QCOMPARE(stack->sizeHint().height(), stack->currentWidget()->sizeHint().height());
}

void TstPlotReadability::leftPanelFitsA1366x768Window() {
    // At 1366x768 the left panel was cut off at "Controller Ts": every control of the default
    // session (design, cubic trajectory, actuator) is now visible without scrolling.
    QScrollArea* panel = nullptr;
    for (QScrollArea* area : window_->findChildren<QScrollArea*>())
        if (area->widget() && area->widget()->isAncestorOf(window_->trajectoryEditor()))
            panel = area;
    QVERIFY(panel);
    QTest::qWait(50);
    QCOMPARE(panel->verticalScrollBar()->maximum(), 0);
}

void TstPlotReadability::valueTicksFitTheirPanel() {
    // At 1366x768 the u panel is about 60 px tall: five tick labels crowded it.
    TimeResponsePlot* plot = window_->timePlot();
    window_->lowerTabs()->setCurrentIndex(0);
    plot->replot(QCustomPlot::rpImmediateRefresh);
    for (QCPAxisRect* rect : plot->axisRects()) {
        QCPAxis* axis = rect->axis(QCPAxis::atLeft);
        plot->replot(QCustomPlot::rpImmediateRefresh);
        QVector<double> inside;
        for (double v : axis->tickVector())
            if (axis->range().contains(v))
                inside << axis->coordToPixel(v);
        QVERIFY(inside.size() >= 2);
        // At least 16 px from label to label: an 8-9 pt tick label is about 12 px tall.
        for (int i = 1; i < inside.size(); ++i)
            QVERIFY2(
                std::abs(inside[i] - inside[i - 1]) >= 16.0,
                qPrintable(QString("%1 ticks in %2 px").arg(inside.size()).arg(rect->height())));
    }
    // The position panel is the tallest (about 100 px here): one label per 30 px fits four
    // (0, 200, 400, 600 mm), where it showed 0 and 500 or 0, 250, 500.
    QCPAxis* position = plot->outputGraph()->valueAxis();
    const QVector<double> ticks = position->tickVector();
    const QVector<QString> labels = position->tickVectorLabels();
    QStringList shown;
    for (int i = 0; i < ticks.size() && i < labels.size(); ++i)
        if (position->range().contains(ticks[i]) && !labels[i].isEmpty())
            shown << labels[i];
    QVERIFY2(
        shown.size() >= 4,
        qPrintable(
            QString("'%1' in %2 px").arg(shown.join("', '")).arg(position->axisRect()->height())));
}

void TstPlotReadability::displayNumberHasSignificantDigits() {
    // Four significant digits in fixed notation from 1e-4 to 1e6 (rounded half away from zero
    // by QString::number), exponent notation outside; n/a for what is not a number.
    QCOMPARE(displayNumber(40552.6), QString("40553"));
    QCOMPARE(displayNumber(5.87354), QString("5.874"));
    QCOMPARE(displayNumber(0.00056191), QString("0.0005619"));
    QCOMPARE(displayNumber(-0.40883), QString("-0.4088"));
    QCOMPARE(displayNumber(9.99996), QString("10.00")); // the carry does not add a fifth digit
    QCOMPARE(displayNumber(0.0), QString("0"));
    QCOMPARE(displayNumber(2.5e6), QString("2.5e+06"));
    QCOMPARE(displayNumber(1.234e-5), QString("1.234e-05"));
    QCOMPARE(displayNumber(std::nan("")), QString("n/a"));
    QCOMPARE(displayNumber(-INFINITY), QString("n/a"));
}

void TstPlotReadability::moveAndSettleRowsShowTheCoreFigures() {
    // The default cubic runs past tf until it settles; the panel quotes the core's
    // settle time after tf, final error and overrun, judged against the settle limit.
    QTableWidget* table = window_->metricsPanel()->table();
    for (int c = 0; c < 2; ++c) {
        const AxisEvaluation& e = session_->axisEvaluation(c);
        QVERIFY(e.moveSettle.has_value());
        const MoveSettleMetrics& m = *e.moveSettle;
        const QString settle = table->item(MetricsPanel::SettleAfterMove, c)->text();
        if (m.settleTimeSeconds)
            QVERIFY2(settle.startsWith(displayNumber(*m.settleTimeSeconds)), qPrintable(settle));
        else { // a lower bound: the run's end after tf, and a tooltip that says it
            QVERIFY2(settle.startsWith("> " + displayNumber(m.runEndSeconds - m.moveEndSeconds)),
                     qPrintable(settle));
            QVERIFY(
                table->item(MetricsPanel::SettleAfterMove, c)->toolTip().startsWith("not settled"));
        }
        QVERIFY(settle.endsWith(e.check.settle ? "✓" : "✗"));
        QCOMPARE(table->item(MetricsPanel::FinalError, c)->text(), displayNumber(m.finalErrorMm));
        QCOMPARE(table->item(MetricsPanel::FinalOvershoot, c)->text(),
                 displayNumber(m.finalOvershootMm));
    }
    // A circle has no move to settle: the rows say so, unjudged.
    TrajectorySettings t = session_->session().trajectory;
    t.kind = TrajectoryKind::Circle;
    session_->setTrajectory(t);
    QCOMPARE(table->item(MetricsPanel::SettleAfterMove, 0)->text(), QString("—"));
    // The settle limit edited in the panel is the session's, one undoable step.
    auto* field = window_->metricsPanel()->specField("settle");
    QVERIFY(field);
    field->setValue(900.0);
    emit field->valueAccepted(900.0);
    QCOMPARE(session_->session().spec.maxSettleTimeSeconds, 900.0);
}

void TstPlotReadability::metricsAreGroupedAndNeverCut_data() {
    QTest::addColumn<bool>("polePlacement");
    QTest::addColumn<QSize>("size");
    QTest::newRow("GT 1366x768") << false << QSize(1366, 768);
    QTest::newRow("GT 1600x1000") << false << QSize(1600, 1000);
    QTest::newRow("pole placement 1366x768") << true << QSize(1366, 768);
    QTest::newRow("pole placement 1600x1000") << true << QSize(1600, 1000);
}

void TstPlotReadability::metricsAreGroupedAndNeverCut() {
    // "0.000562..." was cut in the Y column at 1600x1000, and ITAE printed 0.4 for both
    // pole-placement axes; the step figures stood among the tracking figures without a word.
    QFETCH(bool, polePlacement);
    QFETCH(QSize, size);
    if (polePlacement) {
        usePolePlacement(0);
        usePolePlacement(1);
        TrajectorySettings t = session_->session().trajectory;
        t.kind = TrajectoryKind::Circle;
        t.radius = 30.0;
        t.omegaRadPerSec = 0.1;
        t.rampInSeconds = 0.0;
        session_->setTrajectory(t);
    }
    window_->resize(size);
    QTest::qWait(50);
    QTableWidget* table = window_->metricsPanel()->table();
    QCOMPARE(table->item(MetricsPanel::TrackingGroup, 0)->text(),
             QString("Tracking the trajectory"));
    QCOMPARE(table->item(MetricsPanel::StepGroup, 0)->text(),
             QString("Unit step, as each axis runs"));
    QCOMPARE(table->columnSpan(MetricsPanel::StepGroup, 0), 3);
    // Every figure fits its column: no elided text, and the table fits its viewport.
    const int width = table->verticalHeader()->width() + table->horizontalHeader()->length();
    QString widths;
    for (int c = 0; c < 3; ++c)
        widths += QString(" %1").arg(table->columnWidth(c));
    QVERIFY2(width <= table->width(), qPrintable(QString("%1 > %2: header %3, columns%4")
                                                     .arg(width)
                                                     .arg(table->width())
                                                     .arg(table->verticalHeader()->width())
                                                     .arg(widths)));
    const QFontMetrics fm(table->font());
    QFont bold = table->font();
    bold.setBold(true);
    const int span = table->columnWidth(0) + table->columnWidth(1) + table->columnWidth(2);
    for (int r = 0; r < MetricsPanel::RowCount; ++r)
        if (MetricsPanel::isGroupRow(r))
            QVERIFY2(QFontMetrics(bold).horizontalAdvance(table->item(r, 0)->text()) + 6 <= span,
                     qPrintable(table->item(r, 0)->text()));
    for (int r = 0; r < MetricsPanel::RowCount; ++r)
        for (int c = 0; c < 3 && !MetricsPanel::isGroupRow(r); ++c) {
            const QString text = table->item(r, c)->text();
            QVERIFY2(fm.horizontalAdvance(text) + 6 <= table->columnWidth(c),
                     qPrintable(QString("row %1 col %2 '%3' in %4 px")
                                    .arg(r)
                                    .arg(c)
                                    .arg(text)
                                    .arg(table->columnWidth(c))));
            QVERIFY(!text.contains("nan", Qt::CaseInsensitive));
        }
    // Four significant digits: the ITAE of the two pole-placement axes (0.4088 and 0.4228 from the
    // core) differ on the panel as they do in the core.
    const AxisEvaluation& x = session_->axisEvaluation(0);
    QCOMPARE(table->item(MetricsPanel::Itae, 0)->text(), displayNumber(x.metrics.itae));
    QVERIFY(displayNumber(x.metrics.itae)
                .remove('.')
                .remove('-')
                .remove(QRegularExpression("^0+"))
                .size() >= 4);
    if (polePlacement)
        QVERIFY(table->item(MetricsPanel::Itae, 0)->text() !=
                table->item(MetricsPanel::Itae, 1)->text());
}

QTEST_MAIN(TstPlotReadability)
#include "tst_plot_readability.moc"
