// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session_evaluation.h"

#include <QMap>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace xyt::ui {
class NumberField;
}

namespace xyt::ui {

/// The figures of both axes side by side (RMSE, max error, max |u|, saturation, settling,
/// overshoot, ITAE, ZPETC improvement) against the editable specification, with a pass/fail
/// mark on each judged figure. Values that are not finite show as "n/a", never as NaN.
class MetricsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MetricsPanel(QWidget* parent = nullptr);
    /// Shows both axes' figures and warnings; @p liveNotice says what the live view limited.
    void showEvaluation(const Session& session, const SessionEvaluation& evaluation,
                        const QString& liveNotice = QString());
    QTableWidget* table() const { return table_; }
    NumberField* specField(const QString& name) const { return spec_.value(name); }
    /// The warnings of both axes and of the live view, one per line ("" when there are none).
    QString noticeText() const;

    /// Row order of the table.
    enum Row { Rmse, MaxError, MaxErrorPct, MaxU, Saturated, Settling, Overshoot, Itae,
               Improvement, RowCount };

signals:
    void specificationEdited(const Specification& spec);

private:
    QTableWidget* table_;
    QLabel* notices_;
    QMap<QString, NumberField*> spec_;
    Specification current_;
};

/// "1.2345" or "n/a" for non-finite values.
QString displayNumber(double v, int decimals = 4);

} // namespace xyt::ui
