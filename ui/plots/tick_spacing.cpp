// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/tick_spacing.h"

#include <qcustomplot.h>

#include <algorithm>

namespace xyt::ui {

namespace {

constexpr char kMostTicks[] = "xyt-most-ticks"; ///< the ticker's count before any fitting
constexpr char kLeastSpacing[] = "xyt-least-tick-spacing"; ///< pixels per tick at least
constexpr double kGapPx = 12.0;    ///< blank space wanted between two labels side by side
constexpr double kLineGapPx = 6.0; ///< between two labels one above the other

} // namespace

bool fitTickCounts(QCustomPlot* plot) {
    bool changed = false;
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes()) {
            if (!axis->visible() || !axis->tickLabels() || !axis->ticker())
                continue;
            QCPAxisTicker* ticker = axis->ticker().data();
            QVariant most = axis->property(kMostTicks);
            if (!most.isValid()) {
                most = ticker->tickCount();
                axis->setProperty(kMostTicks, most);
            }
            const QFontMetricsF metrics(axis->tickLabelFont());
            const bool horizontal = axis->orientation() == Qt::Horizontal;
            double widest = 0.0; // along the axis
            for (const QString& label : axis->tickVectorLabels())
                widest = std::max(widest,
                                  horizontal ? metrics.horizontalAdvance(label) : metrics.height());
            if (widest <= 0.0)
                continue;
            const double length = horizontal ? rect->width() : rect->height();
            int mostHere = most.toInt();
            if (const QVariant spacing = axis->property(kLeastSpacing); spacing.isValid())
                mostHere =
                    std::min(mostHere, std::max(2, static_cast<int>(length) / spacing.toInt()));
            const double gap = horizontal ? kGapPx : kLineGapPx;
            // Ticks land on round steps: up to about twice the asked-for count can show (a
            // count of 3 over [0, 1] gives 0, 0.5, 1 or 0, 0.2, ..., 1), so ask for half of
            // what fits, at least 2.
            const auto countFor = [&](double labelWidth) {
                const int fit = static_cast<int>(length / (labelWidth + gap));
                return std::clamp(fit / 2, 2, std::max(2, mostHere));
            };
            int count = countFor(widest);
            // More ticks only with room to spare for labels half as wide again: the labels
            // of a finer step can be longer ("2.75" for "3"), and a count that went up and
            // down again would redraw the plot without end.
            if (count > ticker->tickCount())
                count = std::max(ticker->tickCount(), countFor(1.5 * widest));
            if (count != ticker->tickCount()) {
                ticker->setTickCount(count);
                changed = true;
            }
        }
    return changed;
}

void setLeastTickSpacing(QCPAxis* axis, int pixels) {
    axis->setProperty(kLeastSpacing, pixels);
}

} // namespace xyt::ui
