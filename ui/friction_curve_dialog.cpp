// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/friction_curve_dialog.h"

#include "core/identification/experiment_file.h"
#include "core/io/file_io.h"
#include "core/model/errors.h"
#include "core/model/table_friction.h"
#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {

const char* const kRoles[4] = {"t", "r", "y", "u"};

/// The fitted curve of @p e at velocity @p v (mm/s).
double curve(const FrictionEstimate& e, double v) {
    return stribeckFriction(e.coulombVolts, e.hasStribeck ? e.staticVolts : e.coulombVolts,
                            e.stribeckVelocityMmPerS, e.viscousVoltsPerMmPerS, v,
                            v > 0.0 ? 1.0 : -1.0);
}

QString withStd(double v, double sd, const QString& unit) {
    return QStringLiteral("%1 ± %2 %3").arg(v, 0, 'g', 5).arg(sd, 0, 'g', 2).arg(unit);
}

} // namespace

FrictionCurveDialog::FrictionCurveDialog(TuningSession* session, QWidget* parent)
    : QDialog(parent), session_(session) {
    setWindowTitle(tr("Friction curve from a jog log"));
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    auto* open = new QPushButton(tr("&Open log…"), this);
    file_ = new QLabel(tr("No log: run xytune-cli excite --signal jog, or log jogs from the "
                          "machine (time, reference, position, command)"),
                       this);
    file_->setWordWrap(true);
    top->addWidget(open);
    top->addWidget(file_, 1);
    layout->addLayout(top);
    auto* form = new QFormLayout;
    const QString labels[4] = {tr("Time (s)"), tr("Reference (mm)"), tr("Position (mm)"),
                               tr("Command (V)")};
    auto* columnRow = new QHBoxLayout;
    for (int i = 0; i < 4; ++i) {
        columns_[i] = new QComboBox(this);
        columns_[i]->setAccessibleName(labels[i]);
        columns_[i]->setToolTip(tr("The log's column of the %1").arg(labels[i]));
        columnRow->addWidget(new QLabel(labels[i], this));
        columnRow->addWidget(columns_[i], 1);
        connect(columns_[i], &QComboBox::activated, this, [this] { runEstimate(); });
    }
    form->addRow(columnRow);
    layout->addLayout(form);
    plot_ = new QCustomPlot(this);
    plot_->setMinimumSize(560, 340);
    plot_->setToolTip(tr("The Stribeck curve: each jog's steady command (V, mean ± one standard "
                         "deviation over its cruise) against its velocity (mm/s), and the fitted "
                         "friction curve sign(v)(Fc + (Fs − Fc) exp(−(v/vs)²)) + bv v"));
    open->setToolTip(tr("Read a jog log (CSV with time, reference, position and command "
                        "columns) and estimate the friction levels"));
    styleAxisRect(plot_->axisRect());
    plot_->xAxis->setLabel(tr("velocity (mm/s)"));
    plot_->yAxis->setLabel(tr("steady command (V)"));
    points_ = plot_->addGraph();
    points_->setName(tr("jogs (mean ± 1 sd)"));
    points_->setLineStyle(QCPGraph::lsNone);
    points_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colors::output, 6));
    bars_ = new QCPErrorBars(plot_->xAxis, plot_->yAxis);
    bars_->setDataPlottable(points_);
    bars_->setPen(QPen(colors::output));
    bars_->removeFromLegend();
    forward_ = plot_->addGraph();
    forward_->setName(tr("fitted curve"));
    forward_->setPen(QPen(colors::error, 1.6));
    backward_ = plot_->addGraph();
    backward_->setPen(QPen(colors::error, 1.6));
    backward_->removeFromLegend();
    plot_->legend->setVisible(true);
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    setupInteractivePlot(plot_);
    layout->addWidget(plot_, 1);
    result_ = new QLabel(this);
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(result_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    apply_ = buttons->addButton(tr("&Use for the current axis"), QDialogButtonBox::ApplyRole);
    apply_->setToolTip(tr("Set the estimated levels as the current axis' table friction (one "
                          "undoable step)"));
    apply_->setEnabled(false);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(apply_, &QPushButton::clicked, this, &FrictionCurveDialog::apply);
    connect(open, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open a jog log"), QString(),
            tr("Experiment logs (*.csv *.tsv *.txt *.lvm *.mat);;All files (*)"));
        if (!path.isEmpty())
            loadFile(path);
    });
}

void FrictionCurveDialog::loadFile(const QString& path) {
    path_ = path;
    names_.clear();
    data_.clear();
    estimate_.reset();
    for (QComboBox* box : columns_)
        box->clear();
    try {
        ExperimentTable table = readExperimentTable(path.toStdString(), 1);
        names_ = table.names;
        data_ = std::move(table.columns);
    } catch (const std::exception& e) {
        file_->setText(QFileInfo(path).fileName());
        result_->setText(QStringLiteral("<span style='color:#d62728'>%1</span>")
                             .arg(exceptionText(e).toHtmlEscaped()));
        draw();
        return;
    }
    file_->setText(tr("%1: %2 columns, %3 rows")
                       .arg(QFileInfo(path).fileName())
                       .arg(names_.size())
                       .arg(data_.empty() ? 0 : data_.front().size()));
    for (int i = 0; i < 4; ++i) {
        for (const std::string& n : names_)
            columns_[i]->addItem(QString::fromStdString(n));
        // The columns of excite --signal jog by name, else the file's order.
        const int named = columns_[i]->findText(kRoles[i]);
        columns_[i]->setCurrentIndex(named >= 0 ? named : std::min(i, columns_[i]->count() - 1));
    }
    runEstimate();
}

void FrictionCurveDialog::runEstimate() {
    estimate_.reset();
    const QString roles[4] = {tr("time"), tr("reference"), tr("position"), tr("command")};
    try {
        std::vector<double> cols[4];
        for (int i = 0; i < 4; ++i) {
            const int c = columns_[i]->currentIndex();
            if (c < 0)
                throw InvalidInput(roles[i].toStdString(), tr("choose its column").toStdString());
            cols[i] = data_[static_cast<std::size_t>(c)];
        }
        estimate_ = identifyFriction(cols[0], cols[1], cols[2], cols[3]);
    } catch (const InvalidInput& e) {
        result_->setText(QStringLiteral("<span style='color:#d62728'>%1</span>")
                             .arg(exceptionText(e).toHtmlEscaped()));
    }
    draw();
}

void FrictionCurveDialog::draw() {
    points_->data()->clear();
    bars_->data()->clear();
    forward_->data()->clear();
    backward_->data()->clear();
    apply_->setEnabled(estimate_.has_value());
    if (!estimate_) {
        plot_->replot();
        return;
    }
    const FrictionEstimate& e = *estimate_;
    QVector<double> v, u, sd;
    double top = 0.0;
    for (const FrictionPoint& p : e.points) {
        v << p.velocityMmPerS;
        u << p.volts;
        sd << p.voltsStd;
        top = std::max(top, std::abs(p.velocityMmPerS));
    }
    points_->setData(v, u, true);
    bars_->setData(sd);
    // The curve on each side of v = 0 (the Coulomb step between them is not drawn as a line).
    for (int side : {1, -1}) {
        QVector<double> cv, cu;
        for (int i = 0; i <= 200; ++i) {
            const double x = side * top * 1.05 * (0.002 + 0.998 * i / 200.0);
            cv << x;
            cu << curve(e, x);
        }
        (side > 0 ? forward_ : backward_)->setData(cv, cu, side > 0);
    }
    plot_->rescaleAxes();
    plot_->xAxis->scaleRange(1.1);
    plot_->yAxis->scaleRange(1.15);
    // The slope against the model's own damping (a2/k0 per mm of travel).
    const AxisSettings& axis =
        session_->session().axes.at(static_cast<std::size_t>(session_->currentAxis()));
    const double model = axis.gt.plant.a2 / axis.gt.plant.k0 * axis.gt.modelUnitsPerPositionUnit;
    QString text = tr("Coulomb %1; slope %2 (the model's own a2/k0: %3 V per mm/s, so %4 beyond "
                      "it)")
                       .arg(withStd(e.coulombVolts, e.coulombStd, tr("V")),
                            withStd(e.viscousVoltsPerMmPerS, e.viscousStd, tr("V per mm/s")))
                       .arg(model, 0, 'g', 5)
                       .arg(e.viscousVoltsPerMmPerS - model, 0, 'g', 3);
    if (e.hasStribeck)
        text += tr("; static %1, Stribeck velocity %2")
                    .arg(withStd(e.staticVolts, e.staticStd, tr("V")),
                         withStd(e.stribeckVelocityMmPerS, e.stribeckStd, tr("mm/s")));
    text +=
        tr(". %1 jogs, residual sd %2 V.").arg(e.points.size()).arg(e.residualStdVolts, 0, 'g', 3);
    result_->setText(text.toHtmlEscaped());
    plot_->replot();
}

void FrictionCurveDialog::apply() {
    if (!estimate_)
        return;
    const FrictionEstimate& e = *estimate_;
    const int axisIndex = session_->currentAxis();
    const AxisSettings& axis = session_->session().axes.at(static_cast<std::size_t>(axisIndex));
    const double model = axis.gt.plant.a2 / axis.gt.plant.k0 * axis.gt.modelUnitsPerPositionUnit;
    TableFriction f = axis.friction;
    f.coulombVolts = std::max(0.0, e.coulombVolts);
    // The model already holds a2/k0 of the slope: only the excess is the table's viscous term.
    f.viscousVoltsPerMmPerS = std::max(0.0, e.viscousVoltsPerMmPerS - model);
    f.staticVolts = e.hasStribeck ? std::max(e.staticVolts, f.coulombVolts) : 0.0;
    f.stribeckVelocityMmPerS = e.hasStribeck ? e.stribeckVelocityMmPerS : 0.0;
    try {
        validateTableFriction(f);
    } catch (const InvalidInput& error) {
        result_->setText(exceptionText(error).toHtmlEscaped());
        return;
    }
    session_->setFriction(axisIndex, f, axis.frictionCompensation);
}

} // namespace xyt::ui
