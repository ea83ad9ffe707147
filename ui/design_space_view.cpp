// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/design_space_view.h"
#include "ui/plots/number_text.h"

#include "core/model/errors.h"
#include "core/session/pid_feedforward_method.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/trajectory.h"
#include "ui/panels/stale_veil.h"
#include "ui/panels/status_strip.h"
#include "ui/plots/design_space_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QShowEvent>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace xyt::ui {

Specification initialSpecification(const Session& session) {
    Specification spec = session.spec; // the session's limits; its actuator limit is umax
    spec.umaxVolts = session.umaxVolts;
    return spec;
}

namespace {

/// Lowers the calling thread's scheduling priority (nice +10 on Linux, where nice is per
/// thread): the study's workers then yield the cores to the GUI thread whenever it has work,
/// so a live map never delays a slider's repaint.
void lowerThisThreadPriority() {
#ifdef __linux__
    (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

const SweepCriterion kCriteria[] = {SweepCriterion::Itae,      SweepCriterion::MaxError,
                                    SweepCriterion::Rmse,      SweepCriterion::MaxU,
                                    SweepCriterion::Settle,    SweepCriterion::PhaseMargin,
                                    SweepCriterion::GainMargin};

QDoubleSpinBox* numberBox(double value, double minimum, double maximum, int decimals,
                          const QString& suffix) {
    auto* box = new QDoubleSpinBox;
    box->setRange(minimum, maximum);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    box->setMinimumWidth(64);
    return box;
}

QSpinBox* countBox(int value) {
    auto* box = new QSpinBox;
    // The heat map needs at least two values per axis to size its cells.
    box->setRange(2, SweepAxis::kMaxCount);
    box->setValue(value);
    box->setPrefix(QStringLiteral("N "));
    return box;
}

QComboBox* criterionCombo() {
    auto* box = new QComboBox;
    for (SweepCriterion c : kCriteria)
        box->addItem(metricLabel(c), static_cast<int>(c));
    return box;
}

SweepCriterion selected(const QComboBox* box) {
    return static_cast<SweepCriterion>(box->currentData().toInt());
}

/// The criteria a design fails, for the readout.
QStringList failures(const DesignPoint& p, const Specification& spec) {
    QStringList out;
    if (!p.computed)
        return {QObject::tr("not computed (the study was cancelled)")};
    if (!p.stable)
        out << QObject::tr("unstable closed loop");
    if (!p.metricsFinite)
        out << QObject::tr("the run diverged");
    if (p.stable && !p.check.settlingTime)
        out << QObject::tr("settling %1 s > %2 s")
                   .arg(significant(p.step.settlingTimeSeconds, 4))
                   .arg(significant(spec.maxSettlingTimeSeconds, 4));
    if (p.stable && !p.check.overshoot)
        out << QObject::tr("overshoot %1 % > %2 %")
                   .arg(significant(p.step.overshootPct, 4))
                   .arg(significant(spec.maxOvershootPct, 4));
    if (p.metricsFinite && !p.check.noSaturation)
        out << (p.tracking.saturated
                    ? QObject::tr("|u| saturates at %1 V").arg(significant(spec.umaxVolts, 4))
                    : QObject::tr("|u| %1 V > %2 V")
                          .arg(significant(p.tracking.maxAbsU, 4))
                          .arg(significant(spec.umaxVolts, 4)));
    if (p.stable && !p.check.phaseMargin)
        out << QObject::tr("phase margin %1° < %2°")
                   .arg(significant(p.phaseMarginDeg, 4))
                   .arg(significant(spec.minPhaseMarginDeg, 4));
    if (p.stable && !p.check.gainMargin)
        out << QObject::tr("gain margin %1 dB < %2 dB")
                   .arg(significant(p.gainMarginDb, 4))
                   .arg(significant(spec.minGainMarginDb, 4));
    if (p.metricsFinite && !p.check.trackingError)
        out << QObject::tr("max error %1 % > %2 %")
                   .arg(significant(p.tracking.maxAbsErrorPct, 4))
                   .arg(significant(spec.maxErrorPct, 4));
    return out;
}

QString describePoint(const DesignPoint& p, const Specification& spec, SweepCriterion metric) {
    const QString value = std::isfinite(criterionMetric(p, metric))
                              ? significant(criterionMetric(p, metric), 4)
                              : QObject::tr("—");
    QString text = QObject::tr("ωn = %1 rad/s   kp = %2   %3 = %4   feasible: %5")
                       .arg(significant(p.wn, 4))
                       .arg(significant(p.kp, 4))
                       .arg(metricLabel(metric))
                       .arg(value)
                       .arg(p.feasible ? QObject::tr("yes") : QObject::tr("no"));
    if (!p.feasible)
        text += QObject::tr("\nfails: %1").arg(failures(p, spec).join(QStringLiteral("; ")));
    return text;
}

} // namespace

namespace {

/// What the map's colours and shades mean (the colour scale is the metric's, whatever its sense).
QString shadesText() {
    return QObject::tr(
        "colour: the metric, by the scale at the right (yellow is the high end, better only for "
        "the "
        "margins) · unveiled and outlined: feasible · veiled: infeasible · grey: unstable or "
        "diverged · light grey: not computed (cancelled)");
}

} // namespace

DesignSpaceView::DesignSpaceView(TuningSession* session, QWidget* parent)
    : QWidget(parent), session_(session),
      runner_(this, {[this](double fraction) { showProgress(progress_, fraction); },
                     [this](Outcome&& outcome, const ResultStamp& stamp) {
                         onFinished(std::move(outcome), stamp);
                     },
                     [this](const QString& error, const ResultStamp&) {
                         cancel_->setEnabled(false);
                         progress_->setValue(0);
                         setStatus(tr("The study failed: %1").arg(error), true);
                     },
                     exceptionText}) {
    // The steps make the widgets in their tab order.
    const Specification spec = initialSpecification(session_->session());
    lastUmaxVolts_ = session_->session().umaxVolts;

    QGroupBox* grid = buildGrid();
    QGroupBox* choice = buildChoice();
    QGroupBox* specBox = buildSpecification(spec);
    QHBoxLayout* actions = buildActions();
    buildControlPanel({grid, choice, specBox});
    QHBoxLayout* texts = buildMapAndTexts();
    auto* right = new QVBoxLayout;
    right->addWidget(plot_, 1);
    auto* middle = new QHBoxLayout;
    middle->addWidget(controlPanel_);
    connect(settings_, &QToolButton::toggled, controlPanel_, &QWidget::setVisible);
    middle->addLayout(right, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(actions);
    layout->addLayout(middle, 1);
    layout->addLayout(texts);
    connectControls();
    updateCurrentDesign();
}

QGroupBox* DesignSpaceView::buildGrid() {
    wnMin_ = numberBox(0.2, 1e-3, 1e4, 3, QString());
    wnMax_ = numberBox(20.0, 1e-3, 1e4, 3, QString());
    wnCount_ = countBox(60);
    kpMin_ = numberBox(3.0, 1e-3, 1e7, 3, QString());
    kpMax_ = numberBox(3000.0, 1e-3, 1e7, 3, QString());
    kpCount_ = countBox(60);
    // Range bounds are typed; the arrows only crowd the row.
    for (QDoubleSpinBox* box : {wnMin_, wnMax_, kpMin_, kpMax_})
        box->setButtonSymbols(QAbstractSpinBox::NoButtons);
    logGrid_ = new QCheckBox(tr("logarithmic spacing"));
    wnMin_->setToolTip(tr("Smallest ωn (rad/s) of the grid: the reference model's natural "
                          "frequency of the first row of designs"));
    wnMax_->setToolTip(tr("Largest ωn (rad/s) of the grid"));
    wnCount_->setToolTip(tr("Number of ωn values of the grid (rows); each cell is one design run "
                            "on the session's trajectory"));
    kpMin_->setToolTip(tr("Smallest proportional gain kp (V per model unit) of the grid"));
    kpMax_->setToolTip(tr("Largest proportional gain kp (V per model unit) of the grid"));
    kpCount_->setToolTip(tr("Number of kp values of the grid (columns)"));
    logGrid_->setToolTip(tr("Space the ωn and kp values evenly on a logarithmic scale (else "
                            "linearly between the bounds)"));
    logGrid_->setChecked(true);
    auto* grid = new QGroupBox(tr("Grid"));
    auto* gridForm = new QFormLayout(grid);
    gridForm->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fits a narrow column
    const auto rangeRow = [](QWidget* a, QWidget* b, QWidget* c) {
        auto* row = new QHBoxLayout;
        row->addWidget(a);
        row->addWidget(new QLabel(QStringLiteral("–")));
        row->addWidget(b);
        row->addWidget(c);
        return row;
    };
    gridForm->addRow(tr("ωn (rad/s)"), rangeRow(wnMin_, wnMax_, wnCount_));
    gridForm->addRow(tr("kp"), rangeRow(kpMin_, kpMax_, kpCount_));
    gridForm->addRow(logGrid_);
    return grid;
}

QGroupBox* DesignSpaceView::buildChoice() {
    criterion_ = criterionCombo();
    metric_ = criterionCombo();
    logColor_ = new QCheckBox(tr("logarithmic colour scale"));
    criterion_->setToolTip(tr("The figure that picks the best feasible design: minimized (ITAE, "
                              "max |e|, RMSE, max |u|, settle time) or maximized (the margins)"));
    metric_->setToolTip(tr("The figure the heat map's colours show for each design of the grid"));
    logColor_->setToolTip(tr("Colour the heat map by the logarithm of the figure (its values "
                             "often span decades)"));
    logColor_->setChecked(true);
    auto* choice = new QGroupBox(tr("Choice"));
    auto* choiceForm = new QFormLayout(choice);
    choiceForm->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fits a narrow column
    choiceForm->addRow(tr("Best design (min; max for margins)"), criterion_);
    choiceForm->addRow(tr("Heat map shows"), metric_);
    choiceForm->addRow(logColor_);
    return choice;
}

QGroupBox* DesignSpaceView::buildSpecification(const Specification& spec) {
    settling_ = numberBox(spec.maxSettlingTimeSeconds, 0.001, 1e6, 3, tr(" s"));
    overshoot_ = numberBox(spec.maxOvershootPct, 0.0, 1000.0, 3, tr(" %"));
    error_ = numberBox(spec.maxErrorPct, 0.001, 1000.0, 3, tr(" %"));
    umax_ = numberBox(spec.umaxVolts, 0.001, 1e4, 3, tr(" V"));
    phaseMargin_ = numberBox(spec.minPhaseMarginDeg, 0.0, 180.0, 2, tr("°"));
    gainMargin_ = numberBox(spec.minGainMarginDb, 0.0, 1000.0, 2, tr(" dB"));
    settling_->setToolTip(tr("Maximum settling time (s, 2 % band) of the closed loop's unit "
                             "step"));
    overshoot_->setToolTip(tr("Maximum overshoot (%) of the closed loop's unit step"));
    error_->setToolTip(tr("Maximum tracking error max |e| as a percentage of the travel"));
    umax_->setToolTip(tr("Actuator limit umax (V): a design whose run asks for more is "
                         "infeasible; the session's |u| limit"));
    phaseMargin_->setToolTip(tr("Minimum phase margin (°) of the loop, 180° + arg L(jωc); 0: "
                                "none"));
    gainMargin_->setToolTip(tr("Minimum gain margin (dB) of the loop, −20 log10 |L(jω180)|; 0: "
                               "none"));
    auto* specBox = new QGroupBox(tr("Specification"));
    auto* specForm = new QFormLayout(specBox);
    specForm->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above: fits a narrow column
    specForm->addRow(tr("settling time ≤"), settling_);
    specForm->addRow(tr("step overshoot ≤"), overshoot_);
    specForm->addRow(tr("max tracking error ≤"), error_);
    specForm->addRow(tr("|u| ≤ (actuator limit)"), umax_);
    specForm->addRow(tr("phase margin ≥ (0 = none)"), phaseMargin_);
    specForm->addRow(tr("gain margin ≥ (0 = none)"), gainMargin_);

    auto* shared =
        new QLabel(tr("<i>The session's specification, shared with the metrics panel.</i>"));
    shared->setWordWrap(true); // the column is narrow: never let the note widen it
    specForm->addRow(shared);
    // One specification: the boxes edit the session's (an undoable step), and show it.
    for (QDoubleSpinBox* box : {settling_, overshoot_, error_, umax_, phaseMargin_, gainMargin_})
        connect(box, &QDoubleSpinBox::editingFinished, this, &DesignSpaceView::applySpecification);
    return specBox;
}

QHBoxLayout* DesignSpaceView::buildActions() {
    run_ = new QPushButton(tr("Run"));
    run_->setDefault(true);
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setEnabled(false);
    run_->setToolTip(tr("Run the study: every design of the grid on the session's trajectory at "
                        "its dt, judged against the specification"));
    cancel_->setToolTip(tr("Stop the study; the designs computed so far are shown"));
    progress_ = new QProgressBar;
    progress_->setRange(0, 100);
    progress_->setValue(0);
    status_ = new QLabel(tr("Set the grid and press Run to study the current axis."));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Run, Cancel and the progress stay at the top of the tab, outside the scrolling controls:
    // in reach at 1366x768, and never moved by the text of a result.
    relax_ = new QPushButton(tr("Relax the limits"));
    relax_->setToolTip(tr("Set the specification to the smallest limits the least-violating design "
                          "(▲) meets (an undoable step)"));
    relax_->setVisible(false);
    connect(relax_, &QPushButton::clicked, this, &DesignSpaceView::relaxSpecification);
    live_ = new QCheckBox(tr("Live"));
    live_->setChecked(true);
    live_->setToolTip(tr("Recompute the map when the plant, the trajectory or the limits change: a "
                         "coarse preview at once, the full study when the inputs rest"));
    rest_ = new QTimer(this);
    rest_->setSingleShot(true);
    rest_->setInterval(kLiveRestMs);
    connect(rest_, &QTimer::timeout, this, &DesignSpaceView::onRest);
    connect(live_, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            scheduleLive();
        else
            rest_->stop();
    });
    // The controls give the map their width when hidden: hidden by default while the view is
    // narrow (the lower tabs at 1366x768 left the map 80 px wide), shown or hidden for good
    // once the user chooses.
    settings_ = new QToolButton;
    settings_->setText(tr("Settings"));
    settings_->setCheckable(true);
    settings_->setChecked(true);
    settings_->setToolTip(tr("Show or hide the grid, the choice of the best design and the "
                             "specification (hidden, the map takes the whole width)"));
    connect(settings_, &QToolButton::clicked, this, [this] { settingsChosen_ = true; });
    auto* actions = new QHBoxLayout;
    actions->addWidget(settings_);
    actions->addWidget(live_);
    actions->addWidget(run_);
    actions->addWidget(cancel_);
    actions->addWidget(relax_);
    actions->addWidget(progress_, 1);
    return actions;
}

void DesignSpaceView::buildControlPanel(std::initializer_list<QGroupBox*> groups) {
    auto* controls = new QVBoxLayout;
    for (QGroupBox* group : groups)
        controls->addWidget(group);
    controls->addStretch(1);
    auto* controlContent = new QWidget;
    controlContent->setLayout(controls);
    // In a scroll area, so the view fits a 1366x768 window: the controls scroll, the map stays.
    controlPanel_ = new QScrollArea;
    controlPanel_->setWidget(controlContent);
    controlPanel_->setWidgetResizable(true);
    controlPanel_->setFrameShape(QFrame::NoFrame);
    controlPanel_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // As wide as the controls need beside the vertical scroll bar (they were clipped on the
    // right: "N 6" for "N 60"), and never narrower than 250 px.
    const int scrollBar = controlPanel_->style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    controlPanel_->setFixedWidth(
        std::max(250, controlContent->minimumSizeHint().width() + scrollBar + 4));
    // The wheel over a field that has no focus scrolls the panel; it changes a value only in the
    // field being edited (a scroll through the panel must not retune the study).
    for (QAbstractSpinBox* box : controlContent->findChildren<QAbstractSpinBox*>()) {
        box->setFocusPolicy(Qt::StrongFocus);
        box->installEventFilter(this);
    }
    for (QComboBox* box : controlContent->findChildren<QComboBox*>()) {
        box->setFocusPolicy(Qt::StrongFocus);
        box->installEventFilter(this);
    }
}

QHBoxLayout* DesignSpaceView::buildMapAndTexts() {
    plot_ = new DesignSpacePlot;
    // The colour is the metric (its scale beside the map: yellow is a high value, not a good
    // one); feasibility is the veil and the outline.
    readout_ =
        new QLabel(tr("Hover a cell for its figures; click it to load that design. Colour: the "
                      "metric (scale at the right) · unveiled, outlined: feasible · veiled: "
                      "infeasible · grey: unstable or diverged."));
    readout_->setWordWrap(true);
    readout_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    readout_->setToolTip(shadesText());
    // Status and readout share one strip of fixed height under the map (four lines,
    // side by side): a longer text never pushes the map or the buttons.
    // A longer text scrolls in its strip (it was cut at the fourth line).
    const int lines = 4 * status_->fontMetrics().lineSpacing() + 6;
    auto* texts = new QHBoxLayout;
    for (QLabel* label : {status_, readout_}) {
        label->setAlignment(Qt::AlignTop | Qt::AlignLeft);
        auto* strip = new QScrollArea;
        strip->setWidget(label);
        strip->setWidgetResizable(true);
        strip->setFrameShape(QFrame::NoFrame);
        strip->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        strip->setFixedHeight(lines);
        strip->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        texts->addWidget(strip, label == status_ ? 3 : 2);
    }
    // What the cell shades mean, one hover away on the map (a label here cost the map height).
    plot_->setToolTip(shadesText());
    veil_ = new StaleVeil(plot_);
    return texts;
}

void DesignSpaceView::connectControls() {
    connect(run_, &QPushButton::clicked, this, &DesignSpaceView::run);
    connect(cancel_, &QPushButton::clicked, this, &DesignSpaceView::cancel);
    const auto redraw = [this] { plot_->setMetric(selected(metric_), logColor_->isChecked()); };
    connect(metric_, &QComboBox::currentIndexChanged, this, [this, redraw] {
        // ITAE spans decades over the grid; the other figures rarely do.
        logColor_->setChecked(selected(metric_) == SweepCriterion::Itae);
        redraw();
    });
    connect(logColor_, &QCheckBox::toggled, this, redraw);
    connect(plot_, &DesignSpacePlot::cellHovered, this, &DesignSpaceView::showHover);
    connect(plot_, &DesignSpacePlot::cellClicked, this, &DesignSpaceView::loadCell);
    connect(session_, &TuningSession::designChanged, this, &DesignSpaceView::updateCurrentDesign);
    connect(session_, &TuningSession::currentAxisChanged, this,
            &DesignSpaceView::updateCurrentDesign);
    // A new grid or criterion is a new study: the live map follows it too.
    for (QDoubleSpinBox* box : {wnMin_, wnMax_, kpMin_, kpMax_})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { scheduleLive(true); });
    for (QSpinBox* box : {wnCount_, kpCount_})
        connect(box, &QSpinBox::valueChanged, this, [this] { scheduleLive(true); });
    connect(logGrid_, &QCheckBox::toggled, this, [this] { scheduleLive(true); });
    connect(criterion_, &QComboBox::currentIndexChanged, this, [this] { scheduleLive(true); });
}

void DesignSpaceView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (!settingsChosen_)
        settings_->setChecked(width() >= kWideEnoughForSettings);
}

void DesignSpaceView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    scheduleLive();
}

namespace {

/// Whether the map can study axis @p axis of @p s: a Guillemin-Truxal axis, or a PID +
/// feedforward axis without D (its PI over the same (wn, kp) family, sessionDesignProblem).
bool studiable(const Session& s, int axis) {
    const AxisSettings& a = s.axes.at(static_cast<std::size_t>(axis));
    if (a.method == DesignMethod::GuilleminTruxal)
        return true;
    if (a.method != DesignMethod::PidFeedforward)
        return false;
    const auto d = a.parameters.find("d");
    return d == a.parameters.end() || d->second == 0.0;
}

/// The (wn, kp) of an axis' current design as the map places it: a PID's PI as P = kp u,
/// I = ki u with ki = wn^4 / k0 (Braga et al. Eq. 11, 16); unset when there is none.
std::optional<std::pair<double, double>> mapCoordinates(const TuningSession& session, int axis) {
    const AxisSettings& a = session.session().axes.at(static_cast<std::size_t>(axis));
    if (a.method == DesignMethod::GuilleminTruxal)
        return std::make_pair(a.gt.omegaNRadPerSec, a.gt.kp);
    const AxisEvaluation& e = session.axisEvaluation(axis);
    if (a.method != DesignMethod::PidFeedforward || !e.methodDesign)
        return std::nullopt;
    const PidFeedforwardDesign& d = pidFeedforwardDesign(e);
    const double ki = d.gains.i / d.unit;
    if (!(ki > 0.0) || !(a.gt.plant.k0 > 0.0))
        return std::nullopt;
    return std::make_pair(std::pow(ki * a.gt.plant.k0, 0.25), d.gains.p / d.unit);
}

} // namespace

void DesignSpaceView::scheduleLive(bool force) {
    if (!live_ || !live_->isChecked() || !isVisible())
        return;
    const Session& s = session_->session();
    const int axis = session_->currentAxis();
    if (!studiable(s, axis))
        return; // the status says so when a study is asked for
    // What is shown, or being computed: a running study's settings, else the last result's.
    const bool running = isRunning();
    const bool upToDate =
        running ? session_->isCurrent(runner_.runningStamp()) && runner_.runningStamp().axis == axis
                : resultIsCurrent();
    if (upToDate && !force)
        return;
    startStudy(StudyKind::Preview);
    rest_->start();
}

void DesignSpaceView::onRest() {
    if (!live_->isChecked() || !isVisible() || isRunning())
        return; // a preview under way starts the full study when it finishes
    if (resultIsCurrent() && resultIsPreview_ && result_->status == SweepStatus::Completed)
        startStudy(StudyKind::Full);
}

DesignSpaceView::~DesignSpaceView() = default; // the runner cancels and waits for its study

QString DesignSpaceView::statusText() const {
    return status_->text();
}

bool DesignSpaceView::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Wheel) {
        auto* field = qobject_cast<QWidget*>(watched);
        if (field && !field->hasFocus()) {
            QCoreApplication::sendEvent(controlPanel_->verticalScrollBar(), event);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}
QString DesignSpaceView::readoutText() const {
    return readout_->text();
}

void DesignSpaceView::setStatus(const QString& text, bool isError) {
    setStatusText(status_, text, isError);
}

void DesignSpaceView::run() {
    startStudy(StudyKind::Full);
}

void DesignSpaceView::startStudy(StudyKind kind) {
    runner_.discard(); // a study of other settings: its map would not be shown
    const int axis = session_->currentAxis();
    const Session& s = session_->session();
    const AxisSettings& settings = s.axes.at(static_cast<std::size_t>(axis));
    if (!studiable(s, axis)) {
        setStatus(settings.method == DesignMethod::PidFeedforward
                      ? tr("The design space maps a PI with its feedforward; axis %1 has D: set "
                           "D to 0 to map it.")
                            .arg(axisName(s, axis))
                      : tr("The design space applies to Guillemin–Truxal and PI + feedforward "
                           "axes; axis %1 uses %2.")
                            .arg(axisName(s, axis), methodDisplayName(settings.method)),
                  true);
        return;
    }
    const bool preview = kind == StudyKind::Preview;
    // The preview is the live map: at most kLivePreviewCount designs a side, coarse in time
    // (kLivePreviewFidelity); the full study uses the grid and the session's dt.
    const int wnCount =
        preview ? std::min(wnCount_->value(), kLivePreviewCount) : wnCount_->value();
    const int kpCount =
        preview ? std::min(kpCount_->value(), kLivePreviewCount) : kpCount_->value();
    DesignProblem problem;
    SweepAxis wnAxis{wnMin_->value(), wnMax_->value(), wnCount, logGrid_->isChecked()};
    SweepAxis kpAxis{kpMin_->value(), kpMax_->value(), kpCount, logGrid_->isChecked()};
    try {
        wnAxis.validate("ωn range");
        kpAxis.validate("kp range");
        problem = sessionDesignProblem(s, axis, preview ? kLivePreviewFidelity : StudyFidelity{});
    } catch (const InvalidInput& e) {
        setStatus(tr("Cannot run: %1").arg(exceptionText(e)), true);
        return;
    }
    SweepOptions options;
    options.criterion = selected(criterion_);
    options.refine = !preview; // the preview shows the map; the best design is the full study's
    options.onWorkerStart = lowerThisThreadPriority;

    runningKind_ = kind;
    const bool logGrid = logGrid_->isChecked();
    // The work holds copies of its inputs only: it may outlive a change of the design.
    runner_.start(
        session_->stamp(axis, ResultScope::AxisStudy),
        [problem, wnAxis, kpAxis, options, kind, logGrid](const JobProgress& progress) mutable {
            lowerThisThreadPriority();
            options.progress = progress;
            const auto start = std::chrono::steady_clock::now();
            Outcome outcome{sweepDesignSpace(problem, wnAxis, kpAxis, options), problem, kind,
                            logGrid, 0.0};
            outcome.elapsedMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            return outcome;
        });
    progress_->setValue(0);
    cancel_->setEnabled(true);
    if (preview)
        setStatus(tr("Live preview of axis %1: %2 × %3 designs…")
                      .arg(axisName(s, axis))
                      .arg(wnCount)
                      .arg(kpCount));
    else
        setStatus(tr("Studying %1 × %2 designs of axis %3…")
                      .arg(wnAxis.count)
                      .arg(kpAxis.count)
                      .arg(axisName(s, axis)));
}

void DesignSpaceView::cancel() {
    if (!runner_.isRunning())
        return;
    runner_.cancel();
    cancel_->setEnabled(false);
    setStatus(tr("Cancelling…"));
}

void DesignSpaceView::onFinished(Outcome&& outcome, const ResultStamp& stamp) {
    cancel_->setEnabled(false);
    const StudyKind kind = outcome.kind;
    result_ = std::move(outcome.result);
    resultIsPreview_ = kind == StudyKind::Preview;
    lastElapsedMs_ = outcome.elapsedMs;
    problem_ = std::move(outcome.problem);
    stamp_ = stamp;
    staleStatus_ = false;
    studiedLogGrid_ = outcome.logGrid;
    plot_->showResult(
        *result_, studiedLogGrid_, selected(metric_), logColor_->isChecked(),
        tr("%1, axis %2").arg(metricLabel(selected(metric_)), axisName(stamp.session, stamp.axis)));
    showOutcome();
    updateCurrentDesign(); // judged by the session's limits; veiled if it changed meanwhile
    emit studyFinished(kind);
    // The full study follows a completed preview once the inputs have rested.
    if (resultIsPreview_ && result_->status == SweepStatus::Completed && live_->isChecked() &&
        !rest_->isActive() && !isRunning() && resultIsCurrent())
        startStudy(StudyKind::Full);
}

void DesignSpaceView::showOutcome() {
    if (resultIsPreview_ && result_->status == SweepStatus::Completed) {
        showOutcomeText();
        setStatus(
            tr("Live preview (%1 × %2 designs, dt %3 s, %4 ms): the full study follows when the "
               "inputs rest.\n")
                    .arg(result_->wnValues.size())
                    .arg(result_->kpValues.size())
                    .arg(significant(problem_->dtSeconds, 3))
                    .arg(qRound(lastElapsedMs_)) +
                status_->text(),
            !status_->styleSheet().isEmpty());
        return;
    }
    showOutcomeText();
}

void DesignSpaceView::showOutcomeText() {
    const DesignSweepResult& r = *result_;
    const int total = static_cast<int>(r.points.size());
    const QString crit = metricLabel(r.criterion);
    if (r.status == SweepStatus::Cancelled) {
        progress_->setValue(total > 0 ? 100 * r.computedCount / total : 0);
        setStatus(tr("Cancelled: %1 of %2 designs computed, %3 feasible.")
                      .arg(r.computedCount)
                      .arg(total)
                      .arg(r.feasibleCount));
        return;
    }
    progress_->setValue(100);
    QString text = tr("Done: %1 designs, %2 stable, %3 feasible.")
                       .arg(total)
                       .arg(r.stableCount)
                       .arg(r.feasibleCount);
    diagnosis_ = diagnoseSweep(r, problem_ ? problem_->spec : session_->session().spec);
    plot_->setLeastViolating(
        diagnosis_->leastViolating && !r.bestIndex
            ? std::optional<std::pair<double, double>>{{r.points[*diagnosis_->leastViolating].wn,
                                                        r.points[*diagnosis_->leastViolating].kp}}
            : std::nullopt);
    relax_->setVisible(!r.bestIndex && diagnosis_->relaxed.has_value());
    for (const auto& w : diagnosis_->warnings)
        if (r.bestIndex || diagnosis_->noneFeasible)
            text += QStringLiteral("\n") + diagnosticText(w);
    if (r.bestIndex) {
        const DesignPoint& b = r.points[*r.bestIndex];
        text += tr("\nBest on the grid (★): ωn = %1 rad/s, kp = %2, %3 = %4.")
                    .arg(significant(b.wn, 4), significant(b.kp, 4), crit,
                         significant(criterionMetric(b, r.criterion), 4));
        if (r.refined && r.refined->improved) {
            const DesignPoint& p = r.refined->point;
            text += tr("\nRefined (◆): ωn = %1 rad/s, kp = %2, %3 = %4.")
                        .arg(significant(p.wn, 4), significant(p.kp, 4), crit,
                             significant(criterionMetric(p, r.criterion), 4));
        }
        text += tr("\nClick a cell to load its design.");
        setStatus(text, diagnosis_->onEdge());
        return;
    }
    // No feasible design: the core's diagnosis says which limit is to blame, the best value
    // the grid reaches for it, and the least-violating design (marked ▲, offered to relax to).
    if (diagnosis_->failingEverywhere.size() == 1 &&
        diagnosis_->failingEverywhere.front().criterion == SpecCriterion::Overshoot)
        text += tr("\nEvery GT design overshoots (its reference model is type 2); relax the "
                   "overshoot limit.");
    setStatus(text, true);
}

void DesignSpaceView::relaxSpecification() {
    if (!diagnosis_ || !diagnosis_->relaxed)
        return;
    Specification relaxed = *diagnosis_->relaxed;
    relaxed.umaxVolts = session_->session().spec.umaxVolts;
    session_->setSpecification(relaxed);
    relax_->setVisible(false);
}

void DesignSpaceView::applySpecification() {
    Specification spec = session_->session().spec;
    spec.maxSettlingTimeSeconds = settling_->value();
    spec.maxOvershootPct = overshoot_->value();
    spec.maxErrorPct = error_->value();
    spec.minPhaseMarginDeg = phaseMargin_->value();
    spec.minGainMarginDb = gainMargin_->value();
    session_->setSpecificationAndLimit(spec, umax_->value());
}

void DesignSpaceView::updateCurrentDesign() {
    const Session& s = session_->session();
    {
        const QSignalBlocker b1(settling_), b2(overshoot_), b3(error_), b4(umax_), b5(phaseMargin_),
            b6(gainMargin_);
        settling_->setValue(s.spec.maxSettlingTimeSeconds);
        overshoot_->setValue(s.spec.maxOvershootPct);
        error_->setValue(s.spec.maxErrorPct);
        umax_->setValue(s.umaxVolts);
        phaseMargin_->setValue(s.spec.minPhaseMarginDeg);
        gainMargin_->setValue(s.spec.minGainMarginDb);
    }
    lastUmaxVolts_ = s.umaxVolts;
    // A study stays judged by the session's specification: when only its limits changed (the
    // runs did not), every design is judged again (exact; the refinement is dropped).
    if (problem_ && resultIsCurrent()) {
        Specification spec = s.spec;
        spec.umaxVolts = s.umaxVolts;
        if (!(spec == problem_->spec)) {
            try {
                rejudgeDesignSpace(*result_, spec);
                problem_->spec = spec;
                plot_->showResult(
                    *result_, studiedLogGrid_, selected(metric_), logColor_->isChecked(),
                    tr("%1, axis %2")
                        .arg(metricLabel(selected(metric_)), axisName(s, stamp_->axis)));
                readout_->clear(); // it described a cell as judged before
                showOutcome();
            } catch (const InvalidInput& e) {
                setStatus(tr("Cannot judge the study: %1").arg(exceptionText(e)), true);
            }
        }
    }
    if (const auto at = mapCoordinates(*session_, studiedAxis()))
        plot_->setCurrentDesign(at->first, at->second);
    showFreshness();
    scheduleLive();
}

bool DesignSpaceView::resultIsCurrent() const {
    return result_ && stamp_ && session_->isCurrent(*stamp_) &&
           stamp_->axis == session_->currentAxis();
}

void DesignSpaceView::showFreshness() {
    if (!result_ || !stamp_)
        return;
    if (resultIsCurrent()) {
        veil_->lift();
        if (staleStatus_ && !isRunning())
            showOutcome(); // back to the studied settings (an undo)
        staleStatus_ = false;
        return;
    }
    readout_->clear();
    const QString what = TuningSession::describe(*stamp_);
    const Session& s = session_->session();
    const int axis = session_->currentAxis();
    QString why;
    if (stamp_->axis != axis)
        why = tr("This tab shows axis %1.").arg(axisName(s, axis));
    else if (!studiable(s, axis))
        why = tr("Axis %1 now uses %2: the map applies to Guillemin–Truxal and PI + feedforward "
                 "axes.")
                  .arg(axisName(s, axis),
                       methodDisplayName(s.axes.at(static_cast<std::size_t>(axis)).method));
    else
        why = tr("The plant, the trajectory or the limits the runs depend on have changed since.");
    const QString next = !studiable(s, axis) ? QString()
                         : live_->isChecked() && isVisible()
                             ? tr("The live map of the current design follows.")
                             : tr("Press Run to study the current design.");
    veil_->veil(tr("Map computed for %1. %2 %3").arg(what, why, next).trimmed());
    if (!isRunning()) {
        setStatus(tr("The map shown is not of the session's study (computed for %1). %2")
                      .arg(what, next)
                      .trimmed());
        staleStatus_ = true;
    }
}

void DesignSpaceView::showHover(std::optional<std::pair<std::size_t, std::size_t>> cell) {
    if (!cell || !resultIsCurrent())
        return;
    readout_->setText(
        describePoint(result_->at(cell->first, cell->second), problem_->spec, selected(metric_)));
}

void DesignSpaceView::loadCell(std::size_t iWn, std::size_t iKp) {
    if (!result_)
        return;
    if (!resultIsCurrent())
        return; // a cell of another study's map (veiled: no click reaches it)
    const AxisSettings& axis = session_->session().axes.at(static_cast<std::size_t>(stamp_->axis));
    if (axis.method == DesignMethod::PidFeedforward) {
        // The cell's PI in LinuxCNC's units; the feedforward and the limits stay.
        const DesignPoint& point = result_->at(iWn, iKp);
        AxisSettings next = axis;
        next.parameters["p"] = point.kp * axis.gt.modelUnitsPerPositionUnit;
        next.parameters["i"] = point.ki * axis.gt.modelUnitsPerPositionUnit;
        session_->setAxis(stamp_->axis, next, tr("Load design from the design space"));
        return;
    }
    GtAxisSettings gt = axis.gt;
    gt.omegaNRadPerSec = result_->wnValues.at(iWn);
    gt.kp = result_->kpValues.at(iKp);
    session_->setGt(stamp_->axis, gt, tr("Load design from the design space"));
}

} // namespace xyt::ui
