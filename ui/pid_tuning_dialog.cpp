// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/pid_tuning_dialog.h"

#include "core/analysis/stability_margins.h"
#include "core/model/errors.h"
#include "ui/panels/number_field.h"
#include "ui/plots/number_text.h"
#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"
#include "ui/session/tuning_session.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace xyt::ui {

namespace {

/// The loop's crossover and phase margin of gains @p g on the plant (NaN when none).
void measureLoop(ProposedGains& g, const ThirdOrderPlant& plant, double unit) {
    const TransferFunction c(Polynomial::fromDescending({g.d / unit, g.p / unit, g.i / unit}),
                             Polynomial::fromDescending({1.0, 0.0}));
    const StabilityMargins m = stabilityMargins(series(c, plant.transferFunction()));
    g.phaseMarginDeg = m.phaseMarginDeg;
    g.crossoverRadPerSec =
        m.phaseMargins.empty() ? std::nan("") : m.phaseMargins.front().omegaRadPerSec;
}

QString shown(double v) {
    return std::isfinite(v) ? significant(v, 4) : QStringLiteral("—");
}

} // namespace

PidTuningDialog::PidTuningDialog(TuningSession* session, int axis, QWidget* parent)
    : QDialog(parent), session_(session), axis_(axis) {
    const AxisSettings& a = session->session().axes.at(static_cast<std::size_t>(axis));
    plant_ = a.gt.plant;
    unit_ = a.gt.modelUnitsPerPositionUnit;
    setWindowTitle(tr("Tune the PID of axis %1").arg(QString::fromStdString(a.id).toUpper()));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    structure_ = new QComboBox(this);
    structure_->addItem(tr("PI"));
    structure_->addItem(tr("PID (Ti = 4 Td)"));
    structure_->setAccessibleName(tr("Controller structure"));
    structure_->setToolTip(tr("PI, or PID with Ti = 4 Td, for the closed-form rule"));
    const auto positive = [](const char* name) {
        return [name](double v) { requirePositive(v, name); };
    };
    crossover_ = new NumberField("crossover", positive("crossover"), this);
    phaseMargin_ = new NumberField(
        "phase_margin",
        [](double v) {
            requireFinite(v, "phase_margin");
            if (!(v > 0.0 && v < 180.0))
                throw InvalidInput("phase_margin",
                                   tr("must be between 0 and 180 degrees").toStdString());
        },
        this);
    relay_ = new NumberField("relay_amplitude", positive("relay_amplitude"), this);
    crossover_->setValue(5.0); // reachable by a PI on both of Braga et al.'s bases
    phaseMargin_->setValue(60.0);
    relay_->setValue(1.0);
    crossover_->setToolTip(tr("Target gain crossover ωc (rad/s): the closed-form gains make "
                              "|L(jωc)| = 1, L = (P + I/s + D s) G/u"));
    phaseMargin_->setToolTip(tr("Target phase margin (°) at ωc: arg L(jωc) = −180° + PM"));
    relay_->setToolTip(tr("Relay amplitude d (V) of the simulated relay experiment; its limit "
                          "cycle's amplitude a and period Tu give Ku = 4d/(πa) for Ziegler–Nichols "
                          "and Tyreus–Luyben"));
    form->addRow(tr("Structure"), structure_);
    form->addRow(tr("Crossover ωc (rad/s)"), crossover_);
    form->addRow(tr("Phase margin (°)"), phaseMargin_);
    form->addRow(tr("Relay amplitude d (V)"), relay_);
    layout->addLayout(form);
    table_ = new QTableWidget(3, 7, this);
    table_->setHorizontalHeaderLabels({tr("Rule"), tr("P (V/mm)"), tr("I (V/(mm s))"),
                                       tr("D (V s/mm)"), tr("ωc (rad/s)"), tr("PM (°)"),
                                       QString()});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int row = 0; row < 3; ++row) {
        auto* button = new QPushButton(tr("Apply"), table_);
        button->setToolTip(tr("Set this row's P, I and D on the axis (one undoable step)"));
        apply_[static_cast<std::size_t>(row)] = button;
        table_->setCellWidget(row, 6, button);
        connect(button, &QPushButton::clicked, this, [this, row] { apply(row); });
    }
    layout->addWidget(table_);
    relayLabel_ = new QLabel(this);
    relayLabel_->setWordWrap(true);
    relayLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(relayLabel_);
    plot_ = new QCustomPlot(this);
    plot_->setMinimumHeight(180);
    plot_->setToolTip(tr("The simulated relay experiment: the position y (mm) and the relay's "
                         "command u (V) against time (s), settling into the limit cycle"));
    plot_->addGraph();
    plot_->graph(0)->setName(tr("position y (mm)"));
    plot_->graph(0)->setPen(QPen(colors::output, 1.5));
    plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    plot_->graph(1)->setName(tr("relay u (V)"));
    plot_->graph(1)->setPen(QPen(colors::control, 1.2));
    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->yAxis->setLabel(tr("y (mm)"));
    plot_->yAxis2->setLabel(tr("u (V)"));
    plot_->yAxis2->setVisible(true);
    plot_->legend->setVisible(true);
    plot_->legend->setFont(QFont(font().family(), 8));
    plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    setupInteractivePlot(plot_);
    layout->addWidget(plot_, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    for (NumberField* f : {crossover_, phaseMargin_, relay_})
        connect(f, &NumberField::valueAccepted, this, &PidTuningDialog::recompute);
    connect(structure_, &QComboBox::activated, this, &PidTuningDialog::recompute);
    resize(720, 560);
    recompute();
}

void PidTuningDialog::recompute() {
    const PidStructure structure =
        structure_->currentIndex() == 1 ? PidStructure::Pid : PidStructure::Pi;
    const auto fail = [](ProposedGains& g, const QString& reason) {
        g.ok = false;
        g.reason = reason;
    };
    rows_ = {};
    rows_[0].rule = tr("Crossover and phase margin");
    rows_[1].rule = tr("Relay: Ziegler–Nichols");
    rows_[2].rule = tr("Relay: Tyreus–Luyben");
    try {
        const PidTuningResult r =
            tunePidForMargin(plant_, unit_, structure, crossover_->value(), phaseMargin_->value());
        ProposedGains& g = rows_[0];
        if (r.ok()) {
            g.ok = true;
            g.p = r.p;
            g.i = r.i;
            g.d = r.d;
            g.crossoverRadPerSec = r.achievedCrossoverRadPerSec;
            g.phaseMarginDeg = r.achievedPhaseMarginDeg;
        } else {
            fail(g, diagnosticText(r.reason));
        }
    } catch (const InvalidInput& e) {
        fail(rows_[0], exceptionText(e));
    }
    plot_->graph(0)->data()->clear();
    plot_->graph(1)->data()->clear();
    try {
        const double d = relay_->value();
        const RelayLimitCycle cycle = relayLimitCycle(plant_, unit_, d);
        const RelayDescribingFunction df = relayDescribingFunction(plant_, unit_, d);
        if (!cycle.found)
            throw InvalidInput("relay_amplitude", cycle.status);
        RelaySimulationOptions options;
        options.durationSeconds = 8.0 * cycle.periodSeconds;
        options.stepSeconds = cycle.periodSeconds / 400.0;
        options.initialOffsetMm = 0.1 * cycle.amplitudeMm;
        const RelaySimulation sim = simulateRelayFeedback(plant_, unit_, d, options);
        plot_->graph(0)->setData(QVector<double>(sim.tSeconds.begin(), sim.tSeconds.end()),
                                 QVector<double>(sim.yMm.begin(), sim.yMm.end()), true);
        plot_->graph(1)->setData(QVector<double>(sim.tSeconds.begin(), sim.tSeconds.end()),
                                 QVector<double>(sim.uVolts.begin(), sim.uVolts.end()), true);
        plot_->xAxis->setRange(sim.tSeconds.front(), sim.tSeconds.back());
        // Headroom above the curves for the legend.
        plot_->yAxis->setRange(-1.2 * cycle.amplitudeMm, 1.9 * cycle.amplitudeMm);
        plot_->yAxis2->setRange(-1.2 * d, 1.9 * d);
        relayLabel_->setText(
            tr("Relay limit cycle on the model: period Tu = %1 s, amplitude a = %2 mm, "
               "Ku = 4d/(πa) = %3 V/mm (describing function: Tu = %4 s, a = %5 mm).")
                .arg(shown(cycle.periodSeconds), shown(cycle.amplitudeMm),
                     shown(cycle.ultimateGainVoltsPerMm), shown(df.periodSeconds),
                     shown(df.amplitudeMm)));
        const UltimateCycleRule rules[2] = {UltimateCycleRule::ZieglerNichols,
                                            UltimateCycleRule::TyreusLuyben};
        for (int k = 0; k < 2; ++k) {
            const UltimateCycleGains u = ultimateCycleGains(
                cycle.ultimateGainVoltsPerMm, cycle.periodSeconds, rules[k], structure);
            ProposedGains& g = rows_[static_cast<std::size_t>(k + 1)];
            g.ok = true;
            g.p = u.p;
            g.i = u.i;
            g.d = u.d;
            measureLoop(g, plant_, unit_);
        }
    } catch (const InvalidInput& e) {
        relayLabel_->setText(tr("No relay experiment: %1").arg(exceptionText(e)));
        fail(rows_[1], relayLabel_->text());
        fail(rows_[2], relayLabel_->text());
    }
    plot_->replot(QCustomPlot::rpQueuedReplot);
    for (int row = 0; row < 3; ++row) {
        const ProposedGains& g = rows_[static_cast<std::size_t>(row)];
        const QStringList cells = g.ok ? QStringList{g.rule,
                                                     shown(g.p),
                                                     shown(g.i),
                                                     shown(g.d),
                                                     shown(g.crossoverRadPerSec),
                                                     shown(g.phaseMarginDeg)}
                                       : QStringList{g.rule, g.reason};
        for (int column = 0; column < 6; ++column) {
            auto* item = new QTableWidgetItem(column < cells.size() ? cells[column] : QString());
            item->setToolTip(g.ok ? QString() : g.reason);
            table_->setItem(row, column, item);
        }
        if (!g.ok)
            table_->setSpan(row, 1, 1, 5);
        else if (table_->columnSpan(row, 1) > 1)
            table_->setSpan(row, 1, 1, 1);
        apply_[static_cast<std::size_t>(row)]->setEnabled(g.ok);
    }
    table_->resizeColumnsToContents();
    table_->setFixedHeight(table_->horizontalHeader()->height() + 3 * table_->rowHeight(0) +
                           2 * table_->frameWidth());
}

void PidTuningDialog::apply(int row) {
    const ProposedGains& g = rows_.at(static_cast<std::size_t>(row));
    if (!g.ok)
        return;
    AxisSettings next = session_->session().axes.at(static_cast<std::size_t>(axis_));
    next.parameters["p"] = g.p;
    next.parameters["i"] = g.i;
    next.parameters["d"] = g.d;
    session_->setAxis(
        axis_, next,
        tr("Tune %1 by %2").arg(QString::fromStdString(next.id).toUpper(), g.rule.toLower()));
}

const ProposedGains& PidTuningDialog::proposal(int row) const {
    return rows_.at(static_cast<std::size_t>(row));
}

QPushButton* PidTuningDialog::applyButton(int row) const {
    return apply_.at(static_cast<std::size_t>(row));
}

QString PidTuningDialog::relayText() const {
    return relayLabel_->text();
}

} // namespace xyt::ui
