// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/session/session.h"

#include <QDialog>

class QComboBox;
class QTableWidget;

namespace xyt::ui {

/// A table comparing two designs (the current one or stored snapshots): gains, closed-loop
/// poles and metrics of both axes, side by side.
class SnapshotCompareDialog : public QDialog {
    Q_OBJECT
public:
    SnapshotCompareDialog(const Session& session, QWidget* parent = nullptr);
    QTableWidget* table() const { return table_; }
    QComboBox* leftBox() const { return left_; }
    QComboBox* rightBox() const { return right_; }

private:
    void rebuild();
    Session designAt(int index) const;

    Session session_;
    QComboBox* left_ = nullptr;
    QComboBox* right_ = nullptr;
    QTableWidget* table_ = nullptr;
};

/// The rows of the comparison for one design: (label, value) pairs.
QList<QPair<QString, QString>> comparisonRows(const Session& design);

} // namespace xyt::ui
