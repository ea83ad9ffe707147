// SPDX-License-Identifier: GPL-3.0-or-later
// The cross-coupling's gains tuned by the contour error in the workbench, through its real
// widgets offscreen: "Tune…" in the Cross-coupling fold opens the sweep and runs it in the
// background; the colour map holds the core's sweep of the same session (sweepSessionCoupling,
// computed here again); a hover reads a cell; a click and Apply set its gains as one undo step;
// Cancel stops a run; a session changed while the sweep runs leaves its result stale, veiled and
// never applied; the dialog fits a 1366x768 screen with nothing clipped.
#include "tests/support/plot_layout_checks.h"
#include "ui/coupling_sweep_dialog.h"
#include "ui/main_window.h"
#include "ui/panels/cross_coupling_editor.h"
#include "ui/panels/number_field.h"
#include "ui/panels/stale_veil.h"
#include "ui/plots/plot_widget.h"
#include "ui/session/tuning_session.h"

#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTest>
#include <QToolButton>
#include <QToolTip>
#include <QUndoStack>
#include <qcustomplot.h>

#include <bit>
#include <cmath>
#include <cstdint>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// Braga et al.'s check circle as the session's program (25 mm at 90 mm/min), at the session's
/// dt of 10 ms: a sweep of the default grid takes a second or two.
Session paperCircleSession(Session s) {
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "paper_circle.nc";
    s.trajectory.gcode.program = "F90\nG3 X0 Y0 I-25 J0\n";
    return s;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// The markers of @p graph as grid cells (cell (i, j) spans i +- 0.5, j +- 0.5 on the map's
/// axes; a marker may sit in a corner of its cell), in the order drawn.
std::vector<std::pair<long, long>> markedCells(QCPGraph* graph) {
    std::vector<std::pair<long, long>> out;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        out.emplace_back(std::lround(it->key), std::lround(it->value));
    return out;
}

constexpr int kSweepTimeoutMs = 120000;

} // namespace

class TstCouplingSweepDialog : public QObject {
    Q_OBJECT

private slots:
    void init() {
        QCoreApplication::setOrganizationName("xytune-tests");
        window_.reset(); // before its session
        session_ = std::make_unique<TuningSession>();
        session_->reset(paperCircleSession(session_->session()));
        window_ = std::make_unique<MainWindow>(session_.get());
        window_->resize(1366, 768);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }
    void cleanup() {
        window_.reset();
        session_.reset();
    }

    /// Source: the core's sweep of the same session. The fold's button opens the dialog, which
    /// sweeps the session at once; each cell of the colour map is the core cell's max contour
    /// error (bit for bit; NaN, the grey background, where the cell has no figure), the markers
    /// are its refused, saturating and best cells, and the independent axes' figure is written.
    void theFoldOpensASweepThatIsTheCores() {
        CouplingSweepDialog* dialog = openFromTheFold();
        QVERIFY(dialog);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->result().has_value(), kSweepTimeoutMs);
        const CouplingSweepResult core = sweepSessionCoupling(
            session_->liveSession(), session_->evaluation(), defaultCouplingSweepGrid());
        const CouplingSweepResult& shown = *dialog->result();
        QCOMPARE(shown.cells.size(), core.cells.size());
        QCPColorMapData* data = dialog->colorMap()->data();
        const std::size_t nKp = core.grid.kpVoltsPerMm.size();
        const std::size_t nKi = core.grid.kiVoltsPerMmSecond.size();
        QCOMPARE(data->keySize(), int(nKp));
        QCOMPARE(data->valueSize(), int(nKi));
        std::vector<std::pair<long, long>> unstable, saturated;
        for (std::size_t i = 0; i < nKp; ++i)
            for (std::size_t j = 0; j < nKi; ++j) {
                const CouplingSweepCell& c = core.cell(i, j);
                const double drawn = data->cell(int(i), int(j));
                if (c.status == CouplingCellStatus::Ok)
                    QVERIFY2(sameBits(drawn, c.maxAbsMm),
                             qPrintable(QString("cell %1, %2: %3 against %4")
                                            .arg(i)
                                            .arg(j)
                                            .arg(drawn)
                                            .arg(c.maxAbsMm)));
                else
                    QVERIFY(std::isnan(drawn));
                if (c.status == CouplingCellStatus::Unstable)
                    unstable.emplace_back(long(i), long(j));
                if (c.status == CouplingCellStatus::Ok && c.saturated)
                    saturated.emplace_back(long(i), long(j));
            }
        QCOMPARE(markedCells(dialog->unstableMarkers()), unstable);
        QCOMPARE(markedCells(dialog->saturatedMarkers()), saturated);
        QVERIFY(core.best.has_value());
        QCOMPARE(shown.best, core.best);
        QCOMPARE(
            markedCells(dialog->bestMarker()),
            (std::vector<std::pair<long, long>>{{long(*core.best / nKi), long(*core.best % nKi)}}));
        // The colour scale is logarithmic over the figures drawn.
        QCOMPARE(dialog->colorMap()->dataScaleType(), QCPAxis::stLogarithmic);
        QVERIFY(dialog->colorMap()->dataRange().lower > 0.0);
        // The independent axes' figure in words, as the core has it.
        QVERIFY2(dialog->summaryText().contains(
                     QString("Independent axes (coupling off): max %1 mm")
                         .arg(QString::number(core.independent.maxAbsMm, 'g', 3))),
                 qPrintable(dialog->summaryText()));
        QVERIFY(dialog->summaryText().contains(QStringLiteral("Best: kp ")));
        // The best is selected, ready to apply.
        QCOMPARE(dialog->selectedCell(), core.best);
        QVERIFY(dialog->applyButton()->isEnabled());
        QVERIFY(!dialog->progressBar()->isVisible());
    }

    /// Source: the core's cell. A hover over a cell shows its gains and figures, as the result
    /// holds them; off the grid nothing.
    void aHoverReadsTheCell() {
        CouplingSweepDialog* dialog = runSmallSweep({0.0, 0.1, 3.0}, {0.0, 1.0});
        QVERIFY(dialog);
        const CouplingSweepResult& r = *dialog->result();
        const std::size_t index = r.cellIndex(1, 1); // kp 0.1, ki 1
        const CouplingSweepCell& c = r.cells[index];
        QCOMPARE(c.status, CouplingCellStatus::Ok);
        hoverOver(dialog->plot(), dialog->pixelOfCell(index));
        QVERIFY(!dialog->hoverText().isEmpty());
        QCOMPARE(QToolTip::text(), dialog->hoverText()); // what the tooltip shows
        const QString text = dialog->hoverText();
        for (const QString& part :
             {QStringLiteral("kp 0.1 V/mm, ki 1 V/(mm·s)"),
              QString("Max contour error %1 mm, RMS %2 mm")
                  .arg(QString::number(c.maxAbsMm, 'g', 3), QString::number(c.rmsMm, 'g', 3)),
              QString("spectral radius %1").arg(QString::number(c.spectralRadius, 'g', 6)),
              QString("disk margin %1").arg(QString::number(c.diskMargin, 'g', 3)),
              QString("independent axes: max %1 mm")
                  .arg(QString::number(r.independent.maxAbsMm, 'g', 3))})
            QVERIFY2(text.contains(part), qPrintable(text + " lacks " + part));
        QVERIFY(text.contains(c.saturated ? "reaches its actuator limit" : "inside their"));
        QCOMPARE(text, dialog->cellToolTip(index));
        // The (0, 0) cell is the coupling off; off the grid, nothing.
        QVERIFY(dialog->cellToolTip(0).contains(QStringLiteral("the coupling off")));
        hoverOver(dialog->plot(), QPointF(2, 2));
        QVERIFY(dialog->hoverText().isEmpty());
    }

    /// Source: TuningSession's undo stack. A click selects a cell; Apply sets its gains as the
    /// session's cross-coupling in one undo step, the estimate kept; undo restores the gains.
    void applyingACellIsOneUndoStep() {
        CouplingSweepDialog* dialog = runSmallSweep({0.0, 0.1, 0.3}, {0.0, 1.0});
        QVERIFY(dialog);
        const CouplingSweepResult& r = *dialog->result();
        const std::size_t index = r.cellIndex(2, 0); // kp 0.3, ki 0
        QCOMPARE(r.cells[index].status, CouplingCellStatus::Ok);
        QTest::mouseClick(dialog->plot(), Qt::LeftButton, Qt::NoModifier,
                          dialog->pixelOfCell(index).toPoint());
        QCOMPARE(dialog->selectedCell(), std::optional<std::size_t>(index));
        QVERIFY(dialog->summaryText().contains(QStringLiteral("Selected: kp 0.3 V/mm, ki 0")));
        const CrossCoupling before = session_->session().crossCoupling;
        const int steps = session_->undoStack()->count();
        QVERIFY(dialog->applyButton()->isEnabled());
        QTest::mouseClick(dialog->applyButton(), Qt::LeftButton);
        const CrossCoupling applied{0.3, 0.0, before.estimate};
        QCOMPARE(session_->session().crossCoupling, applied);
        QCOMPARE(session_->undoStack()->count(), steps + 1);
        // The gains' change leaves the sweep current (it varies them), with nothing to apply.
        QVERIFY(dialog->isCurrent());
        QVERIFY(!dialog->staleVeil()->isVeiled());
        QVERIFY(!dialog->applyButton()->isEnabled());
        QVERIFY(dialog->summaryText().contains(QStringLiteral("These are the session's gains")));
        // The fold shows the applied gains, and the evaluation runs them: the cell's figure.
        QCOMPARE(window_->crossCouplingEditor()->kpField()->value(), 0.3);
        QVERIFY(session_->evaluation().program != nullptr);
        QVERIFY(sameBits(session_->evaluation().program->contour.maxAbs, r.cells[index].maxAbsMm));
        session_->undoStack()->undo();
        QCOMPARE(session_->session().crossCoupling, before);
        QVERIFY(dialog->applyButton()->isEnabled()); // the cell's gains are not the session's
    }

    /// Source: CouplingSweepOptions::progress through JobRunner::cancel. Cancel right after the
    /// start stops the sweep before its cells (the independent axes run first): the result
    /// says so, and the cells not run are drawn as such.
    void cancelStopsARunningSweep() {
        CouplingSweepDialog* dialog = openDialog();
        QVERIFY(dialog);
        setLists(dialog, "0, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.3, 0.5, 1",
                 "0, 0.1, 0.2, 0.3, 0.5, 1, 2, 3");
        QVERIFY(dialog->run());
        QVERIFY(dialog->isRunning());
        QVERIFY(dialog->progressBar()->isVisible());
        QVERIFY(dialog->cancelButton()->isVisible());
        QTest::mouseClick(dialog->cancelButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QVERIFY(dialog->result().has_value());
        const CouplingSweepResult& r = *dialog->result();
        QVERIFY(r.cancelled);
        QVERIFY(r.cellsRun < r.cells.size());
        QVERIFY2(dialog->statusText().startsWith(
                     QStringLiteral("Cancelled: %1 of 80 pairs ran").arg(r.cellsRun)),
                 qPrintable(dialog->statusText()));
        int notRun = 0;
        for (const CouplingSweepCell& c : r.cells)
            notRun += c.status == CouplingCellStatus::NotRun;
        QCOMPARE(dialog->plot()->graphCount() > 0, true);
        int drawnNotRun = 0;
        for (int g = 0; g < dialog->plot()->graphCount(); ++g)
            if (dialog->plot()->graph(g)->name().startsWith(QStringLiteral("not run")))
                drawnNotRun = dialog->plot()->graph(g)->dataCount();
        QCOMPARE(drawnNotRun, notRun);
        QVERIFY(!dialog->progressBar()->isVisible());
        // A cell that did not run has nothing to apply.
        dialog->selectCell(r.cells.size() - 1);
        QCOMPARE(r.cells.back().status, CouplingCellStatus::NotRun);
        QVERIFY(!dialog->applyButton()->isEnabled());
        QVERIFY(!dialog->apply());
        QVERIFY(dialog->summaryText().contains(QStringLiteral("not run, nothing to apply")));
        // The best is of the pairs that ran only, and said so.
        QVERIFY(dialog->summaryText().contains(QStringLiteral("Best of the pairs that ran")));
    }

    /// Source: sameCouplingSweepInputs. A session changed while the sweep runs (the actuator
    /// limit) leaves its result for the session as it was: veiled, named stale, never applied;
    /// undoing the change makes it current again.
    void aSessionChangedWhileRunningLeavesItStale() {
        CouplingSweepDialog* dialog = openDialog();
        QVERIFY(dialog);
        setLists(dialog, "0, 0.1, 0.3", "0, 1");
        const double umax = session_->session().umaxVolts;
        QVERIFY(dialog->run());
        session_->setUmax(3.0);
        QVERIFY(dialog->isRunning());
        QVERIFY2(dialog->statusText().contains(QStringLiteral("changed since the sweep started")),
                 qPrintable(dialog->statusText()));
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QCOMPARE(dialog->result()->cells.size(), std::size_t(6)); // this run's, not the first
        QVERIFY(!dialog->isCurrent());
        QVERIFY(dialog->staleVeil()->isVeiled());
        QVERIFY2(dialog->staleVeil()->note().startsWith(QStringLiteral(
                     "Computed for the session before it changed (the actuator limit, 2.5 V "
                     "then)")),
                 qPrintable(dialog->staleVeil()->note()));
        QVERIFY(dialog->statusText().startsWith(QStringLiteral("Stale:")));
        QVERIFY(!dialog->applyButton()->isEnabled());
        const CrossCoupling before = session_->session().crossCoupling;
        const int steps = session_->undoStack()->count();
        dialog->selectCell(dialog->result()->cellIndex(1, 0));
        QVERIFY(!dialog->apply()); // gains computed for another session are never applied
        QCOMPARE(session_->session().crossCoupling, before);
        QCOMPARE(session_->undoStack()->count(), steps);
        // A stale map is out of reach of the mouse: no hover readout.
        hoverOver(dialog->plot(), dialog->pixelOfCell(0));
        QVERIFY(dialog->hoverText().isEmpty());
        // Back to the limit it was computed for: current again.
        session_->undoStack()->undo();
        QCOMPARE(session_->session().umaxVolts, umax);
        QVERIFY(dialog->isCurrent());
        QVERIFY(!dialog->staleVeil()->isVeiled());
        QVERIFY(dialog->applyButton()->isEnabled());
        // Reopened from the fold on a stale result, it sweeps the session as it is.
        session_->setUmax(3.0);
        QVERIFY(!dialog->isCurrent());
        QCOMPARE(openFromTheFold(), dialog);
        QVERIFY(dialog->isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QVERIFY(dialog->isCurrent());
        // Changed while running, then "Tune…" again: the sweep restarts for the session as it
        // is, and its result is current.
        QVERIFY(dialog->run());
        session_->setUmax(2.0);
        QCOMPARE(openFromTheFold(), dialog);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QVERIFY(dialog->isCurrent());
        QVERIFY(!dialog->staleVeil()->isVeiled());
    }

    /// Source: the layout checks of the plots (plot_layout_checks.h) and the widgets' own size
    /// hints. At 1366x768 the dialog fits the screen; no label, field or button is narrower or
    /// lower than it needs, no text of the map leaves it or overlaps another, no tick labels
    /// overlap, with the default grid and with 20 x 20 values (turned tick labels, no values in
    /// the cells).
    void itFitsA1366x768Screen() {
        CouplingSweepDialog* dialog = openFromTheFold();
        QTRY_VERIFY_WITH_TIMEOUT(dialog->result().has_value(), kSweepTimeoutMs);
        const QSize screen(1366, 768);
        QVERIFY(dialog->minimumSizeHint().width() <= screen.width());
        QVERIFY(dialog->minimumSizeHint().height() <= screen.height() - 60); // title, task bar
        QVERIFY(dialog->width() <= screen.width());
        QVERIFY(dialog->height() <= screen.height() - 60);
        checkLayout(dialog);

        // The largest grid with the values in its cells: 10 x 10, the figures' three digits
        // inside their cells.
        setLists(dialog, "0, 0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1, 3, 10",
                 "0, 0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1, 3, 10");
        QVERIFY(dialog->run());
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QCOMPARE(dialog->result()->cells.size(), std::size_t(100));
        checkLayout(dialog);

        QString many;
        for (int i = 0; i < 20; ++i)
            many += QString::number(0.05 * i) + (i < 19 ? ", " : "");
        setLists(dialog, many, many);
        QVERIFY(dialog->run());
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isRunning(), kSweepTimeoutMs);
        QCOMPARE(dialog->result()->cells.size(), std::size_t(400));
        checkLayout(dialog);
    }

private:
    /// A mouse move with no button over @p pixel of @p widget. Sent to the widget itself: the
    /// offscreen platform's cursor gives a move to the first top-level window under it, the
    /// main window, whatever window is on top.
    static void hoverOver(QWidget* widget, QPointF pixel) {
        QMouseEvent move(QEvent::MouseMove, pixel, widget->mapToGlobal(pixel), Qt::NoButton,
                         Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(widget, &move);
    }

    CouplingSweepDialog* openFromTheFold() {
        CrossCouplingEditor* editor = window_->crossCouplingEditor();
        if (!editor->tuneButton()->isVisible())
            QTest::mouseClick(editor->foldButton(), Qt::LeftButton);
        if (!editor->tuneButton()->isVisible())
            return nullptr;
        QTest::mouseClick(editor->tuneButton(), Qt::LeftButton);
        auto* dialog = window_->findChild<CouplingSweepDialog*>();
        if (dialog && !QTest::qWaitForWindowExposed(dialog))
            return nullptr;
        return dialog;
    }

    /// The dialog opened from the fold, its first sweep (the default grid) done.
    CouplingSweepDialog* openDialog() {
        CouplingSweepDialog* dialog = openFromTheFold();
        if (!dialog || !QTest::qWaitFor([dialog] { return !dialog->isRunning(); }, kSweepTimeoutMs))
            return nullptr;
        return dialog;
    }

    void setLists(CouplingSweepDialog* dialog, const QString& kp, const QString& ki) {
        dialog->kpListField()->setText(kp);
        dialog->kiListField()->setText(ki);
    }

    /// The dialog with a sweep of the lists run to its end.
    CouplingSweepDialog* runSmallSweep(const std::vector<double>& kp,
                                       const std::vector<double>& ki) {
        CouplingSweepDialog* dialog = openDialog();
        const auto list = [](const std::vector<double>& v) {
            QStringList words;
            for (double x : v)
                words << QString::number(x);
            return words.join(", ");
        };
        if (!dialog)
            return nullptr;
        setLists(dialog, list(kp), list(ki));
        if (!dialog->run() ||
            !QTest::qWaitFor([dialog] { return !dialog->isRunning(); }, kSweepTimeoutMs))
            return nullptr;
        return dialog;
    }

    void checkLayout(CouplingSweepDialog* dialog) {
        dialog->plot()->replot();
        QApplication::processEvents();
        const QStringList problems = test::annotationProblems(dialog->plot());
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        const QRect area = dialog->rect();
        for (QWidget* w : dialog->findChildren<QWidget*>()) {
            if (!w->isVisibleTo(dialog) || w->parentWidget() != dialog)
                continue;
            if (!qobject_cast<QLabel*>(w) && !qobject_cast<QAbstractButton*>(w) &&
                !qobject_cast<QLineEdit*>(w) && !qobject_cast<QCustomPlot*>(w))
                continue;
            const QRect at(w->mapTo(dialog, QPoint(0, 0)), w->size());
            QVERIFY2(area.contains(at), qPrintable(w->objectName() + " leaves the dialog"));
            const QSize needs = w->minimumSizeHint();
            auto* label = qobject_cast<QLabel*>(w);
            if (label && label->wordWrap()) {
                QVERIFY2(label->heightForWidth(label->width()) <= label->height(),
                         qPrintable("cut: " + label->text().left(60)));
            } else {
                QVERIFY2(w->width() >= needs.width() && w->height() >= needs.height(),
                         qPrintable(QString("%1 '%2': %3 x %4, needs %5 x %6")
                                        .arg(w->metaObject()->className(),
                                             label ? label->text().left(40) : QString())
                                        .arg(w->width())
                                        .arg(w->height())
                                        .arg(needs.width())
                                        .arg(needs.height())));
            }
        }
        // The map keeps most of the room.
        QVERIFY(dialog->plot()->axisRect()->height() > 200);
    }

    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TstCouplingSweepDialog)
#include "tst_coupling_sweep_dialog.moc"
