// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/legend_columns.h"

#include <qcustomplot.h>

#include <algorithm>
#include <vector>

namespace xyt::ui {

namespace {

constexpr char kMaxColumns[] = "xyt-legend-max-columns";

/// Width of the entries laid out in @p columns columns (row by row), spacing included.
int widthInColumns(const std::vector<int>& widths, int columns, int spacing) {
    std::vector<int> column(static_cast<std::size_t>(columns), 0);
    for (std::size_t i = 0; i < widths.size(); ++i) {
        int& w = column[i % static_cast<std::size_t>(columns)];
        w = std::max(w, widths[i]);
    }
    int total = spacing * (columns - 1);
    for (int w : column)
        total += w;
    return total;
}

/// The most columns (up to @p most) that fit @p legend's row; 1 when none does.
int columnsThatFit(QCPLegend* legend, int most) {
    std::vector<int> widths;
    for (int i = 0; i < legend->itemCount(); ++i) {
        // minimumOuterSizeHint is public on the layout element: the entry's icon and text.
        // A cell is empty where an entry was taken out (QCPLegend::itemCount counts cells;
        // fitLegendColumns packs the entries again).
        if (const QCPLayoutElement* item = legend->item(i))
            widths.push_back(item->minimumOuterSizeHint().width());
    }
    const int room = legend->rect().width();
    most = std::min(most, static_cast<int>(widths.size()));
    for (int columns = most; columns > 1; --columns)
        if (widthInColumns(widths, columns, legend->columnSpacing()) <= room)
            return columns;
    return 1;
}

} // namespace

void setMaxLegendColumns(QCPLegend* legend, int columns) {
    legend->setProperty(kMaxColumns, columns);
    legend->setWrap(columns);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
}

bool fitLegendColumns(QCustomPlot* plot) {
    bool changed = false;
    for (int k = 0; k < plot->plotLayout()->elementCount(); ++k) {
        auto* legend = qobject_cast<QCPLegend*>(plot->plotLayout()->elementAt(k));
        if (!legend || !legend->visible() || legend->itemCount() == 0)
            continue;
        const QVariant most = legend->property(kMaxColumns);
        if (!most.isValid())
            continue;
        // A gap where an entry was taken out: an empty cell before an entry (the cells after
        // the last entry of a grid that does not fill its last row are empty too).
        bool holes = false, gap = false;
        for (int i = 0; i < legend->itemCount(); ++i) {
            holes = holes || (gap && legend->item(i));
            gap = gap || !legend->item(i);
        }
        const int columns =
            legend->rect().width() > 0 ? columnsThatFit(legend, most.toInt()) : legend->wrap();
        if (columns != legend->wrap() || holes) {
            legend->setWrap(columns);
            legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true); // the entries re-placed
            changed = true;
        }
    }
    return changed;
}

} // namespace xyt::ui
