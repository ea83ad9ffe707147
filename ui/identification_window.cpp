// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/identification_window.h"

#include "core/identification/spectral_estimate.h"

#include "core/identification/continuous_fit.h"
#include "core/identification/experiment_data.h"
#include "core/identification/experiment_file.h"
#include "core/identification/preprocessing.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/session/identified_axis.h"
#include "ui/panels/status_strip.h"
#include "ui/plots/plot_notice.h"
#include "ui/plots/plot_tools.h"
#include "ui/plots/pole_zero_plot.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace xyt::ui {

namespace {

/// The name of the fitted model's set on the pole-zero map.
constexpr const char* kModelSet = "model";

QStringList columnNames(const ExperimentTable& table) {
    QStringList names;
    for (const std::string& n : table.names)
        names << QString::fromStdString(n);
    return names;
}

/// The column whose name looks like a time column, or -1.
int guessTimeColumn(const QStringList& names) {
    for (int i = 0; i < names.size(); ++i) {
        const QString n = names[i].toLower();
        if (n == "t" || n.startsWith("time") || n == "t_s" || n == "t [s]" ||
            n == "x_value") // x_value: LVM
            return i;
    }
    return -1;
}

QString percent(double v) {
    return std::isfinite(v) ? QString::number(v, 'f', 2) : QStringLiteral("–");
}

QVector<double> toVector(const std::vector<double>& v) {
    return QVector<double>(v.begin(), v.end());
}

/// The curves' extent with room above them for the notice in the top corner (a few lines,
/// about a fifth of the plot's height): the notice does not sit on the trace.
void fitTimeAxes(QCustomPlot* plot) {
    plot->rescaleAxes();
    const QCPRange r = plot->yAxis->range();
    const double span = r.size() > 0.0 ? r.size() : 1.0;
    plot->yAxis->setRange(r.lower - 0.04 * span, r.upper + 0.22 * span);
}

/// The unit of a parameter of the continuous fit (u in V, y in mm); "" for the dimensionless
/// polynomial coefficients.
QString parameterUnit(const IdentifiedModel& m, const std::string& name) {
    if (m.spec.structure != ModelStructure::ContinuousThirdOrder)
        return {};
    if (name == "k0")
        return QStringLiteral(" mm/(V·s³)");
    if (name == "a1")
        return QStringLiteral(" 1/s");
    if (name == "a2")
        return QStringLiteral(" 1/s²");
    return {};
}

/// "name = value ± sd unit" per parameter, non-breaking inside an entry so that the label
/// wraps between entries only.
QString parameterLines(const IdentifiedModel& m) {
    QStringList entries;
    const QChar nbsp(0x00A0);
    for (std::size_t i = 0; i < m.parameters.size() && i < m.parameterNames.size(); ++i) {
        const double sd = i < m.standardDeviations.size() ? m.standardDeviations[i] : std::nan("");
        QString entry = QString::fromStdString(m.parameterNames[i]) + " = " +
                        QString::number(m.parameters[i], 'g', 6) + " ± " +
                        (std::isfinite(sd) ? QString::number(sd, 'g', 3) : QStringLiteral("–")) +
                        parameterUnit(m, m.parameterNames[i]);
        entries << entry.replace(' ', nbsp);
    }
    return entries.join(QStringLiteral("   "));
}

} // namespace

IdentificationWindow::IdentificationWindow(TuningSession* session, QWidget* parent)
    : QDialog(parent), session_(session),
      runner_(this, {[this](double fraction) { showProgress(progress_, fraction); },
                     [this](IdentifiedModel&& model, const Candidate& candidate) {
                         onFinished(std::move(model), candidate);
                     },
                     [this](const QString& error, const Candidate&) { onFailed(error); },
                     exceptionText}) {
    setWindowTitle(tr("Identify a model from data"));
    setModal(false);
    setObjectName("identificationWindow");

    // The steps make the widgets in their tab order.
    QGroupBox* dataBox = buildDataBox();
    QGroupBox* modelBox = buildModelBox();
    QScrollArea* statusArea = buildStatus();
    QHBoxLayout* useRow = buildCandidates();
    auto* left = new QWidget;
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(dataBox);
    leftLayout->addWidget(modelBox);
    leftLayout->addWidget(statusArea);
    leftLayout->addWidget(table_, 1);
    leftLayout->addWidget(parameters_);
    leftLayout->addLayout(useRow);

    buildPlots();
    auto* splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(left);
    splitter->addWidget(tabs_);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({560, 740}); // the candidates' seven columns without a scroll bar
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(splitter);
    resize(1300, 750);

    connectControls();
    updateOrderBoxes();
    clearPlots(tr("Fit a model to see it here."));
}

QGroupBox* IdentificationWindow::buildDataBox() {
    // Data: file, columns, sample time, unit, preprocessing.
    load_ = new QPushButton(tr("Load data…"));
    fileName_ = new QLabel(tr("(no file)"));
    fileName_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    loadValidation_ = new QPushButton(tr("Validation data…"));
    validationName_ = new QLabel(tr("(none: judged on the estimation data)"));
    input_ = new QComboBox;
    output_ = new QComboBox;
    time_ = new QComboBox;
    ts_ = new QDoubleSpinBox;
    ts_->setDecimals(6);
    ts_->setRange(1e-6, 1e3);
    ts_->setValue(0.001);
    ts_->setSuffix(tr(" s"));
    unit_ = new QComboBox;
    unit_->addItems({tr("mm"), tr("m")});
    t0_ = new QDoubleSpinBox;
    t1_ = new QDoubleSpinBox;
    for (QDoubleSpinBox* b : {t0_, t1_}) {
        b->setDecimals(4);
        b->setRange(0.0, 1e6);
        b->setSuffix(tr(" s"));
    }
    t0_->setToolTip(tr("Range of the record to use; 0 to 0 uses all of it"));
    t1_->setToolTip(t0_->toolTip());
    detrend_ = new QCheckBox(tr("Remove trends"));
    detrend_->setToolTip(tr("Remove a straight line fitted by least squares from the input and "
                            "the output before the fit (else their means)"));
    load_->setToolTip(tr("Read a logged experiment: CSV/TSV, LabVIEW .lvm or MATLAB .mat, with "
                         "the input in V and the position"));
    loadValidation_->setToolTip(tr("A second record of the same axis on which the candidates' "
                                   "fit is judged (else on the estimation data)"));
    input_->setToolTip(tr("The column of the command u (V) sent to the amplifier"));
    output_->setToolTip(tr("The column of the measured position y"));
    time_->setToolTip(tr("The column of the time (s), or none: the sample time Ts below"));
    ts_->setToolTip(tr("Sample time Ts (s) of the record when it has no time column"));
    unit_->setToolTip(tr("The unit of the output column: mm, or m (converted to mm)"));
    decimate_ = new QSpinBox;
    decimate_->setRange(1, 1000);
    decimate_->setToolTip(tr("Keep every n-th sample after an anti-alias filter (1: all)"));

    auto* dataBox = new QGroupBox(tr("Data"));
    auto* dataForm = new QFormLayout(dataBox);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(load_);
    fileRow->addWidget(fileName_, 1);
    dataForm->addRow(fileRow);
    dataForm->addRow(tr("Input (V):"), input_);
    dataForm->addRow(tr("Output:"), output_);
    auto* unitRow = new QHBoxLayout;
    unitRow->addWidget(unit_);
    unitRow->addStretch();
    dataForm->addRow(tr("Output unit:"), unitRow);
    dataForm->addRow(tr("Time:"), time_);
    dataForm->addRow(tr("Ts:"), ts_);
    auto* rangeRow = new QHBoxLayout;
    rangeRow->addWidget(t0_);
    rangeRow->addWidget(new QLabel(tr("to")));
    rangeRow->addWidget(t1_);
    dataForm->addRow(tr("Range:"), rangeRow);
    auto* prepRow = new QHBoxLayout;
    prepRow->addWidget(detrend_);
    prepRow->addWidget(new QLabel(tr("Decimate:")));
    prepRow->addWidget(decimate_);
    dataForm->addRow(prepRow);
    auto* validationRow = new QHBoxLayout;
    validationRow->addWidget(loadValidation_);
    validationRow->addWidget(validationName_, 1);
    dataForm->addRow(validationRow);
    return dataBox;
}

QGroupBox* IdentificationWindow::buildModelBox() {
    // Model: structure, orders, search.
    structure_ = new QComboBox;
    structure_->addItem(tr("ARX"), static_cast<int>(ModelStructure::Arx));
    structure_->addItem(tr("OE"), static_cast<int>(ModelStructure::Oe));
    structure_->addItem(tr("BJ"), static_cast<int>(ModelStructure::Bj));
    structure_->addItem(tr("GT3 continuous"),
                        static_cast<int>(ModelStructure::ContinuousThirdOrder));
    auto* modelBox = new QGroupBox(tr("Model"));
    auto* modelForm = new QFormLayout(modelBox);
    modelForm->addRow(tr("Structure:"), structure_);
    structure_->setToolTip(tr("ARX: A y = B u + e by least squares; OE: y = B/F u + e and BJ: "
                              "y = B/F u + C/D e by prediction error (Levenberg–Marquardt); GT3: "
                              "Braga et al.'s k0/(s³ + a1 s² + a2 s) fitted to the output"));
    auto* orderRow = new QHBoxLayout;
    for (const auto& [name, value, minimum] :
         {std::tuple{"na", 2, 0}, std::tuple{"nb", 3, 1}, std::tuple{"nc", 1, 0},
          std::tuple{"nd", 1, 0}, std::tuple{"nf", 2, 0}, std::tuple{"nk", 1, 0}}) {
        auto* box = new QSpinBox;
        box->setRange(minimum, 100);
        box->setValue(value);
        box->setObjectName(name);
        box->setToolTip(tr("Order %1 of the model: na, nb, nc, nd, nf the numbers of "
                           "coefficients of A, B, C, D, F; nk the input delay in samples")
                            .arg(QString::fromLatin1(name)));
        orderRow->addWidget(new QLabel(QString::fromLatin1(name)));
        orderRow->addWidget(box);
        orders_.emplace_back(QString::fromLatin1(name), box);
    }
    orderRow->addStretch();
    modelForm->addRow(orderRow);
    maxIterations_ = new QSpinBox;
    maxIterations_->setRange(1, 100000);
    maxIterations_->setValue(100);
    maxIterations_->setToolTip(tr("The most Levenberg–Marquardt iterations of an OE, BJ or GT3 "
                                  "fit before it stops with the best estimate so far"));
    modelForm->addRow(tr("Max iterations:"), maxIterations_);
    fit_ = new QPushButton(tr("Fit"));
    fit_->setEnabled(false);
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setEnabled(false);
    fit_->setToolTip(tr("Estimate the model of the chosen structure and orders; it is added to "
                        "the candidates with its fit, AIC and residual tests"));
    cancel_->setToolTip(tr("Stop the fit running"));
    progress_ = new QProgressBar;
    progress_->setRange(0, 100);
    progress_->setValue(0);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(fit_);
    runRow->addWidget(cancel_);
    runRow->addWidget(progress_, 1);
    modelForm->addRow(runRow);
    return modelBox;
}

QScrollArea* IdentificationWindow::buildStatus() {
    status_ = new QLabel;
    status_->setWordWrap(true);
    status_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    // At most five lines high, scrolling beyond: a long message never squeezes the candidates.
    auto* statusArea = new QScrollArea;
    statusArea->setWidget(status_);
    statusArea->setWidgetResizable(true);
    statusArea->setFrameShape(QFrame::NoFrame);
    statusArea->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    statusArea->setMaximumHeight(5 * status_->fontMetrics().lineSpacing() + 6);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    setStatus(tr("Load a record of the axis (input in V, output position) to begin."));
    return statusArea;
}

QHBoxLayout* IdentificationWindow::buildCandidates() {
    // Candidates.
    table_ = new QTableWidget(0, 7);
    table_->setHorizontalHeaderLabels({tr("Model"), tr("Status"), tr("Fit % est"), tr("Fit % val"),
                                       tr("AIC"), tr("Residuals"), tr("NMP")});
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->setVisible(false);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    // The selected candidate's estimate: what "Use for axis" would take, before it is taken.
    parameters_ = new QLabel;
    parameters_->setObjectName("identificationParameters");
    parameters_->setWordWrap(true);
    parameters_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    parameters_->setToolTip(tr("The selected model's parameters, each ± one standard deviation"));
    parameters_->hide();
    useX_ = new QPushButton(tr("Use for axis X"));
    useY_ = new QPushButton(tr("Use for axis Y"));
    useX_->setToolTip(tr("Make the selected model axis X's plant (an undoable step): GT3 as "
                         "the Guillemin–Truxal plant, ARX/OE/BJ as the pole-placement model"));
    useY_->setToolTip(tr("Make the selected model axis Y's plant (an undoable step)"));
    useX_->setEnabled(false);
    useY_->setEnabled(false);
    // The record's measured frequency response (Welch), drawn against the model of an axis.
    frequencyX_ = new QPushButton(tr("Response → X"));
    frequencyY_ = new QPushButton(tr("Response → Y"));
    for (QPushButton* b : {frequencyX_, frequencyY_})
        b->setToolTip(tr("Welch's estimate of y/u (Hann window, 50 % overlap) with its coherence, "
                         "drawn over the axis' model in the Vibration view"));
    auto* useRow = new QHBoxLayout;
    useRow->addWidget(useX_);
    useRow->addWidget(useY_);
    useRow->addStretch();
    useRow->addWidget(frequencyX_);
    useRow->addWidget(frequencyY_);
    return useRow;
}

void IdentificationWindow::connectControls() {
    connect(load_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Load experiment data"), QString(),
            tr("Experiment files (*.csv *.tsv *.txt *.lvm *.mat);;All files (*)"));
        if (!path.isEmpty())
            loadFile(path);
    });
    connect(loadValidation_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Load validation data"), QString(),
            tr("Experiment files (*.csv *.tsv *.txt *.lvm *.mat);;All files (*)"));
        if (!path.isEmpty())
            loadValidationFile(path);
    });
    connect(time_, &QComboBox::currentIndexChanged, this, [this](int index) {
        ts_->setEnabled(index == 0);
        previewRecord();
    });
    for (QComboBox* box : {input_, output_, unit_})
        connect(box, &QComboBox::currentIndexChanged, this, [this] { previewRecord(); });
    connect(ts_, &QDoubleSpinBox::valueChanged, this, [this] { previewRecord(); });
    connect(session_->undoStack(), &QUndoStack::indexChanged, this, [this](int index) {
        if (!usedStep_)
            return;
        if (index < usedIndex_ || session_->undoStack()->command(usedIndex_ - 1) != usedStep_) {
            usedStep_ = nullptr; // the step the status names is gone: say what is current instead
            showSelectionStatus();
        }
    });
    connect(structure_, &QComboBox::currentIndexChanged, this,
            &IdentificationWindow::updateOrderBoxes);
    connect(fit_, &QPushButton::clicked, this, &IdentificationWindow::fit);
    connect(cancel_, &QPushButton::clicked, this, &IdentificationWindow::cancel);
    connect(frequencyX_, &QPushButton::clicked, this, [this] { showFrequencyResponse(0); });
    connect(frequencyY_, &QPushButton::clicked, this, [this] { showFrequencyResponse(1); });
    connect(useX_, &QPushButton::clicked, this, [this] { useForAxis(0); });
    connect(useY_, &QPushButton::clicked, this, [this] { useForAxis(1); });
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto rows = table_->selectionModel()->selectedRows();
        showCandidate(rows.isEmpty() ? -1 : rows.front().row());
        if (selectedCandidate()) // the message area follows the row (an error stays until then)
            showSelectionStatus();
    });
}

IdentificationWindow::~IdentificationWindow() = default; // the runner cancels and waits

void IdentificationWindow::buildPlots() {
    tabs_ = new QTabWidget;
    const auto makePlot = [](const QString& objectName) {
        auto* plot = new QCustomPlot;
        plot->setObjectName(objectName);
        plot->setMinimumSize(420, 300);
        setupInteractivePlot(plot);
        styleAxisRect(plot->axisRect());
        return plot;
    };

    timePlot_ = makePlot("identificationTimePlot");
    measured_ = timePlot_->addGraph();
    measured_->setName(tr("measured y"));
    // Wide and pale under the model's thin line: both stay visible where they coincide.
    measured_->setPen(QPen(colors::snapshot, 3.0));
    simulated_ = timePlot_->addGraph();
    simulated_->setName(tr("simulated ŷ (model)"));
    simulated_->setPen(QPen(colors::output, 1.2));
    timePlot_->xAxis->setLabel(tr("t (s)"));
    timePlot_->yAxis->setLabel(tr("position (mm)"));
    timePlot_->legend->setVisible(true);
    placeLegendBelow(timePlot_, 1, 2);
    timeNotice_ = std::make_unique<PlotNotice>(timePlot_, timePlot_->axisRect(),
                                               Qt::AlignTop | Qt::AlignRight);
    timePlot_->setToolTip(tr("The measured output y (mm) against time (s) and the selected "
                             "model's simulated output ŷ from the same input"));
    tabs_->addTab(timePlot_, tr("Output"));

    // Two stacked axis rects: residual autocorrelation, input-residual cross-correlation.
    residualPlot_ = makePlot("identificationResidualPlot");
    residualPlot_->setToolTip(tr("The residuals' autocorrelation and their cross-correlation "
                                 "with the input against the lag, with the 99 % confidence band "
                                 "of white, independent residuals"));
    QCPAxisRect* autoRect = residualPlot_->axisRect();
    auto* crossRect = new QCPAxisRect(residualPlot_);
    styleAxisRect(crossRect);
    residualPlot_->plotLayout()->addElement(1, 0, crossRect);
    const auto stems = [this](QCPAxisRect* rect, QCPGraph*& stemsGraph, QCPGraph*(&bound)[2],
                              const QString& yLabel, const QString& xLabel) {
        stemsGraph =
            residualPlot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        stemsGraph->setLineStyle(QCPGraph::lsImpulse);
        stemsGraph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 4));
        stemsGraph->setPen(QPen(colors::output, 1.5));
        for (QCPGraph*& b : bound) {
            b = residualPlot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            b->setPen(QPen(colors::limit, 1.0, Qt::DashLine));
        }
        rect->axis(QCPAxis::atLeft)->setLabel(yLabel);
        rect->axis(QCPAxis::atBottom)->setLabel(xLabel);
    };
    stems(autoRect, autoStems_, autoBound_, tr("residual autocorr."), tr("lag (samples)"));
    stems(crossRect, crossStems_, crossBound_, tr("input–residual corr."), tr("lag (samples)"));
    residualNotice_ =
        std::make_unique<PlotNotice>(residualPlot_, autoRect, Qt::AlignTop | Qt::AlignRight);
    tabs_->addTab(residualPlot_, tr("Residuals"));

    // The workbench's own map: the same marks, z-plane grid, unit circle and view fitting.
    pzPlot_ = new PoleZeroPlot;
    pzPlot_->setObjectName("identificationPoleZeroPlot");
    pzPlot_->setMinimumSize(420, 300);
    tabs_->addTab(pzPlot_, tr("Poles and zeros"));
}

QSpinBox* IdentificationWindow::orderBox(const QString& name) const {
    for (const auto& [n, box] : orders_)
        if (n == name)
            return box;
    return nullptr;
}

void IdentificationWindow::updateOrderBoxes() {
    const auto structure = static_cast<ModelStructure>(structure_->currentData().toInt());
    QStringList used;
    switch (structure) {
    case ModelStructure::Arx:
        used = {"na", "nb", "nk"};
        break;
    case ModelStructure::Oe:
        used = {"nb", "nf", "nk"};
        break;
    case ModelStructure::Bj:
        used = {"nb", "nc", "nd", "nf", "nk"};
        break;
    case ModelStructure::ContinuousThirdOrder:
        break;
    }
    for (const auto& [name, box] : orders_)
        box->setEnabled(used.contains(name));
    maxIterations_->setEnabled(structure != ModelStructure::Arx);
}

void IdentificationWindow::setStatus(const QString& text, bool isError) {
    setStatusText(status_, text, isError);
}

QString IdentificationWindow::statusText() const {
    return status_->text();
}

bool IdentificationWindow::loadFile(const QString& path) {
    try {
        ExperimentTable table = readExperimentTable(path.toStdString(), 1);
        const QStringList names = columnNames(table);
        // The candidates were fitted to the previous file: they go with it (a running fit too).
        const bool hadCandidates = !candidates_.empty() || isRunning();
        runner_.discard();
        cancel_->setEnabled(false);
        progress_->setValue(0);
        candidates_.clear();
        {
            const QSignalBlocker blockTable(table_);
            table_->setRowCount(0);
        }
        clearPlots(tr("Fit a model to see it here."));
        usedStep_ = nullptr;
        const QSignalBlocker b1(input_), b2(output_), b3(time_), b4(ts_), b5(t0_), b6(t1_);
        t0_->setValue(0.0); // the new record's whole range (previewRecord shows it)
        t1_->setValue(0.0);
        input_->clear();
        output_->clear();
        time_->clear();
        input_->addItems(names);
        output_->addItems(names);
        time_->addItem(tr("(sample time)"));
        time_->addItems(names);
        const int timeLike = guessTimeColumn(names);
        const int timeColumn = table.sampleTimeSeconds ? -1 : timeLike;
        time_->setCurrentIndex(timeColumn + 1);
        ts_->setEnabled(timeColumn < 0);
        if (table.sampleTimeSeconds)
            ts_->setValue(*table.sampleTimeSeconds);
        // The first two columns that are not the time column: command, then position.
        QList<int> others;
        for (int i = 0; i < names.size(); ++i)
            if (i != timeLike)
                others << i;
        input_->setCurrentIndex(others.value(0, 0));
        output_->setCurrentIndex(others.value(1, others.value(0, 0)));
        experiment_ = std::move(table);
        fileName_->setText(QFileInfo(path).fileName());
        fileName_->setToolTip(path);
        fit_->setEnabled(!isRunning());
        QString text =
            tr("%1: %2 columns, %3 rows%4. Pick the columns and press Fit.")
                .arg(QFileInfo(path).fileName())
                .arg(names.size())
                .arg(experiment_->rowNumbers.size())
                .arg(experiment_->sampleTimeSeconds
                         ? tr(", Ts = %1 s stated by the file").arg(*experiment_->sampleTimeSeconds)
                         : QString());
        if (hadCandidates)
            text += "\n" + tr("The candidates fitted to the previous file were cleared.");
        for (const auto& w : experiment_->warnings)
            text += "\n" + diagnosticText(w);
        const QString problem = previewRecord();
        if (!problem.isEmpty())
            text += "\n" + tr("These columns cannot be used yet: %1").arg(problem);
        setStatus(text);
        return true;
    } catch (const std::exception& e) { // InvalidInput, FileError: the message names the place
        experiment_.reset();
        input_->clear();
        output_->clear();
        time_->clear();
        fileName_->setText(tr("(no file)"));
        fit_->setEnabled(false);
        wholeRange_.reset();
        table_->clearSelection();
        clearPlots(tr("No data loaded."));
        setStatus(tr("Cannot read %1: %2").arg(QFileInfo(path).fileName(), exceptionText(e)), true);
        return false;
    }
}

bool IdentificationWindow::loadValidationFile(const QString& path) {
    if (path.isEmpty()) {
        validationExperiment_.reset();
        validationName_->setText(tr("(none: judged on the estimation data)"));
        return true;
    }
    try {
        validationExperiment_ = readExperimentTable(path.toStdString(), 1);
        validationName_->setText(QFileInfo(path).fileName());
        validationName_->setToolTip(path);
        setStatus(tr("Validation data: %1 (%2 rows).")
                      .arg(QFileInfo(path).fileName())
                      .arg(validationExperiment_->rowNumbers.size()));
        return true;
    } catch (const std::exception& e) {
        validationExperiment_.reset();
        validationName_->setText(tr("(none: judged on the estimation data)"));
        setStatus(tr("Cannot read %1: %2").arg(QFileInfo(path).fileName(), exceptionText(e)), true);
        return false;
    }
}

ExperimentColumns IdentificationWindow::columns(const ExperimentTable& table) const {
    ExperimentColumns c;
    c.input = input_->currentText().toStdString();
    c.output = output_->currentText().toStdString();
    if (time_->currentIndex() > 0)
        c.time = time_->currentText().toStdString();
    else if (table.sampleTimeSeconds && std::abs(ts_->value() - *table.sampleTimeSeconds) <= 1e-12)
        c.fileSampleTime = true;
    else
        c.sampleTimeSeconds = ts_->value();
    c.outputScale.unit = unit_->currentIndex() == 1 ? OutputUnit::Metres : OutputUnit::Millimetres;
    return c;
}

IoData IdentificationWindow::record(const ExperimentTable& table) const {
    const ExperimentColumns c = columns(table);
    PreprocessingSteps steps;
    const double t0 = t0_->value(), t1 = t1_->value();
    if (!rangeIsWhole()) {
        if (!(t1 > t0))
            throw InvalidInput(
                "range",
                tr("the end must be after the start (0 to 0 uses the whole record)").toStdString());
        steps.rangeSeconds = std::array<double, 2>{t0, t1};
    }
    steps.offsets = detrend_->isChecked() ? OffsetRemoval::Trends : OffsetRemoval::None;
    steps.decimateFactor = decimate_->value();
    return preprocess(experimentData(table, c), steps);
}

void IdentificationWindow::fit() {
    if (isRunning() || !experiment_)
        return;
    IdentificationSpec spec;
    spec.structure = static_cast<ModelStructure>(structure_->currentData().toInt());
    const auto order = [this](const char* name) {
        return orderBox(QString::fromLatin1(name))->value();
    };
    spec.arx = {order("na"), order("nb"), order("nk")};
    spec.oe = {order("nb"), order("nf"), order("nk")};
    spec.bj = {order("nb"), order("nc"), order("nd"), order("nf"), order("nk")};
    spec.search.maxIterations = maxIterations_->value();
    Candidate candidate;
    try {
        candidate.estimation = record(*experiment_);
        if (validationExperiment_)
            candidate.validation = record(*validationExperiment_);
    } catch (const std::exception& e) {
        table_->clearSelection();
        clearPlots(tr("No model: the data could not be used."));
        setStatus(tr("Cannot fit: %1").arg(exceptionText(e)), true);
        emit fitFinished();
        return;
    }
    if (spec.structure == ModelStructure::ContinuousThirdOrder) {
        // The plant integrates: its model starts at rest at position 0, so the record's initial
        // position is taken off (as xytune-cli identify does), and said.
        for (IoData* d :
             {&candidate.estimation, candidate.validation ? &*candidate.validation : nullptr}) {
            const std::optional<double> y0 = d ? subtractInitialPosition(*d) : std::nullopt;
            if (!y0)
                continue;
            candidate.notes
                << tr("%1: the first sample %2 mm was subtracted (the plant starts at rest at 0); "
                      "the fit estimates where the table stood")
                       .arg(QString::fromStdString(d->source))
                       .arg(*y0, 0, 'g', 10);
        }
    }
    const IoData estimation = candidate.estimation;
    const std::optional<IoData> validation = candidate.validation;
    // The work holds copies of its inputs only; the candidate is the result's stamp.
    runner_.start(candidate, [spec, estimation, validation](const JobProgress& progress) mutable {
        spec.search.progress = progress;
        return identifyModel(estimation, validation ? &*validation : nullptr, spec);
    });
    progress_->setValue(0);
    fit_->setEnabled(false);
    cancel_->setEnabled(true);
    setStatus(tr("Fitting %1 to %2 samples…")
                  .arg(QString::fromStdString(spec.describe()))
                  .arg(candidate.estimation.size()));
}

bool IdentificationWindow::showFrequencyResponse(int axis) {
    if (!experiment_) {
        setStatus(tr("No frequency response: load a record first"), true);
        return false;
    }
    try {
        const IoData d = record(*experiment_);
        auto measured = std::make_shared<TuningSession::MeasuredResponse>();
        measured->estimate = estimateFrequencyResponse(d.u, d.y, d.tsSeconds);
        measured->source = QString::fromStdString(d.source);
        const auto& e = measured->estimate;
        session_->setMeasuredResponse(axis, std::move(measured));
        setStatus(tr("Frequency response of %1: %2 averages of %3 samples, drawn in the Vibration "
                     "view of axis %4")
                      .arg(QString::fromStdString(d.source))
                      .arg(e.segments.count)
                      .arg(e.segments.segmentLength)
                      .arg(axis == 0 ? "X" : "Y"));
        return true;
    } catch (const std::exception& e) {
        setStatus(tr("No frequency response: %1").arg(exceptionText(e)), true);
        return false;
    }
}

void IdentificationWindow::cancel() {
    if (!runner_.isRunning())
        return;
    runner_.cancel();
    cancel_->setEnabled(false);
    setStatus(tr("Cancelling…"));
}

void IdentificationWindow::onFailed(const QString& error) {
    cancel_->setEnabled(false);
    fit_->setEnabled(experiment_.has_value());
    progress_->setValue(100);
    table_->clearSelection();
    clearPlots(tr("No model: the fit failed."));
    setStatus(tr("The fit failed: %1").arg(error), true);
    emit fitFinished();
}

void IdentificationWindow::onFinished(IdentifiedModel&& model, const Candidate& fitted) {
    cancel_->setEnabled(false);
    fit_->setEnabled(experiment_.has_value());
    progress_->setValue(100);
    Candidate candidate = fitted;
    candidate.model = std::move(model);
    const IdentifiedModel& m = candidate.model;
    QString text =
        tr("%1: %2").arg(QString::fromStdString(m.structure),
                         coreText("xyt::EstimationStatus", estimationStatusName(m.status)));
    if (!m.message.text.empty())
        text += tr(" (%1)").arg(diagnosticText(m.message));
    for (const QString& n : candidate.notes)
        text += "\n" + n;
    if (m.plant)
        text += "\n" + tr("Estimated initial position: %1 mm").arg(m.initialPositionMm, 0, 'g', 6);
    for (const auto& w : m.warnings)
        text += "\n" + diagnosticText(w);
    if (!m.hasEstimate()) {
        setStatus(tr("No estimate: %1").arg(text), true);
        emit fitFinished();
        return;
    }
    candidate.message = text;
    candidate.messageIsError = m.status != EstimationStatus::Converged;
    candidates_.push_back(std::move(candidate));
    addRow(candidates_.back());
    setStatus(text, candidates_.back().messageIsError);
    table_->selectRow(static_cast<int>(candidates_.size()) - 1);
    emit fitFinished();
}

void IdentificationWindow::addRow(const Candidate& c) {
    const IdentifiedModel& m = c.model;
    const int row = table_->rowCount();
    table_->insertRow(row);
    const auto set = [&](int column, const QString& text) {
        table_->setItem(row, column, new QTableWidgetItem(text));
    };
    // The continuous fit's long formula is the tooltip; "GT3" keeps the seven columns in view.
    set(0, m.spec.structure == ModelStructure::ContinuousThirdOrder
               ? tr("GT3")
               : QString::fromStdString(m.structure));
    set(1, coreText("xyt::EstimationStatus", estimationStatusName(m.status)));
    set(2, percent(m.fit.estimationSimulation.fitPercent));
    set(3, m.fit.validationSimulation ? percent(m.fit.validationSimulation->fitPercent)
                                      : QStringLiteral("–"));
    set(4, m.criteria.samples > 0 ? QString::number(m.criteria.aic, 'f', 2) : QStringLiteral("–"));
    set(5, m.residualTests.samples == 0 ? QStringLiteral("–")
           : m.residualTests.passed()   ? tr("pass")
                                        : tr("fail"));
    set(6, m.roots.nonMinimumPhase ? tr("yes") : tr("no"));
    table_->item(row, 0)->setToolTip(QString::fromStdString(m.spec.describe()));
}

const IdentificationWindow::Candidate* IdentificationWindow::selectedCandidate() const {
    return shown_ >= 0 && shown_ < static_cast<int>(candidates_.size())
               ? &candidates_[static_cast<std::size_t>(shown_)]
               : nullptr;
}

void IdentificationWindow::clearPlots(const QString& reason) {
    shown_ = -1;
    useX_->setEnabled(false);
    useY_->setEnabled(false);
    parameters_->clear();
    parameters_->hide();
    clearWithNotice(timePlot_, *timeNotice_, {measured_, simulated_}, reason);
    clearWithNotice(
        residualPlot_, *residualNotice_,
        {autoStems_, autoBound_[0], autoBound_[1], crossStems_, crossBound_[0], crossBound_[1]},
        reason);
    pzPlot_->showNoResult(tr("Pole-zero map (z-plane)"), reason);
    // Now, not queued: not one frame of the old candidate's curves next to an error.
    for (QCustomPlot* plot : {timePlot_, residualPlot_, static_cast<QCustomPlot*>(pzPlot_)})
        plot->replot();
}

void IdentificationWindow::showCandidate(int index) {
    if (index < 0 || index >= static_cast<int>(candidates_.size())) {
        clearPlots(tr("Select a candidate to see it here."));
        return;
    }
    shown_ = index;
    const Candidate& c = candidates_[static_cast<std::size_t>(index)];
    const IdentifiedModel& m = c.model;
    useX_->setEnabled(true);
    useY_->setEnabled(true);
    parameters_->setText(tr("Parameters (± 1 SD): %1").arg(parameterLines(m)));
    parameters_->show();

    // Output: measured and simulated over time.
    const IoData& d = c.estimation;
    QVector<double> t(static_cast<int>(d.size()));
    for (int k = 0; k < t.size(); ++k)
        t[k] = d.startSeconds + k * d.tsSeconds;
    measured_->setData(t, toVector(d.y), true);
    const std::vector<double>& yhat = m.fit.estimationSimulation.yhat;
    simulated_->setData(t.mid(0, static_cast<int>(yhat.size())), toVector(yhat), true);
    timeNotice_->setSevere(false);
    timeNotice_->setLines(c.notes);
    fitTimeAxes(timePlot_);
    timePlot_->replot();

    // Residual tests.
    const auto drawTest = [](const CorrelationTest& test, QCPGraph* stems, QCPGraph*(&bound)[2]) {
        QVector<double> lags, values;
        for (std::size_t i = 0; i < test.lags.size() && i < test.values.size(); ++i) {
            lags << test.lags[i];
            values << test.values[i];
        }
        stems->setData(lags, values, true);
        const double lo = lags.isEmpty() ? 0.0 : lags.front(),
                     hi = lags.isEmpty() ? 1.0 : lags.back();
        bound[0]->setData({lo, hi}, {test.bound, test.bound});
        bound[1]->setData({lo, hi}, {-test.bound, -test.bound});
        QCPAxis* x = stems->keyAxis();
        QCPAxis* y = stems->valueAxis();
        x->setRange(lo - 1.0, hi + 1.0);
        double top = 1.5 * test.bound;
        for (double v : values)
            top = std::max(top, 1.1 * std::abs(v));
        y->setRange(-top, top);
        stems->setName(test.passed ? QObject::tr("within ±bound")
                                   : QObject::tr("%1 lags outside").arg(test.outsideCount));
    };
    drawTest(m.residualTests.autocorrelation, autoStems_, autoBound_);
    drawTest(m.residualTests.crossCorrelation, crossStems_, crossBound_);
    autoStems_->valueAxis()->setLabel(
        tr("residual autocorr. (%1)")
            .arg(m.residualTests.autocorrelation.passed ? tr("pass") : tr("fail")));
    crossStems_->valueAxis()->setLabel(
        tr("input–residual corr. (%1)")
            .arg(m.residualTests.crossCorrelation.passed ? tr("pass") : tr("fail")));
    residualNotice_->setLines({});
    residualPlot_->replot();

    // Poles and zeros in the z-plane, drawn as the workbench draws its own.
    PoleZeroSet set{kModelSet, m.roots.tsSeconds, m.roots.poles, m.roots.zeros};
    pzPlot_->showSets({set},
                      m.roots.nonMinimumPhase
                          ? tr("Pole-zero map (z-plane): a zero outside the unit circle (NMP)")
                          : tr("Pole-zero map (z-plane)"));
    QStringList notes;
    for (const auto& n : m.roots.notes)
        notes << diagnosticText(n);
    if (m.roots.integrating)
        notes << tr("A pole at z = 1: the model integrates, as the position of a motor axis does "
                    "(every other pole is inside the unit circle).");
    else if (!m.roots.stable)
        notes << tr("A pole is on or outside the unit circle: the model is unstable.");
    pzPlot_->setNotes(notes);
    pzPlot_->replot();
}

QCPGraph* IdentificationWindow::polesGraph() const {
    return pzPlot_->polesGraph(kModelSet);
}

QCPGraph* IdentificationWindow::zerosGraph() const {
    return pzPlot_->zerosGraph(kModelSet);
}

QString IdentificationWindow::poleZeroNoticeText() const {
    return pzPlot_->noticeText();
}

bool IdentificationWindow::rangeIsWhole() const {
    // 0 to 0, or the record's own range as previewRecord showed it (the boxes round to 0.1 ms,
    // which must not cut the last sample off).
    const double t0 = t0_->value(), t1 = t1_->value();
    return (t0 == 0.0 && t1 == 0.0) ||
           (wholeRange_ && t0 == (*wholeRange_)[0] && t1 == (*wholeRange_)[1]);
}

QString IdentificationWindow::parametersText() const {
    return parameters_->text();
}

void IdentificationWindow::showSelectionStatus() {
    if (const Candidate* c = selectedCandidate())
        setStatus(c->message, c->messageIsError);
    else
        setStatus(experiment_
                      ? tr("Pick the columns and press Fit.")
                      : tr("Load a record of the axis (input in V, output position) to begin."));
}

QString IdentificationWindow::previewRecord() {
    if (!experiment_)
        return {};
    const QSignalBlocker b1(ts_), b2(t0_), b3(t1_);
    try {
        const IoData d = experimentData(*experiment_, columns(*experiment_));
        const double first = d.startSeconds;
        const double last = d.startSeconds + static_cast<double>(d.size() - 1) * d.tsSeconds;
        ts_->setValue(
            d.tsSeconds);     // the time column's (or the file's) sample time, not the last file's
        if (rangeIsWhole()) { // a range the user chose stays
            t0_->setValue(first);
            t1_->setValue(last);
            wholeRange_ = std::array<double, 2>{t0_->value(), t1_->value()};
        }
        if (shown_ < 0) { // a candidate's plot is not replaced by the raw record
            clearPlots(tr("Fit a model to see it here."));
            QVector<double> t(static_cast<int>(d.size()));
            for (int k = 0; k < t.size(); ++k)
                t[k] = d.startSeconds + k * d.tsSeconds;
            measured_->setData(t, toVector(d.y), true);
            timeNotice_->setSevere(false);
            timeNotice_->setLines(
                {tr("The record: %1 samples, %2 s to %3 s, Ts = %4 s (no model yet)")
                     .arg(d.size())
                     .arg(first, 0, 'g', 6)
                     .arg(last, 0, 'g', 6)
                     .arg(d.tsSeconds, 0, 'g', 6)});
            fitTimeAxes(timePlot_);
            timePlot_->replot();
        }
        return {};
    } catch (const std::exception& e) {
        if (rangeIsWhole()) {
            t0_->setValue(0.0);
            t1_->setValue(0.0);
            wholeRange_.reset();
        }
        if (shown_ < 0)
            clearPlots(tr("The record cannot be drawn: %1").arg(exceptionText(e)));
        return exceptionText(e);
    }
}

void IdentificationWindow::useForAxis(int axis) {
    const Candidate* c = selectedCandidate();
    if (!c)
        return;
    try {
        const AxisSettings next = axisWithIdentifiedModel(
            session_->session().axes.at(static_cast<std::size_t>(axis)), c->model, c->estimation);
        const bool changed = session_->setAxis(
            axis, next,
            tr("Use the identified %1 for axis %2")
                .arg(QString::fromStdString(c->model.structure), axis == 0 ? tr("X") : tr("Y")));
        QUndoStack* stack = session_->undoStack();
        usedIndex_ = stack->index();
        usedStep_ = changed ? stack->command(usedIndex_ - 1) : nullptr;
        setStatus(
            tr("Axis %1 now uses the identified %2 (Edit › Undo restores the previous plant).")
                .arg(axis == 0 ? tr("X") : tr("Y"), QString::fromStdString(c->model.structure)));
    } catch (const std::exception& e) {
        setStatus(tr("Cannot use this model: %1").arg(exceptionText(e)), true);
    }
}

} // namespace xyt::ui
