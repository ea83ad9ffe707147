// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/parameter_locus_plot.h"

#include "ui/plots/plot_tools.h"
#include "ui/session/diagnostic_text.h"

#include <algorithm>
#include <cmath>

namespace xyt::ui {

namespace {
/// How a parameter reads on the plot: "ωn" for wn, the name itself otherwise.
QString symbolOf(const std::string& name) {
    return name == "wn" ? QStringLiteral("ωn") : QString::fromStdString(name);
}

QString formatValue(double v) {
    return QString::number(v, 'g', 3);
}

/// Up to @p wanted "nice" values (1, 2, 5 times a power of ten) strictly inside [lo, hi],
/// spread over the range (every other one when there are too many).
std::vector<double> niceValues(double lo, double hi, std::size_t wanted) {
    std::vector<double> all;
    if (!(lo > 0.0) || !(hi > lo))
        return all;
    for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= std::ceil(std::log10(hi)); ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, e);
            if (v > lo * 1.0001 && v < hi / 1.0001)
                all.push_back(v);
        }
    std::vector<double> picked;
    const std::size_t stride = std::max<std::size_t>(1, (all.size() + wanted - 1) / wanted);
    for (std::size_t i = 0; i < all.size(); i += stride)
        picked.push_back(all[i]);
    return picked;
}
} // namespace

ParameterLocusPlot::ParameterLocusPlot(QWidget* parent)
    : PlotWidget(parent), grid_(this), notice_(this, axisRect(), Qt::AlignTop | Qt::AlignRight) {
    setToolTip(tr("Parameter locus: the closed-loop poles as the chosen parameter (ωn or kp) "
                  "sweeps its range, with the design's value marked and the value where the loop "
                  "turns unstable (a pole crossing the imaginary axis) marked."));
    setObjectName("parameter-locus");
    plotLayout()->insertRow(0);
    title_ = new QCPTextElement(this, QString(), QFont(font().family(), 10, QFont::Bold));
    plotLayout()->addElement(0, 0, title_);
    styleAxisRect(axisRect());
    xAxis->setLabel(tr("real"));
    yAxis->setLabel(tr("imaginary"));
    current_ = addGraph();
    current_->setLineStyle(QCPGraph::lsNone);
    current_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(colors::error, 1.5),
                                              QBrush(colors::error), 10));
    current_->setName(tr("current design"));
    ends_ = addGraph();
    ends_->setLineStyle(QCPGraph::lsNone);
    ends_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(Qt::black, 1.2), Qt::NoBrush, 6));
    ends_->setName(tr("start of the sweep"));
    boundary_ = addGraph();
    boundary_->setLineStyle(QCPGraph::lsNone);
    boundary_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssStar,
                                               QPen(QColor(0xd6, 0x27, 0x28), 2), Qt::NoBrush, 13));
    boundary_->setName(tr("stability boundary crossed"));
    // The legend sits in a row under the plane, where it hides no branch or pole.
    placeLegendBelow(this, 2);
    setupInteractivePlot(this);
}

void ParameterLocusPlot::showLocus(const ParameterLocus& locus,
                                   const std::vector<std::complex<double>>& current,
                                   const QString& title) {
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    hasResult_ = true;
    QStringList warnings;
    for (const auto& w : locus.warnings)
        warnings << diagnosticText(w);
    legend->setVisible(true);
    notice_.setSevere(false);
    showBranches(this, branches_, locus.branches,
                 [](std::size_t) { return QPen(colors::output, 1.6); });
    std::vector<std::complex<double>> starts;
    double extent = 1e-6;
    for (const auto& roots : locus.branches) {
        for (const auto& r : roots)
            extent = std::max(extent, std::abs(r));
        if (!roots.empty())
            starts.push_back(roots.front());
    }
    setComplexPoints(current_, current);
    setComplexPoints(ends_, starts);
    std::vector<std::complex<double>> crossings;
    for (const StabilityChange& c : locus.stabilityChanges) {
        crossings.push_back(c.pole);
        crossings.push_back(std::conj(c.pole));
    }
    setComplexPoints(boundary_, crossings);
    grid_.show(0.0, extent);

    // Frame the view on where the branches go: a branch that barely moves over the whole sweep
    // (travel below 5 % of its distance from the origin, like the plant's fast poles as wn
    // sweeps) would otherwise set the scale and squeeze the dominant poles into a few pixels.
    // Both half-planes are shown, with room right of the imaginary axis.
    std::vector<std::complex<double>> framed = crossings, fixedPoles;
    std::vector<bool> moving(locus.branches.size(), false);
    for (std::size_t b = 0; b < locus.branches.size(); ++b) {
        const auto& roots = locus.branches[b];
        if (roots.empty())
            continue;
        double travel = 0.0, size = 0.0;
        for (const auto& r : roots) {
            travel = std::max(travel, std::abs(r - roots.front()));
            size = std::max(size, std::abs(r));
        }
        moving[b] = travel >= 0.05 * size;
        if (moving[b])
            framed.insert(framed.end(), roots.begin(), roots.end());
        else
            fixedPoles.push_back(roots.back());
    }
    framedBranches_ = static_cast<int>(std::count(moving.begin(), moving.end(), true));
    if (framedBranches_ == 0) { // nothing moves: show everything
        fixedPoles.clear();
        for (const auto& roots : locus.branches)
            framed.insert(framed.end(), roots.begin(), roots.end());
    }
    if (fixedPoles.size() > 0) {
        QStringList where;
        for (const auto& p : fixedPoles)
            if (p.imag() >= -1e-12)
                where << QString::number(p.real(), 'g', 3) +
                             (std::abs(p.imag()) > 1e-9
                                  ? QStringLiteral(" ± %1j").arg(std::abs(p.imag()), 0, 'g', 3)
                                  : QString());
        warnings << (fixedPoles.size() == 1
                         ? tr("framed on the poles that move; one pole barely moves and may lie "
                              "outside the view: %1")
                         : tr("framed on the poles that move; %1 poles barely move and may lie "
                              "outside the view: %2")
                               .arg(fixedPoles.size()))
                        .arg(where.join(", "));
    }
    notice_.setLines(warnings);
    PlaneBox box = fittedBox({}, framed);
    const double span = std::max(box.reMax - box.reMin, box.imMax - box.imMin);
    box.reMax = std::max(box.reMax, 0.2 * span); // the right half-plane is always in view
    if (!ranged_ || (!viewHeld() && anyOutsideView(this, framed))) {
        setView(this, box);
        ranged_ = true;
    }

    // Labels: the parameter at a few nice values along each moving branch (upper half-plane
    // and real axis only: conjugates would repeat them), and at each boundary crossing.
    for (QCPItemText* t : labels_)
        removeItem(t);
    labels_.clear();
    // A label too close (in pixels, at the view just fitted) to one already placed is left
    // out: near the origin the small parameter values crowd together.
    std::vector<QPointF> placed;
    const auto addLabel = [this, &placed](std::complex<double> at, const QString& text,
                                          const QColor& color, Qt::Alignment align, bool always) {
        const QPointF px(xAxis->coordToPixel(at.real()), yAxis->coordToPixel(at.imag()));
        for (const QPointF& q : placed)
            if (!always && std::abs(q.x() - px.x()) < 60 && std::abs(q.y() - px.y()) < 14)
                return;
        placed.push_back(px);
        auto* t = new QCPItemText(this);
        t->position->setCoords(at.real(), at.imag());
        t->setPositionAlignment(align);
        t->setText(text);
        t->setColor(color);
        t->setFont(QFont(font().family(), 7));
        t->setClipToAxisRect(true);
        t->setPadding(QMargins(8, 1, 3, 1));
        labels_.push_back(t);
    };
    const QString symbol = symbolOf(locus.parameterName);
    for (const StabilityChange& c : locus.stabilityChanges)
        addLabel(c.pole,
                 (c.becomesUnstable ? tr("unstable above %1 = %2") : tr("unstable below %1 = %2"))
                     .arg(symbol, formatValue(c.value)),
                 QColor(0xd6, 0x27, 0x28), Qt::AlignLeft | Qt::AlignVCenter, true);
    if (!locus.values.empty()) {
        const auto [lo, hi] = std::minmax_element(locus.values.begin(), locus.values.end());
        for (double v : niceValues(*lo, *hi, 5)) {
            std::size_t best = 0;
            for (std::size_t i = 1; i < locus.values.size(); ++i)
                if (std::abs(std::log(locus.values[i] / v)) <
                    std::abs(std::log(locus.values[best] / v)))
                    best = i;
            for (std::size_t b = 0; b < locus.branches.size(); ++b)
                if (moving[b] && best < locus.branches[b].size() &&
                    locus.branches[b][best].imag() >= -1e-9)
                    addLabel(locus.branches[b][best], symbol + "=" + formatValue(v),
                             QColor(0x55, 0x55, 0x55), Qt::AlignLeft | Qt::AlignBottom, false);
        }
    }
    replot(QCustomPlot::rpQueuedReplot);
}

QStringList ParameterLocusPlot::labelTexts() const {
    QStringList texts;
    for (const QCPItemText* t : labels_)
        texts << t->text();
    return texts;
}

void ParameterLocusPlot::showNoResult(const QString& title, const QString& reason) {
    hasResult_ = false;
    title_->setText(title);
    title_->setTextColor(colors::error);
    showBranches(this, branches_, {}, [](std::size_t) { return QPen(); });
    current_->data()->clear();
    ends_->data()->clear();
    boundary_->data()->clear();
    for (QCPItemText* t : labels_)
        removeItem(t);
    labels_.clear();
    legend->setVisible(false);
    notice_.setSevere(true);
    notice_.setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
