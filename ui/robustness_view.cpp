// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/robustness_view.h"

#include "core/model/errors.h"
#include "core/session/robustness_problem.h"
#include "ui/plots/envelope_plot.h"
#include "ui/plots/histogram_plot.h"
#include "ui/plots/sensitivity_plot.h"
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
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <cmath>

namespace xyt::ui {

namespace {

QString num(double v, int digits = 4) { return std::isfinite(v) ? QString::number(v, 'g', digits) : QStringLiteral("n/a"); }

/// What the analysis of an axis depends on: everything of the session but other axes.
bool sameAxis(const Session& a, const Session& b, int axis) {
    return a.axes.at(static_cast<std::size_t>(axis)) == b.axes.at(static_cast<std::size_t>(axis)) &&
           a.trajectory == b.trajectory && a.umaxVolts == b.umaxVolts && a.spec == b.spec;
}

QString parameterList(const std::vector<std::string>& names, const std::vector<double>& values) {
    QStringList parts;
    for (std::size_t i = 0; i < names.size(); ++i)
        parts << QStringLiteral("%1 = %2").arg(QString::fromStdString(names[i]), num(values[i], 6));
    return parts.join(QStringLiteral(", "));
}

} // namespace

RobustnessView::RobustnessView(TuningSession* session, QWidget* parent) : QWidget(parent), session_(session) {
    // The ranges on the left (3 to 5 rows: they fit the lower tab at 1366 x 768 without
    // scrolling); how many plants and what to show in a row under the actions.
    auto* rangeBox = new QGroupBox(tr("Ranges (± %)"));
    rangeForm_ = new QFormLayout(rangeBox);
    controlContent_ = rangeBox;
    rangeBox->setFixedWidth(136);
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
    corners_->setToolTip(tr("also every corner of the box of ranges (the deterministic worst-case search)"));
    signal_ = new QComboBox;
    signal_->addItems({tr("error e"), tr("output y"), tr("command u")});
    signal_->setToolTip(tr("the signal whose envelope is drawn"));
    figure_ = new QComboBox;
    figure_->addItems({tr("RMSE"), tr("max |e|"), tr("max |u|"), tr("ZPETC sensitivity")});
    figure_->setToolTip(tr("the figure whose distribution is drawn"));
    auto* options = new QHBoxLayout;
    options->addWidget(new QLabel(tr("plants")));
    options->addWidget(samples_);
    options->addWidget(new QLabel(tr("seed")));
    options->addWidget(seed_);
    options->addWidget(corners_);
    options->addStretch(1);

    run_ = new QPushButton(tr("Run"));
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setEnabled(false);
    worst_ = new QPushButton(tr("Load worst case"));
    worst_->setToolTip(tr("Make the worst plant found (largest RMSE) the session's plant (an undoable step)"));
    worst_->setEnabled(false);
    progress_ = new QProgressBar;
    progress_->setRange(0, 100);
    progress_->setValue(0);
    auto* actions = new QHBoxLayout;
    actions->addWidget(run_);
    actions->addWidget(cancel_);
    actions->addWidget(worst_);
    actions->addWidget(progress_, 1);

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
    auto* plots = new QHBoxLayout;
    plots->addWidget(envelope_, 3);
    plots->addWidget(figureStack_, 2);
    status_ = new QLabel(tr("Set a range for the parameters you doubt and press Run."));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    status_->setFixedHeight(3 * status_->fontMetrics().lineSpacing() + 6);
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    status_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    auto* right = new QVBoxLayout;
    right->addLayout(plots, 1);
    right->addWidget(status_);
    // What to show under the ranges, in the same narrow column (a row of its own made the tab
    // wider than a 1366 x 768 window gives it).
    auto* showBox = new QGroupBox(tr("Show"));
    showBox->setFixedWidth(136);
    auto* showLayout = new QVBoxLayout(showBox);
    showLayout->addWidget(signal_);
    showLayout->addWidget(figure_);
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

    connect(run_, &QPushButton::clicked, this, &RobustnessView::run);
    connect(cancel_, &QPushButton::clicked, this, &RobustnessView::cancel);
    connect(worst_, &QPushButton::clicked, this, &RobustnessView::loadWorstCase);
    connect(signal_, &QComboBox::currentIndexChanged, this, &RobustnessView::redraw);
    connect(figure_, &QComboBox::currentIndexChanged, this, &RobustnessView::redraw);
    connect(session_, &TuningSession::designChanged, this, &RobustnessView::onDesignChanged);
    rebuildRanges();
}

RobustnessView::~RobustnessView() { stopJob(); }

QString RobustnessView::statusText() const { return status_->text(); }

void RobustnessView::setStatus(const QString& text, bool isError) { setStatusText(status_, text, isError); }

void RobustnessView::stopJob() {
    if (!job_)
        return;
    job_->stop(); // the workers stop after the item each is computing: a short wait
    job_.reset();
}

void RobustnessView::rebuildRanges() {
    for (auto it = ranges_.begin(); it != ranges_.end(); ++it)
        rangePct_[it.key()] = it.value()->value();
    QStringList names;
    std::vector<UncertainParameter> parameters;
    try {
        // From the settings alone: this runs on every design change (a slider step).
        parameters = axisUncertainParameters(
            session_->session().axes.at(static_cast<std::size_t>(session_->currentAxis())));
    } catch (const InvalidInput&) {
        // An axis without a valid design has nothing to perturb; the run says why.
    }
    for (const UncertainParameter& p : parameters)
        names << QString::fromStdString(p.name);
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
        box->setToolTip(tr("%1: nominal %2; drawn uniformly within ± this share of it").arg(name, num(p.nominal, 6)));
        rangeForm_->addRow(name, box);
        ranges_.insert(name, box);
    }
}

void RobustnessView::onDesignChanged() {
    rebuildRanges();
    if (!result_ || isRunning())
        return;
    const Session& s = session_->session();
    if (axis_ == session_->currentAxis() && sameAxis(s, analyzedSession_, axis_))
        return;
    // The result describes another controller or plant: never show it as this design's.
    result_.reset();
    curve_.clear();
    problem_.reset();
    worst_->setEnabled(false);
    sensitivity_->showNoResult(tr("The design changed since the analysis: press Run."));
    const QString why = tr("The design changed since the analysis: press Run.");
    envelope_->showNoResult(tr("Envelope"), why);
    histogram_->showNoResult(tr("Distribution"), why);
    setStatus(why);
}

void RobustnessView::run() {
    stopJob();
    const int axis = session_->currentAxis();
    RobustnessProblem problem;
    try {
        problem = sessionRobustnessProblem(session_->session(), axis);
        for (UncertainParameter& p : problem.parameters)
            if (QDoubleSpinBox* box = rangeBox(QString::fromStdString(p.name)))
                setRelativeRange(problem.parameters, p.name, box->value() / 100.0);
    } catch (const InvalidInput& e) {
        setStatus(tr("Cannot run: %1").arg(QString::fromStdString(e.what())), true);
        return;
    }
    RobustnessOptions options;
    options.samples = samples_->value();
    options.seed = static_cast<std::uint64_t>(seed_->value());
    options.corners = corners_->isChecked();
    pendingProblem_ = problem;
    pendingAxis_ = axis;
    analyzedSession_ = session_->session();
    job_ = std::make_unique<Job>();
    const int id = job_->id = ++lastJobId_;
    std::atomic<bool>* cancelFlag = &job_->cancel;
    job_->thread = std::thread([this, id, cancelFlag, problem, options]() mutable {
        options.progress = [this, id, cancelFlag](double fraction) {
            QMetaObject::invokeMethod(this, [this, id, fraction] {
                if (job_ && job_->id == id)
                    progress_->setValue(static_cast<int>(std::lround(100.0 * fraction)));
            }, Qt::QueuedConnection);
            return !cancelFlag->load();
        };
        auto result = std::make_shared<RobustnessResult>();
        auto curve = std::make_shared<std::vector<ZpetcSensitivityPoint>>();
        QString error;
        try {
            *result = analyzeRobustness(problem, options);
            if (problem.loop && problem.zpetcEnabled && result->status == RobustnessStatus::Completed) {
                RobustnessOptions quiet = options; // the bar has reached 100 %: cancel only
                quiet.progress = [cancelFlag](double) { return !cancelFlag->load(); };
                *curve = zpetcSensitivity(problem, sensitivityScales(), quiet);
            }
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(this, [this, id, result, curve, error] { onFinished(id, result, curve, error); },
                                  Qt::QueuedConnection);
    });
    progress_->setValue(0);
    cancel_->setEnabled(true);
    run_->setEnabled(true);
    setStatus(tr("Running %1 plants%2…").arg(options.samples).arg(options.corners ? tr(" and the corners") : QString()));
}

void RobustnessView::cancel() {
    if (!job_)
        return;
    job_->cancel = true;
    cancel_->setEnabled(false);
    setStatus(tr("Cancelling…"));
}

void RobustnessView::onFinished(int jobId, std::shared_ptr<RobustnessResult> result,
                                std::shared_ptr<std::vector<ZpetcSensitivityPoint>> curve, QString error) {
    if (!job_ || job_->id != jobId)
        return;
    job_->thread.join();
    job_.reset();
    cancel_->setEnabled(false);
    if (!error.isEmpty()) {
        setStatus(tr("The analysis failed: %1").arg(error), true);
        return;
    }
    result_ = std::move(*result);
    curve_ = std::move(*curve);
    problem_ = pendingProblem_;
    axis_ = pendingAxis_;
    progress_->setValue(100);
    const RobustnessResult& r = *result_;
    const int corners = static_cast<int>(r.runs.size()) - samples_->value();
    QString text = r.status == RobustnessStatus::Cancelled
                       ? tr("Cancelled after %1 of %2 plants. ").arg(r.computedCount).arg(r.runs.size())
                       : tr("%1 plants%2: ").arg(samples_->value()).arg(corners > 0 ? tr(" + %1 corners").arg(corners) : QString());
    text += tr("%1 % meet the spec (the nominal %2); %3 unstable.")
                .arg(num(100.0 * r.fractionMeetingSpec, 3))
                .arg(r.nominal.meetsSpec ? tr("does") : tr("does not"))
                .arg(r.unstable.size());
    // Only the parameters that vary name a plant.
    std::vector<std::string> varied;
    std::vector<std::size_t> variedIndex;
    for (std::size_t i = 0; i < problem_->parameters.size(); ++i)
        if (problem_->parameters[i].relative > 0.0) {
            varied.push_back(problem_->parameters[i].name);
            variedIndex.push_back(i);
        }
    const auto plantText = [&](std::size_t run) {
        std::vector<double> values;
        for (std::size_t i : variedIndex)
            values.push_back(r.runs[run].values[i]);
        return parameterList(varied, values);
    };
    if (r.worst && !varied.empty())
        text += tr("\nWorst: RMSE %1 mm at %2.").arg(num(r.runs[*r.worst].tracking.rmse), plantText(*r.worst));
    if (!r.unstable.empty() && !varied.empty())
        text += tr("\nUnstable, e.g. at %1.").arg(plantText(r.unstable.front()));
    setStatus(text, !r.unstable.empty());
    worst_->setEnabled(r.worst.has_value());
    redraw();
    emit analysisFinished();
}

void RobustnessView::redraw() {
    if (!result_)
        return;
    const RobustnessResult& r = *result_;
    const int s = signal_->currentIndex();
    const SignalEnvelope& e = s == 0 ? r.error : s == 1 ? r.output : r.command;
    const QString names[] = {tr("Error e of the plants"), tr("Output y of the plants"), tr("Command u of the plants")};
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
    const RobustnessFigure figure = f == 0 ? RobustnessFigure::Rmse : f == 1 ? RobustnessFigure::MaxAbsError
                                                                              : RobustnessFigure::MaxAbsU;
    const double nominal = f == 0 ? r.nominal.tracking.rmse : f == 1 ? r.nominal.tracking.maxAbsError
                                                                      : r.nominal.tracking.maxAbsU;
    // The limits of the specification a figure has: max |e| (% of the travel) and |u| <= umax.
    std::optional<double> limit;
    if (f == 1 && problem_) {
        const auto [lo, hi] = std::minmax_element(problem_->reference.begin(),
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
    if (!result_ || !result_->worst || !problem_)
        return;
    const std::vector<double>& v = result_->runs[*result_->worst].values;
    const auto value = [&](const std::string& name, double fallback) {
        for (std::size_t i = 0; i < result_->parameterNames.size(); ++i)
            if (result_->parameterNames[i] == name)
                return v[i];
        return fallback;
    };
    const AxisSettings& axis = session_->session().axes.at(static_cast<std::size_t>(axis_));
    if (problem_->controller) {
        ThirdOrderPlant plant = axis.gt.plant;
        plant.k0 = value("k0", plant.k0);
        plant.a1 = value("a1", plant.a1);
        plant.a2 = value("a2", plant.a2);
        session_->setPlant(axis_, plant);
    } else {
        PpAxisSettings pp = axis.pp;
        // The typed A may not be monic: the analysis perturbed the normalized one (A/A(0), B/A(0)).
        std::vector<double> a = problem_->loop->a.ascending(), b = problem_->loop->b.ascending();
        for (std::size_t i = 1; i < a.size(); ++i)
            a[i] = value("a" + std::to_string(i), a[i]);
        for (std::size_t i = 1; i < b.size(); ++i)
            b[i] = value("b" + std::to_string(i), b[i]);
        pp.a = a;
        pp.b = b;
        session_->setPp(axis_, pp);
    }
}

} // namespace xyt::ui
