// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QUrl>

#include <optional>

#include <vector>

class QComboBox;
class QDialog;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QScrollArea;
class QSplitter;
class QStackedWidget;
class QTabBar;
class QTabWidget;
class QToolButton;

namespace xyt::ui {

class ContourControls;
class ContourPlot;
class RecoveryStore;
class ReportExporter;
class EquationsPanel;
class ImplementationEditor;
class MetricsPanel;
class NumberField;
class ParameterSlider;
class CrossCouplingEditor;
class FlexibleModeEditor;
class FrictionEditor;
class PlantEditor;
class ParameterLocusPlot;
class BodePlot;
class NyquistPlot;
class VibrationPlot;
class PoleZeroPlot;
class PpEditor;
class PresenterView;
class TimeResponseView;
class PoleZeroView;
class ParameterLocusView;
class MethodEditor;
class RootLocusPlot;
class StepPlot;
class SessionFileController;
class StaleVeil;
class TimeResponsePlot;
class TrajectoryEditor;
class TuningSession;
class UserGuideWindow;

/**
 * The workbench window: axis and design controls on the left, plots in the middle, figures and
 * equations on the right. It only wires widgets to the TuningSession presenter and redraws from
 * it on designChanged().
 */
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(TuningSession* session, QWidget* parent = nullptr);
    /// Stops editing first: a field that commits as the window closes (losing the focus) must
    /// not change the session through a window half destroyed.
    ~MainWindow() override;

    ParameterSlider* omegaNSlider() const { return omegaN_; }
    ParameterSlider* kpSlider() const { return kp_; }
    /// Shrinks and moves the window into its screen's available area (done on restore).
    void fitIntoScreen();
    PlantEditor* plantEditor() const { return plantEditor_; }
    TrajectoryEditor* trajectoryEditor() const { return trajectoryEditor_; }
    TimeResponsePlot* timePlot() const { return timePlot_; }
    StepPlot* stepPlot() const { return stepPlot_; }
    RootLocusPlot* rootLocusPlot() const { return rootLocusPlot_; }
    PoleZeroPlot* poleZeroPlot() const { return poleZeroPlot_; }
    ParameterLocusPlot* parameterLocusPlot() const { return parameterLocusPlot_; }
    BodePlot* bodePlot() const { return bodePlot_; }
    NyquistPlot* nyquistPlot() const { return nyquistPlot_; }
    VibrationPlot* vibrationPlot() const { return vibrationPlot_; }
    PpEditor* ppEditor() const { return ppEditor_; }
    QComboBox* methodBox() const { return method_; }
    QTabWidget* upperTabs() const { return upperTabs_; }
    QTabWidget* lowerTabs() const { return lowerTabs_; }
    ContourPlot* contourPlot() const { return contourPlot_; }
    /// The covers over the trajectory plots while the editor's trajectory is not the session's.
    StaleVeil* timeVeil() const { return timeVeil_; }
    StaleVeil* contourVeil() const { return contourVeil_; }
    ContourControls* contourControls() const { return contourControls_; }
    MetricsPanel* metricsPanel() const { return metrics_; }
    FrictionEditor* frictionEditor() const { return frictionEditor_; }
    FlexibleModeEditor* flexibleModeEditor() const { return flexibleModeEditor_; }
    CrossCouplingEditor* crossCouplingEditor() const { return crossCouplingEditor_; }
    ImplementationEditor* implementationEditor() const { return implementation_; }
    QToolButton* implementationToggle() const { return implementationToggle_; }
    /// View > Show the digital implementation (time-plot overlay), on by default.
    QAction* digitalOverlayAction() const { return digitalOverlayAction_; }
    /// View > Pole-zero map of the digital loop (z-plane), off by default.
    QAction* zPlaneAction() const { return zPlaneAction_; }
    /// Design › Add feedforward from the model, and Design › Tune the PID.
    QAction* feedforwardAction() const { return feedforwardAction_; }
    QAction* tuneAction() const { return tuneAction_; }
    EquationsPanel* equationsPanel() const { return equations_; }
    QTabBar* axisTabs() const { return axisTabs_; }
    SessionFileController* files() const { return files_; }
    /// File › Export report.
    ReportExporter* reportExporter() const { return report_; }
    RecoveryStore* recovery() const { return recovery_; }
    /// Stores the current design as a snapshot named @p name (undoable).
    void storeSnapshot(const QString& name);
    /// Overlays snapshot @p index on the time plot (-1: none).
    void setOverlaySnapshot(int index);
    int overlaySnapshot() const;
    /// Time from the last change of the design to the last view drawn, in milliseconds.
    double lastRefreshMs() const { return lastRefreshMs_; }
    /// Help › User guide: shows the guide's window (one, kept when closed) at @p page (a qrc URL
    /// under :/docs; its home page when empty) and returns it.
    UserGuideWindow* showUserGuide(const QUrl& page = QUrl());
    /// Help › Tutorials: the first-start page (WelcomeDialog), non-modal; returns it.
    QDialog* showWelcome();
    /// The views that draw the window from the presenter.
    const std::vector<PresenterView*>& views() const { return views_; }

protected:
    void closeEvent(QCloseEvent* event) override;
    /// The views drawn before the window was shown are drawn again at their size on screen.
    void showEvent(QShowEvent* event) override;
    /// Ctrl+Z / Ctrl+Shift+Z in a text field undo and redo the session, as the Edit menu does
    /// (not the field's own text history).
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// The left panel: axis tabs, design, trajectory, actuator and digital controller.
    QWidget* buildControls();
    QTabBar* buildAxisTabs(QWidget* panel);
    /// The method box over a page per method (the Guillemin–Truxal page, the pole-placement
    /// editor).
    QGroupBox* buildDesignBox(QWidget* panel);
    QWidget* buildGtPage(QWidget* pages);
    QGroupBox* buildActuatorBox(QWidget* panel);
    /// The implementation settings under a toggle, folded by default.
    void addImplementationFold(QGroupBox* box, QFormLayout* form);
    /// Every edit in the left panel goes to the presenter.
    void connectControls();
    /// Switches the current axis to method @p index of the method box and says in the status
    /// bar that the plant changed with it.
    void chooseMethod(int index);
    void buildMenus();
    void buildLanguageMenu(QMenu* view);
    void syncControls();
    /// The coupling editor's line: what the evaluation found of the cross-coupling.
    void showCouplingStatus();
    void restoreLayout();

    void saveLayout() const;

    TuningSession* session_;
    QTabBar* axisTabs_ = nullptr;
    QComboBox* method_ = nullptr;
    PlantEditor* plantEditor_ = nullptr;
    FrictionEditor* frictionEditor_ = nullptr;
    FlexibleModeEditor* flexibleModeEditor_ = nullptr;
    CrossCouplingEditor* crossCouplingEditor_ = nullptr;
    ParameterSlider* omegaN_ = nullptr;
    ParameterSlider* kp_ = nullptr;
    TrajectoryEditor* trajectoryEditor_ = nullptr;
    NumberField* umax_ = nullptr;
    NumberField* controllerTs_ = nullptr;
    QComboBox* discretization_ = nullptr;
    QToolButton* implementationToggle_ = nullptr;
    ImplementationEditor* implementation_ = nullptr;
    QAction* digitalOverlayAction_ = nullptr;
    QAction* zPlaneAction_ = nullptr;
    QAction* feedforwardAction_ = nullptr;
    /// The axis as it was when a drag of a closed-loop pole along the root locus began.
    std::optional<AxisSettings> gainDragBase_;
    QAction* tuneAction_ = nullptr;
    QDoubleSpinBox* magnification_ = nullptr;
    ContourControls* contourControls_ = nullptr;
    QTabWidget* upperTabs_ = nullptr;
    QTabWidget* lowerTabs_ = nullptr;
    QSplitter* mainSplitter_ = nullptr;
    QSplitter* plotSplitter_ = nullptr;
    TimeResponsePlot* timePlot_ = nullptr;
    StepPlot* stepPlot_ = nullptr;
    RootLocusPlot* rootLocusPlot_ = nullptr;
    PoleZeroPlot* poleZeroPlot_ = nullptr;
    ParameterLocusPlot* parameterLocusPlot_ = nullptr;
    BodePlot* bodePlot_ = nullptr;
    NyquistPlot* nyquistPlot_ = nullptr;
    VibrationPlot* vibrationPlot_ = nullptr;
    QComboBox* sweptParameter_ = nullptr;
    PpEditor* ppEditor_ = nullptr;
    std::vector<MethodEditor*> methodEditors_; ///< of the registered methods
    QStackedWidget* methodPages_ = nullptr;
    ContourPlot* contourPlot_ = nullptr;
    StaleVeil* timeVeil_ = nullptr;
    StaleVeil* contourVeil_ = nullptr;
    MetricsPanel* metrics_ = nullptr;
    EquationsPanel* equations_ = nullptr;
    QLabel* status_ = nullptr;
    double lastRefreshMs_ = 0.0;
    QElapsedTimer changeTimer_; ///< started by a design change, read when the views are drawn
    std::vector<PresenterView*> views_;
    TimeResponseView* timeView_ = nullptr;
    PoleZeroView* poleZeroView_ = nullptr;
    ParameterLocusView* parameterLocusView_ = nullptr;
    SessionFileController* files_ = nullptr;
    ReportExporter* report_ = nullptr;
    RecoveryStore* recovery_ = nullptr;
    QMenu* overlayMenu_ = nullptr;
    void updateTitle();
    void rebuildOverlayMenu();
    /// The left panel of controls, in a scroll area.
    QScrollArea* buildControlPanel();
    /// The plots, each in its tab: root locus, parameter locus, pole-zero, Bode and Nyquist
    /// above (with the swept parameter's box); time, step, contour (with its magnification),
    /// design space and robustness below.
    void buildPlots();
    void buildUpperTabs();
    void buildLowerTabs();
    /// The right panel: the metrics and the equations.
    QWidget* buildSidePanel();
    /// The views that observe the presenter, one per plot and panel.
    void buildViews();
    /// The controls that belong to one tab, shown with it.
    void showTabControls();
    /// The status bar's verdict per axis and the time the views took.
    void updateStatus();
};

} // namespace xyt::ui
