// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/metrics_panel.h"

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace xyt::ui {

QString displayNumber(double v, int decimals) {
    if (!std::isfinite(v))
        return QObject::tr("n/a");
    if (v != 0.0 && (std::abs(v) >= 1e6 || std::abs(v) < 1e-3))
        return QString::number(v, 'g', decimals + 1);
    return QString::number(v, 'f', decimals);
}

MetricsPanel::MetricsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    table_ = new QTableWidget(RowCount, 2, this);
    table_->setHorizontalHeaderLabels({tr("X"), tr("Y")});
    table_->setVerticalHeaderLabels({tr("RMSE (mm)"), tr("max |e| (mm)"), tr("max |e| (% travel)"),
                                     tr("max |u| (V)"), tr("saturated (s)"),
                                     tr("settling 2 % (s)"), tr("overshoot (%)"), tr("ITAE")});
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setAccessibleName(tr("Metrics"));
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    layout->addWidget(table_);
}

void MetricsPanel::showEvaluation(const Session& session, const SessionEvaluation& evaluation) {
    for (int c = 0; c < 2; ++c) {
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(c)];
        const QString header = QString::fromStdString(session.axes[static_cast<std::size_t>(c)].id).toUpper();
        table_->setHorizontalHeaderItem(c, new QTableWidgetItem(header));
        QStringList values;
        if (!a.ok) {
            for (int r = 0; r < RowCount; ++r)
                values << tr("—");
        } else {
            const auto& m = a.metrics;
            values << displayNumber(m.rmse) << displayNumber(m.maxAbsError)
                   << displayNumber(m.maxAbsErrorPct, 3) << displayNumber(m.maxAbsU)
                   << (m.saturated ? displayNumber(m.saturatedTimeSeconds, 2) : tr("no"))
                   << (a.step.stable ? displayNumber(a.step.settlingTimeSeconds, 2) : tr("unstable"))
                   << (a.step.stable ? displayNumber(a.step.overshootPct, 3) : tr("unstable"))
                   << displayNumber(m.itae, 1);
        }
        for (int r = 0; r < RowCount; ++r) {
            auto* item = new QTableWidgetItem(values[r]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (!a.ok)
                item->setToolTip(QString::fromStdString(a.errorField + ": " + a.error));
            table_->setItem(r, c, item);
        }
    }
}

} // namespace xyt::ui
