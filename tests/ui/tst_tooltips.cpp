// SPDX-License-Identifier: GPL-3.0-or-later
// Every input, button, plot and metric row of the workbench says what it is: the main window in
// two states (a Guillemin–Truxal axis; a PID + feedforward axis beside a pole-placement one),
// with every fold open and every tab shown in turn, and the dialogs of the Design menu.
//
// The rule, as a user meets it: hovering a widget shows its own toolTip(). A widget is checked
// when it is visible and is a QLineEdit, QAbstractSpinBox, QSlider, QComboBox, QCheckBox,
// QCustomPlot or QAbstractButton, except the parts Qt builds inside another widget, which the
// user sees as that widget (so that one is checked instead): the line edit of a spin box or of an
// editable combo box, the scroll buttons of a tab bar, the corner button of a table, and the
// standard buttons of a QDialogButtonBox (OK, Cancel, Close say what they do; a button of its own
// added to the box is checked). It passes when its
// own toolTip() is not empty; a tooltip on a group box or a label beside it does not count,
// since hovering the field does not show it. A metric row passes when its header item (the row
// title the user hovers) has a tooltip.
#include "ui/coupling_sweep_dialog.h"
#include "ui/friction_curve_dialog.h"
#include "ui/help/user_guide_window.h"
#include "ui/help/welcome_dialog.h"
#include "ui/identification_window.h"
#include "ui/main_window.h"
#include "ui/panels/friction_editor.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/pid_tuning_dialog.h"
#include "ui/session/install_paths.h"
#include "ui/session/tuning_session.h"
#include "ui/snapshot_compare_dialog.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QSet>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <memory>

using namespace xyt;
using namespace xyt::ui;

namespace {

bool tooltipChecked(QWidget* w) {
    const bool kind = qobject_cast<QLineEdit*>(w) || qobject_cast<QAbstractSpinBox*>(w) ||
                      qobject_cast<QSlider*>(w) || qobject_cast<QComboBox*>(w) ||
                      qobject_cast<QCheckBox*>(w) || qobject_cast<QCustomPlot*>(w) ||
                      qobject_cast<QAbstractButton*>(w);
    if (!kind)
        return false;
    QWidget* parent = w->parentWidget();
    // Parts Qt builds inside another widget (see the rule above).
    if (qobject_cast<QLineEdit*>(w) && parent &&
        (qobject_cast<QAbstractSpinBox*>(parent) || qobject_cast<QComboBox*>(parent)))
        return false;
    if (auto* button = qobject_cast<QAbstractButton*>(w); button && parent) {
        if (qobject_cast<QTabBar*>(parent) || qobject_cast<QAbstractItemView*>(parent) ||
            QByteArray(w->metaObject()->className()) == "QTableCornerButton")
            return false;
        if (auto* box = qobject_cast<QDialogButtonBox*>(parent);
            box && box->standardButton(button) != QDialogButtonBox::NoButton)
            return false;
    }
    return true;
}

/// How an offender is named in the failure message: class, object and accessible names, its
/// text, and the nearest named ancestor.
QString describe(QWidget* w) {
    QString text;
    if (auto* button = qobject_cast<QAbstractButton*>(w))
        text = button->text();
    else if (auto* edit = qobject_cast<QLineEdit*>(w))
        text = edit->placeholderText();
    QString ancestor;
    for (QWidget* p = w->parentWidget(); p && ancestor.isEmpty(); p = p->parentWidget())
        if (!p->objectName().isEmpty() && !p->objectName().startsWith("qt_"))
            ancestor = p->objectName();
    return QStringLiteral("%1 '%2' (accessible '%3', text '%4', in '%5')")
        .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(),
             w->accessibleName(), text, ancestor);
}

/// What a walk found: the offenders, and every widget it checked.
struct Walk {
    QStringList offenders;
    QSet<QWidget*> checked;
    /// The checked widgets of type T (to show the walk saw what it claims to).
    template <typename T> int count() const {
        return static_cast<int>(std::count_if(checked.begin(), checked.end(),
                                              [](QWidget* w) { return qobject_cast<T*>(w); }));
    }
};

/// Adds the visible widgets of @p root that the rule checks to @p walk, and those without a
/// tooltip to its offenders.
void walkVisible(QWidget* root, Walk& walk) {
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets) {
        if (!w->isVisible() || !tooltipChecked(w))
            continue;
        walk.checked.insert(w);
        const QString name = describe(w);
        if (w->toolTip().trimmed().isEmpty() && !walk.offenders.contains(name))
            walk.offenders << name;
    }
}

QStringList offenders(QWidget* root) {
    Walk walk;
    walkVisible(root, walk);
    return walk.offenders;
}

/// Opens every fold of the window (checkable flat tool buttons with a body under them).
void openFolds(QWidget* root) {
    for (QToolButton* fold : root->findChildren<QToolButton*>())
        if (fold->isCheckable() && !fold->isChecked() && fold->isVisible() && fold->isEnabled() &&
            fold->autoRaise())
            fold->click();
    QApplication::processEvents();
}

/// The walk of @p root with every tab of every tab widget shown in turn.
Walk walkEveryTab(QWidget* root) {
    Walk walk;
    walkVisible(root, walk);
    for (QTabWidget* tabs : root->findChildren<QTabWidget*>()) {
        if (!tabs->isVisible())
            continue;
        const int before = tabs->currentIndex();
        for (int i = 0; i < tabs->count(); ++i) {
            tabs->setCurrentIndex(i);
            QApplication::processEvents();
            openFolds(tabs->widget(i));
            walkVisible(root, walk);
        }
        tabs->setCurrentIndex(before);
    }
    return walk;
}

} // namespace

class TstTooltips : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings stay out of $HOME
        QCoreApplication::setOrganizationName("xytune-tests");
    }

    void init() {
        window_.reset(); // before its session
        session_ = std::make_unique<TuningSession>();
        window_ = std::make_unique<MainWindow>(session_.get());
        window_->resize(1366, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }
    void cleanup() {
        window_.reset();
        session_.reset();
    }

    // The default session: Guillemin–Truxal axes, every fold open, every tab shown.
    void guilleminTruxalAxis() {
        openFolds(window_.get());
        const Walk walk = walkEveryTab(window_.get());
        QVERIFY2(walk.offenders.isEmpty(),
                 qPrintable("without a tooltip:\n" + walk.offenders.join("\n")));
        // The walk saw what it claims to: the ωn and kp sliders, every plot of the six upper and
        // three lower plot tabs plus the design-space map and the robustness plots, the method
        // and trajectory boxes, and the folds' fields.
        QVERIFY2(walk.count<QSlider>() >= 2, qPrintable(QString::number(walk.count<QSlider>())));
        QVERIFY2(walk.count<QCustomPlot>() >= 11,
                 qPrintable(QString::number(walk.count<QCustomPlot>())));
        QVERIFY2(walk.count<QComboBox>() >= 5,
                 qPrintable(QString::number(walk.count<QComboBox>())));
        QVERIFY2(walk.count<QLineEdit>() >= 25,
                 qPrintable(QString::number(walk.count<QLineEdit>())));
        QVERIFY(walk.checked.contains(window_->frictionEditor()->field("coulomb")));
    }

    // A PID + feedforward axis x (its own editor) and a pole-placement axis y.
    void pidAndPolePlacementAxes() {
        Session s = Session::paperDefault();
        s.axes[0].method = DesignMethod::PidFeedforward;
        s.axes[1].method = DesignMethod::PolePlacementZpetc;
        session_->reset(s);
        QApplication::processEvents();
        for (int axis : {0, 1}) {
            session_->setCurrentAxis(axis);
            QApplication::processEvents();
            openFolds(window_.get());
            const Walk walk = walkEveryTab(window_.get());
            QVERIFY2(walk.offenders.isEmpty(),
                     qPrintable(QStringLiteral("axis %1, without a tooltip:\n").arg(axis) +
                                walk.offenders.join("\n")));
            QVERIFY(walk.checked.size() >= 40);
        }
    }

    // The other trajectory pages: a circle, then a G-code program (its fields, the examples box,
    // the contour controls and the cross-coupling fold that a contour brings).
    void circleAndProgramTrajectories() {
        Session s = Session::paperDefault();
        s.trajectory.kind = TrajectoryKind::Circle;
        session_->reset(s);
        QApplication::processEvents();
        openFolds(window_.get());
        Walk walk = walkEveryTab(window_.get());
        QVERIFY(walk.checked.contains(window_->trajectoryEditor()->field("radius")));
        QVERIFY2(walk.offenders.isEmpty(),
                 qPrintable("circle, without a tooltip:\n" + walk.offenders.join("\n")));
        QVERIFY(window_->trajectoryEditor()->loadProgramFile(examplesFolder() + "/circle_25mm.nc"));
        QCOMPARE(session_->session().trajectory.kind, TrajectoryKind::Gcode);
        QApplication::processEvents();
        openFolds(window_.get());
        walk = walkEveryTab(window_.get());
        QVERIFY(walk.checked.contains(window_->trajectoryEditor()->field("max_accel")));
        QVERIFY(walk.checked.contains(window_->trajectoryEditor()->programField()));
        QVERIFY2(walk.offenders.isEmpty(),
                 qPrintable("G-code program, without a tooltip:\n" + walk.offenders.join("\n")));
    }

    // Every figure row of the metrics panel says what it is, its unit and how it is computed.
    void everyMetricRowIsDescribed() {
        QTableWidget* table = window_->metricsPanel()->table();
        QStringList missing;
        for (int row = 0; row < table->rowCount(); ++row) {
            if (MetricsPanel::isGroupRow(row))
                continue;
            const QTableWidgetItem* header = table->verticalHeaderItem(row);
            QVERIFY(header);
            if (header->toolTip().trimmed().isEmpty())
                missing << header->text();
        }
        QVERIFY2(missing.isEmpty(),
                 qPrintable("metric rows without a tooltip: " + missing.join(", ")));
        QCOMPARE(table->rowCount(), int(MetricsPanel::RowCount));
    }

    // The dialogs of the Design and Help menus, shown as the menus show them.
    void designDialogs() {
        std::vector<std::unique_ptr<QWidget>> dialogs;
        dialogs.emplace_back(new PidTuningDialog(session_.get(), 0));
        dialogs.emplace_back(new FrictionCurveDialog(session_.get()));
        dialogs.emplace_back(new IdentificationWindow(session_.get()));
        dialogs.emplace_back(new CouplingSweepDialog(session_.get()));
        dialogs.emplace_back(new SnapshotCompareDialog(session_->session()));
        // Help › Tutorials and Help › User guide.
        dialogs.emplace_back(new WelcomeDialog(window_->files(), QStringLiteral(XYT_SOURCE_DIR) +
                                                                     "/resources/examples"));
        dialogs.emplace_back(new UserGuideWindow);
        for (const auto& dialog : dialogs) {
            dialog->show();
            QVERIFY(QTest::qWaitForWindowExposed(dialog.get()));
            const Walk walk = walkEveryTab(dialog.get());
            QVERIFY2(walk.offenders.isEmpty(),
                     qPrintable(QStringLiteral("%1, without a tooltip:\n")
                                    .arg(dialog->metaObject()->className()) +
                                walk.offenders.join("\n")));
            QVERIFY(walk.checked.size() >= 2); // the compare dialog has two boxes, the others more
            dialog->close();
        }
    }

    // The rule catches a widget without one (so that the checks above cannot pass vacuously).
    void theRuleCatchesAMissingTooltip() {
        QWidget root;
        auto* named = new QCheckBox("described", &root);
        named->setToolTip("a tooltip");
        auto* bare = new QCheckBox("bare", &root);
        bare->setObjectName("bareBox");
        auto* spin = new QSpinBox(&root); // its inner line edit is not checked, the box is
        spin->setToolTip("a spin box");
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok, &root);
        auto* layout = new QVBoxLayout(&root);
        for (QWidget* w : std::initializer_list<QWidget*>{named, bare, spin, buttons})
            layout->addWidget(w);
        root.show();
        QVERIFY(QTest::qWaitForWindowExposed(&root));
        const QStringList found = offenders(&root);
        QCOMPARE(found.size(), 1);
        QVERIFY(found.first().contains("bareBox"));
    }

private:
    std::unique_ptr<TuningSession> session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TstTooltips)
#include "tst_tooltips.moc"
