// SPDX-License-Identifier: GPL-3.0-or-later
// Every action of every menu and every dialog, in several states of the session, with every
// dialog answered both ways. Its purpose is to crash (or trip ASan/UBSan, since the whole suite
// also runs instrumented) wherever a menu or dialog mishandles a state: the class of defect that
// made Design > Compare designs... segfault with one snapshot stored.
#include "tests/support/gui_checks.h"
#include "ui/main_window.h"
#include "ui/plots/plot_tools.h"
#include "ui/session/tuning_session.h"
#include "ui/snapshot_compare_dialog.h"

#include <QMenuBar>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

#include <qcustomplot.h>

using namespace xyt;
using namespace xyt::ui;
using xyt::test::DialogAnswerer;

Q_DECLARE_METATYPE(xyt::Session)

namespace {

/**
 * The paper's session with a 13 s move of 60 mm instead of 600 mm in 130 s. The states below
 * differ in their designs and snapshots, which is what the menus see; the shorter run (52 s
 * automatic, a tenth of the default's samples) keeps 16 rows x every action affordable in the
 * instrumented build. The "default" state keeps the paper's run.
 */
Session shortMove() {
    Session s = Session::paperDefault();
    s.trajectory.xf = 60.0;
    s.trajectory.tfSeconds = 13.0;
    return s;
}

Session withTwoSnapshots() {
    Session s = shortMove();
    s.snapshots.push_back(s.snapshot("paper design"));
    s.axes[0].gt.kp = 60.0;
    s.axes[1].gt.omegaNRadPerSec *= 1.5;
    s.snapshots.push_back(s.snapshot("faster"));
    s.axes[0].gt.kp = 45.0;
    return s;
}

Session bothPolePlacement() {
    Session s = shortMove();
    for (AxisSettings& a : s.axes)
        a.method = DesignMethod::PolePlacementZpetc;
    s.snapshots.push_back(s.snapshot("both pp"));
    return s;
}

Session oneAxisInvalid() {
    Session s = shortMove();
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    s.axes[1].pp.b = {0.0, 0.0, 0.0}; // B = 0: no design
    s.snapshots.push_back(Session::paperDefault().snapshot("valid"));
    return s;
}

Session unstable() {
    Session s = shortMove();
    s.axes[0].gt.plant.a1 = -100.0; // the closed loop is unstable and the run diverges
    s.snapshots.push_back(s.snapshot("diverged"));
    return s;
}

/// A G-code program as the trajectory: a 20 mm square with a rounded corner, run by
/// both axes, with a snapshot of the cubic move to compare against.
Session gcodeProgram() {
    Session s = shortMove();
    s.snapshots.push_back(s.snapshot("cubic move"));
    s.trajectory.kind = TrajectoryKind::Gcode;
    s.trajectory.gcode.fileName = "menu_square.nc";
    s.trajectory.gcode.program =
        "G21 G90\nG1 X20 Y0 F600\nX20 Y15\nG3 X15 Y20 I-5 J0\nG1 X0 Y20\nX0 Y0\n";
    return s;
}

/// The digital implementation at its least ideal: a coarse encoder, an 8-bit DAC,
/// two samples of delay, back-calculation, a slow controller, and one axis by pole placement.
Session digitalImplementation() {
    Session s = shortMove();
    s.axes[1].method = DesignMethod::PolePlacementZpetc;
    s.controllerTsSeconds = 0.05;
    s.implementation.encoderResolutionMm = 0.1;
    s.implementation.dacBits = 8;
    s.implementation.delaySamples = 2;
    s.implementation.antiWindup = AntiWindup::BackCalculation;
    s.snapshots.push_back(Session::paperDefault().snapshot("ideal"));
    return s;
}

/// Axis x on the PID + feedforward method (its tuning dialog is enabled), y Guillemin-Truxal.
Session pidFeedforward() {
    Session s = Session::paperDefault();
    s.axes[0].method = DesignMethod::PidFeedforward;
    return s;
}

} // namespace

class TstMenuActions : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyActionInEveryState_data();
    void everyActionInEveryState();
    void compareDialogWithSnapshots_data();
    void compareDialogWithSnapshots();
};

void TstMenuActions::initTestCase() {
    QStandardPaths::setTestModeEnabled(true); // settings and recovery copies stay out of $HOME
    QCoreApplication::setOrganizationName("xytune-tests");
}

void TstMenuActions::everyActionInEveryState_data() {
    QTest::addColumn<Session>("state");
    QTest::addColumn<bool>("modified");
    QTest::addColumn<bool>("accept");
    const QList<QPair<const char*, Session>> states = {
        {"default", Session::paperDefault()},
        {"two snapshots", withTwoSnapshots()},
        {"both pole placement", bothPolePlacement()},
        {"one axis invalid", oneAxisInvalid()},
        {"unstable", unstable()},
        {"gcode program", gcodeProgram()},
        {"digital implementation", digitalImplementation()},
        {"PID + feedforward", pidFeedforward()}};
    for (const auto& [name, state] : states)
        for (const bool modified : {false, true})
            for (const bool accept : {false, true})
                QTest::addRow("%s, %s, dialogs %s", name, modified ? "modified" : "saved",
                              accept ? "accepted" : "rejected")
                    << state << modified << accept;
}

void TstMenuActions::everyActionInEveryState() {
    QFETCH(Session, state);
    QFETCH(bool, modified);
    QFETCH(bool, accept);
    TuningSession session;
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const auto enterState = [&] {
        session.reset(state);
        if (modified) {
            Session next = state;
            next.umaxVolts = 2.4;
            session.apply(next, "a change");
        }
        if (!window.isVisible())
            window.show();
    };
    enterState();
    QStringList paths;
    for (QAction* a : test::allMenuActions(window.menuBar()))
        paths << test::actionPath(a);
    QVERIFY2(paths.size() >= 12, qPrintable(paths.join(", ")));
    DialogAnswerer answerer(accept ? DialogAnswerer::Mode::Accept : DialogAnswerer::Mode::Reject);
    QStringList triggered;
    for (const QString& path : paths) {
        for (int axis : {0, 1}) {
            enterState();
            session.setCurrentAxis(axis);
            // Found again each time: an earlier action may have rebuilt its menu.
            QAction* action = test::findMenuAction(window.menuBar(), path);
            if (!action || !action->isEnabled())
                continue;
            action->trigger();
            QApplication::processEvents();
            triggered << path;
            // Whatever the action did, the plots show the state it left, never an older one.
            const QString mismatch = test::plotsMismatch(&window, &session);
            QVERIFY2(mismatch.isEmpty(), qPrintable(path + ": " + mismatch));
        }
    }
    // Every plot's context menu and its save dialog.
    enterState();
    for (QCustomPlot* plot : window.findChildren<QCustomPlot*>()) {
        emit plot->customContextMenuRequested(QPoint(20, 20));
        savePlotDialog(plot, plot->objectName() + ".png");
    }
    QVERIFY(!triggered.isEmpty());
    QVERIFY(answerer.answered() >= 3); // at least About, Compare designs and the file dialogs
}

void TstMenuActions::compareDialogWithSnapshots_data() {
    QTest::addColumn<int>("snapshots");
    QTest::newRow("none") << 0;
    QTest::newRow("one (crashed before the fix)") << 1;
    QTest::newRow("two") << 2;
}

void TstMenuActions::compareDialogWithSnapshots() {
    QFETCH(int, snapshots);
    TuningSession session;
    MainWindow window(&session);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // Store the snapshots through the real menu and its input dialog.
    QAction* store = nullptr;
    QAction* compare = nullptr;
    for (QAction* a : test::allMenuActions(window.menuBar())) {
        if (a->text().contains("Store snapshot"))
            store = a;
        if (a->text().contains("Compare designs"))
            compare = a;
    }
    QVERIFY(store && compare);
    {
        DialogAnswerer accept(DialogAnswerer::Mode::Accept);
        for (int i = 0; i < snapshots; ++i) {
            session.setKp(0, 30.0 + 10.0 * i);
            store->trigger();
        }
    }
    QCOMPARE(static_cast<int>(session.session().snapshots.size()), snapshots);
    int rows = -1;
    QString left, right;
    DialogAnswerer answerer(DialogAnswerer::Mode::Reject, [&](QWidget* dialog) {
        if (auto* d = qobject_cast<SnapshotCompareDialog*>(dialog)) {
            rows = d->table()->rowCount();
            left = d->table()->horizontalHeaderItem(0)->text();
            right = d->table()->horizontalHeaderItem(1)->text();
        }
    });
    compare->trigger();
    QTRY_VERIFY(rows >= 0);
    // One row per figure of the current design (both columns show GT designs of the same shape).
    QCOMPARE(rows, static_cast<int>(comparisonRows(session.session()).size()));
    QCOMPARE(left, tr("Current design"));
    QCOMPARE(right, snapshots == 0
                        ? tr("Current design")
                        : QString::fromStdString(session.session().snapshots.back().name));
}

QTEST_MAIN(TstMenuActions)
#include "tst_menu_actions.moc"
