// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/contour_controls.h"

#include "ui/plots/contour_plot.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QToolButton>

namespace xyt::ui {

ContourControls::ContourControls(ContourPlot* plot) : QWidget(plot), plot_(plot) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    polar_ = new QCheckBox(tr("Ballbar"), this);
    polar_->setAccessibleName(tr("Ballbar polar view"));
    polar_->setToolTip(
        tr("The ISO 230-4 circular test of the program's full circles, as a ballbar plots it"));
    previous_ = new QToolButton(this);
    previous_->setText(tr("◀"));
    previous_->setAccessibleName(tr("Previous corner"));
    previous_->setToolTip(tr("Zoom to the previous sharp corner"));
    next_ = new QToolButton(this);
    next_->setText(tr("▶"));
    next_->setAccessibleName(tr("Next corner"));
    next_->setToolTip(tr("Zoom to the next sharp corner (after the last one: the whole path)"));
    for (QWidget* w : std::initializer_list<QWidget*>{polar_, previous_, next_})
        layout->addWidget(w);
    connect(polar_, &QCheckBox::toggled, this, [this](bool on) {
        plot_->setPolar(on);
        sync();
    });
    connect(previous_, &QToolButton::clicked, this, [this] { step(-1); });
    connect(next_, &QToolButton::clicked, this, [this] { step(+1); });
    connect(plot, &ContourPlot::cornerChanged, this, &ContourControls::sync);
    plot->installEventFilter(this);
    sync();
}

bool ContourControls::eventFilter(QObject* watched, QEvent* event) {
    if (watched == plot_ && event->type() == QEvent::Resize)
        place();
    return QWidget::eventFilter(watched, event);
}

void ContourControls::place() {
    adjustSize();
    move(plot_->width() - width() - 4, 2);
    raise();
    plot_->reserveTitleRoom(isVisibleTo(plot_) ? width() + 8 : 0);
}

void ContourControls::step(int direction) {
    const int count = plot_->cornerCount();
    if (count == 0)
        return;
    // Positions -1 (the whole path), 0 .. count - 1, cycling.
    const int next = (plot_->currentCorner() + 1 + direction + count + 1) % (count + 1) - 1;
    if (next < 0)
        plot_->fitAll();
    else
        plot_->zoomToCorner(next);
}

void ContourControls::sync() {
    const int count = plot_->cornerCount();
    polar_->setVisible(plot_->polarAvailable());
    previous_->setVisible(count > 0);
    next_->setVisible(count > 0);
    setVisible(count > 0 || plot_->polarAvailable());
    place();
}

} // namespace xyt::ui
