// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/snapshot_compare_dialog.h"

#include "core/session/design_method_module.h"
#include "core/session/session_evaluation.h"
#include "ui/panels/metrics_panel.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace xyt::ui {

QList<QPair<QString, QString>> comparisonRows(const Session& design) {
    const SessionEvaluation e = evaluateSession(design);
    QList<QPair<QString, QString>> rows;
    for (int i = 0; i < 2; ++i) {
        const AxisSettings& s = design.axes[static_cast<std::size_t>(i)];
        const AxisEvaluation& a = e.axes[static_cast<std::size_t>(i)];
        const QString id = QString::fromStdString(s.id).toUpper();
        if (!a.ok) {
            rows.append({QObject::tr("%1 design").arg(id),
                         QString::fromStdString(a.errorField + ": " + a.error.text)});
            continue;
        }
        for (const DesignCoefficient& c : designMethodModule(a.method).coefficients(a))
            rows.append(
                {c.unit.empty()
                     ? QStringLiteral("%1 %2").arg(id, QString::fromStdString(c.name))
                     : QStringLiteral("%1 %2 (%3)")
                           .arg(id, QString::fromStdString(c.name), QString::fromStdString(c.unit)),
                 QString::number(c.value, 'g', 6)});
        const std::vector<std::complex<double>> poles = a.closedLoop().poles();
        QStringList shown;
        for (const auto& p : poles)
            shown << (p.imag() == 0.0 ? QString::number(p.real(), 'g', 4)
                                      : QStringLiteral("%1%2%3j")
                                            .arg(p.real(), 0, 'g', 4)
                                            .arg(p.imag() < 0 ? "−" : "+")
                                            .arg(std::abs(p.imag()), 0, 'g', 4));
        rows.append({QObject::tr("%1 closed-loop poles").arg(id), shown.join(", ")});
        rows.append({QObject::tr("%1 RMSE (mm)").arg(id), displayNumber(a.metrics.rmse)});
        rows.append({QObject::tr("%1 max |e| (mm)").arg(id), displayNumber(a.metrics.maxAbsError)});
        rows.append({QObject::tr("%1 max |u| (V)").arg(id), displayNumber(a.metrics.maxAbsU)});
        rows.append(
            {QObject::tr("%1 settling (s)").arg(id),
             a.step.stable ? displayNumber(a.step.settlingTimeSeconds) : QObject::tr("unstable")});
        rows.append({QObject::tr("%1 overshoot (%)").arg(id),
                     a.step.stable ? displayNumber(a.step.overshootPct) : QObject::tr("unstable")});
        rows.append({QObject::tr("%1 ITAE").arg(id), displayNumber(a.metrics.itae)});
    }
    return rows;
}

SnapshotCompareDialog::SnapshotCompareDialog(const Session& session, QWidget* parent)
    : QDialog(parent), session_(session) {
    setWindowTitle(tr("Compare designs"));
    auto* layout = new QVBoxLayout(this);
    auto* pick = new QHBoxLayout;
    left_ = new QComboBox(this);
    right_ = new QComboBox(this);
    for (QComboBox* box : {left_, right_}) {
        box->addItem(tr("Current design"));
        for (const DesignSnapshot& s : session.snapshots)
            box->addItem(QString::fromStdString(s.name));
    }
    // Compare with the newest snapshot. Set before the signals are connected: rebuild() needs
    // the table, which does not exist yet.
    if (right_->count() > 1)
        right_->setCurrentIndex(right_->count() - 1);
    pick->addWidget(new QLabel(tr("Compare"), this));
    left_->setToolTip(tr("The first design of the comparison: the current one or a stored "
                         "snapshot (Design › Store snapshot)"));
    right_->setToolTip(tr("The second design of the comparison; the table lists both designs' "
                          "settings and figures side by side"));
    pick->addWidget(left_, 1);
    pick->addWidget(new QLabel(tr("with"), this));
    pick->addWidget(right_, 1);
    layout->addLayout(pick);
    table_ = new QTableWidget(this);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    layout->addWidget(table_);
    for (QComboBox* box : {left_, right_})
        connect(box, &QComboBox::currentIndexChanged, this, &SnapshotCompareDialog::rebuild);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(720, 560);
    rebuild();
}

Session SnapshotCompareDialog::designAt(int index) const {
    if (index <= 0)
        return session_;
    return session_.withDesign(session_.snapshots.at(static_cast<std::size_t>(index - 1)));
}

void SnapshotCompareDialog::rebuild() {
    const auto a = comparisonRows(designAt(left_->currentIndex()));
    const auto b = comparisonRows(designAt(right_->currentIndex()));
    table_->clear();
    table_->setColumnCount(2);
    table_->setHorizontalHeaderLabels({left_->currentText(), right_->currentText()});
    QStringList labels;
    for (const auto& row : a)
        if (!labels.contains(row.first))
            labels << row.first;
    for (const auto& row : b)
        if (!labels.contains(row.first))
            labels << row.first;
    table_->setRowCount(static_cast<int>(labels.size()));
    table_->setVerticalHeaderLabels(labels);
    auto fill = [&](const QList<QPair<QString, QString>>& rows, int column) {
        for (const auto& row : rows) {
            auto* item = new QTableWidgetItem(row.second);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(static_cast<int>(labels.indexOf(row.first)), column, item);
        }
    };
    fill(a, 0);
    fill(b, 1);
}

} // namespace xyt::ui
