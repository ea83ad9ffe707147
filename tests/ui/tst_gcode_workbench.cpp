// SPDX-License-Identifier: GPL-3.0-or-later
// G-code programs in the workbench: the G-code trajectory in the editor, the session, the XY
// contour view (programmed path, traced path, magnified error, corners, ballbar view) and the
// metrics panel. The expected values come from the core (core/contour, core/session), which
// has its own tests against closed forms; here the views must show exactly those.
#include "core/contour/contour_metrics.h"
#include "core/contour/gcode_reader.h"
#include "core/session/program_trajectory.h"
#include "tests/support/ballbar_program.h"
#include "tests/support/gui_checks.h"
#include "tests/support/tolerance.h"
#include "ui/main_window.h"
#include "ui/panels/contour_controls.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/contour_points.h"
#include "ui/session/install_paths.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <cmath>

using namespace xyt;
using namespace xyt::ui;

class TstGcodeWorkbench : public QObject {
    Q_OBJECT
private slots:
    void init();
    void everyExampleLoads_data();
    void everyExampleLoads();
    void examplesBoxLoadsAProgram();
    void openButtonStartsInTheExamples();
    void badProgramIsShownAtTheFieldAndChangesNothing();
    void gcodeKindWithoutAProgramChangesNothing();
    void profileFieldsAreUndoableSteps();
    void badProfileFieldIsRefusedAtTheField();
    void contourViewShowsTheCoreData();
    void magnifiedErrorOfAKnownOffset();
    void cornerZoomVisitsEveryCorner();
    void ballbarViewShowsTheIsoFigures();
    void longProgramAtAFineStepSaysTheLiveViewIsLimited();
    void circlePresetStillDrawsAsBefore();
    void ballbarProgramShowsBothDirections();
    void octaveExportIsDisabledOnAProgram();

private:
    QString example(const QString& name) const { return QDir(examplesFolder()).filePath(name); }
    void loadExample(const QString& name);

    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

namespace {

std::string fileText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll().toStdString() : std::string();
}

QVector<double> keys(QCPCurve* c) {
    QVector<double> out;
    for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it)
        out << it->key;
    return out;
}

QVector<double> values(QCPCurve* c) {
    QVector<double> out;
    for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it)
        out << it->value;
    return out;
}

/// Centre and radius of a drawn circle (its first point and the one half way round).
void drawnCircle(QCPCurve* c, double& cx, double& cy, double& r) {
    const QVector<double> x = keys(c), y = values(c);
    QVERIFY(x.size() == 361);
    cx = (x[0] + x[180]) / 2.0;
    cy = (y[0] + y[180]) / 2.0;
    r = std::hypot(x[0] - cx, y[0] - cy);
}

} // namespace

void TstGcodeWorkbench::init() {
    QCoreApplication::setOrganizationName("xytune-tests");
    session_ = std::make_unique<TuningSession>();
    window_ = std::make_unique<MainWindow>(session_.get());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QVERIFY2(!examplesFolder().isEmpty(), "resources/examples not found");
}

void TstGcodeWorkbench::loadExample(const QString& name) {
    QVERIFY2(window_->trajectoryEditor()->loadProgramFile(example(name)),
             qPrintable(window_->trajectoryEditor()->programField()->toolTip()));
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Gcode);
}

void TstGcodeWorkbench::everyExampleLoads_data() {
    QTest::addColumn<QString>("name");
    for (const QString& name : QDir(examplesFolder()).entryList({"*.nc"}, QDir::Files))
        QTest::newRow(qPrintable(name)) << name;
}

void TstGcodeWorkbench::everyExampleLoads() {
    QFETCH(QString, name);
    const int steps = session_->undoStack()->count();
    loadExample(name);
    const TrajectorySettings& t = session_->session().trajectory;
    // The session holds the program's text itself (shared sessions are complete) and its name.
    QCOMPARE(t.gcode.program, fileText(example(name)));
    QCOMPARE(QString::fromStdString(t.gcode.fileName), name);
    QCOMPARE(session_->undoStack()->count(), steps + 1);
    TrajectoryEditor* editor = window_->trajectoryEditor();
    QCOMPARE(editor->kindBox()->currentIndex(), 2);
    QCOMPARE(editor->programField()->text(), name);
    // The summary is the core's (program_trajectory.h).
    const ProgramSummary s = summarizeProgram(t);
    QVERIFY2(editor->programSummary()->text().contains(QString::number(s.lengthMm, 'f', 1) + " mm"),
             qPrintable(editor->programSummary()->text()));
    QVERIFY(
        editor->programSummary()->text().contains(QString::number(s.runSeconds, 'f', 2) + " s"));
    // Both axes ran along the program's profile: the run lasts the profile's time.
    const AxisEvaluation& x = session_->axisEvaluation(0);
    QVERIFY2(x.ok, x.error.text.c_str());
    QVERIFY(session_->evaluation().program);
    XYT_COMPARE_NEAR(session_->evaluation().duration.seconds, s.runSeconds, 1e-12, 0.0);
    // Circle programs get the ISO 230-4 figures in the metrics panel; the others do not.
    const QString figures = window_->metricsPanel()->contourText();
    const auto& program = *session_->evaluation().program;
    QVERIFY(figures.contains(QString::number(program.contour.maxAbs, 'f', 4)));
    QCOMPARE(figures.contains("ISO 230-4"), program.circular.has_value());
    QCOMPARE(s.singleFullCircle, name.startsWith("circle"));
}

void TstGcodeWorkbench::examplesBoxLoadsAProgram() {
    QComboBox* box = window_->trajectoryEditor()->examplesBox();
    const int index = box->findText("star.nc");
    QVERIFY(index > 0);
    box->setCurrentIndex(index);
    emit box->activated(index);
    QCOMPARE(QString::fromStdString(session_->session().trajectory.gcode.fileName),
             QString("star.nc"));
    QCOMPARE(box->currentIndex(), 0); // back to "Examples…" for the next pick
}

void TstGcodeWorkbench::openButtonStartsInTheExamples() {
    QString startFolder;
    // Poll until the dialog is up, then pick the square from the folder it opened in (the click
    // below blocks in the dialog, so poll outlives every call).
    std::function<void()> poll = [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) {
            QTimer::singleShot(10, this, poll);
            return;
        }
        startFolder = dialog->directory().absolutePath();
        dialog->selectFile(example("square_sharp_corners.nc"));
        static_cast<QDialog*>(dialog)->accept(); // as its Open button does
    };
    QTimer::singleShot(0, this, poll);
    QTest::mouseClick(window_->trajectoryEditor()->openButton(), Qt::LeftButton);
    QCOMPARE(startFolder, examplesFolder());
    QCOMPARE(QString::fromStdString(session_->session().trajectory.gcode.fileName),
             QString("square_sharp_corners.nc"));
}

void TstGcodeWorkbench::badProgramIsShownAtTheFieldAndChangesNothing() {
    loadExample("star.nc");
    const Session before = session_->session();
    const int steps = session_->undoStack()->count();
    TrajectoryEditor* editor = window_->trajectoryEditor();
    // The reader's error (gcode_reader.h), named by the session path, line, word and column.
    QVERIFY(!editor->loadProgramText("bad.nc", "G21\nG1 X1 F100\nG5 X2\n"));
    QVERIFY2(editor->programField()->toolTip().contains(
                 "trajectory.gcode.program: line 3: unknown word G5 at column 1"),
             qPrintable(editor->programField()->toolTip()));
    QVERIFY(!editor->programField()->styleSheet().isEmpty()); // marked
    QVERIFY(editor->programSummary()->text().contains("line 3"));
    QVERIFY(session_->session() == before);
    QCOMPARE(session_->undoStack()->count(), steps);
    // A file that cannot be read is refused the same way.
    QVERIFY(!editor->loadProgramFile(example("no_such_program.nc")));
    QVERIFY(editor->programField()->toolTip().startsWith("no_such_program.nc: "));
    QVERIFY(session_->session() == before);
    // A good program clears the marking.
    loadExample("square_sharp_corners.nc");
    QVERIFY(editor->programField()->styleSheet().isEmpty());
}

void TstGcodeWorkbench::gcodeKindWithoutAProgramChangesNothing() {
    const Session before = session_->session();
    QComboBox* kind = window_->trajectoryEditor()->kindBox();
    kind->setCurrentIndex(2);
    emit kind->activated(2);
    QVERIFY(session_->session() == before); // still the cubic: nothing to run yet
    QVERIFY(window_->trajectoryEditor()->programField()->toolTip().contains("no program"));
    QVERIFY(window_->trajectoryEditor()->programSummary()->text().contains("Open a program"));
}

void TstGcodeWorkbench::profileFieldsAreUndoableSteps() {
    loadExample("square_sharp_corners.nc");
    const Session loaded = session_->session();
    const double runBefore = session_->evaluation().duration.seconds;
    TrajectoryEditor* editor = window_->trajectoryEditor();
    test::typeInto(editor->field("feed_scale"), "2");
    QCOMPARE(session_->session().trajectory.gcode.feedScale, 2.0);
    test::typeInto(editor->field("max_accel"), "2000");
    QCOMPARE(session_->session().trajectory.gcode.maxAccelMmPerS2, 2000.0);
    test::typeInto(editor->field("max_jerk"), "50000");
    QCOMPARE(session_->session().trajectory.gcode.maxJerkMmPerS3, 50000.0);
    // Twice the feed, a faster profile: the run is shorter (the core's run time).
    XYT_COMPARE_NEAR(session_->evaluation().duration.seconds,
                     programRunSeconds(session_->session().trajectory), 1e-12, 0.0);
    QVERIFY(session_->evaluation().duration.seconds < runBefore);
    session_->undoStack()->undo();
    QCOMPARE(session_->session().trajectory.gcode.maxJerkMmPerS3, 0.0);
    QCOMPARE(editor->field("max_jerk")->value(), 0.0);
    session_->undoStack()->undo();
    session_->undoStack()->undo();
    QVERIFY(session_->session() == loaded);
    QCOMPARE(editor->field("feed_scale")->value(), 1.0);
    session_->undoStack()->undo(); // the load itself
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Cubic);
    QCOMPARE(editor->kindBox()->currentIndex(), 0);
}

void TstGcodeWorkbench::badProfileFieldIsRefusedAtTheField() {
    loadExample("square_sharp_corners.nc");
    const Session before = session_->session();
    NumberField* scale = window_->trajectoryEditor()->field("feed_scale");
    test::typeInto(scale, "-1");
    QVERIFY(scale->hasError());
    QVERIFY(session_->session() == before);
    NumberField* jerk = window_->trajectoryEditor()->field("max_jerk");
    test::typeInto(jerk, "-5");
    QVERIFY(jerk->hasError());
    QVERIFY(session_->session() == before);
}

void TstGcodeWorkbench::contourViewShowsTheCoreData() {
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    loadExample("star.nc");
    ContourPlot* plot = window_->contourPlot();
    const SessionEvaluation& e = session_->evaluation();
    QVERIFY(e.program && e.programPath);
    // The programmed path: the star's lines are drawn by their ends, from the core's Path.
    const Path& path = *e.programPath;
    const QVector<double> px = keys(plot->commandedCurve()), py = values(plot->commandedCurve());
    QCOMPARE(px.size(), static_cast<qsizetype>(path.size() + 1));
    for (std::size_t i = 0; i < path.size(); ++i) {
        QCOMPARE(px[static_cast<qsizetype>(i)], path.segments()[i].start().x);
        QCOMPARE(py[static_cast<qsizetype>(i)], path.segments()[i].start().y);
    }
    QCOMPARE(px.back(), path.segments().back().end().x);
    // The traced path: the contour run's traced points, sample for sample.
    const ContourTrace& trace = e.program->trace;
    const QVector<double> tx = keys(plot->tracedCurve()), ty = values(plot->tracedCurve());
    QCOMPARE(tx.size(), static_cast<qsizetype>(trace.x.size()));
    for (qsizetype k = 0; k < tx.size(); k += 97) {
        QCOMPARE(tx[k], trace.x[static_cast<std::size_t>(k)]);
        QCOMPARE(ty[k], trace.y[static_cast<std::size_t>(k)]);
    }
    // The magnified error: |m_k - p(s_k)| = M |e_k| along the normal at the nearest point.
    auto* factor =
        qobject_cast<QDoubleSpinBox*>(window_->lowerTabs()->cornerWidget(Qt::TopRightCorner));
    QVERIFY(factor);
    factor->setValue(20.0);
    const ContourErrorResult& c = e.program->contour;
    const QVector<double> mx = keys(plot->magnifiedCurve()), my = values(plot->magnifiedCurve());
    QCOMPARE(mx.size(), static_cast<qsizetype>(c.error.size()));
    for (std::size_t k = 0; k < c.error.size(); k += 101) {
        if (!c.measured[k])
            continue;
        const PathPoint p = path.at(c.pathPosition[k], c.segment[k]);
        const double along = (mx[static_cast<qsizetype>(k)] - p.point.x) * -p.tangent.y +
                             (my[static_cast<qsizetype>(k)] - p.point.y) * p.tangent.x;
        XYT_COMPARE_NEAR(along, 20.0 * c.error[k], 1e-9, 1e-12);
    }
    // The colour bands hold the samples from 1/4, 1/2, 3/4 of the largest |e| up.
    for (std::size_t b = 0; b < 3; ++b) {
        const QVector<double> bx = keys(plot->errorBands()[b]);
        const double threshold = (b + 1) * 0.25 * c.maxAbs;
        for (std::size_t k = 0; k < c.error.size(); k += 53)
            QCOMPARE(!std::isnan(bx[static_cast<qsizetype>(k)]),
                     c.measured[k] && std::abs(c.error[k]) >= threshold);
    }
    // The worst point is the core's.
    QCOMPARE(plot->worstMarker()->data()->size(), 1);
    QCOMPARE(plot->worstMarker()->data()->at(0)->key, c.maxPoint.x);
    QCOMPARE(plot->worstMarker()->data()->at(0)->value, c.maxPoint.y);
    QVERIFY2(plot->figuresText().contains("max " + QString::number(c.maxAbs, 'g', 3) + ", RMS " +
                                          QString::number(c.rms, 'g', 3) + " mm"),
             qPrintable(plot->figuresText()));
}

void TstGcodeWorkbench::magnifiedErrorOfAKnownOffset() {
    // Closed form: a path along +x traced 0.1 mm to its left has e = +0.1 everywhere; magnified
    // 50 times it is drawn at y = 5 mm; an arc of R = 5 traced 0.2 mm inside (left of
    // counter-clockwise travel, e = +0.2) magnified 10 times is drawn at R - 10 x 0.2 = 3 mm.
    const Path line({PathSegment::line({0, 0}, {10, 0})});
    const std::vector<double> t{0, 1, 2}, x{1, 4, 9}, y{0.1, 0.1, 0.1};
    const ContourErrorResult c = contourError(line, t, x, y);
    const XyPoints m = magnifiedContourPoints(line, c, 50.0);
    for (qsizetype k = 0; k < 3; ++k) {
        XYT_COMPARE_NEAR(m.x[k], x[static_cast<std::size_t>(k)], 0.0, 1e-12);
        XYT_COMPARE_NEAR(m.y[k], 5.0, 1e-12, 0.0);
    }
    const Path arc({PathSegment::arc({0, 0}, 5.0, 0.0, 1.5)});
    const std::vector<double> ax{4.8 * std::cos(0.3), 4.8 * std::cos(1.2)},
        ay{4.8 * std::sin(0.3), 4.8 * std::sin(1.2)};
    const ContourErrorResult ca = contourError(arc, {0, 1}, ax, ay);
    const XyPoints ma = magnifiedContourPoints(arc, ca, 10.0);
    for (qsizetype k = 0; k < 2; ++k) {
        XYT_COMPARE_NEAR(ca.error[static_cast<std::size_t>(k)], 0.2, 1e-9, 0.0);
        XYT_COMPARE_NEAR(std::hypot(ma.x[k], ma.y[k]), 3.0, 1e-9, 0.0);
    }
}

void TstGcodeWorkbench::cornerZoomVisitsEveryCorner() {
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    loadExample("square_sharp_corners.nc");
    ContourPlot* plot = window_->contourPlot();
    const auto& corners = session_->evaluation().program->contour.corners;
    QVERIFY(!corners.empty());
    QCOMPARE(plot->cornerCount(), static_cast<int>(corners.size()));
    QToolButton* next = window_->contourControls()->nextCorner();
    QVERIFY(next->isVisible());
    const QCPRange wholeX = plot->xAxis->range();
    for (std::size_t i = 0; i < corners.size(); ++i) {
        QTest::mouseClick(next, Qt::LeftButton);
        QCOMPARE(plot->currentCorner(), static_cast<int>(i));
        // Centred on the core's corner point, and closer in than the whole path.
        XYT_COMPARE_NEAR(plot->xAxis->range().center(), corners[i].corner.x, 1e-9, 1e-9);
        XYT_COMPARE_NEAR(plot->yAxis->range().center(), corners[i].corner.y, 1e-9, 1e-9);
        QVERIFY(plot->xAxis->range().size() < wholeX.size());
        QVERIFY(
            plot->figuresText().contains(QString("corner %1/%2").arg(i + 1).arg(corners.size())));
    }
    QTest::mouseClick(next, Qt::LeftButton); // past the last: the whole path again
    QCOMPARE(plot->currentCorner(), -1);
    XYT_COMPARE_NEAR(plot->xAxis->range().size(), wholeX.size(), 1e-9, 0.0);
    QTest::mouseClick(window_->contourControls()->previousCorner(), Qt::LeftButton);
    QCOMPARE(plot->currentCorner(), static_cast<int>(corners.size()) - 1);
}

void TstGcodeWorkbench::ballbarViewShowsTheIsoFigures() {
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    loadExample("circle_30mm.nc");
    ContourPlot* plot = window_->contourPlot();
    QVERIFY(plot->polarAvailable());
    QCheckBox* ballbar = window_->contourControls()->polarView();
    QVERIFY(ballbar->isVisible());
    ballbar->setChecked(true);
    QVERIFY(plot->polar());
    const ContourCircularTest& test = *session_->evaluation().program->circular;
    // The figures recomputed here by the core's iso230Circular from the two runs.
    const Iso230Circular iso =
        iso230Circular(test.x, test.y, test.reverseX, test.reverseY, test.nominal);
    const double m = plot->magnification();
    double cx = 0, cy = 0, r = 0;
    drawnCircle(plot->fMaxCircle(), cx, cy, r);
    XYT_COMPARE_NEAR((r - test.nominal.radius) / m, iso.radialDeviationFMax, 1e-9, 1e-12);
    drawnCircle(plot->fMinCircle(), cx, cy, r);
    XYT_COMPARE_NEAR((r - test.nominal.radius) / m, iso.radialDeviationFMin, 1e-9, 1e-12);
    double ox = 0, oy = 0, outer = 0, ix = 0, iy = 0, inner = 0;
    drawnCircle(plot->gOuterCircle(), ox, oy, outer);
    drawnCircle(plot->gInnerCircle(), ix, iy, inner);
    XYT_COMPARE_NEAR((outer - inner) / m, iso.circularDeviationG, 1e-9, 1e-12);
    XYT_COMPARE_NEAR(
        ox, test.nominal.centre.x + m * (iso.leastSquares.centre.x - test.nominal.centre.x), 1e-9,
        1e-9);
    QVERIFY(plot->figuresText().contains(QString::number(iso.circularDeviationG, 'f', 4)));
    QVERIFY(iso.hysteresisH &&
            plot->figuresText().contains("H " + QString::number(*iso.hysteresisH, 'f', 4)));
    // Both runs drawn; the metrics panel names the same G.
    QCOMPARE(plot->magnifiedCurve()->data()->size(), static_cast<int>(test.x.size()));
    QCOMPARE(plot->reverseCurve()->data()->size(), static_cast<int>(test.reverseX.size()));
    const Iso230Circular reverse = iso230Circular(test.reverseX, test.reverseY, test.nominal);
    QVERIFY2(window_->metricsPanel()->contourText().contains(
                 QString("G CW %1, CCW %2, F %3/%4, H %5 mm")
                     .arg(QString::number(iso.circularDeviationG, 'f', 4),
                          QString::number(reverse.circularDeviationG, 'f', 4),
                          QString::number(iso.radialDeviationFMax, 'f', 4),
                          QString::number(iso.radialDeviationFMin, 'f', 4),
                          QString::number(*iso.hysteresisH, 'f', 4))),
             qPrintable(window_->metricsPanel()->contourText()));
    ballbar->setChecked(false);
    QVERIFY(!plot->polar());
    QVERIFY(plot->fMaxCircle()->data()->isEmpty());
}

void TstGcodeWorkbench::longProgramAtAFineStepSaysTheLiveViewIsLimited() {
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    loadExample("square_sharp_corners.nc");
    Session s = session_->session();
    const double run = programRunSeconds(s.trajectory);
    s.trajectory.dtSeconds = run / (2.0 * TuningSession::kLiveSampleLimit); // twice the live limit
    session_->apply(s, "fine dt");
    QVERIFY(!session_->liveNotice().isEmpty());
    // Evaluated at the live dt, and the contour view says so.
    QVERIFY(session_->evaluation().program->trace.profile.t.size() <=
            TuningSession::kLiveSampleLimit + 1);
    QVERIFY2(window_->contourPlot()->noticeText().contains("live view"),
             qPrintable(window_->contourPlot()->noticeText()));
}

void TstGcodeWorkbench::circlePresetStillDrawsAsBefore() {
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    loadExample("star.nc");
    QComboBox* kind = window_->trajectoryEditor()->kindBox();
    kind->setCurrentIndex(1);
    emit kind->activated(1);
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Circle);
    ContourPlot* plot = window_->contourPlot();
    QVERIFY(!session_->evaluation().program);
    QCOMPARE(plot->cornerCount(), 0);
    QVERIFY(!plot->polarAvailable());
    QVERIFY(!window_->contourControls()->isVisible());
    QCOMPARE(plot->tracedCurve()->data()->size(),
             static_cast<int>(session_->axisEvaluation(0).run.t.size()));
    QVERIFY(plot->errorBands()[0]->data()->isEmpty());
    QVERIFY(plot->figuresText().startsWith("Contour error (radial"));
}

void TstGcodeWorkbench::ballbarProgramShowsBothDirections() {
    // A ballbar program as machine shops write it: before, the view had no ISO 230-4 figures
    // for it, and nothing said why.
    window_->lowerTabs()->setCurrentWidget(window_->contourPlot());
    QTemporaryDir dir;
    QFile f(dir.filePath("ballbar.nc"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(test::kBallbarProgram);
    f.close();
    QVERIFY2(window_->trajectoryEditor()->loadProgramFile(f.fileName()),
             qPrintable(window_->trajectoryEditor()->programField()->toolTip()));
    QVERIFY(session_->evaluation().program && session_->evaluation().program->circular);
    const ContourCircularTest& test = *session_->evaluation().program->circular;
    QVERIFY(test.fromProgram);
    // The figures recomputed by the core's iso230Circular from the program's two circles.
    const Iso230Circular both =
        iso230Circular(test.x, test.y, test.reverseX, test.reverseY, test.nominal);
    const Iso230Circular reverse = iso230Circular(test.reverseX, test.reverseY, test.nominal);
    QVERIFY(both.hysteresisH);
    const QString expected = QString("ISO 230-4: G CW %1, CCW %2, F %3/%4, H %5 mm")
                                 .arg(QString::number(both.circularDeviationG, 'f', 4),
                                      QString::number(reverse.circularDeviationG, 'f', 4),
                                      QString::number(both.radialDeviationFMax, 'f', 4),
                                      QString::number(both.radialDeviationFMin, 'f', 4),
                                      QString::number(*both.hysteresisH, 'f', 4));
    QVERIFY2(window_->metricsPanel()->contourText().contains(expected),
             qPrintable(window_->metricsPanel()->contourText() + " | expected " + expected));
    ContourPlot* plot = window_->contourPlot();
    QVERIFY(plot->polarAvailable());
    window_->contourControls()->polarView()->setChecked(true);
    QCOMPARE(plot->magnifiedCurve()->data()->size(), static_cast<int>(test.x.size()));
    QCOMPARE(plot->reverseCurve()->data()->size(), static_cast<int>(test.reverseX.size()));
}

void TstGcodeWorkbench::octaveExportIsDisabledOnAProgram() {
    // The Octave script has no closed form for a program's feed profile: the action is
    // disabled, saying why, instead of refusing after a file name was asked for.
    QAction* octave = window_->files()->octaveExportAction();
    QVERIFY(octave);
    const auto enabledForTheCubic = [&] {
        return octave->isEnabled() && !octave->toolTip().contains("G-code");
    };
    QVERIFY(enabledForTheCubic());
    loadExample("square_sharp_corners.nc");
    QVERIFY(!octave->isEnabled());
    QVERIFY2(octave->toolTip().startsWith("Not for a G-code trajectory") &&
                 octave->toolTip().contains("CSV"),
             qPrintable(octave->toolTip()));
    // Back to the cubic and to the circle through the editor: enabled again.
    QComboBox* kind = window_->trajectoryEditor()->kindBox();
    kind->setCurrentIndex(0);
    emit kind->activated(0);
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Cubic);
    QVERIFY(enabledForTheCubic());
    kind->setCurrentIndex(1);
    emit kind->activated(1);
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Circle);
    QVERIFY(enabledForTheCubic());
    // Undo back to the program, then redo: the action follows each step.
    session_->undoStack()->undo();
    session_->undoStack()->undo();
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Gcode);
    QVERIFY(!octave->isEnabled());
    session_->undoStack()->redo();
    QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Cubic);
    QVERIFY(enabledForTheCubic());
    // A reset to the paper's default cubic (File > New) from the program.
    session_->undoStack()->undo();
    QVERIFY(!octave->isEnabled());
    session_->reset(Session::paperDefault());
    QVERIFY(enabledForTheCubic());
    // The disabled action's tooltip is shown by its menu.
    const auto menus = window_->findChildren<QMenu*>();
    const bool shown = std::any_of(menus.begin(), menus.end(), [&](QMenu* m) {
        return m->actions().contains(octave) && m->toolTipsVisible();
    });
    QVERIFY(shown);
}

QTEST_MAIN(TstGcodeWorkbench)
#include "tst_gcode_workbench.moc"
