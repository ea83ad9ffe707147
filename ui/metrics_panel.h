// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session_evaluation.h"

#include <QWidget>

class QTableWidget;

namespace xyt::ui {

/// The figures of both axes side by side (RMSE, max error, max |u|, saturation, settling,
/// overshoot, ITAE). Values that are not finite show as "n/a", never as NaN.
class MetricsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MetricsPanel(QWidget* parent = nullptr);
    void showEvaluation(const Session& session, const SessionEvaluation& evaluation);
    QTableWidget* table() const { return table_; }

    /// Row order of the table.
    enum Row { Rmse, MaxError, MaxErrorPct, MaxU, Saturated, Settling, Overshoot, Itae, RowCount };

private:
    QTableWidget* table_;
};

/// "1.2345" or "n/a" for non-finite values.
QString displayNumber(double v, int decimals = 4);

} // namespace xyt::ui
