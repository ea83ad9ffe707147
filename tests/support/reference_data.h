// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Reads the reference tables under tests/data (directory from the XYT_TEST_DATA_DIR compile
// definition): comma-separated, one header line, text and number cells.

#include <QFile>
#include <QString>
#include <QStringList>
#include <QTest>

#include <vector>

namespace xyt::test {

struct CsvTable {
    QStringList header;
    std::vector<QStringList> rows;

    /// Column index by header name, -1 when absent.
    int column(const QString& name) const { return static_cast<int>(header.indexOf(name)); }
    double number(std::size_t row, const QString& name) const {
        return rows.at(row).at(column(name)).toDouble();
    }
};

/// The table in XYT_TEST_DATA_DIR/@p fileName; empty (no header) when it cannot be read.
inline CsvTable readCsv(const QString& fileName) {
    CsvTable table;
    QFile file(QStringLiteral(XYT_TEST_DATA_DIR) + '/' + fileName);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return table;
    table.header = QString::fromUtf8(file.readLine()).trimmed().split(',');
    while (!file.atEnd()) {
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        if (!line.isEmpty())
            table.rows.push_back(line.split(','));
    }
    return table;
}

} // namespace xyt::test
