// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/main_window.h"

#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/pid_feedforward_method.h"
#include "core/simulation/step_view.h"
#include "ui/coupling_sweep_dialog.h"
#include "ui/design_space_view.h"
#include "ui/files/session_file.h"
#include "ui/friction_curve_dialog.h"
#include "ui/help/user_guide_window.h"
#include "ui/help/welcome_dialog.h"
#include "ui/identification_window.h"
#include "ui/panels/contour_controls.h"
#include "ui/panels/cross_coupling_editor.h"
#include "ui/panels/equations_panel.h"
#include "ui/panels/fitted_stack.h"
#include "ui/panels/flexible_mode_editor.h"
#include "ui/panels/fold_button.h"
#include "ui/panels/friction_editor.h"
#include "ui/panels/implementation_editor.h"
#include "ui/panels/method_editor.h"
#include "ui/panels/metrics_panel.h"
#include "ui/panels/number_field.h"
#include "ui/panels/parameter_slider.h"
#include "ui/panels/plant_editor.h"
#include "ui/panels/pp_editor.h"
#include "ui/panels/stale_veil.h"
#include "ui/panels/trajectory_editor.h"
#include "ui/pid_tuning_dialog.h"
#include "ui/plots/bode_plot.h"
#include "ui/plots/contour_plot.h"
#include "ui/plots/nyquist_plot.h"
#include "ui/plots/parameter_locus_plot.h"
#include "ui/plots/plot_tools.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/plots/root_locus_plot.h"
#include "ui/plots/step_plot.h"
#include "ui/plots/time_response_plot.h"
#include "ui/plots/vibration_plot.h"
#include "ui/report/report_exporter.h"
#include "ui/robustness_view.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/install_paths.h"
#include "ui/session/interface_language.h"
#include "ui/session/recovery_store.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"
#include "ui/snapshot_compare_dialog.h"
#include "ui/views/bode_view.h"
#include "ui/views/contour_view.h"
#include "ui/views/equations_view.h"
#include "ui/views/metrics_view.h"
#include "ui/views/nyquist_view.h"
#include "ui/views/parameter_locus_view.h"
#include "ui/views/pole_zero_view.h"
#include "ui/views/root_locus_view.h"
#include "ui/views/step_response_view.h"
#include "ui/views/time_response_view.h"
#include "ui/views/vibration_view.h"

#include <algorithm>
#include <cmath>

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QInputDialog>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <qcustomplot.h>

namespace xyt::ui {

MainWindow::MainWindow(TuningSession* session, QWidget* parent)
    : QMainWindow(parent), session_(session) {
    setWindowTitle(tr("XY Tune"));
    QScrollArea* controlScroll = buildControlPanel();
    buildPlots();
    buildUpperTabs();
    buildLowerTabs();
    // A tab shown: its view is drawn if it went stale while hidden, and its controls shown.
    const auto tabShown = [this] {
        for (PresenterView* view : views_)
            view->drawIfStale();
        showTabControls();
    };
    connect(upperTabs_, &QTabWidget::currentChanged, this, tabShown);
    connect(lowerTabs_, &QTabWidget::currentChanged, this, tabShown);
    connect(rootLocusPlot_, &RootLocusPlot::gainPicked, this, [this](double gain) {
        const int axis = session_->currentAxis();
        const bool pid = session_->session().axes.at(static_cast<std::size_t>(axis)).method ==
                         DesignMethod::PidFeedforward;
        if (!session_->applyLoopGain(axis, gain))
            statusBar()->showMessage(
                tr("Picking a gain sets kp and ωn of a Guillemin–Truxal axis, or P, I and D of a "
                   "PID; this axis uses %1.")
                    .arg(methodDisplayName(
                        session_->session()
                            .axes.at(static_cast<std::size_t>(session_->currentAxis()))
                            .method)),
                6000);
        else
            statusBar()->showMessage(
                pid ? tr("Loop gain %1 applied: P, I and D scaled").arg(gain, 0, 'g', 4)
                    : tr("Loop gain %1 applied: kp and ωn scaled").arg(gain, 0, 'g', 4),
                5000);
    });
    connect(rootLocusPlot_, &RootLocusPlot::gainDragged, this, [this](double gain, bool finished) {
        const int axis = session_->currentAxis();
        if (!gainDragBase_)
            gainDragBase_ = session_->session().axes.at(static_cast<std::size_t>(axis));
        const bool applied =
            session_->applyLoopGainTo(axis, *gainDragBase_, gain, kMergeGainDrag + axis);
        if (finished || !applied) {
            gainDragBase_.reset();
            statusBar()->showMessage(
                applied
                    ? tr("Loop gain %1 of the design before the drag applied").arg(gain, 0, 'g', 4)
                    : tr("Dragging a pole sets the loop gain of a Guillemin–Truxal axis or "
                         "a PID."),
                5000);
        }
    });
    connect(rootLocusPlot_, &RootLocusPlot::zeroDragged, this,
            [this](std::complex<double> from, std::complex<double> to, bool finished) {
                const QString refused =
                    session_->moveControllerZero(session_->currentAxis(), from, to);
                if (!refused.isEmpty())
                    statusBar()->showMessage(tr("The zero stays: %1").arg(refused), 6000);
                else if (finished)
                    statusBar()->showMessage(tr("Zero moved to %1 %2 %3j")
                                                 .arg(to.real(), 0, 'g', 4)
                                                 .arg(to.imag() < 0 ? "−" : "+")
                                                 .arg(std::abs(to.imag()), 0, 'g', 4),
                                             5000);
            });
    plotSplitter_ = new QSplitter(Qt::Vertical, this);
    plotSplitter_->addWidget(upperTabs_);
    plotSplitter_->addWidget(lowerTabs_);
    plotSplitter_->setChildrenCollapsible(false);
    plotSplitter_->setSizes({330, 400});

    QWidget* right = buildSidePanel();
    mainSplitter_ = new QSplitter(Qt::Horizontal, this);
    mainSplitter_->addWidget(controlScroll);
    mainSplitter_->addWidget(plotSplitter_);
    mainSplitter_->addWidget(right);
    mainSplitter_->setStretchFactor(0, 0);
    mainSplitter_->setStretchFactor(1, 1);
    mainSplitter_->setStretchFactor(2, 0);
    mainSplitter_->setChildrenCollapsible(false);
    setCentralWidget(mainSplitter_);

    status_ = new QLabel(this);
    statusBar()->addPermanentWidget(status_);
    files_ = new SessionFileController(session_, this);
    connect(files_, &SessionFileController::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(files_, &SessionFileController::currentFileChanged, this, &MainWindow::updateTitle);
    recovery_ = new RecoveryStore(session_, RecoveryStore::defaultDirectory(), this);
    connect(files_, &SessionFileController::currentFileChanged, recovery_,
            &RecoveryStore::setSessionFile);
    connect(session_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    buildMenus();
    updateTitle();

    // A change reaches the controls first, then each view (each draws what it shows), then the
    // status (Qt calls the slots of one signal in the order they were connected).
    const auto controlsFirst = [this] {
        changeTimer_.start();
        syncControls();
    };
    connect(session_, &TuningSession::designChanged, this, controlsFirst);
    connect(session_, &TuningSession::currentAxisChanged, this, controlsFirst);
    buildViews();
    connect(session_, &TuningSession::designChanged, this, &MainWindow::updateStatus);
    connect(session_, &TuningSession::currentAxisChanged, this, &MainWindow::updateStatus);
    // A trajectory kind chosen but not applied (G-code without a program): the trajectory plots
    // still show the session's, and say so over it rather than pass it for the chosen one.
    timeVeil_ = new StaleVeil(timePlot_);
    contourVeil_ = new StaleVeil(contourPlot_);
    connect(trajectoryEditor_, &TrajectoryEditor::refusalChanged, this, [this](const QString& why) {
        for (StaleVeil* veil : {timeVeil_, contourVeil_}) {
            if (why.isEmpty())
                veil->lift();
            else
                veil->veil(why);
        }
    });
    resize(1366, 768);
    restoreLayout();
    for (QLineEdit* field : findChildren<QLineEdit*>())
        field->installEventFilter(this);
    changeTimer_.start();
    syncControls();
    for (PresenterView* view : views_)
        view->requestRedraw();
    updateStatus();
}

QScrollArea* MainWindow::buildControlPanel() {
    auto* controls = buildControls();
    // Compact rows: the whole left panel (design, trajectory, actuator) fits a 1366x768 window
    // without scrolling for the default cubic session.
    for (QFormLayout* form : controls->findChildren<QFormLayout*>())
        form->setVerticalSpacing(2);
    for (QVBoxLayout* box : controls->findChildren<QVBoxLayout*>())
        box->setSpacing(3);
    auto* controlScroll = new QScrollArea(this);
    controlScroll->setWidget(controls);
    controlScroll->setWidgetResizable(true);
    controlScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // It may shrink to what its rows can (their minimum, not their preferred width): the
    // Portuguese labels are longer, and at their preferred width the window outgrew 1366 px.
    // The splitter still gives it its preferred width when the window has room.
    controlScroll->setMinimumWidth(controls->minimumSizeHint().width() + 20);

    return controlScroll;
}

void MainWindow::buildPlots() {
    timePlot_ = new TimeResponsePlot(this);
    stepPlot_ = new StepPlot(this);
    contourPlot_ = new ContourPlot(this);
    rootLocusPlot_ = new RootLocusPlot(this);
    poleZeroPlot_ = new PoleZeroPlot(this);
    parameterLocusPlot_ = new ParameterLocusPlot(this);
    bodePlot_ = new BodePlot(this);
    nyquistPlot_ = new NyquistPlot(this);
    vibrationPlot_ = new VibrationPlot(this);
}

void MainWindow::buildUpperTabs() {
    upperTabs_ = new QTabWidget(this);
    upperTabs_->addTab(rootLocusPlot_, tr("&Root locus"));
    upperTabs_->addTab(parameterLocusPlot_, tr("P&arameter locus"));
    upperTabs_->addTab(poleZeroPlot_, tr("&Pole-zero"));
    upperTabs_->addTab(bodePlot_, tr("&Bode"));
    upperTabs_->addTab(nyquistPlot_, tr("&Nyquist"));
    upperTabs_->addTab(vibrationPlot_, tr("&Vibration"));
    sweptParameter_ = new QComboBox(this);
    sweptParameter_->addItem(tr("sweep ωn (kp fixed)"));
    sweptParameter_->addItem(tr("sweep kp (ωn fixed)"));
    sweptParameter_->setAccessibleName(tr("Swept parameter"));
    sweptParameter_->setToolTip(tr("The parameter the parameter locus sweeps over its slider's "
                                   "range, the other held at the design's value"));
    upperTabs_->setCornerWidget(sweptParameter_, Qt::TopRightCorner);
    connect(sweptParameter_, &QComboBox::currentIndexChanged, this, [this](int index) {
        parameterLocusView_->setSweptParameter(index == 1 ? GtSweptParameter::Kp
                                                          : GtSweptParameter::OmegaN);
    });
}

void MainWindow::buildLowerTabs() {
    lowerTabs_ = new QTabWidget(this);
    // Short tab names: all five tabs fit beside each other at 1366x768 (with the longer
    // "Time response" and "Step response", Robustness hid behind the scroll arrows).
    lowerTabs_->addTab(timePlot_, tr("&Time"));
    lowerTabs_->setTabToolTip(
        0, tr("Time response: the trajectory, the tracking error and the control signal"));
    lowerTabs_->addTab(stepPlot_, tr("&Step"));
    lowerTabs_->setTabToolTip(
        1, tr("Step response of each axis against the specification's envelope"));
    lowerTabs_->addTab(contourPlot_, tr("&XY contour"));
    magnification_ = new QDoubleSpinBox(this);
    magnification_->setRange(1.0, 10000.0);
    magnification_->setDecimals(0);
    magnification_->setValue(contourPlot_->magnification());
    magnification_->setPrefix(tr("error × "));
    magnification_->setAccessibleName(tr("Contour error magnification"));
    magnification_->setToolTip(
        tr("Magnification of the contour error in the XY plot (as a ballbar plot)"));
    lowerTabs_->setCornerWidget(magnification_, Qt::TopRightCorner);
    connect(magnification_, &QDoubleSpinBox::valueChanged, contourPlot_,
            &ContourPlot::setMagnification);
    contourControls_ = new ContourControls(contourPlot_);
    lowerTabs_->addTab(new DesignSpaceView(session_, this), tr("&Design space"));
    lowerTabs_->addTab(new RobustnessView(session_, this), tr("R&obustness"));
    lowerTabs_->setUsesScrollButtons(
        true); // six tabs and a corner control: scroll, never widen the window
}

QWidget* MainWindow::buildSidePanel() {
    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(4, 4, 4, 4);
    auto* metricsBox = new QGroupBox(tr("Metrics"), right);
    auto* metricsLayout = new QVBoxLayout(metricsBox);
    metrics_ = new MetricsPanel(metricsBox);
    metricsLayout->addWidget(metrics_);
    connect(metrics_, &MetricsPanel::specificationEdited, session_,
            &TuningSession::setSpecification);
    auto* equationsBox = new QGroupBox(tr("Equations"), right);
    auto* equationsLayout = new QVBoxLayout(equationsBox);
    equations_ = new EquationsPanel(equationsBox);
    // Three lines at the least (it scrolls): the metrics panel's warnings need the height at
    // 1366x768.
    equations_->setMinimumHeight(3 * equations_->fontMetrics().lineSpacing() + 6);
    equationsLayout->addWidget(equations_);
    rightLayout->addWidget(metricsBox);
    rightLayout->addWidget(equationsBox, 1);
    // The column scrolls when the window is shorter than it: with a program's contour figures
    // and several warnings it needs about 790 px, and a 1366x768 screen must not get a window
    // taller than itself.
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(right);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // 400 px with the scroll bar, as wide as the column was before it scrolled: the plots in
    // the middle keep their width (their legends are laid out for it at 1366 px).
    scroll->setMinimumWidth(400);
    right->setMinimumWidth(400 - scroll->verticalScrollBar()->sizeHint().width());
    return scroll;
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
            // Left unaccepted, the override lets the shortcut reach the Edit menu's action.
            event->ignore();
            return true;
        }
    }
    return QMainWindow::eventFilter(watched, event);
}

QWidget* MainWindow::buildControls() {
    auto* panel = new QWidget(this);
    auto* layout = new QVBoxLayout(panel);
    layout->addWidget(buildAxisTabs(panel));
    layout->addWidget(buildDesignBox(panel));
    auto* trajectoryBox = new QGroupBox(tr("Trajectory"), panel);
    auto* trajectoryLayout = new QVBoxLayout(trajectoryBox);
    trajectoryEditor_ = new TrajectoryEditor(trajectoryBox);
    trajectoryLayout->addWidget(trajectoryEditor_);
    crossCouplingEditor_ = new CrossCouplingEditor(trajectoryBox);
    trajectoryLayout->addWidget(crossCouplingEditor_);
    layout->addWidget(trajectoryBox);
    layout->addWidget(buildActuatorBox(panel));
    layout->addStretch(1);
    connectControls();
    return panel;
}

QTabBar* MainWindow::buildAxisTabs(QWidget* panel) {
    axisTabs_ = new QTabBar(panel);
    for (const AxisSettings& a : session_->session().axes)
        axisTabs_->addTab(tr("Axis %1").arg(QString::fromStdString(a.id).toUpper()));
    axisTabs_->setExpanding(true);
    axisTabs_->setAccessibleName(tr("Axis"));
    return axisTabs_;
}

QGroupBox* MainWindow::buildDesignBox(QWidget* panel) {
    auto* designBox = new QGroupBox(tr("Design"), panel);
    auto* designLayout = new QVBoxLayout(designBox);
    method_ = new QComboBox(designBox);
    method_->setAccessibleName(tr("Design method"));
    method_->setToolTip(tr("How the current axis is controlled: Guillemin–Truxal PI (Braga et "
                           "al.), pole placement + ZPETC (Patrick, Ishak and Adnan) or LinuxCNC's "
                           "PID with command feedforward"));
    // The friction fold's button shares the method's row (the panel fits 1366 x 768); its body
    // opens below the method's page.
    frictionEditor_ = new FrictionEditor(designBox);
    flexibleModeEditor_ = new FlexibleModeEditor(designBox);
    method_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    method_->setMinimumContentsLength(10);
    auto* methodRow = new QHBoxLayout;
    methodRow->addWidget(method_, 1);
    methodRow->addWidget(frictionEditor_->foldButton());
    methodRow->addWidget(flexibleModeEditor_->foldButton());
    designLayout->addLayout(methodRow);
    methodPages_ = new QStackedWidget(designBox);
    // One entry and one editor page per registered method, in the registry's order: the
    // built-in methods have their own editors, a registered one its parameters' editor.
    for (const DesignMethodModule* module : designMethodModules()) {
        QWidget* page = nullptr;
        if (module->method() == DesignMethod::GuilleminTruxal) {
            method_->addItem(tr("Guillemin–Truxal PI (continuous)"));
            page = buildGtPage(methodPages_);
        } else if (module->method() == DesignMethod::PolePlacementZpetc) {
            method_->addItem(tr("Pole placement + ZPETC (discrete)"));
            page = ppEditor_ = new PpEditor(methodPages_);
        } else {
            method_->addItem(methodDisplayName(module->method()));
            MethodEditor* editor = createMethodEditor(*module, methodPages_);
            methodEditors_.push_back(editor);
            page = editor;
        }
        methodPages_->addWidget(page);
    }
    fitStackToCurrentPage(methodPages_);
    designLayout->addWidget(methodPages_);
    designLayout->addWidget(frictionEditor_);
    frictionEditor_->hide();
    connect(frictionEditor_->foldButton(), &QToolButton::toggled, frictionEditor_,
            &QWidget::setVisible);
    designLayout->addWidget(flexibleModeEditor_);
    flexibleModeEditor_->hide();
    connect(flexibleModeEditor_->foldButton(), &QToolButton::toggled, flexibleModeEditor_,
            &QWidget::setVisible);
    return designBox;
}

QWidget* MainWindow::buildGtPage(QWidget* pages) {
    auto* gtPage = new QWidget(pages);
    auto* gtLayout = new QVBoxLayout(gtPage);
    gtLayout->setContentsMargins(0, 0, 0, 0);
    plantEditor_ = new PlantEditor(gtPage);
    gtLayout->addWidget(plantEditor_);
    omegaN_ = new ParameterSlider(tr("ω&n"), tr("rad/s"), 0.05, 20.0, true, gtPage);
    kp_ = new ParameterSlider(tr("k&p"), tr("V/m"), 0.1, 1000.0, true, gtPage);
    // The fields take any positive value a design can have; the sliders cover the usual range.
    omegaN_->setFieldRange(1e-6, 1e6);
    omegaN_->setDescription(tr("ωn (rad/s): the natural frequency of the 4th-order reference "
                               "model G_R(s); the PI follows as f3 = kp k0/ωn³, ki = ωn⁴/k0 "
                               "(Braga et al. Eq. 11–18)"));
    kp_->setDescription(tr("kp (V per model unit): the PI's proportional gain; with ωn it sets "
                           "ki = kp ψ1 = ωn⁴/k0 and the reference model's f3 = kp k0/ωn³"));
    kp_->setFieldRange(1e-6, 1e12);
    gtLayout->addWidget(omegaN_);
    gtLayout->addWidget(kp_);
    gtLayout->addStretch(1);
    return gtPage;
}

void MainWindow::chooseMethod(int index) {
    const int axis = session_->currentAxis();
    if (index < 0 || static_cast<std::size_t>(index) >= designMethodModules().size())
        return;
    const DesignMethod method = designMethodModules()[static_cast<std::size_t>(index)]->method();
    if (session_->session().axes[static_cast<std::size_t>(axis)].method == method)
        return;
    session_->setMethod(axis, method);
    // The plant changes with the method (each method has its own model): say which.
    const AxisSettings& a = session_->session().axes[static_cast<std::size_t>(axis)];
    const QString name = QString::fromStdString(a.id).toUpper();
    if (method != DesignMethod::GuilleminTruxal && method != DesignMethod::PolePlacementZpetc) {
        statusBar()->showMessage(tr("Axis %1 now uses %2; Edit › Undo switches back")
                                     .arg(name, methodDisplayName(method)),
                                 10000);
        return;
    }
    statusBar()->showMessage(method == DesignMethod::PolePlacementZpetc
                                 ? (a.pp == PpAxisSettings{}
                                        ? tr("Axis %1 now uses pole placement on Patrick, "
                                             "Ishak and Adnan's ARX model (the "
                                             "pole-placement plant, not the Guillemin–Truxal "
                                             "one); Edit › Undo switches back")
                                              .arg(name)
                                        : tr("Axis %1 now uses pole placement on its ARX "
                                             "model; Edit › Undo switches back")
                                              .arg(name))
                                 : tr("Axis %1 now uses the Guillemin–Truxal PI on its "
                                      "continuous plant; Edit › Undo switches back")
                                       .arg(name),
                             10000);
}

QGroupBox* MainWindow::buildActuatorBox(QWidget* panel) {
    auto* actuatorBox = new QGroupBox(tr("Actuator and digital controller"), panel);
    auto* actuatorForm = new QFormLayout(actuatorBox);
    umax_ = new NumberField(
        "umax", [](double v) { requirePositive(v, "umax"); }, actuatorBox);
    umax_->setToolTip(tr("Actuator limit umax (V): every run clips the command to ±umax, and "
                         "the anti-windup acts at it"));
    actuatorForm->addRow(tr("|u| limit (V)"), umax_);
    controllerTs_ = new NumberField(
        "controller Ts", [](double v) { requirePositive(v, "controller Ts"); }, actuatorBox);
    controllerTs_->setToolTip(tr("Controller sample time Ts (s) of the digital PI or PID: the "
                                 "digital implementation runs and the exports are at it"));
    discretization_ = new QComboBox(actuatorBox);
    discretization_->addItem(tr("Tustin"));
    discretization_->addItem(tr("backward Euler"));
    discretization_->setAccessibleName(tr("PI discretization"));
    discretization_->setToolTip(tr("How the PI kp + ki/s is discretized at the controller sample "
                                   "time: Tustin s = (2/Ts)(z − 1)/(z + 1), or backward Euler "
                                   "s = (z − 1)/(z Ts)"));
    // One row for the sample time and the discretization: the implementation's row below
    // keeps the left panel within a 1366x768 window.
    auto* tsRow = new QHBoxLayout;
    tsRow->setContentsMargins(0, 0, 0, 0);
    // Their own size hints side by side would widen the panel (and narrow the plots): they
    // share the field column instead.
    controllerTs_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    controllerTs_->setMinimumWidth(70);
    discretization_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    discretization_->setMinimumWidth(120);
    tsRow->addWidget(controllerTs_, 1);
    tsRow->addWidget(discretization_, 1);
    actuatorForm->addRow(tr("Controller Ts (s)"), tsRow);
    addImplementationFold(actuatorBox, actuatorForm);
    return actuatorBox;
}

void MainWindow::addImplementationFold(QGroupBox* box, QFormLayout* form) {
    // The implementation folds away: open, its five fields would push the default
    // session's controls below a 1366x768 window.
    implementation_ = new ImplementationEditor(box);
    implementationToggle_ =
        makeFoldButton(box, tr("Digital implementation settings"), implementation_);
    implementationToggle_->setToolTip(
        tr("Delay, encoder, DAC and anti-windup of the digital controller"));
    form->addRow(implementationToggle_);
    form->addRow(implementation_);
}

void MainWindow::connectControls() {
    connect(axisTabs_, &QTabBar::currentChanged, session_, &TuningSession::setCurrentAxis);
    connect(method_, &QComboBox::activated, this, &MainWindow::chooseMethod);
    connect(ppEditor_, &PpEditor::settingsEdited, this,
            [this](const PpAxisSettings& pp, int mergeKey) {
                session_->setPp(session_->currentAxis(), pp, mergeKey);
            });
    for (MethodEditor* editor : methodEditors_)
        connect(editor, &MethodEditor::settingsEdited, this,
                [this](const AxisSettings& settings, const QString& description, int mergeKey) {
                    const int axis = session_->currentAxis();
                    session_->setAxis(axis, settings, description,
                                      mergeKey < 0 ? -1
                                                   : kMergeMethodEditor + 10 * mergeKey + axis);
                });
    connect(
        implementation_, &ImplementationEditor::implementationEdited, this,
        [this](const ImplementationSettings& settings) { session_->setImplementation(settings); });
    connect(controllerTs_, &NumberField::valueAccepted, this, [this](double v) {
        if (v != session_->session().controllerTsSeconds)
            session_->setControllerTs(v);
    });
    connect(discretization_, &QComboBox::activated, this, [this](int index) {
        session_->setPiDiscretization(index == 0 ? PiDiscretization::Tustin
                                                 : PiDiscretization::BackwardEuler);
    });
    connect(omegaN_, &ParameterSlider::valueChanged, this,
            [this](double v) { session_->setOmegaN(session_->currentAxis(), v); });
    connect(kp_, &ParameterSlider::valueChanged, this,
            [this](double v) { session_->setKp(session_->currentAxis(), v); });
    connect(plantEditor_, &PlantEditor::plantEdited, this,
            [this](const ThirdOrderPlant& p) { session_->setPlant(session_->currentAxis(), p); });
    connect(frictionEditor_, &FrictionEditor::frictionEdited, this,
            [this](const TableFriction& f, const FrictionCompensation& c) {
                session_->setFriction(session_->currentAxis(), f, c);
            });
    connect(flexibleModeEditor_, &FlexibleModeEditor::loopElementsEdited, this,
            [this](const FlexibleMode& m, const NotchFilter& n) {
                session_->setLoopElements(session_->currentAxis(), m, n);
            });
    connect(flexibleModeEditor_, &FlexibleModeEditor::accelerationLoaded, this,
            [this](const AccelerometerSpectra& spectra, const QString& source) {
                session_->setMeasuredAcceleration(
                    std::make_shared<const TuningSession::MeasuredAcceleration>(
                        TuningSession::MeasuredAcceleration{spectra, source}));
            });
    connect(flexibleModeEditor_, &FlexibleModeEditor::shapingEdited, this,
            [this](const ReferenceShaping& shaping) {
                TrajectorySettings t = session_->session().trajectory;
                t.shaping = shaping;
                session_->setTrajectory(t);
            });
    connect(plantEditor_, &PlantEditor::modelUnitEdited, this,
            [this](double v) { session_->setModelUnitScale(session_->currentAxis(), v); });
    connect(plantEditor_, &PlantEditor::presetChosen, this, [this](const GtPreset& preset) {
        // The preset is a rigid plant and its design; the axis keeps its flexible mode and notch.
        GtAxisSettings gt =
            session_->session().axes.at(static_cast<std::size_t>(session_->currentAxis())).gt;
        gt.plant = preset.plant;
        gt.omegaNRadPerSec = preset.omegaNRadPerSec;
        gt.kp = preset.kp;
        gt.modelUnitsPerPositionUnit = preset.modelUnitsPerPositionUnit;
        session_->setGt(session_->currentAxis(), gt,
                        tr("Load preset %1").arg(coreText("xyt::PresetName", preset.name)));
    });
    connect(trajectoryEditor_, &TrajectoryEditor::trajectoryEdited, session_,
            &TuningSession::setTrajectory);
    connect(crossCouplingEditor_, &CrossCouplingEditor::couplingEdited, session_,
            &TuningSession::setCrossCoupling);
    connect(crossCouplingEditor_, &CrossCouplingEditor::tuneRequested, this, [this] {
        // One dialog, kept with its last sweep; opened without a current one, it sweeps.
        auto* dialog = findChild<CouplingSweepDialog*>();
        if (!dialog)
            dialog = new CouplingSweepDialog(session_, this);
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
        dialog->runUnlessCurrent();
    });
    connect(umax_, &NumberField::valueAccepted, this, [this](double v) {
        if (v != session_->session().umaxVolts)
            session_->setUmax(v);
    });
}

MainWindow::~MainWindow() {
    // (The session may be gone already: the window only reads it, so it is not touched here.)
    for (MethodEditor* editor : methodEditors_)
        editor->disconnect(this);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    files_->populateMenu(file);
    report_ = new ReportExporter(session_, files_, this);
    report_->addToMenu(file);
    connect(report_, &ReportExporter::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = session_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = session_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    QMenu* design = menuBar()->addMenu(tr("&Design"));
    design->addAction(tr("&Store snapshot..."), QKeySequence(tr("Ctrl+T")), this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(
            this, tr("Store snapshot"), tr("Name of the snapshot:"), QLineEdit::Normal,
            tr("design %1").arg(session_->session().snapshots.size() + 1), &ok);
        if (ok && !name.trimmed().isEmpty())
            storeSnapshot(name.trimmed());
    });
    design->addAction(tr("&Compare designs..."), this, [this] {
        SnapshotCompareDialog dialog(session_->session(), this);
        dialog.exec();
    });
    design->addAction(tr("&Identify from data..."), this, [this] {
        // One window, kept (with its candidates) when closed; a child, so found again here.
        auto* window = findChild<IdentificationWindow*>();
        if (!window)
            window = new IdentificationWindow(session_, this);
        window->show();
        window->raise();
        window->activateWindow();
    });
    design->addAction(tr("F&riction curve from a jog log..."), this, [this] {
        auto* dialog = findChild<FrictionCurveDialog*>();
        if (!dialog)
            dialog = new FrictionCurveDialog(session_, this);
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    design->addSeparator();
    feedforwardAction_ = design->addAction(tr("Add &feedforward from the model"), this, [this] {
        const int axis = session_->currentAxis();
        try {
            const AxisSettings next = withModelFeedforward(
                session_->session().axes.at(static_cast<std::size_t>(axis)), axis);
            session_->setAxis(
                axis, next,
                tr("Feedforward of %1 from the model").arg(axisName(session_->session(), axis)));
        } catch (const InvalidInput& e) {
            QMessageBox::warning(this, tr("No feedforward from the model"), exceptionText(e));
        }
    });
    feedforwardAction_->setToolTip(
        tr("The plant's exact inverse as FF1, FF2, FF3: a Guillemin–Truxal axis becomes the same "
           "PI in LinuxCNC's units on the PID + feedforward method"));
    tuneAction_ = design->addAction(tr("&Tune the PID..."), this, [this] {
        PidTuningDialog dialog(session_, session_->currentAxis(), this);
        dialog.exec();
    });
    tuneAction_->setToolTip(tr("PI or PID gains from a crossover and phase margin, or from a "
                               "simulated relay experiment (PID + feedforward axes)"));
    design->addSeparator();
    overlayMenu_ = design->addMenu(tr("&Overlay snapshot"));
    // Filled when shown: never rebuilt (its actions deleted) while one of them runs.
    connect(overlayMenu_, &QMenu::aboutToShow, this, &MainWindow::rebuildOverlayMenu);
    QMenu* view = menuBar()->addMenu(tr("&View"));
    digitalOverlayAction_ = view->addAction(tr("Show the &digital implementation"));
    digitalOverlayAction_->setCheckable(true);
    digitalOverlayAction_->setChecked(true);
    digitalOverlayAction_->setToolTip(
        tr("Overlay the loop as the firmware runs it on the time plots"));
    connect(digitalOverlayAction_, &QAction::toggled, this, [this](bool on) {
        timePlot_->setDigitalVisible(on);
        timeView_->requestRedraw();
    });
    zPlaneAction_ = view->addAction(tr("Pole-zero map of the digital loop (&z-plane)"));
    zPlaneAction_->setCheckable(true);
    connect(zPlaneAction_, &QAction::toggled, this,
            [this](bool on) { poleZeroView_->setDigitalPlane(on); });
    view->addAction(tr("&Reset plot views"), QKeySequence(tr("Ctrl+0")), this, [this] {
        for (QCustomPlot* plot : findChildren<QCustomPlot*>())
            resetView(plot);
    });
    buildLanguageMenu(view);
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User guide"), QKeySequence::HelpContents, this,
                    [this] { showUserGuide(); });
    help->addAction(tr("&Tutorials..."), this, [this] { showWelcome(); });
    help->addAction(tr("&Command-line reference"), this,
                    [this] { showUserGuide(UserGuideWindow::docsUrl("cli.md")); });
    help->addSeparator();
    help->addAction(tr("&About XY Tune"), this, [this] {
        QMessageBox::about(this, tr("About XY Tune"),
                           tr("<b>XY Tune</b> %1<br>Tuning workbench for XY coordinate-table "
                              "position controllers.<br>GPL-3.0-or-later.")
                               .arg(QApplication::applicationVersion()));
    });
}

UserGuideWindow* MainWindow::showUserGuide(const QUrl& page) {
    // One window, kept (with its history) when closed; a child, so found again here.
    auto* guide = findChild<UserGuideWindow*>();
    if (!guide)
        guide = new UserGuideWindow(this);
    if (page.isValid())
        guide->showPage(page);
    guide->show();
    guide->raise();
    guide->activateWindow();
    return guide;
}

QDialog* MainWindow::showWelcome() {
    auto* welcome = findChild<WelcomeDialog*>();
    if (!welcome) {
        welcome = new WelcomeDialog(files_, examplesFolder(), this);
        connect(welcome, &WelcomeDialog::tutorialRequested, this,
                [this](const QUrl& page) { showUserGuide(page); });
    }
    welcome->show();
    welcome->raise();
    welcome->activateWindow();
    return welcome;
}

void MainWindow::buildLanguageMenu(QMenu* view) {
    // The languages by their own names (a user who cannot read the current one finds theirs);
    // the choice applies at the next start, when the window is built in it (interface_language.h).
    QMenu* languages = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(languages);
    const QString stored = storedUiLanguage();
    const QList<QPair<QString, QString>> choices = {
        {QString(), tr("&System language")},
        {QStringLiteral("en"), QStringLiteral("&English")},
        {QStringLiteral("pt_BR"), QStringLiteral("&Português (Brasil)")}};
    for (const auto& [code, name] : choices) {
        QAction* action = languages->addAction(name);
        action->setCheckable(true);
        action->setChecked(code == stored);
        action->setData(code);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, code = code] {
            storeUiLanguage(code);
            const char* const context = "xyt::ui::MainWindow";
            QMessageBox::information(
                this,
                translatedFor(code, context, QT_TRANSLATE_NOOP("xyt::ui::MainWindow", "Language")),
                translatedFor(
                    code, context,
                    QT_TRANSLATE_NOOP("xyt::ui::MainWindow",
                                      "The language changes when XY Tune is started again.")));
        });
    }
}

namespace {

/// The coupled loop's stability as the coupling's fold states it (CouplingStability).
QString stabilityText(const CouplingStability& st) {
    const CoupledLineLoop& w = st.worst;
    const QString direction = QString::number(st.worstThetaRad * 180.0 / M_PI, 'f', 1);
    QString text = st.linesChecked > 0
                       ? MainWindow::tr("On its lines the coupled loop is stable: spectral radius "
                                        "%1 at worst (direction %2°)")
                       : MainWindow::tr("Frozen at each direction the coupled loop is stable: "
                                        "spectral radius %1 at worst (direction %2°)");
    text = text.arg(QString::number(w.spectralRadius, 'g', 6), direction);
    if (w.hiddenIntegralMode)
        text += MainWindow::tr(", beside a pole at z = 1 the contour never sees (the coupling's "
                               "integral and the axes' integrators sharing a constant voltage)");
    if (w.diskMargin > 0.0)
        text += MainWindow::tr("; disk margin %1: ±%2 dB, ±%3°")
                    .arg(QString::number(w.diskMargin, 'g', 3),
                         QString::number(w.diskGainMarginDb, 'g', 3),
                         QString::number(w.diskPhaseMarginDeg, 'g', 3));
    // Broken at each axis' input, the other closed.
    for (const auto& [broken, axis] : {std::pair{&w.brokenAtX, "x"}, std::pair{&w.brokenAtY, "y"}})
        if (*broken && std::isfinite((*broken)->phaseMarginDeg))
            text +=
                MainWindow::tr("; at the %1 input: phase margin %2°")
                    .arg(QLatin1String(axis), QString::number((*broken)->phaseMarginDeg, 'f', 1));
    return text + ".";
}

} // namespace

void MainWindow::showCouplingStatus() {
    const Session& s = session_->session();
    const SessionEvaluation& ev = session_->evaluation();
    QString text;
    bool warning = false;
    if (!s.crossCoupling.active()) {
        // nothing to say
    } else if (!ev.couplingError.text.empty()) {
        text = diagnosticText(ev.couplingError);
        warning = true;
    } else if (ev.program && ev.program->independent) {
        text = tr("Contour error max %1 mm (independent axes %2 mm).")
                   .arg(QString::number(ev.program->contour.maxAbs, 'g', 3),
                        QString::number(ev.program->independent->contour.maxAbs, 'g', 3));
        if (const auto& st = ev.program->couplingStability) {
            text += " " + stabilityText(*st);
            if (!st->warning.text.empty()) {
                text += " " + diagnosticText(st->warning) + ".";
                warning = true;
            }
        }
    } else if (ev.coupledTrajectory) {
        const CoupledTrajectoryRun& run = *ev.coupledTrajectory;
        text = tr("Contour error max %1 mm (independent axes %2 mm). ")
                   .arg(QString::number(run.coupledError.maxAbs, 'g', 3),
                        QString::number(run.independentError.maxAbs, 'g', 3)) +
               stabilityText(run.stability);
        if (!run.stability.warning.text.empty()) {
            text += " " + diagnosticText(run.stability.warning) + ".";
            warning = true;
        }
    }
    crossCouplingEditor_->setStability(text, warning);
}

void MainWindow::syncControls() {
    const int axis = session_->currentAxis();
    const Session& s = session_->session();
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    feedforwardAction_->setEnabled(a.method == DesignMethod::GuilleminTruxal ||
                                   a.method == DesignMethod::PidFeedforward);
    tuneAction_->setEnabled(a.method == DesignMethod::PidFeedforward);
    rootLocusPlot_->setZerosDraggable(a.method == DesignMethod::PidFeedforward);
    const QSignalBlocker blockTabs(axisTabs_);
    axisTabs_->setCurrentIndex(axis);
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& ai = s.axes.at(static_cast<std::size_t>(i));
        axisTabs_->setTabText(i, tr("%1: %2").arg(QString::fromStdString(ai.id).toUpper(),
                                                  QString::fromStdString(ai.label)));
    }
    {
        const QSignalBlocker b1(omegaN_), b2(kp_), b3(method_);
        omegaN_->setValue(a.gt.omegaNRadPerSec);
        kp_->setValue(a.gt.kp);
        const auto& modules = designMethodModules();
        const int page = static_cast<int>(
            std::find(modules.begin(), modules.end(), &designMethodModule(a.method)) -
            modules.begin());
        method_->setCurrentIndex(page);
        methodPages_->setCurrentIndex(page);
    }
    ppEditor_->setSettings(a.pp);
    for (MethodEditor* editor : methodEditors_)
        editor->setSettings(a);
    plantEditor_->setPlant(a.gt.plant, a.gt.modelUnitsPerPositionUnit);
    frictionEditor_->setSettings(a.friction, a.frictionCompensation,
                                 a.method != DesignMethod::PolePlacementZpetc);
    flexibleModeEditor_->setSettings(a.gt.flexibleMode, a.gt.notch,
                                     a.method != DesignMethod::PolePlacementZpetc,
                                     a.method == DesignMethod::GuilleminTruxal);
    flexibleModeEditor_->setShaping(s.trajectory.shaping);
    trajectoryEditor_->setTrajectory(s.trajectory);
    crossCouplingEditor_->setCoupling(s.crossCoupling);
    showCouplingStatus();
    umax_->setValue(s.umaxVolts);
    controllerTs_->setValue(s.controllerTsSeconds);
    const QSignalBlocker blockDiscretization(discretization_);
    discretization_->setCurrentIndex(s.piDiscretization == PiDiscretization::Tustin ? 0 : 1);
    implementation_->setSettings(s.implementation);
    sweptParameter_->setEnabled(a.method == DesignMethod::GuilleminTruxal);
    showTabControls();
    contourControls_->sync();
    overlayMenu_->setEnabled(!s.snapshots.empty());
    const ImplementationSettings& impl = s.implementation;
    // A short summary on the folded row (the panel's width is the plots' loss), the whole in
    // its tooltip.
    const bool quantized = impl.encoderResolutionMm > 0 || impl.dacBits > 0;
    const QString antiWindup = impl.antiWindup == AntiWindup::Clamp ? tr("clamp")
                               : impl.antiWindup == AntiWindup::BackCalculation
                                   ? tr("back-calc.")
                                   : tr("no anti-windup");
    implementationToggle_->setText(
        tr("Implementation: %1, %2%3")
            .arg(quantized ? tr("quantized") : tr("ideal"), antiWindup,
                 impl.delaySamples > 0 ? tr(", delay %1").arg(impl.delaySamples) : QString()));
    implementationToggle_->setToolTip(
        tr("Encoder %1, DAC %2, anti-windup %3, computation delay %4 sample(s). Click to edit.")
            .arg(impl.encoderResolutionMm > 0 ? tr("%1 mm/count").arg(impl.encoderResolutionMm)
                                              : tr("ideal"),
                 impl.dacBits > 0 ? tr("%1 bits").arg(impl.dacBits) : tr("ideal"),
                 coreText("xyt::AntiWindup", antiWindupName(impl.antiWindup)))
            .arg(impl.delaySamples));
}

void MainWindow::buildViews() {
    timeView_ = new TimeResponseView(session_, timePlot_);
    poleZeroView_ = new PoleZeroView(session_, poleZeroPlot_);
    parameterLocusView_ = new ParameterLocusView(session_, parameterLocusPlot_);
    views_ = {timeView_,
              new StepResponseView(session_, stepPlot_),
              new ContourView(session_, contourPlot_),
              new RootLocusView(session_, rootLocusPlot_),
              poleZeroView_,
              parameterLocusView_,
              new BodeView(session_, bodePlot_),
              new NyquistView(session_, nyquistPlot_),
              new VibrationView(session_, vibrationPlot_),
              new MetricsView(session_, metrics_),
              new EquationsView(session_, equations_)};
}

void MainWindow::showTabControls() {
    sweptParameter_->setVisible(upperTabs_->currentWidget() == parameterLocusPlot_);
    magnification_->setVisible(lowerTabs_->currentWidget() == contourPlot_);
}

void MainWindow::updateStatus() {
    const Session& s = session_->session();
    QString state;
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& ai = session_->axisEvaluation(i);
        const QString id =
            QString::fromStdString(s.axes.at(static_cast<std::size_t>(i)).id).toUpper();
        if (!ai.ok)
            state += tr("%1: invalid (%2)  ").arg(id, QString::fromStdString(ai.errorField));
        else if (!ai.step.stable)
            state += tr("%1: UNSTABLE  ").arg(id);
        else
            state += tr("%1: stable  ").arg(id);
    }
    if (changeTimer_.isValid())
        lastRefreshMs_ = static_cast<double>(changeTimer_.nsecsElapsed()) / 1e6;
    status_->setText(state + tr("| updated in %1 ms").arg(lastRefreshMs_, 0, 'f', 1));
    setWindowModified(session_->isModified());
}

void MainWindow::storeSnapshot(const QString& name) {
    session_->storeSnapshot(name);
}

void MainWindow::setOverlaySnapshot(int index) {
    timeView_->setOverlaySnapshot(index);
}

int MainWindow::overlaySnapshot() const {
    return timeView_->overlaySnapshot();
}

void MainWindow::rebuildOverlayMenu() {
    if (!overlayMenu_)
        return;
    overlayMenu_->clear();
    const auto& snapshots = session_->session().snapshots;
    const int overlay = timeView_->overlaySnapshot() < static_cast<int>(snapshots.size())
                            ? timeView_->overlaySnapshot()
                            : -1;
    QAction* none = overlayMenu_->addAction(tr("None"), this, [this] { setOverlaySnapshot(-1); });
    none->setCheckable(true);
    none->setChecked(overlay < 0);
    for (int i = 0; i < static_cast<int>(snapshots.size()); ++i) {
        QAction* a = overlayMenu_->addAction(
            QString::fromStdString(snapshots[static_cast<std::size_t>(i)].name), this,
            [this, i] { setOverlaySnapshot(i); });
        a->setCheckable(true);
        a->setChecked(overlay == i);
    }
}

void MainWindow::updateTitle() {
    const QString file = files_->currentFile();
    setWindowTitle(
        tr("%1[*] — XY Tune").arg(file.isEmpty() ? tr("untitled") : QFileInfo(file).fileName()));
    setWindowModified(session_->isModified());
}

void MainWindow::restoreLayout() {
    QSettings settings;
    if (settings.contains("window/geometry")) {
        restoreGeometry(settings.value("window/geometry").toByteArray());
        fitIntoScreen();
    }
    if (settings.contains("window/mainSplitter"))
        mainSplitter_->restoreState(settings.value("window/mainSplitter").toByteArray());
    if (settings.contains("window/plotSplitter"))
        plotSplitter_->restoreState(settings.value("window/plotSplitter").toByteArray());
}

void MainWindow::fitIntoScreen() {
    // A size saved on a larger screen (1600 x 1000 restored on 1366 x 768) would put the
    // window's edges and the status bar off screen: keep it within the available area.
    const QScreen* screen = this->screen();
    if (!screen)
        return;
    const QRect available = screen->availableGeometry();
    const QSize frameExtra = frameGeometry().size() - geometry().size();
    const QSize most = available.size() - frameExtra;
    if (width() > most.width() || height() > most.height())
        resize(std::min(width(), most.width()), std::min(height(), most.height()));
    QRect frame = frameGeometry();
    if (!available.contains(frame)) {
        frame.moveLeft(
            std::clamp(frame.left(), available.left(),
                       std::max(available.left(), available.right() - frame.width() + 1)));
        frame.moveTop(
            std::clamp(frame.top(), available.top(),
                       std::max(available.top(), available.bottom() - frame.height() + 1)));
        move(frame.topLeft());
    }
}

void MainWindow::saveLayout() const {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/mainSplitter", mainSplitter_->saveState());
    settings.setValue("window/plotSplitter", plotSplitter_->saveState());
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    for (PresenterView* view : views_)
        view->drawIfStale();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!files_->maybeSave()) {
        event->ignore();
        return;
    }
    saveLayout();
    recovery_->discard(); // saved or deliberately discarded: nothing to recover
    // The last values come back on the next start, unless the user discarded them: a session
    // still modified here was answered "Discard", and must not return as a clean "untitled".
    if (!session_->isModified())
        QSettings().setValue("session/last",
                             QJsonDocument(files::sessionToJson(session_->session()))
                                 .toJson(QJsonDocument::Compact));
    event->accept();
}

} // namespace xyt::ui
