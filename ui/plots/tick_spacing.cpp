// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/tick_spacing.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt::ui {

namespace {

constexpr char kMostTicks[] = "xyt-most-ticks"; ///< the ticker's count before any fitting
constexpr char kLeastSpacing[] = "xyt-least-tick-spacing"; ///< pixels per tick at least
constexpr double kGapPx = 12.0;    ///< blank space wanted between two labels side by side
constexpr double kLineGapPx = 6.0; ///< between two labels one above the other

/// The count for a horizontal axis, whose labels grow with a finer step ("2.75" for "3").
int horizontalCount(const QCPAxis* axis, double length, double widest, int most) {
    const QCPAxisTicker* ticker = axis->ticker().data();
    // Ticks land on round steps: up to about twice the asked-for count can show (a count of 3
    // over [0, 1] gives 0, 0.5, 1 or 0, 0.2, ..., 1), so ask for half of what fits, at least 2.
    const auto countFor = [&](double labelWidth) {
        const int fit = static_cast<int>(length / (labelWidth + kGapPx));
        return std::clamp(fit / 2, 2, std::max(2, most));
    };
    int count = countFor(widest);
    // More ticks only with room to spare for labels half as wide again: the labels of a finer
    // step can be longer, and a count that went up and down again would redraw the plot
    // without end.
    if (count > ticker->tickCount())
        count = std::max(ticker->tickCount(), countFor(1.5 * widest));
    return count;
}

/// The count for a vertical axis. Its labels are one line tall whatever the step, so the ticks
/// the ticker would make for each count can be measured: the largest count whose ticks are a
/// label's height and a line gap apart, and no more labels than one per @p spacing pixels of
/// the length between the first and the last (0 when the axis asks for no spacing).
int verticalCount(QCPAxis* axis, double labelHeight, int spacing, int most) {
    QCPAxisTicker* ticker = axis->ticker().data();
    const int drawn = ticker->tickCount();
    const double length = axis->axisRect()->height();
    const int mostLabels =
        spacing > 0 ? 1 + static_cast<int>(length / spacing) : std::numeric_limits<int>::max();
    int count = 2;
    QVector<double> ticks;
    for (int asked = std::max(2, most); asked > 2; --asked) {
        ticker->setTickCount(asked);
        // Ticks only (no labels, no sub-ticks): the ticker's own steps for this count.
        ticker->generate(axis->range(), QLocale::c(), QLatin1Char('g'), 6, ticks, nullptr, nullptr);
        double closest = std::numeric_limits<double>::infinity();
        int inside = 0;
        for (int i = 0; i < ticks.size(); ++i) {
            if (!axis->range().contains(ticks[i]))
                continue;
            ++inside;
            if (i > 0 && axis->range().contains(ticks[i - 1]))
                closest = std::min(closest, std::abs(axis->coordToPixel(ticks[i]) -
                                                     axis->coordToPixel(ticks[i - 1])));
        }
        if (closest >= labelHeight + kLineGapPx && inside <= mostLabels) {
            count = asked;
            break;
        }
    }
    ticker->setTickCount(drawn);
    return count;
}

/// Fits the vertical axes of @p plot, and its horizontal ones with @p horizontals; true when a
/// count changed.
bool fitCounts(QCustomPlot* plot, bool horizontals) {
    bool changed = false;
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes()) {
            if (!axis->visible() || !axis->tickLabels() || !axis->ticker())
                continue;
            const bool horizontal = axis->orientation() == Qt::Horizontal;
            if (horizontal && !horizontals)
                continue;
            QCPAxisTicker* ticker = axis->ticker().data();
            QVariant most = axis->property(kMostTicks);
            if (!most.isValid()) {
                most = ticker->tickCount();
                axis->setProperty(kMostTicks, most);
            }
            const QFontMetricsF metrics(axis->tickLabelFont());
            double widest = 0.0; // along the axis
            for (const QString& label : axis->tickVectorLabels())
                widest = std::max(widest,
                                  horizontal ? metrics.horizontalAdvance(label) : metrics.height());
            if (widest <= 0.0)
                continue;
            const QVariant spacing = axis->property(kLeastSpacing);
            int count = 0;
            if (horizontal) {
                const double length = rect->width();
                int mostHere = most.toInt();
                if (spacing.isValid())
                    mostHere =
                        std::min(mostHere, std::max(2, static_cast<int>(length) / spacing.toInt()));
                count = horizontalCount(axis, length, widest, mostHere);
            } else {
                count = verticalCount(axis, widest, spacing.isValid() ? spacing.toInt() : 0,
                                      most.toInt());
            }
            if (count != ticker->tickCount()) {
                ticker->setTickCount(count);
                changed = true;
            }
        }
    return changed;
}

} // namespace

bool fitTickCounts(QCustomPlot* plot) {
    return fitCounts(plot, true);
}

bool fitVerticalTickCounts(QCustomPlot* plot) {
    return fitCounts(plot, false);
}

void setLeastTickSpacing(QCPAxis* axis, int pixels) {
    axis->setProperty(kLeastSpacing, pixels);
}

} // namespace xyt::ui
