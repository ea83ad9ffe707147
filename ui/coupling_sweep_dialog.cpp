// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/coupling_sweep_dialog.h"

#include "core/model/errors.h"
#include "ui/panels/stale_veil.h"
#include "ui/plots/number_text.h"
#include "ui/plots/plot_tools.h"
#include "ui/plots/plot_widget.h"
#include "ui/session/diagnostic_text.h"

#include <qcustomplot.h>

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt::ui {

namespace {

/// The cell of grid index (i kp, j ki) drawn at (i, j): the map's axes count cells, labelled
/// with the gains (a kp of 0 has no place on a logarithmic axis, and the grid is small).
/// Where the corner markers sit in a cell (a cell spans +-0.5 about its centre): the best's star
/// upper left, the saturation's triangle lower right, clear of the figure at the centre.
constexpr double kSweepMarkerOffsetX = 0.36;
constexpr double kSweepMarkerOffsetY = 0.32;

/// Values shown in the cells when both lists are this short (more would not fit a cell).
constexpr std::size_t kSweepMaxLabelledSide = 10;

const QColor kSweepNoFigure(0xdc, 0xdc, 0xdc);

QCPGraph* sweepDialogMarker(QCustomPlot* plot, const QCPScatterStyle& style, const QString& name) {
    QCPGraph* g = plot->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(style);
    g->setName(name);
    return g;
}

QString sweepDialogMm(double v) {
    return significant(v, 3) + QObject::tr(" mm");
}

QString sweepDialogGains(const CrossCoupling& c) {
    return QObject::tr("kp %1 V/mm, ki %2 V/(mm·s)")
        .arg(significant(c.kp, 4), significant(c.ki, 4));
}

/// A list of gains as typed ("0, 0.1 1;3"), or why not (the refusal names the list).
std::vector<double> sweepDialogList(const QString& text, const std::string& field) {
    std::vector<double> out;
    for (const QString& word :
         text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts)) {
        bool ok = false;
        const double v = word.toDouble(&ok);
        if (!ok)
            throw InvalidInput(field, QCoreApplication::translate("xyt::ui::CouplingSweepDialog",
                                                                  "'%1' is not a number")
                                          .arg(word)
                                          .toStdString());
        out.push_back(v);
    }
    return out;
}

QString sweepDialogList(const std::vector<double>& values) {
    QStringList words;
    for (double v : values)
        words << significant(v, 6);
    return words.join(QStringLiteral(", "));
}

/// What a sweep of @p s runs: the session's trajectory in words.
QString sweepDialogSubject(const Session& s) {
    const QString estimate = s.crossCoupling.estimate == ContourEstimateKind::Circular
                                 ? QObject::tr("circular")
                                 : QObject::tr("linear");
    QString path;
    switch (s.trajectory.kind) {
    case TrajectoryKind::Gcode:
        path = s.trajectory.gcode.fileName.empty()
                   ? QObject::tr("the G-code program")
                   : QObject::tr("the program %1")
                         .arg(QString::fromStdString(s.trajectory.gcode.fileName));
        break;
    case TrajectoryKind::Circle:
        path = QObject::tr("the %1 mm circle").arg(significant(s.trajectory.radius, 4));
        break;
    default:
        path = QObject::tr("the point-to-point move");
        break;
    }
    return QObject::tr("The contour of %1, run once for each pair of gains with the axes, the "
                       "limit and the %2 estimate of the session as it is when the sweep starts.")
        .arg(path, estimate);
}

/// What differs between the session a sweep ran for (@p then) and @p now, in what a run reads.
QString sweepDialogChanges(const Session& then, const Session& now) {
    QStringList what;
    if (then.umaxVolts != now.umaxVolts)
        what << QObject::tr("the actuator limit, %1 V then").arg(significant(then.umaxVolts, 4));
    for (int i = 0; i < 2; ++i)
        if (then.axes[std::size_t(i)] != now.axes[std::size_t(i)])
            what << QObject::tr("axis %1").arg(axisName(now, i));
    if (!(then.trajectory == now.trajectory))
        what << QObject::tr("the trajectory");
    if (then.crossCoupling.estimate != now.crossCoupling.estimate)
        what << QObject::tr("the coupling's estimate");
    if (!(then.spec == now.spec))
        what << QObject::tr("the specification");
    if (what.isEmpty())
        what << QObject::tr("the implementation");
    return what.join(QStringLiteral(", "));
}

/// How many times @p ratio, readably ("421", "1140", "2.5").
QString sweepDialogTimes(double ratio) {
    return ratio >= 100.0 && ratio < 1e6 ? QString::number(ratio, 'f', 0) : significant(ratio, 3);
}

} // namespace

CouplingSweepDialog::CouplingSweepDialog(TuningSession* session, QWidget* parent)
    : QDialog(parent), session_(session) {
    setWindowTitle(tr("Tune the cross-coupling by the contour error"));
    auto* layout = new QVBoxLayout(this);
    subject_ = new QLabel(this);
    subject_->setWordWrap(true);
    layout->addWidget(subject_);

    auto* grid = new QHBoxLayout;
    const CouplingSweepGrid defaults = defaultCouplingSweepGrid();
    kpList_ = new QLineEdit(sweepDialogList(defaults.kpVoltsPerMm), this);
    kiList_ = new QLineEdit(sweepDialogList(defaults.kiVoltsPerMmSecond), this);
    kpList_->setAccessibleName(tr("kp values"));
    kiList_->setAccessibleName(tr("ki values"));
    kpList_->setToolTip(tr("The values of kp to try (V/mm), separated by commas; 0 and 0 is "
                           "the coupling off"));
    kiList_->setToolTip(tr("The values of ki to try (V/(mm·s)), separated by commas"));
    grid->addWidget(new QLabel(tr("kp (V/mm)"), this));
    grid->addWidget(kpList_, 1);
    grid->addWidget(new QLabel(tr("ki (V/(mm·s))"), this));
    grid->addWidget(kiList_, 1);
    run_ = new QPushButton(tr("&Run"), this);
    run_->setToolTip(tr("Run the sweep on the session as it is now (at most %1 pairs)")
                         .arg(kMaxCouplingSweepCells));
    grid->addWidget(run_);
    layout->addLayout(grid);
    fieldError_ = new QLabel(this);
    fieldError_->setWordWrap(true);
    fieldError_->setStyleSheet(QStringLiteral("color: #b00020"));
    fieldError_->hide();
    layout->addWidget(fieldError_);

    auto* running = new QHBoxLayout;
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    cancel_ = new QPushButton(tr("&Cancel"), this);
    cancel_->setToolTip(tr("Stop the sweep; the cells run so far are shown"));
    running->addWidget(progress_, 1);
    running->addWidget(cancel_);
    layout->addLayout(running);

    plot_ = new PlotWidget(this);
    plot_->setObjectName(QStringLiteral("coupling-sweep"));
    plot_->setMinimumSize(420, 260);
    plotDescription_ = tr("The sweep's map: each cell one (kp, ki) pair of the cross-coupling, "
                          "coloured by the program's max contour error (mm); hover a cell for its "
                          "figures, click it to select it");
    plot_->setToolTip(plotDescription_);
    styleAxisRect(plot_->axisRect());
    plot_->axisRect()->setBackground(kSweepNoFigure);
    plot_->xAxis->setLabel(tr("kp (V/mm)"));
    plot_->yAxis->setLabel(tr("ki (V/(mm·s))"));
    for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) {
        axis->grid()->setVisible(false);
        axis->setTicker(QSharedPointer<QCPAxisTickerText>::create());
        axis->setSubTicks(false);
    }
    map_ = new QCPColorMap(plot_->xAxis, plot_->yAxis);
    map_->setInterpolate(false);
    map_->setGradient(viridisGradient());
    map_->removeFromLegend();
    scale_ = new QCPColorScale(plot_);
    scale_->setType(QCPAxis::atRight);
    scale_->setBarWidth(14);
    scale_->setDataScaleType(QCPAxis::stLogarithmic);
    scale_->axis()->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
    scale_->axis()->setNumberFormat(QStringLiteral("gb"));
    scale_->axis()->setLabel(tr("max contour error (mm)"));
    QFont f = scale_->axis()->labelFont();
    f.setPointSizeF(9);
    scale_->axis()->setLabelFont(f);
    scale_->axis()->setTickLabelFont(f);
    plot_->plotLayout()->addElement(0, 1, scale_);
    map_->setColorScale(scale_);
    scale_->setGradient(viridisGradient());
    auto* margins = new QCPMarginGroup(plot_);
    plot_->axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    scale_->setMarginGroup(QCP::msBottom | QCP::msTop, margins);

    plot_->addLayer(QStringLiteral("markers"), plot_->layer(QStringLiteral("main")),
                    QCustomPlot::limAbove);
    unstable_ =
        sweepDialogMarker(plot_,
                          QCPScatterStyle(QCPScatterStyle::ssCross,
                                          QPen(QColor(0xb0, 0x00, 0x20), 2.5), Qt::NoBrush, 14),
                          tr("refused: the coupled loop is unstable on a line"));
    failed_ =
        sweepDialogMarker(plot_,
                          QCPScatterStyle(QCPScatterStyle::ssCrossSquare,
                                          QPen(QColor(0x50, 0x50, 0x50), 1.5), Qt::NoBrush, 12),
                          tr("failed: the run was refused or diverged"));
    notRun_ = sweepDialogMarker(plot_,
                                QCPScatterStyle(QCPScatterStyle::ssCircle,
                                                QPen(QColor(0x80, 0x80, 0x80), 1, Qt::DashLine),
                                                Qt::NoBrush, 10),
                                tr("not run (cancelled)"));
    saturated_ = sweepDialogMarker(plot_,
                                   QCPScatterStyle(QCPScatterStyle::ssTriangle, QPen(Qt::black, 1),
                                                   QBrush(QColor(0xff, 0x8c, 0x00)), 9),
                                   tr("an axis reaches its limit"));
    best_ = sweepDialogMarker(plot_,
                              QCPScatterStyle(QCPScatterStyle::ssStar,
                                              QPen(QColor(0xff, 0x30, 0xd0), 2.5), Qt::NoBrush, 15),
                              tr("best"));
    for (QCPGraph* g : {unstable_, failed_, notRun_, saturated_, best_})
        g->setLayer(QStringLiteral("markers"));
    selection_ = new QCPItemRect(plot_);
    selection_->setPen(QPen(Qt::black, 2.5));
    selection_->setBrush(Qt::NoBrush);
    selection_->setLayer(QStringLiteral("markers"));
    selection_->setVisible(false);
    placeLegendBelow(plot_, 1, 3);
    compactLegend(plot_->legend);
    plot_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(plot_, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        QMenu menu(plot_);
        menu.addAction(tr("Save as PNG..."), this,
                       [this] { savePlotDialog(plot_, QStringLiteral("coupling-sweep.png")); });
        menu.addAction(tr("Save as PDF..."), this,
                       [this] { savePlotDialog(plot_, QStringLiteral("coupling-sweep.pdf")); });
        menu.exec(plot_->mapToGlobal(pos));
    });
    layout->addWidget(plot_, 1);
    veil_ = new StaleVeil(plot_);

    status_ = new QLabel(this);
    status_->setWordWrap(true);
    layout->addWidget(status_);
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    summary_->setToolTip(tr("The best: %1.").arg(QString::fromUtf8(kBestCouplingRule)));
    layout->addWidget(summary_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    apply_ = buttons->addButton(tr("&Apply"), QDialogButtonBox::ApplyRole);
    apply_->setToolTip(tr("Set the selected cell's gains as the session's cross-coupling"));
    layout->addWidget(buttons);

    runner_ = std::make_unique<JobRunner<CouplingSweepResult, ResultStamp>>(
        this,
        JobRunner<CouplingSweepResult, ResultStamp>::Handlers{
            [this](double fraction) {
                progress_->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
            },
            [this](CouplingSweepResult&& result, const ResultStamp& stamp) {
                finished(std::move(result), stamp);
            },
            [this](const QString& message, const ResultStamp& stamp) { failed(message, stamp); },
            exceptionText});
    connect(run_, &QPushButton::clicked, this, [this] { run(); });
    connect(cancel_, &QPushButton::clicked, this, &CouplingSweepDialog::cancel);
    connect(apply_, &QPushButton::clicked, this, [this] { apply(); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QLineEdit* field : {kpList_, kiList_})
        connect(field, &QLineEdit::returnPressed, this, [this] { run(); });
    connect(session_, &TuningSession::designChanged, this, &CouplingSweepDialog::updateState);
    // The markers keep to their cells, however many there are and however large the map.
    connect(plot_, &QCustomPlot::beforeReplot, this, [this] {
        if (!result_)
            return;
        const QRect area = plot_->axisRect()->rect();
        const double cell =
            std::min(area.width() / double(result_->grid.kpVoltsPerMm.size()),
                     area.height() / double(result_->grid.kiVoltsPerMmSecond.size()));
        const auto fit = [cell](QCPGraph* g, double fraction, double largest) {
            QCPScatterStyle style = g->scatterStyle();
            style.setSize(std::clamp(fraction * cell, 4.0, largest));
            g->setScatterStyle(style);
        };
        fit(unstable_, 0.5, 14.0);
        fit(failed_, 0.45, 12.0);
        fit(notRun_, 0.4, 10.0);
        fit(saturated_, 0.25, 9.0);
        fit(best_, 0.3, 15.0);
    });
    connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) {
        if (event->buttons() == Qt::NoButton)
            hover(event->pos(), event->globalPosition().toPoint());
    });
    connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent* event) {
        if (event->button() != Qt::LeftButton || veil_->isVeiled())
            return; // a stale map's cells are out of reach
        if (const auto cell = cellAtPixel(event->position()))
            selectCell(*cell);
    });
    subject_->setText(sweepDialogSubject(session_->session()));
    draw();
    updateState();
    resize(780, 640);
}

CouplingSweepDialog::~CouplingSweepDialog() {
    runner_.reset(); // cancels and waits for its job while the dialog's widgets still exist
}

bool CouplingSweepDialog::run() {
    CouplingSweepGrid grid;
    for (QLineEdit* field : {kpList_, kiList_})
        field->setStyleSheet(QString());
    try {
        grid.kpVoltsPerMm = sweepDialogList(kpList_->text(), "kp");
        grid.kiVoltsPerMmSecond = sweepDialogList(kiList_->text(), "ki");
        grid = normalizedCouplingSweepGrid(grid);
    } catch (const InvalidInput& e) {
        fieldError_->setText(exceptionText(e));
        fieldError_->show();
        for (QLineEdit* field : {kpList_, kiList_})
            if (e.field() == "grid" || (field == kpList_) == (e.field() == "kp"))
                field->setStyleSheet(QStringLiteral("QLineEdit { border: 1px solid #b00020; }"));
        return false;
    }
    fieldError_->clear();
    fieldError_->hide();
    failure_.clear();
    // Copies of what the work reads: the session as the views evaluate it, with its evaluation.
    const Session live = session_->liveSession();
    const SessionEvaluation evaluation = session_->evaluation();
    subject_->setText(sweepDialogSubject(session_->session()));
    progress_->setValue(0);
    clock_.start();
    runner_->start(session_->stamp(-1, ResultScope::BothAxes),
                   [live, evaluation, grid](const JobProgress& progress) {
                       CouplingSweepOptions options;
                       options.progress = progress;
                       return sweepSessionCoupling(live, evaluation, grid, options);
                   });
    updateState();
    return true;
}

void CouplingSweepDialog::runUnlessCurrent() {
    const bool forThisSession =
        isRunning() ? sameCouplingSweepInputs(runner_->runningStamp().session, session_->session())
                    : isCurrent();
    if (!forThisSession)
        run();
}

void CouplingSweepDialog::cancel() {
    runner_->cancel();
    updateState();
}

void CouplingSweepDialog::reject() {
    runner_->cancel(); // closing stops the work; what ran still arrives
    QDialog::reject();
}

bool CouplingSweepDialog::isCurrent() const {
    return result_ && sameCouplingSweepInputs(stamp_.session, session_->session());
}

void CouplingSweepDialog::finished(CouplingSweepResult&& result, const ResultStamp& stamp) {
    elapsedMs_ = clock_.elapsed();
    result_ = std::move(result);
    stamp_ = stamp;
    selected_ = result_->best;
    draw();
    updateState();
}

void CouplingSweepDialog::failed(const QString& message, const ResultStamp&) {
    failure_ = message;
    updateState();
}

void CouplingSweepDialog::draw() {
    for (QCPItemText* t : values_)
        plot_->removeItem(t);
    values_.clear();
    for (QCPGraph* g : {unstable_, failed_, notRun_, saturated_, best_})
        g->data()->clear();
    if (!result_) {
        map_->setVisible(false);
        scale_->setVisible(false);
        plot_->xAxis->setRange(-0.5, 0.5);
        plot_->yAxis->setRange(-0.5, 0.5);
        for (QCPGraph* g : {unstable_, failed_, notRun_, saturated_, best_})
            g->removeFromLegend();
        showSelection();
        return;
    }
    const CouplingSweepResult& r = *result_;
    const std::size_t nKp = r.grid.kpVoltsPerMm.size(), nKi = r.grid.kiVoltsPerMmSecond.size();
    map_->setVisible(true);
    scale_->setVisible(true);
    // A side of one cell is drawn as two equal ones a half cell apart (QCPColorMap gives a lone
    // cell no width).
    const int keys = static_cast<int>(std::max<std::size_t>(nKp, 2));
    const int values = static_cast<int>(std::max<std::size_t>(nKi, 2));
    map_->data()->setSize(keys, values);
    map_->data()->setRange(nKp > 1 ? QCPRange(0.0, double(nKp - 1)) : QCPRange(-0.25, 0.25),
                           nKi > 1 ? QCPRange(0.0, double(nKi - 1)) : QCPRange(-0.25, 0.25));
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    const auto include = [&](const CouplingSweepCell& c) {
        if (c.status == CouplingCellStatus::Ok && c.maxAbsMm > 0.0 && std::isfinite(c.maxAbsMm)) {
            lo = std::min(lo, c.maxAbsMm);
            hi = std::max(hi, c.maxAbsMm);
        }
    };
    include(r.independent);
    for (const CouplingSweepCell& c : r.cells)
        include(c);
    for (int a = 0; a < keys; ++a)
        for (int b = 0; b < values; ++b) {
            const CouplingSweepCell& c = r.cell(std::min<std::size_t>(std::size_t(a), nKp - 1),
                                                std::min<std::size_t>(std::size_t(b), nKi - 1));
            const bool drawn =
                c.status == CouplingCellStatus::Ok && c.maxAbsMm > 0.0 && std::isfinite(c.maxAbsMm);
            map_->data()->setCell(a, b,
                                  drawn ? c.maxAbsMm : std::numeric_limits<double>::quiet_NaN());
        }
    if (!(lo <= hi)) {
        lo = 0.1;
        hi = 1.0;
    } else if (lo == hi) {
        lo /= 2.0;
        hi *= 2.0;
    }
    map_->setDataRange(QCPRange(lo, hi));
    map_->setDataScaleType(QCPAxis::stLogarithmic);
    QCPColorGradient gradient = viridisGradient();

    const bool labelled = nKp <= kSweepMaxLabelledSide && nKi <= kSweepMaxLabelledSide;
    for (std::size_t i = 0; i < nKp; ++i)
        for (std::size_t j = 0; j < nKi; ++j) {
            const CouplingSweepCell& c = r.cell(i, j);
            const double x = double(i), y = double(j);
            switch (c.status) {
            case CouplingCellStatus::NotRun:
                notRun_->addData(x, y);
                break;
            case CouplingCellStatus::Unstable:
                unstable_->addData(x, y);
                break;
            case CouplingCellStatus::Failed:
                failed_->addData(x, y);
                break;
            case CouplingCellStatus::Ok:
                if (c.saturated)
                    saturated_->addData(x + kSweepMarkerOffsetX, y - kSweepMarkerOffsetY);
                if (labelled && std::isfinite(c.maxAbsMm)) {
                    auto* t = new QCPItemText(plot_);
                    t->setLayer(QStringLiteral("markers"));
                    t->position->setType(QCPItemPosition::ptPlotCoords);
                    t->position->setCoords(x, y);
                    t->setPositionAlignment(Qt::AlignCenter);
                    t->setText(significant(c.maxAbsMm, 3));
                    t->setFont(QFont(font().family(), 8));
                    t->setClipToAxisRect(true);
                    const QColor shade(gradient.color(c.maxAbsMm, QCPRange(lo, hi), true));
                    t->setColor(shade.lightnessF() < 0.5 ? Qt::white : Qt::black);
                    values_.push_back(t);
                }
                break;
            }
        }
    if (r.best) {
        const std::size_t i = *r.best / nKi, j = *r.best % nKi;
        best_->addData(double(i) - kSweepMarkerOffsetX, double(j) + kSweepMarkerOffsetY);
    }
    for (QCPGraph* g : {best_, saturated_, unstable_, failed_, notRun_}) {
        if (g->dataCount() > 0)
            g->addToLegend();
        else
            g->removeFromLegend();
    }
    // The gains as the axes' tick labels, one per cell.
    const auto ticks = [](QCPAxis* axis, const std::vector<double>& gains) {
        auto ticker = qSharedPointerCast<QCPAxisTickerText>(axis->ticker());
        ticker->clear();
        for (std::size_t k = 0; k < gains.size(); ++k)
            ticker->addTick(double(k), significant(gains[k], 3));
        axis->setRange(-0.5, double(gains.size()) - 0.5);
        // Many labels side by side turn to fit (20 values of kp on a 400 px axis).
        axis->setTickLabelRotation(
            axis->orientation() == Qt::Horizontal && gains.size() > 10 ? -90.0 : 0.0);
    };
    ticks(plot_->xAxis, r.grid.kpVoltsPerMm);
    ticks(plot_->yAxis, r.grid.kiVoltsPerMmSecond);
    showSelection();
}

void CouplingSweepDialog::selectCell(std::size_t index) {
    if (!result_ || index >= result_->cells.size())
        return;
    selected_ = index;
    showSelection();
    updateState();
}

void CouplingSweepDialog::showSelection() {
    if (!result_ || !selected_) {
        selection_->setVisible(false);
    } else {
        const std::size_t nKi = result_->grid.kiVoltsPerMmSecond.size();
        const double x = double(*selected_ / nKi), y = double(*selected_ % nKi);
        selection_->topLeft->setCoords(x - 0.5, y + 0.5);
        selection_->bottomRight->setCoords(x + 0.5, y - 0.5);
        selection_->setVisible(true);
    }
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

bool CouplingSweepDialog::apply() {
    if (!result_ || !selected_ || !isCurrent())
        return false;
    const CouplingSweepCell& c = result_->cells[*selected_];
    if (c.status != CouplingCellStatus::Ok)
        return false;
    CrossCoupling next = c.coupling;
    next.estimate = session_->session().crossCoupling.estimate; // the same: the result is current
    if (next == session_->session().crossCoupling)
        return false;
    session_->setCrossCoupling(next);
    return true;
}

QString CouplingSweepDialog::cellToolTip(std::size_t index) const {
    if (!result_ || index >= result_->cells.size())
        return {};
    const CouplingSweepCell& c = result_->cells[index];
    QStringList lines;
    lines << (c.coupling.active() ? sweepDialogGains(c.coupling)
                                  : tr("kp 0, ki 0: the coupling off (the independent axes)"));
    switch (c.status) {
    case CouplingCellStatus::NotRun:
        lines << tr("Not run: the sweep was cancelled before it.");
        break;
    case CouplingCellStatus::Unstable:
    case CouplingCellStatus::Failed:
        lines << tr("Refused: %1").arg(diagnosticText(c.message));
        break;
    case CouplingCellStatus::Ok:
        lines << tr("Max contour error %1, RMS %2 (independent axes: max %3)")
                     .arg(sweepDialogMm(c.maxAbsMm), sweepDialogMm(c.rmsMm),
                          sweepDialogMm(result_->independent.maxAbsMm));
        if (c.coupling.active())
            lines << tr("Coupled loop at its least stable direction: spectral radius %1, disk "
                        "margin %2")
                         .arg(significant(c.spectralRadius, 6), significant(c.diskMargin, 3));
        lines << (c.saturated ? tr("An axis reaches its actuator limit.")
                              : tr("Both axes stay inside their actuator limit."));
        if (!c.warning.text.empty())
            lines << tr("Warning: %1.").arg(diagnosticText(c.warning));
        break;
    }
    if (result_->best == index)
        lines << tr("The best of the grid.");
    return lines.join(QLatin1Char('\n'));
}

std::optional<std::size_t> CouplingSweepDialog::cellAtPixel(const QPointF& pixel) const {
    if (!result_ || !plot_->axisRect()->rect().contains(pixel.toPoint()))
        return std::nullopt;
    const double x = plot_->xAxis->pixelToCoord(pixel.x());
    const double y = plot_->yAxis->pixelToCoord(pixel.y());
    const long i = std::lround(x), j = std::lround(y);
    const std::size_t nKp = result_->grid.kpVoltsPerMm.size();
    const std::size_t nKi = result_->grid.kiVoltsPerMmSecond.size();
    if (i < 0 || j < 0 || std::size_t(i) >= nKp || std::size_t(j) >= nKi)
        return std::nullopt;
    return result_->cellIndex(std::size_t(i), std::size_t(j));
}

QPointF CouplingSweepDialog::pixelOfCell(std::size_t index) const {
    if (!result_)
        return {};
    const std::size_t nKi = result_->grid.kiVoltsPerMmSecond.size();
    return {plot_->xAxis->coordToPixel(double(index / nKi)),
            plot_->yAxis->coordToPixel(double(index % nKi))};
}

void CouplingSweepDialog::hover(const QPoint& pixel, const QPoint& global) {
    const auto cell = veil_->isVeiled() ? std::nullopt : cellAtPixel(pixel);
    hover_ = cell ? cellToolTip(*cell) : QString();
    // Resting on a cell shows its figures, elsewhere what the map is.
    plot_->setToolTip(hover_.isEmpty() ? plotDescription_ : hover_);
    if (hover_.isEmpty())
        QToolTip::hideText();
    else
        QToolTip::showText(global, hover_, plot_);
}

QString CouplingSweepDialog::summaryText() const {
    return summary_->text();
}

QString CouplingSweepDialog::statusText() const {
    return status_->text();
}

QString CouplingSweepDialog::fieldErrorText() const {
    return fieldError_->text();
}

void CouplingSweepDialog::updateState() {
    const bool running = runner_->isRunning();
    progress_->setVisible(running);
    cancel_->setVisible(running);
    cancel_->setEnabled(running && !runner_->isCancelling());
    run_->setEnabled(!running);
    run_->setText(result_ ? tr("&Run again") : tr("&Run"));
    const bool current = isCurrent();
    const QString changes =
        result_ && !current ? sweepDialogChanges(stamp_.session, session_->session()) : QString();
    if (result_ && !current)
        veil_->veil(tr("Computed for the session before it changed (%1). Press Run again for "
                       "the session as it is.")
                        .arg(changes));
    else
        veil_->lift();

    // What ran, or why nothing did.
    QString status;
    bool severe = false;
    if (running) {
        status = runner_->isCancelling() ? tr("Cancelling: the runs under way finish first…")
                                         : tr("Running the contour for each pair of gains…");
        if (!sameCouplingSweepInputs(runner_->runningStamp().session, session_->session()))
            status += tr(" The session has changed since the sweep started: its result will be "
                         "for the session as it was.");
    } else if (!failure_.isEmpty()) {
        status = tr("The sweep could not run: %1").arg(failure_);
        severe = true;
    } else if (result_) {
        const CouplingSweepResult& r = *result_;
        std::size_t unstable = 0, failedCells = 0, saturated = 0;
        for (const CouplingSweepCell& c : r.cells) {
            unstable += c.status == CouplingCellStatus::Unstable;
            failedCells += c.status == CouplingCellStatus::Failed;
            saturated += c.status == CouplingCellStatus::Ok && c.saturated;
        }
        status = r.cancelled
                     ? tr("Cancelled: %1 of %2 pairs ran.").arg(r.cellsRun).arg(r.cells.size())
                     : tr("%1 pairs ran in %2 s.")
                           .arg(r.cells.size())
                           .arg(significant(elapsedMs_ / 1000.0, 2));
        if (unstable > 0)
            status += tr(" %1 refused: the coupled loop is unstable on a line of the path.")
                          .arg(unstable);
        if (failedCells > 0)
            status += tr(" %1 failed.").arg(failedCells);
        if (saturated > 0)
            status += tr(" %1 drive an axis to its limit.").arg(saturated);
        if (!current) {
            status = tr("Stale: the session has changed since this sweep (%1); nothing can be "
                        "applied until it runs again. ")
                         .arg(changes) +
                     status;
            severe = true;
        }
    } else {
        status = tr("Not run yet: press Run.");
    }
    status_->setText(status);
    status_->setStyleSheet(severe ? QStringLiteral("color: #b00020") : QString());

    // The independent axes, the best and the selected cell.
    QStringList summary;
    if (result_) {
        const CouplingSweepResult& r = *result_;
        const double alone = r.independent.maxAbsMm;
        summary << (r.independent.status == CouplingCellStatus::Ok
                        ? tr("Independent axes (coupling off): max %1, RMS %2.")
                              .arg(sweepDialogMm(alone), sweepDialogMm(r.independent.rmsMm))
                        : tr("Independent axes (coupling off): %1")
                              .arg(diagnosticText(r.independent.message)));
        const QString bestOf = r.cancelled ? tr("Best of the pairs that ran") : tr("Best");
        if (!r.best) {
            summary << tr("No pair of gains ran: no best.");
        } else {
            const CouplingSweepCell& b = r.cells[*r.best];
            if (!b.coupling.active()) {
                summary << tr("%1: the coupling off.").arg(bestOf) +
                               (r.cancelled ? QString()
                                            : tr(" No pair of the grid beats the independent "
                                                 "axes on this path."));
            } else {
                QString best = tr("%1: %2: max %3, RMS %4")
                                   .arg(bestOf, sweepDialogGains(b.coupling),
                                        sweepDialogMm(b.maxAbsMm), sweepDialogMm(b.rmsMm));
                if (b.maxAbsMm > 0.0 && alone > b.maxAbsMm)
                    best += tr(", %1 times smaller than the independent axes'")
                                .arg(sweepDialogTimes(alone / b.maxAbsMm));
                else if (b.maxAbsMm >= alone)
                    best += tr(", no smaller than the independent axes'");
                best += QLatin1Char('.');
                if (r.bestBasis == CouplingBestBasis::WithinLimit)
                    best += tr(" Every pair inside the limit has a coupled loop unstable at some "
                               "direction of an arc: chosen among them.");
                else if (r.bestBasis == CouplingBestBasis::Saturating)
                    best += tr(" Every pair that ran drives an axis to its limit: chosen among "
                               "them.");
                summary << best;
            }
        }
        if (selected_) {
            const CouplingSweepCell& s = r.cells[*selected_];
            QString line = tr("Selected: %1").arg(sweepDialogGains(s.coupling));
            if (s.status == CouplingCellStatus::Ok)
                line += tr(": max %1.").arg(sweepDialogMm(s.maxAbsMm));
            else
                line += tr(": %1, nothing to apply.").arg(couplingCellStatusName(s.status));
            const CrossCoupling& now = session_->session().crossCoupling;
            if (s.coupling.kp == now.kp && s.coupling.ki == now.ki)
                line += tr(" These are the session's gains.");
            summary << line;
        }
    }
    summary_->setText(summary.join(QLatin1Char('\n')));
    summary_->setVisible(!summary.isEmpty());

    bool applicable = false;
    if (result_ && selected_ && current) {
        const CouplingSweepCell& s = result_->cells[*selected_];
        const CrossCoupling& now = session_->session().crossCoupling;
        applicable = s.status == CouplingCellStatus::Ok &&
                     (s.coupling.kp != now.kp || s.coupling.ki != now.ki);
    }
    apply_->setEnabled(applicable);
}

} // namespace xyt::ui
