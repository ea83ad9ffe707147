// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/robustness_view.h"

#include "core/model/errors.h"
#include "core/session/design_method_module.h"
#include "core/session/robustness_problem.h"
#include "ui/panels/stale_veil.h"
#include "ui/panels/status_strip.h"
#include "ui/plots/contour_band_plot.h"
#include "ui/plots/envelope_plot.h"
#include "ui/plots/histogram_plot.h"
#include "ui/plots/sensitivity_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

namespace xyt::ui {

namespace {

QString figure(double v, int digits = 4) {
    return std::isfinite(v) ? QString::number(v, 'g', digits) : QStringLiteral("n/a");
}

QString parameterList(const std::vector<std::string>& names, const std::vector<double>& values) {
    QStringList parts;
    for (std::size_t i = 0; i < names.size(); ++i)
        parts << QStringLiteral("%1 = %2").arg(QString::fromStdString(names[i]),
                                               figure(values[i], 6));
    return parts.join(QStringLiteral(", "));
}

} // namespace

RobustnessView::RobustnessView(TuningSession* session, QWidget* parent)
    : QWidget(parent), session_(session),
      runner_(this, {[this](double fraction) { showProgress(progress_, fraction); },
                     [this](Outcome&& outcome, const ResultStamp& stamp) {
                         onFinished(std::move(outcome), stamp);
                     },
                     [this](const QString& error, const ResultStamp&) {
                         cancel_->setEnabled(false);
                         setStatus(tr("The analysis failed: %1").arg(error), true);
                     },
                     exceptionText}) {
    // The steps make the widgets in their tab order.
    QGroupBox* rangeBox = buildRangeBox();
    QHBoxLayout* options = buildOptions();
    QHBoxLayout* actions = buildActions();
    QVBoxLayout* right = buildPlots();
    QGroupBox* showBox = buildShowBox();
    auto* left = new QVBoxLayout;
    left->addWidget(rangeBox);
    left->addWidget(showBox);
    left->addStretch(1);
    auto* middle = new QHBoxLayout;
    middle->addLayout(left);
    middle->addLayout(right, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(actions);
    layout->addLayout(options);
    layout->addLayout(middle, 1);

    connectControls();
    fillChoices();
    contour_->setEnabled(session_->session().trajectory.kind != TrajectoryKind::Cubic);
    rebuildRanges();
}

QGroupBox* RobustnessView::buildRangeBox() {
    // The ranges on the left (3 to 5 rows: they fit the lower tab at 1366 x 768 without
    // scrolling); how many plants and what to show in a row under the actions.
    auto* rangeBox = new QGroupBox(tr("Ranges (± %)"));
    rangeForm_ = new QFormLayout(rangeBox);
    controlContent_ = rangeBox;
    rangeBox->setFixedWidth(136);
    return rangeBox;
}

QHBoxLayout* RobustnessView::buildOptions() {
    samples_ = new QSpinBox;
    samples_->setRange(1, 100000);
    samples_->setValue(200);
    samples_->setToolTip(tr("random plants, drawn uniformly within the ranges"));
    seed_ = new QSpinBox;
    seed_->setRange(0, 999999);
    seed_->setValue(1);
    seed_->setToolTip(tr("the same seed draws the same plants"));
    corners_ = new QCheckBox(tr("corners"));
    corners_->setChecked(true);
    corners_->setToolTip(
        tr("also every corner of the box of ranges (the deterministic worst-case search)"));
    contour_ = new QCheckBox(tr("XY contour"));
    contour_->setToolTip(
        tr("Analyze both axes together on the circle or G-code program: pairs of plants, "
           "the contour error they trace, its XY band. Each range applies to the parameter "
           "of that name on every axis that has one."));
    signal_ = new QComboBox;
    signal_->setToolTip(tr("the signal whose envelope is drawn"));
    figure_ = new QComboBox;
    figure_->setToolTip(tr("the figure whose distribution is drawn"));
    auto* options = new QHBoxLayout;
    options->addWidget(new QLabel(tr("plants")));
    options->addWidget(samples_);
    options->addWidget(new QLabel(tr("seed")));
    options->addWidget(seed_);
    options->addWidget(corners_);
    options->addWidget(contour_);
    options->addStretch(1);
    return options;
}

QHBoxLayout* RobustnessView::buildActions() {
    run_ = new QPushButton(tr("Run"));
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setEnabled(false);
    run_->setToolTip(tr("Run the analysis: the session's unchanged controller on every plant "
                        "drawn within the ranges (and the box's corners), each on the trajectory"));
    cancel_->setToolTip(tr("Stop the analysis; the plants run so far are shown"));
    worst_ = new QPushButton(tr("Load worst case"));
    worst_->setToolTip(
        tr("Make the worst plant found (largest RMSE) the session's plant (an undoable step)"));
    worst_->setEnabled(false);
    progress_ = new QProgressBar;
    progress_->setRange(0, 100);
    progress_->setValue(0);
    auto* actions = new QHBoxLayout;
    actions->addWidget(run_);
    actions->addWidget(cancel_);
    actions->addWidget(worst_);
    actions->addWidget(progress_, 1);
    return actions;
}

QVBoxLayout* RobustnessView::buildPlots() {
    envelope_ = new EnvelopePlot;
    histogram_ = new HistogramPlot;
    // Narrower than a plot's usual minimum: beside the controls both fit the lower tab of a
    // 1366 x 768 window (about 750 px) without widening it.
    envelope_->setMinimumWidth(160);
    histogram_->setMinimumWidth(120);
    sensitivity_ = new SensitivityPlot;
    sensitivity_->setMinimumWidth(120);
    figureStack_ = new QStackedWidget;
    figureStack_->addWidget(histogram_);
    figureStack_->addWidget(sensitivity_);
    band_ = new ContourBandPlot;
    band_->setMinimumWidth(120);
    figureStack_->addWidget(band_);
    auto* plotArea = new QWidget;
    auto* plots = new QHBoxLayout(plotArea);
    plots->setContentsMargins(0, 0, 0, 0);
    // Equal halves: at 1366x768 a third of the width left the figure about 150 px, too narrow
    // for the sensitivity plot's notice.
    plots->addWidget(envelope_, 1);
    plots->addWidget(figureStack_, 1);
    status_ = new QLabel(tr("Set a range for the parameters you doubt and press Run."));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    status_->setFixedHeight(3 * status_->fontMetrics().lineSpacing() + 6);
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    status_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    auto* right = new QVBoxLayout;
    right->addWidget(plotArea, 1);
    veil_ = new StaleVeil(plotArea);
    right->addWidget(status_);
    return right;
}

QGroupBox* RobustnessView::buildShowBox() {
    // What to show under the ranges, in the same narrow column (a row of its own made the tab
    // wider than a 1366 x 768 window gives it).
    auto* showBox = new QGroupBox(tr("Show"));
    showBox->setFixedWidth(136);
    auto* showLayout = new QVBoxLayout(showBox);
    showLayout->addWidget(signal_);
    showLayout->addWidget(figure_);
    return showBox;
}

void RobustnessView::connectControls() {
    connect(run_, &QPushButton::clicked, this, &RobustnessView::run);
    connect(cancel_, &QPushButton::clicked, this, &RobustnessView::cancel);
    connect(worst_, &QPushButton::clicked, this, &RobustnessView::loadWorstCase);
    connect(signal_, &QComboBox::currentIndexChanged, this, &RobustnessView::redraw);
    connect(figure_, &QComboBox::currentIndexChanged, this, &RobustnessView::redraw);
    connect(contour_, &QCheckBox::toggled, this, &RobustnessView::onModeChanged);
    connect(session_, &TuningSession::designChanged, this, &RobustnessView::onDesignChanged);
    connect(session_, &TuningSession::currentAxisChanged, this, &RobustnessView::onDesignChanged);
}

bool RobustnessView::contourMode() const {
    return contour_->isChecked();
}

void RobustnessView::fillChoices() {
    const QSignalBlocker blockSignal(signal_), blockFigure(figure_);
    signal_->clear();
    figure_->clear();
    if (contourMode()) {
        signal_->addItems({tr("contour error")});
        figure_->addItems({tr("max |contour e|"), tr("XY band")});
        figure_->setCurrentIndex(1);
    } else {
        signal_->addItems({tr("error e"), tr("output y"), tr("command u")});
        figure_->addItems({tr("RMSE"), tr("max |e|"), tr("max |u|"), tr("ZPETC sensitivity")});
    }
}

void RobustnessView::onModeChanged() {
    runner_.discard(); // a run of the other mode would not be shown
    cancel_->setEnabled(false);
    fillChoices();
    rebuildRanges();
    clearResult(contourMode() ? tr("XY contour: set the ranges and press Run.")
                              : tr("Set a range for the parameters you doubt and press Run."));
    figureStack_->setCurrentWidget(contourMode() ? static_cast<QWidget*>(band_) : histogram_);
}

void RobustnessView::clearResult(const QString& why) {
    result_.reset();
    contourResult_.reset();
    curve_.clear();
    problem_.reset();
    contourProblem_.reset();
    stamp_.reset();
    veil_->lift();
    worst_->setEnabled(false);
    progress_->setValue(0);
    sensitivity_->showNoResult(why);
    band_->showNoResult(why);
    envelope_->showNoResult(tr("Envelope"), why);
    histogram_->showNoResult(tr("Distribution"), why);
    setStatus(why);
}

RobustnessView::~RobustnessView() = default; // the runner cancels and waits for its job

QString RobustnessView::statusText() const {
    return status_->text();
}

void RobustnessView::setStatus(const QString& text, bool isError) {
    setStatusText(status_, text, isError);
}

void RobustnessView::rebuildRanges() {
    for (auto it = ranges_.begin(); it != ranges_.end(); ++it)
        rangePct_[it.key()] = it.value()->value();
    QStringList names;
    std::vector<UncertainParameter> parameters;
    // From the settings alone: this runs on every design change (a slider step). In contour
    // mode, the parameters of both axes (one row per name: it applies to each axis having it).
    for (int axis = 0; axis < 2; ++axis) {
        if (!contourMode() && axis != session_->currentAxis())
            continue;
        try {
            for (const UncertainParameter& p : axisUncertainParameters(
                     session_->session().axes.at(static_cast<std::size_t>(axis))))
                if (!names.contains(QString::fromStdString(p.name))) {
                    names << QString::fromStdString(p.name);
                    parameters.push_back(p);
                }
        } catch (const InvalidInput&) {
            // An axis without a valid design has nothing to perturb; the run says why.
        }
    }
    if (names == rangeOrder_)
        return;
    while (rangeForm_->rowCount() > 0)
        rangeForm_->removeRow(0);
    ranges_.clear();
    rangeOrder_ = names;
    for (const UncertainParameter& p : parameters) {
        const QString name = QString::fromStdString(p.name);
        auto* box = new QDoubleSpinBox;
        box->setRange(0.0, 99.9);
        box->setDecimals(1);
        box->setSuffix(QStringLiteral(" %"));
        box->setValue(rangePct_.value(name, 0.0));
        box->setToolTip(contourMode()
                            ? tr("%1 of every axis that has one: drawn uniformly within ± this "
                                 "share of its nominal")
                                  .arg(name)
                            : tr("%1: nominal %2; drawn uniformly within ± this share of it")
                                  .arg(name, figure(p.nominal, 6)));
        rangeForm_->addRow(name, box);
        ranges_.insert(name, box);
    }
}

void RobustnessView::onDesignChanged() {
    const Session& s = session_->session();
    const bool contourPossible = s.trajectory.kind != TrajectoryKind::Cubic;
    contour_->setEnabled(contourPossible);
    if (!contourPossible && contour_->isChecked()) {
        contour_->setChecked(false); // a cubic drives both axes along one line: no contour
        return;                      // (onModeChanged has cleared the result)
    }
    rebuildRanges();
    showFreshness();
}

bool RobustnessView::resultIsCurrent() const {
    if (!stamp_ || (!result_ && !contourResult_))
        return false;
    return session_->isCurrent(*stamp_) &&
           (stamp_->scope == ResultScope::BothAxes || stamp_->axis == session_->currentAxis());
}

void RobustnessView::showFreshness() {
    if (!stamp_ || (!result_ && !contourResult_))
        return;
    const bool current = resultIsCurrent();
    worst_->setEnabled(current && (contourResult_ ? contourResult_->worst.has_value()
                                                  : result_->worst.has_value()));
    if (current) {
        veil_->lift();
        if (!isRunning()) // else the status says what runs
            setStatus(summary_, summaryIsError_);
        return;
    }
    const QString what = TuningSession::describe(*stamp_);
    if (!isRunning())
        setStatus(tr("Not the current design's (computed for %1): %2").arg(what, summary_),
                  summaryIsError_);
    const bool otherAxis = session_->isCurrent(*stamp_);
    veil_->veil(
        otherAxis
            ? tr("Computed for %1: this tab shows axis %2. Press Run to analyze it.")
                  .arg(what, QString::fromStdString(
                                 session_->session()
                                     .axes.at(static_cast<std::size_t>(session_->currentAxis()))
                                     .id)
                                 .toUpper())
            : tr("Computed for %1. The design has changed since: press Run to "
                 "analyze the current one.")
                  .arg(what));
}

void RobustnessView::run() {
    const int axis = session_->currentAxis();
    Outcome work;
    const auto applyRanges = [this](std::vector<UncertainParameter>& parameters) {
        for (UncertainParameter& p : parameters)
            if (QDoubleSpinBox* box = rangeBox(QString::fromStdString(p.name)))
                setRelativeRange(parameters, p.name, box->value() / 100.0);
    };
    try {
        if (contourMode()) {
            work.contourProblem = sessionContourRobustnessProblem(session_->session());
            applyRanges(work.contourProblem->x.parameters);
            applyRanges(work.contourProblem->y.parameters);
        } else {
            work.problem = sessionRobustnessProblem(session_->session(), axis);
            applyRanges(work.problem->parameters);
        }
    } catch (const InvalidInput& e) {
        setStatus(tr("Cannot run: %1").arg(exceptionText(e)), true);
        return;
    }
    RobustnessOptions options;
    options.samples = samples_->value();
    options.seed = static_cast<std::uint64_t>(seed_->value());
    options.corners = corners_->isChecked();
    const bool contour = work.contourProblem.has_value();
    // The work holds copies of its inputs only: it may outlive a change of the design.
    runner_.start(session_->stamp(axis, contour ? ResultScope::BothAxes : ResultScope::AxisDesign),
                  [work, options](const JobProgress& progress) mutable {
                      options.progress = progress;
                      if (work.contourProblem) {
                          work.contour = analyzeContourRobustness(*work.contourProblem, options);
                          return work;
                      }
                      work.axis = analyzeRobustness(*work.problem, options);
                      if (work.problem->loop && work.problem->zpetcEnabled &&
                          work.axis->status == RobustnessStatus::Completed) {
                          // The bar has reached 100 %: the curve reports nothing but may stop.
                          RobustnessOptions quiet = options;
                          quiet.progress = [progress](double) { return progress(1.0); };
                          work.curve = zpetcSensitivity(*work.problem, sensitivityScales(), quiet);
                      }
                      return work;
                  });
    progress_->setValue(0);
    cancel_->setEnabled(true);
    run_->setEnabled(true);
    setStatus((contour ? tr("Running %1 plant pairs%2…") : tr("Running %1 plants%2…"))
                  .arg(options.samples)
                  .arg(options.corners ? tr(" and the corners") : QString()));
}

void RobustnessView::cancel() {
    if (!runner_.isRunning())
        return;
    runner_.cancel();
    cancel_->setEnabled(false);
    setStatus(tr("Cancelling…"));
}

void RobustnessView::onFinished(Outcome&& outcome, const ResultStamp& stamp) {
    cancel_->setEnabled(false);
    progress_->setValue(100);
    stamp_ = stamp;
    if (outcome.contour) {
        result_.reset();
        problem_.reset();
        curve_.clear();
        contourResult_ = std::move(outcome.contour);
        contourProblem_ = std::move(outcome.contourProblem);
        summary_ = contourSummary(*contourResult_);
        summaryIsError_ = !contourResult_->unstable.empty();
    } else {
        contourResult_.reset();
        contourProblem_.reset();
        result_ = std::move(outcome.axis);
        curve_ = std::move(outcome.curve);
        problem_ = std::move(outcome.problem);
        summary_ = axisSummary(*result_);
        summaryIsError_ = !result_->unstable.empty();
    }
    setStatus(summary_, summaryIsError_);
    redraw();
    showFreshness(); // a run that ended after the design changed is shown as what it is
    emit analysisFinished();
}

namespace {

/// "x.k0 = 70.2, y.a1 = 64": the parameters of @p values that vary (relative > 0).
QString variedParameters(const std::vector<std::string>& names,
                         const std::vector<UncertainParameter>& parameters,
                         const std::vector<double>& values) {
    std::vector<std::string> varied;
    std::vector<double> v;
    for (std::size_t i = 0; i < parameters.size(); ++i)
        if (parameters[i].relative > 0.0) {
            varied.push_back(names[i]);
            v.push_back(values[i]);
        }
    return parameterList(varied, v);
}

QString countsText(const QString& what, int computed, std::size_t total, int samples,
                   bool cancelled) {
    const int corners = static_cast<int>(total) - samples;
    return cancelled ? RobustnessView::tr("Cancelled after %1 of %2 %3. ")
                           .arg(computed)
                           .arg(total)
                           .arg(what)
                     : RobustnessView::tr("%1 %2%3: ")
                           .arg(samples)
                           .arg(what)
                           .arg(corners > 0 ? RobustnessView::tr(" + %1 corners").arg(corners)
                                            : QString());
}

} // namespace

QString RobustnessView::axisSummary(const RobustnessResult& r) const {
    QString text = countsText(tr("plants"), r.computedCount, r.runs.size(), samples_->value(),
                              r.status == RobustnessStatus::Cancelled);
    text += tr("%1 % meet the spec (the nominal %2); %3 unstable.")
                .arg(figure(100.0 * r.fractionMeetingSpec, 3))
                .arg(r.nominal.meetsSpec ? tr("does") : tr("does not"))
                .arg(r.unstable.size());
    if (r.rmseWithoutFf.count > 0 && r.rmse.count > 0 && r.rmse.p50 > 0.0)
        text += tr(" The feedforward divides the RMSE by %1 on the median plant (%2 at the 95 % "
                   "RMSE).")
                    .arg(figure(r.rmseWithoutFf.p50 / r.rmse.p50, 3),
                         figure(r.rmseWithoutFf.p95 / r.rmse.p95, 3));
    const std::vector<UncertainParameter>& parameters = problem_->parameters;
    const bool anyVaried =
        std::any_of(parameters.begin(), parameters.end(),
                    [](const UncertainParameter& p) { return p.relative > 0.0; });
    if (r.worst && anyVaried)
        text += tr("\nWorst: RMSE %1 mm at %2.")
                    .arg(figure(r.runs[*r.worst].tracking.rmse),
                         variedParameters(r.parameterNames, parameters, r.runs[*r.worst].values));
    if (!r.unstable.empty() && anyVaried)
        text += tr("\nUnstable, e.g. at %1.")
                    .arg(variedParameters(r.parameterNames, parameters,
                                          r.runs[r.unstable.front()].values));
    return text;
}

QString RobustnessView::contourSummary(const ContourRobustnessResult& r) const {
    std::vector<UncertainParameter> parameters = contourProblem_->x.parameters;
    parameters.insert(parameters.end(), contourProblem_->y.parameters.begin(),
                      contourProblem_->y.parameters.end());
    QString text = countsText(tr("plant pairs"), r.computedCount, r.runs.size(), samples_->value(),
                              r.status == RobustnessStatus::Cancelled);
    const Distribution& d = r.maxAbsContourError;
    text += d.count > 0
                ? tr("max contour error median %1 mm, 95 % %2 mm (nominal %3 mm); %4 unstable.")
                      .arg(figure(d.p50), figure(d.p95), figure(r.nominal.maxAbsContourError))
                      .arg(r.unstable.size())
                : tr("no stable pair; %1 unstable.").arg(r.unstable.size());
    if (r.worst)
        text += tr("\nWorst: %1 mm at %2.")
                    .arg(figure(r.runs[*r.worst].maxAbsContourError),
                         variedParameters(r.parameterNames, parameters, r.runs[*r.worst].values));
    if (!r.unstable.empty())
        text += tr("\nUnstable, e.g. at %1.")
                    .arg(variedParameters(r.parameterNames, parameters,
                                          r.runs[r.unstable.front()].values));
    return text;
}

void RobustnessView::redraw() {
    if (contourResult_) {
        const ContourRobustnessResult& r = *contourResult_;
        envelope_->showEnvelope(r.error, tr("Contour error of the plant pairs"),
                                tr("contour e (mm)"));
        const bool band = figure_->currentIndex() == 1;
        figureStack_->setCurrentWidget(band ? static_cast<QWidget*>(band_) : histogram_);
        if (band)
            band_->showResult(r);
        else
            histogram_->showHistogram(histogram(contourFigureValues(r), 20),
                                      r.nominal.maxAbsContourError, std::nullopt,
                                      tr("Distribution"), tr("max |contour e| (mm)"));
        return;
    }
    if (!result_)
        return;
    const RobustnessResult& r = *result_;
    const int s = signal_->currentIndex();
    const SignalEnvelope& e = s == 0 ? r.error : s == 1 ? r.output : r.command;
    const QString names[] = {tr("Error e of the plants"), tr("Output y of the plants"),
                             tr("Command u of the plants")};
    const QString units[] = {tr("e (mm)"), tr("y (mm)"), tr("u (V)")};
    envelope_->showEnvelope(e, names[s], units[s]);
    const int f = figure_->currentIndex();
    figureStack_->setCurrentWidget(f == 3 ? static_cast<QWidget*>(sensitivity_) : histogram_);
    if (f == 3) {
        if (curve_.empty())
            sensitivity_->showNoResult(tr("For a pole-placement axis with ZPETC."));
        else
            sensitivity_->showCurve(curve_);
        return;
    }
    const RobustnessFigure figure = f == 0   ? RobustnessFigure::Rmse
                                    : f == 1 ? RobustnessFigure::MaxAbsError
                                             : RobustnessFigure::MaxAbsU;
    const double nominal = f == 0   ? r.nominal.tracking.rmse
                           : f == 1 ? r.nominal.tracking.maxAbsError
                                    : r.nominal.tracking.maxAbsU;
    // The limits of the specification a figure has: max |e| (% of the travel) and |u| <= umax.
    std::optional<double> limit;
    if (f == 1 && problem_) {
        const auto [lo, hi] = std::minmax_element(
            problem_->reference.begin(),
            problem_->reference.begin() + static_cast<std::ptrdiff_t>(problem_->samples));
        limit = problem_->spec.maxErrorPct / 100.0 * (*hi - *lo);
    } else if (f == 2 && problem_) {
        limit = problem_->spec.umaxVolts;
    }
    const QString figureUnits[] = {tr("RMSE (mm)"), tr("max |e| (mm)"), tr("max |u| (V)")};
    histogram_->showHistogram(histogram(figureValues(r, figure), 20), nominal, limit,
                              tr("Distribution"), figureUnits[f]);
}

void RobustnessView::loadWorstCase() {
    if (!resultIsCurrent())
        return; // the worst plant of another design (the button is off then)
    const auto lookup = [](const std::vector<std::string>& names, const std::vector<double>& values,
                           const std::string& prefix) {
        return [&names, &values, prefix](const std::string& name, double fallback) {
            for (std::size_t i = 0; i < names.size(); ++i)
                if (names[i] == prefix + name)
                    return values[i];
            return fallback;
        };
    };
    if (contourResult_ && contourResult_->worst && contourProblem_) {
        const ContourRobustnessResult& r = *contourResult_;
        const std::vector<double>& v = r.runs[*r.worst].values;
        std::array<AxisSettings, 2> axes = session_->session().axes;
        for (std::size_t i = 0; i < 2; ++i)
            axes[i] = designMethodModule(axes[i].method)
                          .withPlantParameters(axes[i],
                                               lookup(r.parameterNames, v, i == 0 ? "x." : "y."));
        session_->setAxes(axes, tr("Load the worst plant pair of the contour analysis"));
        return;
    }
    if (!result_ || !result_->worst || !problem_)
        return;
    const int axis = stamp_->axis;
    const std::vector<double>& v = result_->runs[*result_->worst].values;
    const AxisSettings& current = session_->session().axes.at(static_cast<std::size_t>(axis));
    session_->setAxis(axis,
                      designMethodModule(current.method)
                          .withPlantParameters(current, lookup(result_->parameterNames, v, "")),
                      tr("Load the worst plant of the robustness analysis"));
}

} // namespace xyt::ui
