// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/plots/parameter_locus_plot.h"

#include "ui/plots/plot_tools.h"

#include <cmath>

namespace xyt::ui {

ParameterLocusPlot::ParameterLocusPlot(QWidget* parent)
    : QCustomPlot(parent), grid_(this), notice_(this, axisRect(), Qt::AlignTop | Qt::AlignRight) {
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
    ends_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(Qt::black, 1.2), Qt::NoBrush, 6));
    ends_->setName(tr("start of the sweep"));
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    legend->setBrush(QColor(255, 255, 255, 210));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    setupInteractivePlot(this);
}

void ParameterLocusPlot::showLocus(const ParameterLocus& locus,
                                   const std::vector<std::complex<double>>& current,
                                   const QString& title) {
    title_->setText(title);
    title_->setTextColor(palette().color(QPalette::WindowText));
    hasResult_ = true;
    QStringList warnings;
    for (const std::string& w : locus.warnings)
        warnings << QString::fromStdString(w);
    legend->setVisible(true);
    notice_.setSevere(false);
    notice_.setLines(warnings);
    showBranches(this, branches_, locus.branches, [](std::size_t) { return QPen(colors::output, 1.6); });
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
    grid_.show(0.0, extent);
    // Keep the user's zoom while the current poles and the sweep's ends stay in view.
    std::vector<std::complex<double>> markers = current;
    markers.insert(markers.end(), starts.begin(), starts.end());
    if (!ranged_ || anyOutsideView(this, markers)) {
        std::vector<std::complex<double>> all = markers;
        for (const auto& roots : locus.branches)
            all.insert(all.end(), roots.begin(), roots.end());
        setView(this, fittedBox({}, all));
        ranged_ = true;
    }
    replot(QCustomPlot::rpQueuedReplot);
}

void ParameterLocusPlot::showNoResult(const QString& title, const QString& reason) {
    hasResult_ = false;
    title_->setText(title);
    title_->setTextColor(colors::error);
    showBranches(this, branches_, {}, [](std::size_t) { return QPen(); });
    current_->data()->clear();
    ends_->data()->clear();
    legend->setVisible(false);
    notice_.setSevere(true);
    notice_.setLines({reason});
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace xyt::ui
